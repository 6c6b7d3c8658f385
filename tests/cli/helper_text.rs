//! The help and usage lines of every helper of both dialects: examples in the session's own
//! dialect that run as shown, and no doubled space inside a text.

use crate::util::{code, run_with_stdin_in, stderr, stdout, tempdir};
use tmclsh::shell::helpers;

/// The example of a usage message: what follows `(e.g. ` up to its `)`.
fn example(message: &str) -> &str {
    let start = message
        .find("(e.g. ")
        .unwrap_or_else(|| panic!("no example: {message}"))
        + "(e.g. ".len();
    let end = start + message[start..].find(')').unwrap();
    &message[start..end]
}

#[test]
fn the_watch_and_record_examples_are_in_the_session_s_dialect_and_run_as_shown() {
    for dialect in tmclsh::dialect::all() {
        let dir = tempdir();
        let protocol = ["--sim", "--protocol", dialect.name];
        let usage = |helper: &str| {
            let out = run_with_stdin_in(&dir, &[&protocol[..], &["-c", helper]].concat(), "");
            assert_eq!(code(&out), 2, "{}", stderr(&out));
            stderr(&out)
        };
        let record_usage = usage(":record");
        let watch_usage = usage(":watch");
        let record = example(&record_usage).to_string();
        let watch = example(&watch_usage);
        assert!(record.starts_with(":record ramp.csv "), "{record}");
        // Both name the same parameters, which the session's own module reads.
        let names = record.split_whitespace().nth(2).unwrap();
        assert_eq!(watch.split_whitespace().nth(1), Some(names), "{watch}");
        let out = run_with_stdin_in(&dir, &[&protocol[..], &["-c", &record]].concat(), "");
        assert_eq!(code(&out), 0, "{}: {}", dialect.name, stderr(&out));
        let csv = std::fs::read_to_string(dir.join("ramp.csv")).unwrap();
        let header = csv.lines().next().unwrap().to_ascii_lowercase();
        assert_eq!(
            header,
            format!("time_ms,{names}").to_ascii_lowercase(),
            "{}",
            dialect.name
        );
        assert!(csv.lines().count() > 2, "{csv}");
    }
}

/// Whether `text` has two spaces in a row.
fn doubled_space(text: &str) -> bool {
    text.contains("  ")
}

/// A row of a help table: the indentation and the padding of the one gap between its columns
/// are layout; the texts on either side of the gap are single-spaced.
fn row_is_single_spaced(row: &str) -> bool {
    let row = row.trim_start();
    match row.split_once("  ") {
        Some((left, right)) => !doubled_space(left) && !doubled_space(right.trim_start()),
        None => true,
    }
}

#[test]
fn no_help_or_usage_line_of_any_helper_has_a_doubled_space() {
    for dialect in tmclsh::dialect::all() {
        let names: Vec<&str> = helpers::available(dialect)
            .map(|h| h.name())
            .filter(|&n| n != "quit")
            .collect();
        // The overview, each helper's help, and each helper given arguments it refuses.
        let mut input = String::from(":help\n");
        for name in &names {
            input.push_str(&format!(":help {name}\n:{name} @@ @@\n"));
        }
        let dir = tempdir();
        let out = run_with_stdin_in(
            &dir,
            &["--sim", "--protocol", dialect.name, "--keep-going"],
            &input,
        );
        let (shown, errors) = (stdout(&out), stderr(&out));
        for row in shown.lines() {
            assert!(row_is_single_spaced(row), "{}: {row:?}", dialect.name);
        }
        for line in errors.lines() {
            assert!(!doubled_space(line), "{}: {line:?}", dialect.name);
        }
        // What is checked is there: the table, and the usage of the helpers that have one.
        assert!(shown.contains("Helper commands:"), "{shown}");
        for usage in [
            "usage: :watch",
            "usage: :record",
            "usage: :scan",
            "usage: :snapshot",
        ] {
            assert!(
                errors.contains(usage),
                "{}: {usage}: {errors}",
                dialect.name
            );
        }
    }
}

#[test]
fn params_with_a_filter_nothing_matches_says_so_in_each_dialect() {
    for (protocol, said) in [
        ("tmcl", "no parameter matches 'zzz'"),
        ("smd4", "no setting matches 'zzz'"),
    ] {
        let out = run_with_stdin_in(
            &tempdir(),
            &["--sim", "--protocol", protocol, "-c", ":params zzz"],
            "",
        );
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        assert_eq!(stdout(&out).trim_end(), said, "{protocol}");
    }
}
