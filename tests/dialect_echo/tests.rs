//! The echo dialect registered and driven through the library's own entry points: the command
//! line's `--protocol`, the batch runner of `-c` and piped lines, `:help`, and scripts. Each test
//! runs in a fresh process of this test binary, where the dialect is registered before anything
//! reads the list of dialects (the other tests of the binary read it in theirs).

use std::ffi::OsString;
use std::process::Command;

use clap::FromArgMatches;
use tmclsh::cli::connection::{Audience, ModuleArgs};
use tmclsh::dialect::{self, Configured, Dialect, DialectSession, Purpose, RegisterError};
use tmclsh::exit::Exit;
use tmclsh::script::Limits;
use tmclsh::shell::batch::{self, Lines, Options, Output};
use tmclsh::shell::{Shell, run_source};

use super::DIALECT;

/// Set in the fresh process a test runs its body in.
const FRESH: &str = "TMCLSH_TEST_DIALECT_ECHO";

/// Runs `body` of the test `name` in a fresh process of this binary with the echo dialect
/// registered first, and fails with that process's output when it fails.
fn fresh(name: &str, body: impl FnOnce()) {
    if std::env::var_os(FRESH).is_some() {
        dialect::register(&DIALECT).expect("registered before anything reads the list");
        return body();
    }
    let test = format!("dialect_echo::tests::{name}");
    let exe = std::env::current_exe().expect("the test binary");
    let out = Command::new(exe)
        .args([test.as_str(), "--exact", "--test-threads", "1"])
        .env(FRESH, "1")
        .output()
        .expect("the test binary runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let passed = out.status.success() && stdout.contains("1 passed");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(passed, "{test} in a fresh process:\n{stdout}\n{stderr}");
}

/// A session on the built-in simulator of `protocol`, opened as the command line opens one.
fn session(protocol: &str) -> Box<dyn DialectSession> {
    let argv = ["tmclsh", "--sim", "--protocol", protocol];
    tmclsh::cli::parse(argv.map(OsString::from).to_vec()).expect("--protocol takes it");
    let matches = tmclsh::cli::command().get_matches_from(argv);
    let module = ModuleArgs::from_arg_matches(&matches).expect("connection flags");
    let configs = Configured::load(None).expect("every dialect configures");
    let opened = module.open(&configs, Audience::Batch, Purpose::Talk);
    opened.unwrap_or_else(|f| panic!("{}", f.message))
}

/// `lines` run as `-c` lines in a session of `protocol`: the exit, stdout and stderr.
fn batch(protocol: &str, lines: &[&str], output: Output) -> (Exit, String, String) {
    let mut shell = Shell::new(session(protocol));
    let lines = lines.iter().map(|l| l.to_string()).collect::<Vec<_>>();
    let options = Options {
        output,
        keep_going: false,
    };
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let exit = batch::run(
        &mut shell,
        Lines::Given(lines.into_iter()),
        options,
        &mut out,
        &mut err,
    );
    let text = |bytes: Vec<u8>| String::from_utf8(bytes).unwrap();
    (exit, text(out), text(err))
}

#[test]
fn the_list_takes_the_dialect_once_and_only_before_its_first_use() {
    fresh(
        "the_list_takes_the_dialect_once_and_only_before_its_first_use",
        || {
            let again = dialect::register(&DIALECT);
            assert_eq!(again, Err(RegisterError::NameTaken("echo")));
            let names: Vec<&str> = dialect::all().iter().map(|d| d.name).collect();
            assert_eq!(names, ["tmcl", "smd4", "echo"]);
            assert_eq!(dialect::default_dialect().name, "tmcl");
            let late: &'static Dialect = Box::leak(Box::new(Dialect {
                name: "late",
                ..DIALECT
            }));
            let refused = dialect::register(late).unwrap_err();
            assert_eq!(refused, RegisterError::TooLate("late"));
            assert!(dialect::by_name("late").is_none());
        },
    );
}

