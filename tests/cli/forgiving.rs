//! Forgiving input through the real binary: a line or a script of the other dialect says which
//! `--protocol` it needs (exit 2), trailing `//` comments are accepted, misspelt names get the
//! nearest one.

use crate::repl::{repl, type_in};
use crate::util::{code, run, run_with_stdin, stderr, stdout, tempdir};

const TO_SMD4: &str = "this looks like an SMD4 command — add `--protocol smd4`";
const TO_TMCL: &str = "this looks like a TMCL command — add `--protocol tmcl`";

/// Runs `args` and expects a refusal (exit 2) whose stderr says `said`.
fn refused_saying(out: std::process::Output, said: &str) -> String {
    let err = stderr(&out);
    assert_eq!(code(&out), 2, "{err}");
    assert!(err.contains(said), "{err}");
    assert!(
        !err.contains("column"),
        "the other grammar's failure: {err}"
    );
    err
}

#[test]
fn a_line_of_the_other_dialect_names_its_protocol_in_c_and_piped_input() {
    for line in [
        "MOTOR:VMAX",
        "motor:vmax,2000",
        "MOTOR:VMAX 2000",
        "@3MOTOR:STOP",
        "SYS:FW",
    ] {
        refused_saying(run(&["--sim", "-c", line]), TO_SMD4);
        refused_saying(run_with_stdin(&["--sim"], &format!("{line}\n")), TO_SMD4);
    }
    for line in ["GAP 1, 0", "AGAP 4 0", "mvp abs, 0, 1000", "MST", "136 1"] {
        refused_saying(run(&["--sim", "--protocol", "smd4", "-c", line]), TO_TMCL);
        refused_saying(
            run_with_stdin(&["--sim", "--protocol", "smd4"], &format!("{line}\n")),
            TO_TMCL,
        );
    }
    // Its own mistakes and lines of no dialect keep their own message.
    let err = stderr(&run(&["--sim", "-c", "GAP 4, 9"]));
    assert!(!err.contains("looks like"), "{err}");
    let err = stderr(&run(&["--sim", "-c", "XYZ:ABC"]));
    assert!(
        !err.contains("looks like") && err.contains("column"),
        "{err}"
    );
    let err = stderr(&run(&["--sim", "--protocol", "smd4", "-c", "MOTOR:FOO"]));
    assert!(!err.contains("looks like"), "{err}");
}

#[test]
fn a_keep_going_run_reports_each_foreign_line_and_goes_on() {
    let out = run_with_stdin(&["--sim", "--keep-going"], "MOTOR:STOP\nGAP 4, 0\nSYS:FW\n");
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert_eq!(stderr(&out).matches(TO_SMD4).count(), 2, "{}", stderr(&out));
    assert!(stdout(&out).contains("BA 100"), "{}", stdout(&out));
}

#[test]
fn a_script_of_the_other_dialect_names_its_protocol() {
    let dir = tempdir();
    let tmcl_script = dir.join("tmcl.rhai");
    std::fs::write(&tmcl_script, "let v = gap(4, 0);\nprint(v);\n").unwrap();
    let err = refused_saying(
        run(&[
            "--sim",
            "--protocol",
            "smd4",
            "run",
            tmcl_script.to_str().unwrap(),
        ]),
        "this looks like a TMCL script — add `--protocol tmcl`",
    );
    assert!(err.contains("tmcl.rhai:1:"), "{err}");
    // An SMD4 script on a TMCL session: its device functions, and the lines it sends.
    let smd4_script = dir.join("smd4.rhai");
    std::fs::write(&smd4_script, "wait_standby(1000);\n").unwrap();
    refused_saying(
        run(&["--sim", "run", smd4_script.to_str().unwrap()]),
        "this looks like an SMD4 script — add `--protocol smd4`",
    );
    std::fs::write(&smd4_script, "send(\"MOTOR:STOP\");\n").unwrap();
    refused_saying(
        run(&["--sim", "run", smd4_script.to_str().unwrap()]),
        TO_SMD4,
    );
    // The shipped SMD4 example run without --protocol.
    let example = crate::util::repo().join("scripts/smd4_commission.rhai");
    refused_saying(run(&["--sim", "run", example.to_str().unwrap()]), TO_SMD4);
}

#[test]
fn a_misspelt_script_function_gets_the_nearest_name() {
    let dir = tempdir();
    let script = dir.join("typo.rhai");
    std::fs::write(&script, "let v = gapp(4, 0);\n").unwrap();
    let err = stderr(&run(&["--sim", "run", script.to_str().unwrap()]));
    assert!(
        err.contains("gapp") && err.contains("did you mean gap?"),
        "{err}"
    );
    std::fs::write(&script, "fn settle(m) { mst(m) }\nsettel(0);\n").unwrap();
    let err = stderr(&run(&["--sim", "run", script.to_str().unwrap()]));
    assert!(err.contains("did you mean settle?"), "{err}");
    std::fs::write(&script, "wait_standbi(10);\n").unwrap();
    let err = stderr(&run(&[
        "--sim",
        "--protocol",
        "smd4",
        "run",
        script.to_str().unwrap(),
    ]));
    assert!(err.contains("did you mean wait_standby?"), "{err}");
}

