//! Options in either position: `tmclsh --port P run S` means `tmclsh run S --port P`. The
//! options written before the subcommand are moved behind its name and the command line is
//! parsed again, so the subcommand receives them through its own (flattened) arguments — clap
//! then refuses a duplicate (`--port A run --port B`) or a conflict (`--port A run --tcp B`) as it
//! would in one place. An option the subcommand does not have is refused, never dropped.

use std::ffi::OsString;
use std::ops::Range;

use clap::error::ErrorKind;
use clap::{Arg, ArgMatches, Command};

/// Moves the options given before the subcommand behind the name of the (innermost) subcommand.
/// `cmd` is the built command and `first` the result of parsing `argv` with it once, so the
/// arguments are known to be well formed.
pub(super) fn behind_subcommand(
    cmd: &mut Command,
    first: &ArgMatches,
    argv: Vec<OsString>,
) -> Result<Vec<OsString>, clap::Error> {
    let Some(path) = subcommand_path(first) else {
        return Ok(argv);
    };
    let top = scan(cmd, &argv, 1);
    let mut leaf = &*cmd;
    let mut name_at = top.subcommand.expect("clap found a subcommand");
    for (depth, name) in path.iter().enumerate() {
        leaf = leaf
            .find_subcommand(name)
            .expect("clap found this subcommand");
        if depth + 1 < path.len() {
            name_at = scan(leaf, &argv, name_at + 1)
                .subcommand
                .expect("clap found a deeper subcommand");
        }
    }
    let moved = &top.spans;
    let refused: Vec<String> = moved
        .iter()
        .flat_map(|span| &span.args)
        .filter(|id| {
            leaf.get_arguments()
                .all(|a| a.get_id().as_str() != id.as_str())
        })
        .map(|id| not_taken(cmd, leaf, id, &path))
        .collect();
    if !refused.is_empty() {
        let message = refused.join("\n");
        let leaf = subcommand_mut(cmd, &path);
        return Err(leaf.error(ErrorKind::ArgumentConflict, message));
    }
    let mut out = Vec::with_capacity(argv.len());
    let is_moved = |i: usize| moved.iter().any(|s| s.tokens.contains(&i));
    for (i, token) in argv.iter().enumerate() {
        if !is_moved(i) {
            out.push(token.clone());
        }
        if i == name_at {
            for span in moved {
                out.extend(argv[span.tokens.clone()].iter().cloned());
            }
        }
    }
    Ok(out)
}

/// The names of the nested subcommands given (`["snapshot", "save"]`), if any.
pub(super) fn subcommand_path(matches: &ArgMatches) -> Option<Vec<String>> {
    let mut path = Vec::new();
    let mut current = matches;
    while let Some((name, sub)) = current.subcommand() {
        path.push(name.to_string());
        current = sub;
    }
    (!path.is_empty()).then_some(path)
}

/// The matches of the innermost subcommand (the top level's without one).
pub(super) fn leaf_matches(matches: &ArgMatches) -> &ArgMatches {
    let mut current = matches;
    while let Some((_, sub)) = current.subcommand() {
        current = sub;
    }
    current
}

/// The subcommand at `path`, mutably (for an error that shows its usage).
pub(super) fn subcommand_mut<'a>(cmd: &'a mut Command, path: &[String]) -> &'a mut Command {
    path.iter().fold(cmd, |cmd, name| {
        cmd.find_subcommand_mut(name)
            .expect("the subcommand exists")
    })
}

/// The option as the user writes it: `--port`, or `-c` for an option with only a short name.
pub(super) fn flag(arg: &Arg) -> String {
    match (arg.get_long(), arg.get_short()) {
        (Some(long), _) => format!("--{long}"),
        (None, Some(short)) => format!("-{short}"),
        (None, None) => arg.get_id().to_string(),
    }
}

/// Why `id`, written before the subcommand, is not taken by it.
fn not_taken(cmd: &Command, leaf: &Command, id: &str, path: &[String]) -> String {
    let arg = cmd
        .get_arguments()
        .find(|a| a.get_id().as_str() == id)
        .expect("the option was parsed at the top level");
    let name = flag(arg);
    let words = path.join(" ");
    let namesake = leaf
        .get_arguments()
        .any(|a| a.get_long().is_some() && a.get_long() == arg.get_long());
    if namesake {
        format!(
            "{name} before `{words}` is the shell's option; `tmclsh {words} {name}` means \
             something else (see `tmclsh {words} --help`)"
        )
    } else {
        format!("{name} does not apply to `tmclsh {words}` (its options: `tmclsh {words} --help`)")
    }
}

/// An option found on the command line: the argv indices of its tokens and the arguments they
/// set (several for a cluster of short flags).
struct Span {
    tokens: Range<usize>,
    args: Vec<String>,
}

/// The options of one command level written from `argv[from]` on, and where the subcommand's
/// name is. Every option of the levels scanned takes at most one value.
struct Level {
    spans: Vec<Span>,
    subcommand: Option<usize>,
}