#[test]
fn batch_lines_go_out_and_their_echo_is_printed() {
    fresh("batch_lines_go_out_and_their_echo_is_printed", || {
        let lines = ["ECHO hello world", "# a comment", "echo again"];
        let (exit, out, err) = batch("echo", &lines, Output::Reply);
        assert_eq!(
            (exit, out.as_str()),
            (Exit::Success, "hello world\nagain\n"),
            "{err}"
        );
        let (exit, out, err) = batch("echo", &["ECHO hi"], Output::Json);
        assert_eq!(exit, Exit::Success, "{err}");
        assert!(out.contains(r#""reply":"hi""#), "{out}");
    });
}

#[test]
fn an_unknown_command_is_refused_unsent_with_a_hint() {
    fresh("an_unknown_command_is_refused_unsent_with_a_hint", || {
        let (exit, out, err) = batch("echo", &["SHOUT hi", "ECHO never"], Output::Reply);
        assert_eq!((exit, out.as_str()), (Exit::Refused, ""), "{err}");
        assert!(
            err.contains("unknown command SHOUT: echo lines are `ECHO text`"),
            "{err}"
        );
        let (exit, _, err) = batch("echo", &["GAP 1, 0"], Output::Reply);
        assert_eq!(exit, Exit::Refused, "{err}");
        assert!(
            err.contains("looks like a TMCL command — add `--protocol tmcl`"),
            "{err}"
        );
    });
}

#[test]
fn the_other_dialects_name_it_for_its_lines_and_scripts() {
    fresh(
        "the_other_dialects_name_it_for_its_lines_and_scripts",
        || {
            let (exit, _, err) = batch("tmcl", &["ECHO hi"], Output::Reply);
            assert_eq!(exit, Exit::Refused, "{err}");
            assert!(
                err.contains("looks like an ECHO command — add `--protocol echo`"),
                "{err}"
            );
            let script = r#"echo("hi");"#;
            let (_, outcome) =
                run_source("s.rhai", script, &[], session("smd4"), Limits::default());
            let failure = outcome.unwrap_err();
            assert_eq!(failure.exit, Exit::Refused, "{}", failure.message);
            let named = "looks like an ECHO script — add `--protocol echo`";
            assert!(failure.message.contains(named), "{}", failure.message);
        },
    );
}

#[test]
fn help_shows_its_words_beside_the_shared_helpers() {
    fresh("help_shows_its_words_beside_the_shared_helpers", || {
        let mut shell = Shell::new(session("echo"));
        let mut help = |topic: &str| {
            let mut out = Vec::new();
            shell.helper(topic, &mut out).expect("help");
            String::from_utf8(out).unwrap()
        };
        let overview = help(":help");
        assert!(
            overview.starts_with("Type ECHO text: the loopback"),
            "{overview}"
        );
        assert!(overview.contains(":source SCRIPT.rhai"), "{overview}");
        assert!(
            overview.contains("More: :help echo, :help exit"),
            "{overview}"
        );
        assert!(help(":help ECHO").starts_with("ECHO text    sends text"));
        let tables = dialect::functions::tables();
        let (title, functions) = tables.last().expect("a table per dialect");
        assert_eq!(title, "ECHO scripts (--protocol echo)");
        assert_eq!(functions[0].signature, "echo(text) -> string");
        assert_eq!(help(":params"), "the echo loopback has no parameters\n");
        assert_eq!(shell.prompt(), "echo> ");
    });
}

#[test]
fn a_script_calls_its_function_and_fails_on_a_wrong_answer() {
    fresh(
        "a_script_calls_its_function_and_fails_on_a_wrong_answer",
        || {
            let script = r#"
            assert_eq(echo("hi there"), "hi there");
            let heard = 0;
            for i in 0..3 { if echo(`n${i}`) == `n${i}` { heard += 1; } }
            assert_eq(heard, 3);
        "#;
            let (session, outcome) =
                run_source("ok.rhai", script, &[], session("echo"), Limits::default());
            outcome.unwrap_or_else(|f| panic!("{}", f.message));
            let wrong = r#"assert_eq(echo("a"), "b");"#;
            let (_, outcome) = run_source("wrong.rhai", wrong, &[], session, Limits::default());
            let failure = outcome.unwrap_err();
            assert_eq!(failure.exit, Exit::DeviceError, "{}", failure.message);
        },
    );
}