#[test]
fn in_the_repl_a_line_of_the_other_dialect_names_its_protocol() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line("MOTOR:VMAX").unwrap();
    p.exp_string("this looks like an SMD4 command").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0 // the speed limit").unwrap();
    p.exp_string("max_positioning_speed").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
    let (mut p, _) = repl(&["--protocol", "smd4"]);
    p.exp_string("smd4").unwrap();
    p.exp_string("> ").unwrap();
    type_in(&mut p, "GAP 1, 0\r");
    p.exp_string("this looks like a TMCL command").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_trailing_comment_is_accepted_in_typed_and_piped_lines() {
    let out = run(&[
        "--sim",
        "-c",
        "GAP 4, 0 // top speed",
        "-c",
        "SAP 4, 0, 1500//new",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 1000000\nBA 100 1500\n");
    let input = "// commissioning\nSAP 4, 0, 1200 // slower\n  GAP 4, 0  // check\n";
    let out = run_with_stdin(&["--sim"], input);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 1200\nBA 100 1200\n");
    let out = run_with_stdin(
        &["--sim", "--protocol", "smd4", "--value"],
        "MOTOR:VMAX,1500 // slower\nMOTOR:VMAX // check\n// only a note\n",
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert_eq!(text.lines().count(), 2, "{text}");
    assert!(text.lines().all(|l| l.contains("1.5")), "{text}");
    // What is sent carries no comment: the transcript shows the line as sent.
    let dir = tempdir();
    let log = dir.join("t.log");
    let out = run(&[
        "--sim",
        "--log",
        log.to_str().unwrap(),
        "-c",
        "GAP 4, 0 // x",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(!transcript.contains("//"), "{transcript}");
}

#[test]
fn smd4_near_misses_are_judged_by_the_segment_that_differs() {
    let smd4 = |line: &str| {
        let out = run(&["--sim", "--protocol", "smd4", "-c", line]);
        assert_eq!(code(&out), 2, "{line}: {}", stderr(&out));
        stderr(&out)
    };
    let err = smd4("MOTOR:FOO");
    assert!(
        err.contains("unknown mnemonic 'MOTOR:FOO'") && !err.contains("did you mean"),
        "{err}"
    );
    assert!(smd4("MOTOR:VMXA").contains("did you mean MOTOR:VMAX?"));
    assert!(smd4("MOTR:AMAX").contains("did you mean MOTOR:AMAX?"));
    assert!(smd4("MOTOR:VMAX 2000").contains("did you mean MOTOR:VMAX,2000?"));
    assert!(smd4("@3MOTOR:VMAX=2000").contains("did you mean @3MOTOR:VMAX,2000?"));
}

#[test]
fn one_tab_after_an_smd4_group_lists_its_commands() {
    let (mut p, _) = repl(&["--protocol", "smd4"]);
    p.exp_string("> ").unwrap();
    type_in(&mut p, "MOTOR:");
    type_in(&mut p, "\t");
    p.exp_string("MOTOR:AMAX").unwrap();
    p.exp_string("MOTOR:VMAX").unwrap();
    // The line is kept: typing on completes it.
    type_in(&mut p, "VMAX\r");
    p.exp_string("1000 Hz requested").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

/// The REPL on the built-in simulator with colours on (no NO_COLOR).
fn coloured_repl() -> rexpect::session::PtySession {
    let data = tempdir();
    let mut command = std::process::Command::new(crate::util::bin());
    command
        .env_remove("NO_COLOR")
        .env("TERM", "xterm")
        .env("XDG_DATA_HOME", &data)
        .env("XDG_CONFIG_HOME", &data)
        .env("HOME", &data);
    let mut p = rexpect::session::spawn_command(command, Some(crate::util::EXPECT_MS)).unwrap();
    p.exp_string("A> ").unwrap();
    p
}

/// What the terminal shows up to the next line end, after typing `text`.
fn typed_shows(p: &mut rexpect::session::PtySession, text: &str, until: &str) -> String {
    type_in(p, text);
    p.exp_string(until).unwrap()
}

#[test]
fn an_incomplete_line_stays_neutral_and_an_invalid_one_turns_red_with_its_reason() {
    const RED: &str = "\x1b[38;5;9m";
    let mut p = coloured_repl();
    // On its way: a mnemonic being typed, then a parameter, no red, the parameter's hint.
    let shown = typed_shows(&mut p, "GAP max_cur", "max_current [0..15, RWE]");
    assert!(!shown.contains(RED), "{shown:?}");
    type_in(&mut p, "\x15"); // Ctrl-U: clear the line.
    // Invalid: red, and the hint says why instead of describing the parameter.
    let shown = typed_shows(&mut p, "GAP 4, 7", "motor 7 does not exist");
    assert!(shown.contains(RED), "{shown:?}");
    type_in(&mut p, "\x15");
    typed_shows(&mut p, "MOTOR:VMAX", "this looks like an SMD4 command");
    type_in(&mut p, "\x15");
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_suggestion_ends_its_message() {
    let csv = tempdir().join("r.csv");
    let record = format!(":record {} MOTOR:VMXA 10ms 20ms", csv.display());
    for args in [
        &["--sim", "-c", ":prams"][..],
        &["--sim", "-c", "GPA 4, 0"],
        &["--sim", "--protocol", "smd4", "-c", "MOTOR:VMXA"],
        &["--sim", "--protocol", "smd4", "-c", &record],
    ] {
        let err = stderr(&run(args));
        assert!(err.contains("did you mean"), "{args:?}: {err}");
        assert!(
            !err.contains("?;") && !err.contains("? ;"),
            "{args:?}: {err}"
        );
    }
}