fn scan(cmd: &Command, argv: &[OsString], from: usize) -> Level {
    let mut spans = Vec::new();
    let mut i = from;
    while i < argv.len() {
        // Lossy: option names are ASCII; a value that is not UTF-8 keeps its place all the same.
        let token = argv[i].to_string_lossy();
        let token = token.as_ref();
        if token == "--" {
            break;
        }
        let (args, len) = if let Some(long) = token.strip_prefix("--") {
            let (name, inline) = match long.split_once('=') {
                Some((name, _)) => (name, true),
                None => (long, false),
            };
            match find(cmd, |a| a.get_long() == Some(name) || has_alias(a, name)) {
                Some(arg) => (vec![arg], if takes_value(arg) && !inline { 2 } else { 1 }),
                None => (Vec::new(), 1),
            }
        } else if token.len() > 1 && token.starts_with('-') {
            short_cluster(cmd, &token[1..])
        } else {
            return Level {
                spans,
                subcommand: Some(i),
            };
        };
        spans.push(Span {
            tokens: i..(i + len).min(argv.len()),
            args: args.iter().map(|a| a.get_id().to_string()).collect(),
        });
        i += len;
    }
    Level {
        spans,
        subcommand: None,
    }
}

/// The arguments of `-abc` (flags, then at most one option whose value is the rest of the token
/// or the next one), and how many tokens they take.
fn short_cluster<'a>(cmd: &'a Command, letters: &str) -> (Vec<&'a Arg>, usize) {
    let mut args = Vec::new();
    for (at, letter) in letters.char_indices() {
        let Some(arg) = find(cmd, |a| a.get_short() == Some(letter)) else {
            break;
        };
        args.push(arg);
        if takes_value(arg) {
            let rest_is_value = at + letter.len_utf8() < letters.len();
            return (args, if rest_is_value { 1 } else { 2 });
        }
    }
    (args, 1)
}

fn find(cmd: &Command, pred: impl Fn(&Arg) -> bool) -> Option<&Arg> {
    cmd.get_arguments().find(|a| pred(a))
}

fn has_alias(arg: &Arg, name: &str) -> bool {
    arg.get_all_aliases()
        .is_some_and(|aliases| aliases.contains(&name))
}

fn takes_value(arg: &Arg) -> bool {
    arg.get_action().takes_values()
}

#[cfg(test)]
mod tests {
    use std::ffi::OsString;

    use crate::cli::{Cli, Command, parse};

    fn cli(args: &[&str]) -> Result<Cli, clap::Error> {
        let mut argv = vec![OsString::from("tmclsh")];
        argv.extend(args.iter().map(OsString::from));
        parse(argv)
    }

    fn run_port(args: &[&str]) -> Option<String> {
        match cli(args).unwrap().command {
            Some(Command::Run(run)) => run.module.connection.port,
            other => panic!("not run: {other:?}"),
        }
    }

    #[test]
    fn every_spelling_of_an_option_before_the_subcommand_reaches_it() {
        assert_eq!(
            run_port(&["--port", "/a", "run", "s"]).as_deref(),
            Some("/a")
        );
        assert_eq!(run_port(&["--port=/a", "run", "s"]).as_deref(), Some("/a"));
        // An option's value that reads like a subcommand is still its value.
        assert_eq!(
            run_port(&["--port", "run", "run", "s"]).as_deref(),
            Some("run")
        );
        let Some(Command::Run(run)) = cli(&["-m2", "--no-validate", "run", "s"]).unwrap().command
        else {
            panic!()
        };
        assert_eq!(run.module.session.module, 2);
        assert!(run.module.session.no_validate);
    }

    #[test]
    fn options_reach_a_nested_subcommand_and_leave_its_arguments_alone() {
        let parsed = cli(&["--timeout", "7", "snapshot", "save", "f.toml"]).unwrap();
        let Some(Command::Snapshot(snapshot)) = parsed.command else {
            panic!()
        };
        assert!(
            format!("{snapshot:?}").contains("timeout: 7"),
            "{snapshot:?}"
        );
        let Some(Command::Run(run)) = cli(&["--timeout", "7", "run", "s", "--", "--port", "x"])
            .unwrap()
            .command
        else {
            panic!()
        };
        assert_eq!(run.module.session.timeout, 7);
        assert_eq!(run.args, ["--port", "x"]);
    }

    #[cfg(unix)]
    #[test]
    fn a_value_that_is_not_utf8_keeps_its_place() {
        use std::os::unix::ffi::OsStringExt;
        let argv = vec![
            OsString::from("tmclsh"),
            OsString::from_vec(b"--log=\xff.log".to_vec()),
            OsString::from("run"),
            OsString::from("s"),
        ];
        let Some(Command::Run(run)) = parse(argv).unwrap().command else {
            panic!()
        };
        assert!(run.module.session.log.is_some());
    }

    #[test]
    fn what_the_subcommand_does_not_take_is_refused_by_name() {
        for (args, flag) in [
            (&["-c", "GAP 1, 0", "run", "s"][..], "-c"),
            (&["--port", "/a", "asm", "p.tmc"], "--port"),
            (&["--baud", "300", "sim"], "--baud"),
            (&["--port", "/a", "run", "s", "--port", "/b"], "--port"),
        ] {
            let error = cli(args).unwrap_err();
            assert_eq!(error.exit_code(), 2, "{args:?}");
            assert!(error.to_string().contains(flag), "{args:?}: {error}");
        }
    }
}
