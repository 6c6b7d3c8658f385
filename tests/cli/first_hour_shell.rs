//! A newcomer's first hour with the shell's smaller points, against the real binary: help lists
//! only the options a subcommand takes, the man page's synopsis and examples (each `--sim` one
//! run), each simulator console's `help`, `:target` alone, per-motor parameter values from the
//! shell and the command line, and `ports --probe` asking what it is told to. (Leaving the shell
//! with a motor turning needs a terminal: `tests/repl/leaving.rs`.)

#![cfg(unix)]

use std::process::{Command, Stdio};

use crate::sim::Sim;
use crate::util::{bin, code, repo, run, stderr, stdout, tempdir};

fn ok(args: &[&str]) -> String {
    let out = run(args);
    assert_eq!(code(&out), 0, "{args:?}: {}", stderr(&out));
    stdout(&out)
}

fn refused(args: &[&str]) -> String {
    let out = run(args);
    assert_eq!(code(&out), 2, "{args:?}: {}", stdout(&out));
    stderr(&out)
}

#[test]
fn help_offers_profile_only_where_it_is_taken() {
    for words in [
        &["ports"][..],
        &["completions", "bash"],
        &["man"],
        &["profiles"],
    ] {
        let args = [words[0], "--help"];
        let help = ok(&args);
        assert!(!help.contains("--profile"), "{args:?}:\n{help}");
        let mut given = words.to_vec();
        given.extend(["--profile", "tmcm-6110"]);
        assert!(refused(&given).contains("--profile"), "{given:?}");
        let mut before = vec!["--profile", "tmcm-6110"];
        before.extend(words);
        let said = refused(&before);
        assert!(
            said.contains("--profile does not apply"),
            "{before:?}: {said}"
        );
    }
    for words in [
        &["params"][..],
        &["asm"],
        &["run"],
        &["scan"],
        &["sim"],
        &[],
    ] {
        let mut args = words.to_vec();
        args.push("--help");
        assert!(ok(&args).contains("--profile <NAME|FILE>"), "{args:?}");
    }
    // Where it is taken it works in either position, as before.
    let before = ok(&["--profile", "tmcm-6110", "params", "max_current"]);
    let after = ok(&["params", "max_current", "--profile", "tmcm-6110"]);
    assert_eq!(before, after);
    assert_ne!(before, ok(&["params", "max_current"]));
}

/// The options `-h` lists under the heading `SMD4:` of `words`' help.
fn under_smd4_heading(words: &[&str]) -> Vec<String> {
    let mut args = words.to_vec();
    args.push("-h");
    let help = ok(&args);
    let mut lines = help.lines().skip_while(|l| *l != "SMD4:").skip(1);
    let mut options = Vec::new();
    for line in lines.by_ref() {
        if !line.starts_with(' ') {
            break;
        }
        if line.trim_start().starts_with('-') {
            options.push(line.trim().to_string());
        }
    }
    options
}

#[test]
fn a_subcommand_s_own_options_are_not_listed_under_smd4() {
    let download = ok(&["download", "-h"]);
    assert!(download.contains("--run"), "{download}");
    for words in [
        &["download"][..],
        &["run"],
        &["scan"],
        &["snapshot", "restore"],
        &[],
    ] {
        for option in under_smd4_heading(words) {
            let (flag, help) = option.split_once("  ").unwrap_or((&option, ""));
            assert!(
                help.trim_start().starts_with("SMD4"),
                "{words:?}: {flag} is listed under SMD4: {option}"
            );
        }
    }
}

#[test]
fn the_man_page_synopsis_names_values_and_it_has_examples() {
    let page = ok(&["man"]);
    let synopsis = page
        .split(".SH SYNOPSIS\n")
        .nth(1)
        .and_then(|rest| rest.lines().next())
        .expect("a synopsis");
    assert!(
        synopsis.contains(r"[\fB\-c\fR \fILINE\fR]..."),
        "{synopsis}"
    );
    assert!(
        synopsis.contains(r"[\fB\-\-port\fR \fIPATH\fR]"),
        "{synopsis}"
    );
    assert!(!page.contains(r"\-c \fR]"), "an empty -c in the page");
    let examples = page.split(".SH EXAMPLES\n").nth(1).expect("EXAMPLES");
    for example in tmclsh::cli::man::EXAMPLES {
        let shown = example.command.replace('-', r"\-");
        assert!(
            examples.contains(&shown),
            "{} not in the page",
            example.command
        );
        let placeholder = example.command.contains("/dev/ttyUSB0");
        let no_link = example.command.starts_with("tmclsh ports");
        assert!(
            example.command.contains("--sim") || placeholder || no_link,
            "{} names a real link",
            example.command
        );
    }
}

