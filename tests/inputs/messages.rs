//! The wording of what users read when a line goes wrong: bad lines of both dialects through the
//! real binary, and every message checked for punctuation that reads as a glitch — `?;`, doubled
//! or nested brackets, a usage placeholder (`<value>`) inside a sentence.

use crate::util::{run, run_with_stdin, stderr, stdout};

/// TMCL lines that each fail: refused before sending, refused by the module, or unanswered.
const TMCL: &[&str] = &[
    "GAP 99999999999",
    "SAP",
    "SAP 4,0,",
    "SAP 4, 0, 99999999999",
    "SAP 4, 0, 0xFFFFFFFFF",
    "SAP 4, 300, 1",
    "MVP ABS,0,1e9",
    "MVP ABS, 0, 3000000000",
    "MVP FOO, 0, 1",
    "FOO",
    "GPA 4, 0",
    "GAP",
    "GAP 4,",
    "GAP x, 0",
    "GAP 4, x",
    "GAP 4, 9",
    "GAP -1, 0",
    "GAP 1,,0",
    "GAP (1), 0",
    "GAP [1], 0",
    "GAP 4, 0, 1, 2",
    "GAP 4, 0 ; junk",
    "1GAP 4, 0",
    "SAP 4, 0, 1.5",
    "ROR 0, -99999999999",
    "SIO 0, 2, 5",
    "GIO 99, 0",
    "RFS FOO, 0",
    "CALC ADD, 1",
    "WAIT TICKS, 0, 99999999999",
    "JA 99999999",
    "BIN x",
    "MOTOR:VMAX,1000",
    "é",
    "GAP 200, 0",
    "SGP 255, 9, 1",
    "SAC 0, 0, 0",
    "XGAP 4, 0",
    ":target 99",
    ":echo x",
    ":run x",
    ":download",
    ":download /nonexistent",
    ":watch",
    ":watch nothing_like_this",
    ":watch actual_position 0ms",
    ":watch actual_position 99999d",
    ":record",
    ":plot /nonexistent.csv",
    ":snapshot",
    ":snapshot diff /nonexistent",
    ":log /nonexistent/x",
    ":source /nonexistent",
    ":bogus",
    ":raw x",
    ":status x",
];

/// TMCL lines that each fail on a TMCM-1140, whose profile lacks some commands.
const TMCM_1140: &[&str] = &["SAC 0, 0, 0", "CALC ADD, 1", "GAP 4, 1"];

/// SMD4 lines that each fail.
const SMD4: &[&str] = &[
    "MOTOR:VMAX,99999999999",
    "MOTOR:VMAX 2000",
    "MOTOR:VMAX,",
    "MOTOR:VMAX,,1",
    "MOTOR:VMAX,abc",
    "MOTOR:VMAX,(1)",
    "MOTOR:VMAX,1e99",
    "MOTOR:VMAX,-5",
    "MOTOR:VMAX?",
    "MOTOR:VMAX,1,2",
    "MOTOR:FOO",
    "MOTOR:",
    "FOO",
    "GAP 1, 0",
    "GAP 99999999999",
    "MOTOR:RUNA,1e9",
    "MOTOR:RUNA,99999999999",
    "MOTOR:RUNA",
    "MOTOR:STOP,1",
    "SYS:FW,1",
    "SYS:MODE,7",
    "SYS:MODE,x",
    "MOTOR:IR,99",
    "LIMIT:EN,2",
    "@",
    "@1",
    "@999MOTOR:VMAX",
    "@5MOTOR:VMAX",
    "é",
    ":target 999",
    ":target x",
    ":flags x",
    ":watch",
    ":watch NOTHING:LIKE",
    ":snapshot",
    ":bogus",
];

/// Help topics whose text is checked too (placeholders belong there).
const HELP: &[(&str, &[&str])] = &[
    (
        "tmcl",
        &[
            "",
            "params",
            "exit",
            "ascii",
            "addressing",
            "GAP",
            "SAP",
            "MVP",
            "CALC",
            "SIO",
            "max_current",
            ":target",
            ":watch",
            ":snapshot",
        ],
    ),
    (
        "smd4",
        &["", "params", "exit", "MOTOR:VMAX", "SYS:MODE", ":target"],
    ),
];

/// Leaves out text quoted from the input or the device (`'…'`, `` `…` ``): only our own
/// wording is judged. A quote opens after a space, a bracket or the start, so an apostrophe
/// (`module's`) stays text.
fn our_words(message: &str) -> String {
    let mut kept = String::new();
    let mut quote = None;
    let mut before = ' ';
    for c in message.chars() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if (c == '\'' || c == '`') && " ([:,=".contains(before) => quote = Some(c),
            None => kept.push(c),
        }
        before = c;
    }
    kept
}