#[test]
fn every_man_page_example_on_the_simulator_runs() {
    let dir = tempdir();
    std::os::unix::fs::symlink(repo().join("scripts"), dir.join("scripts")).unwrap();
    let path = format!(
        "{}:{}",
        bin().parent().unwrap().display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let batch = tmclsh::cli::man::EXAMPLES
        .iter()
        .filter(|e| e.batch && e.command.contains("--sim"));
    let mut ran = 0;
    for example in batch {
        // As typed at a shell prompt, with this build first on the PATH.
        let out = Command::new("sh")
            .args(["-c", example.command])
            .current_dir(&dir)
            .env("PATH", &path)
            .env("NO_COLOR", "1")
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert_eq!(code(&out), 0, "{}: {}", example.command, stderr(&out));
        ran += 1;
    }
    assert!(ran >= 5, "only {ran} examples ran");
}

#[test]
fn each_simulator_console_lists_only_its_own_commands() {
    let mut tmcl = Sim::start(&[]);
    let help = tmcl.console("help");
    let names: Vec<&str> = help.split_whitespace().collect();
    for name in ["input", "switch", "@N", "quit"] {
        assert!(names.contains(&name), "{name} missing: {help}");
    }
    for other in [
        "limit",
        "flash-failure",
        "power-cycle",
        "microsteps)",
        "back",
    ] {
        assert!(!names.contains(&other), "{other} in {help}");
    }
    tmcl.quit();
    let mut smd4 = Sim::start(&["--protocol", "smd4"]);
    let help = smd4.console("help");
    let names: Vec<&str> = help.split_whitespace().collect();
    assert!(names.contains(&"power-cycle"), "{help}");
    assert!(!names.contains(&"input"), "{help}");
    smd4.quit();
}

#[test]
fn target_alone_shows_the_target() {
    let text = ok(&["--sim", "-c", ":target", "-c", ":target 1", "-c", ":target"]);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3, "{text}");
    assert!(
        lines[0].starts_with("target: module 1 (A), TMCM-142"),
        "{text}"
    );
    assert_eq!(lines[0], lines[2]);
    let text = ok(&[
        "--sim",
        "--protocol",
        "smd4",
        "-c",
        ":target",
        "-c",
        ":target 3",
        "-c",
        ":target",
    ]);
    assert_eq!(
        text.lines().collect::<Vec<_>>(),
        [
            "requests go to the drive without an address prefix",
            "requests go to drive @3",
            "requests go to drive @3"
        ]
    );
}

/// The places of the lines of a `--values` table (`axis 6 motor 2`).
fn places(text: &str) -> Vec<String> {
    text.lines()
        .map(|l| l.split("  ").next().unwrap_or_default().to_string())
        .collect()
}

#[test]
fn parameter_values_by_motor_from_the_shell_and_the_command_line() {
    let six = ["--sim", "--profile", "tmcm-6110"];
    let all = ok(&[&six[..], &["params", "--values", "max_current"]].concat());
    let motors: Vec<String> = (0..6).map(|m| format!("axis 6 motor {m}")).collect();
    assert_eq!(places(&all), motors, "{all}");
    let two = ok(&[
        &six[..],
        &["params", "--values", "--motor", "2", "max_current"],
    ]
    .concat());
    assert_eq!(places(&two), ["axis 6 motor 2"], "{two}");
    assert!(two.contains("max_current"), "{two}");
    let shell = ok(&[&six[..], &["-c", ":params --values --motor 2 max_current"]].concat());
    assert_eq!(shell, two);
    // Motor 0 is labelled too, on a one-motor module as well.
    let one = ok(&["--sim", "-c", ":params --values --motor 0 max_current"]);
    assert_eq!(places(&one), ["axis 6 motor 0"], "{one}");
    // Nothing of that motor: said on stderr, exit 1 (as the table does).
    let out = run(&["--sim", "params", "--values", "--motor", "9", "max"]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stderr(&out).contains("no readable parameter of motor 9"));
    // --motor goes with --values; a link only with --values.
    assert!(refused(&["params", "--motor", "1"]).contains("--values"));
    assert!(refused(&["--sim", "params"]).contains("without --values"));
    let out = run(&["--sim", "-c", ":params --motor 1"]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert!(stderr(&out).contains("--motor goes with --values"));
}

#[test]
fn ports_probe_asks_the_address_baud_and_protocol_given() {
    let bus = Sim::start(&["--modules", "3"]);
    let pty = bus.first.clone();
    let at_1 = ok(&["ports", "--probe", &pty]);
    assert!(
        at_1.contains("probing address 1 at 9600 baud in tmcl"),
        "{at_1}"
    );
    assert!(
        at_1.contains(&format!("{pty}: no module answered")),
        "{at_1}"
    );
    let at_3 = ok(&["ports", "--probe", "-m", "3", "--baud", "115200", &pty]);
    assert!(
        at_3.contains("probing address 3 at 115200 baud in tmcl"),
        "{at_3}"
    );
    assert!(at_3.contains(&format!("{pty}: TMCM-142 (142V")), "{at_3}");
    bus.quit();
    let drive = Sim::start(&["--protocol", "smd4"]);
    let pty = drive.first.clone();
    let smd4 = ok(&["ports", "--probe", "--protocol", "smd4", &pty]);
    assert!(smd4.contains(&format!("{pty}: SMD4 (firmware ")), "{smd4}");
    drive.quit();
    // Without --probe they would change nothing.
    assert!(refused(&["ports", "--baud", "115200"]).contains("--baud goes with --probe"));
}