/// What reads as a glitch in `message`.
fn flaws(message: &str, placeholders_allowed: bool) -> Vec<&'static str> {
    let text = our_words(message);
    let mut flaws = Vec::new();
    if text.contains("?;") {
        flaws.push("'?;'");
    }
    if message.contains("''") {
        flaws.push("an empty quote");
    }
    if text.contains("((") || text.contains("))") {
        flaws.push("doubled brackets");
    }
    let mut depth = 0usize;
    for c in text.chars() {
        match c {
            '(' | '[' => {
                depth += 1;
                if depth == 2 {
                    flaws.push("nested brackets");
                }
            }
            ')' | ']' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    // A usage line shows placeholders; a sentence names the thing (`the value 7 does not fit`).
    let sentence = text.split("usage:").next().unwrap_or_default();
    let placeholder = sentence.split('<').skip(1).any(|rest| {
        rest.split_once('>').is_some_and(|(word, _)| {
            !word.is_empty() && word.chars().all(|c| c.is_ascii_lowercase() || c == ' ')
        })
    });
    if placeholder && !placeholders_allowed {
        flaws.push("a placeholder in a sentence");
    }
    flaws
}

/// Runs `lines` piped into one `--keep-going` run with `args`; every line must fail with a
/// message, and no line of stderr may have a flaw.
fn check_lines(args: &[&str], lines: &[&str]) {
    let input = lines.join("\n") + "\n";
    let mut all = vec!["--sim", "--timeout", "100", "--keep-going"];
    all.extend(args);
    let out = run_with_stdin(&all, &input);
    let dialect = args.join(" ");
    let err = stderr(&out);
    let mut found = Vec::new();
    for (n, line) in lines.iter().enumerate() {
        let label = format!("tmclsh: line {} ({line}): ", n + 1);
        assert!(
            err.contains(&label),
            "{dialect}: '{line}' should fail with a message:\n{err}"
        );
    }
    for message in err.lines() {
        // The line label quotes the input as typed; the message after it is ours.
        let ours = match message.split_once("): ") {
            Some((label, rest)) if label.starts_with("tmclsh: line ") => rest,
            _ => message.trim_start_matches("tmclsh: "),
        };
        let flaws = flaws(ours, false);
        if !flaws.is_empty() {
            found.push(format!("{flaws:?}: {message}"));
        }
    }
    assert!(found.is_empty(), "{dialect}:\n{}", found.join("\n"));
}

#[test]
fn bad_tmcl_lines_get_messages_without_glitches() {
    check_lines(&["--protocol", "tmcl"], TMCL);
    check_lines(&["--profile", "tmcm-1140"], TMCM_1140);
}

#[test]
fn bad_smd4_lines_get_messages_without_glitches() {
    check_lines(&["--protocol", "smd4"], SMD4);
}

#[test]
fn help_reads_without_nested_brackets() {
    for (dialect, topics) in HELP {
        for topic in *topics {
            let out = run(&[
                "--sim",
                "--protocol",
                dialect,
                "-c",
                &format!(":help {topic}"),
            ]);
            let text = stdout(&out);
            assert!(!text.trim().is_empty(), "{dialect} :help {topic}");
            for line in text.lines() {
                let flaws = flaws(line, true);
                assert!(
                    flaws.is_empty(),
                    "{dialect} :help {topic}: {flaws:?}: {line}"
                );
            }
        }
    }
}

#[test]
fn the_check_sees_each_glitch_and_passes_clean_wording() {
    let glitches = [
        "stopped motor 0 of module 1 (A) (MST)?; then",
        "CALC (calculate (accumulator op value)) is not available",
        "it failed (see [the log])",
        "<value> 99999999999 does not fit",
        "'' is not a mnemonic",
    ];
    for glitch in glitches {
        assert!(!flaws(glitch, false).is_empty(), "{glitch}");
    }
    let clean = [
        "module 1 (A) refused 'AGAP (1), 0': status 3 (wrong type)",
        "the value 99999999999 does not fit: it must lie in -2147483648..2147483647",
        "GAP takes 2 arguments, got 1; usage: GAP <parameter>, <motor>",
        "the TMCM-142's ASCII command list lacks it (use :bin)",
        "found '((' in `((x))`",
    ];
    for text in clean {
        assert_eq!(flaws(text, false), Vec::<&str>::new(), "{text}");
    }
}
