//! The shell's non-interactive faces (`-c` and piped stdin) as a process, against `tmclsh sim`
//! over a real pseudo-terminal and over TCP: echo modes, line endings, a bus of two modules, a
//! module that starts in ASCII mode, silence, faults, exit codes, MST on abort, the transcript.

use crate::sim::{Port, Sim};
use crate::util::{code, run, run_with_stdin, stderr, stdout, tempdir};

/// `tmclsh --port PTY ARGS`.
fn on(sim: &Sim, args: &[&str]) -> std::process::Output {
    let mut all = vec!["--port", sim.first.as_str()];
    all.extend_from_slice(args);
    run(&all)
}

fn lines(out: &std::process::Output) -> Vec<String> {
    stdout(out).lines().map(str::to_string).collect()
}

#[test]
fn one_shot_lines_print_one_reply_each() {
    let sim = Sim::start(&["--pty"]);
    let out = on(
        &sim,
        &[
            "-c",
            "SAP 1, 0, -5000",
            "-c",
            "GAP actual_position, 0",
            "-c",
            "GAP 4, 0",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(
        lines(&out),
        ["BA 100 -5000", "BA 100 -5000", "BA 100 1000000"]
    );
}

#[test]
fn every_echo_mode_is_learnt_by_a_new_session() {
    let sim = Sim::start(&["--pty"]);
    for (mode, gp67) in [("line", 0x10), ("none", 0x20), ("char", 0x00)] {
        let out = on(
            &sim,
            &[
                "-c",
                &format!(":echo {mode}"),
                "-c",
                "GGP 67, 0",
                "-c",
                "GAP 4, 0",
            ],
        );
        assert_eq!(code(&out), 0, "{mode}: {}", stderr(&out));
        assert_eq!(
            lines(&out),
            [
                format!("echo: {mode}"),
                format!("BA 100 {gp67}"),
                "BA 100 1000000".into()
            ]
        );
        // A fresh session finds the module in this echo mode and strips the echo itself.
        let out = on(&sim, &["-c", "SAP 1, 0, 42", "-c", "GAP 1, 0"]);
        assert_eq!(code(&out), 0, "{mode}: {}", stderr(&out));
        assert_eq!(lines(&out), ["BA 100 42", "BA 100 42"], "{mode}");
        assert!(
            stderr(&out).is_empty(),
            "{mode}: nothing to report: {}",
            stderr(&out)
        );
    }
}

#[test]
fn any_line_endings_of_echo_and_reply() {
    for (reply_end, echo_end) in [
        ("lf", "none"),
        ("crlf", "lf"),
        ("cr", "crlf"),
        ("crlf", "none"),
    ] {
        let sim = Sim::start(&["--pty", "--reply-end", reply_end, "--echo-end", echo_end]);
        for echo in ["char", "line", "none"] {
            let out = on(
                &sim,
                &[
                    "-c",
                    &format!(":echo {echo}"),
                    "-c",
                    "SAP 1, 0, 7",
                    "-c",
                    "GAP 1, 0",
                    "-c",
                    "GAP 1, 0",
                ],
            );
            assert_eq!(
                code(&out),
                0,
                "{reply_end}/{echo_end}/{echo}: {}",
                stderr(&out)
            );
            assert_eq!(
                lines(&out)[1..],
                ["BA 100 7", "BA 100 7", "BA 100 7"],
                "{reply_end}/{echo_end}/{echo}"
            );
        }
    }
}

#[test]
fn two_modules_on_one_bus() {
    let sim = Sim::start(&["--pty", "--modules", "1,2"]);
    let out = on(
        &sim,
        &[
            "-c",
            "SAP 1, 0, 11",
            "-c",
            "BSAP 1, 0, 22",
            "-c",
            "GAP 1, 0",
            "-c",
            "B GAP 1, 0",
            ":target 2",
            "-c",
            ":target B",
            "-c",
            "GAP 1, 0",
        ],
    );
    assert_eq!(
        code(&out),
        2,
        "':target 2' without -c is not a flag: usage error"
    );
    let out = on(
        &sim,
        &[
            "-c",
            "SAP 1, 0, 11",
            "-c",
            "BSAP 1, 0, 22",
            "-c",
            "GAP 1, 0",
            "-c",
            "B GAP 1, 0",
            "-c",
            ":target B",
            "-c",
            "GAP 1, 0",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(
        lines(&out),
        [
            "BA 100 11",
            "BB 100 22",
            "BA 100 11",
            "BB 100 22",
            "target: module 2 (B), TMCM-142, firmware 142V1.06, profile tmcm-142 (built in)",
            "BB 100 22"
        ]
    );
    let out = on(&sim, &["--module", "2", "-c", "GAP 1, 0"]);
    assert_eq!(lines(&out), ["BB 100 22"]);
}

#[test]
fn a_module_that_starts_in_ascii_mode_is_left_in_it() {
    let dir = tempdir();
    let state = dir.join("eeprom.toml");
    let state = state.to_str().unwrap();
    {
        let sim = Sim::start(&["--pty", "--state", state]);
        // A bank-0 setting is kept in EEPROM by SGP itself (STGP takes user variables only).
        let out = on(&sim, &["-c", "SGP 67, 0, 0x21"]);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        sim.quit();
    }
    let sim = Sim::start(&["--pty", "--state", state]);
    let log = dir.join("session.log");
    let out = on(&sim, &["--log", log.to_str().unwrap(), "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(lines(&out), ["BA 100 1000000"]);
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(transcript.contains("found in ASCII mode"), "{transcript}");
    assert!(
        !transcript.contains("ABIN"),
        "not switched to binary on exit: {transcript}"
    );
    // The module still answers ASCII lines after tmclsh left.
    let mut port: Port = sim.pty();
    port.send(b"AGAP 4, 0\r");
    assert_eq!(port.read_line(), "BA 100 1000000\r");
}

#[test]
fn a_module_found_in_binary_mode_is_returned_to_it() {
    let sim = Sim::start(&["--pty"]);
    let out = on(&sim, &["-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    {
        let mut port = sim.pty();
        assert_eq!(
            port.transact(1, 6, 4, 0, 0).value,
            1_000_000,
            "binary frames work again"
        );
    }
    let out = on(&sim, &["--stay-ascii", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let mut port = sim.pty();
    port.send(b"AGAP 4, 0\r");
    assert!(
        port.read_line().ends_with("BA 100 1000000\r"),
        "--stay-ascii left it in ASCII mode"
    );
}

#[test]
fn no_enter_talks_to_a_module_already_in_ascii_mode() {
    let sim = Sim::start(&["--pty"]);
    {
        let mut port = sim.pty();
        assert_eq!(port.transact(1, 139, 0, 0, 0).value, 0);
    }
    let out = on(&sim, &["--no-enter", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(lines(&out), ["BA 100 1000000"]);
}

#[test]
fn a_silent_module_fails_with_exit_3_within_the_timeout() {
    let sim = Sim::start(&["--pty", "--silent-after", "0"]);
    let out = on(&sim, &["--timeout", "200", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 3);
    let err = stderr(&out);
    assert!(
        err.contains("module 1 (A) did not answer command 136 (firmware version) within 200 ms"),
        "{err}"
    );
    // A module that does not identify is sent nothing on a guess (no 139).
    assert!(err.contains("sent nothing on a guess"), "{err}");
}

#[test]
fn dropped_and_corrupted_replies_are_errors_not_answers() {
    let sim = Sim::start(&["--pty"]);
    let mut console = sim;
    console.console("drop 1");
    let out = on(&console, &["--timeout", "200", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    console.console("drop 0");
    console.console("corrupt 1");
    let out = on(&console, &["--timeout", "200", "-c", "GAP 1, 0"]);
    assert_eq!(
        code(&out),
        3,
        "corrupted replies are never taken: {}",
        stderr(&out)
    );
    console.console("corrupt 0");
    let out = on(&console, &["--timeout", "200", "-c", "GAP 4, 0"]);
    assert_eq!(
        code(&out),
        0,
        "after the faults stop, it works again: {}",
        stderr(&out)
    );
}

#[test]
fn delayed_replies_within_the_timeout_are_fine() {
    let sim = Sim::start(&["--pty", "--delay-rate", "1", "--delay-ms", "150"]);
    let out = on(&sim, &["--timeout", "2000", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(lines(&out), ["BA 100 1000000"]);
    let out = on(&sim, &["--timeout", "100", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 3);
}

#[test]
fn a_hang_up_over_tcp_is_a_lost_link() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0", "--hangup-after", "3"]);
    let out = run(&[
        "--tcp", &sim.first, "-c", "GAP 1, 0", "-c", "GAP 1, 0", "-c", "GAP 1, 0", "-c", "GAP 1, 0",
    ]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(stderr(&out).contains("link lost"), "{}", stderr(&out));
}

#[test]
fn piped_stdin_skips_blanks_and_comments_and_stops_at_the_first_failure() {
    let sim = Sim::start(&["--pty"]);
    let port = sim.first.clone();
    let ok = run_with_stdin(&["--port", &port], "# set up\n\nSAP 1, 0, 5\nGAP 1, 0\n");
    assert_eq!(code(&ok), 0, "{}", stderr(&ok));
    assert_eq!(lines(&ok), ["BA 100 5", "BA 100 5"]);
    let device = run_with_stdin(&["--port", &port], "GAP 1, 0\nGAP 200, 0\nGAP 1, 0\n");
    assert_eq!(
        code(&device),
        1,
        "a device error status: {}",
        stderr(&device)
    );
    assert_eq!(
        lines(&device),
        ["BA 100 5", "BA 3 0"],
        "the failing reply is printed, nothing after"
    );
    assert!(
        stderr(&device).contains(
            "line 2 (GAP 200, 0): module 1 (A) refused 'AGAP 200, 0': status 3 (wrong type)"
        ),
        "{}",
        stderr(&device)
    );
    let refused = run_with_stdin(&["--port", &port], "GAP 1, 0\nSAP 6, 0, 99\nGAP 1, 0\n");
    assert_eq!(code(&refused), 2);
    assert_eq!(lines(&refused), ["BA 100 5"]);
    assert!(
        stderr(&refused).contains("99 is out of range for max_current"),
        "{}",
        stderr(&refused)
    );
}

#[test]
fn no_validate_sends_what_the_validator_refuses() {
    let sim = Sim::start(&["--pty"]);
    let out = on(&sim, &["--no-validate", "-c", "SAP 6, 0, 99"]);
    assert_eq!(
        code(&out),
        1,
        "the module itself refuses it: {}",
        stderr(&out)
    );
    assert_eq!(lines(&out), ["BA 4 99"]);
    assert!(stderr(&out).contains("not validated"));
}

#[test]
fn an_aborted_run_stops_the_motor_it_started() {
    let sim = Sim::start(&["--pty", "--manual-clock"]);
    let mut sim = sim;
    let out = on(&sim, &["-c", "ROR 0, 200000", "-c", "GAP 300, 0"]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("stopped motor 0 of module 1 (A) with MST"),
        "{}",
        stderr(&out)
    );
    sim.console("advance 10s");
    let motor = sim.console("motor");
    assert!(motor.contains("velocity 0"), "{motor}");
    // Without the abort the motor keeps turning.
    let out = on(&sim, &["-c", "ROR 0, 200000"]);
    assert_eq!(code(&out), 0);
    sim.console("advance 10s");
    let motor = sim.console("motor");
    assert!(!motor.contains("velocity 0 "), "{motor}");
}

#[test]
fn the_transcript_has_every_byte_with_its_meaning() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let log = dir.join("t.log");
    let out = on(&sim, &["--log", log.to_str().unwrap(), "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0);
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(
        text.contains(
            r#" tx "\x01\x8B\x00\x00\x00\x00\x00\x00\x8C" ; enter ASCII mode (139) to module 1"#
        ),
        "{text}"
    );
    assert!(
        text.contains(r#" tx "AGAP 4, 0\r" ; to module 1 (A)"#),
        "{text}"
    );
    assert!(
        text.contains(r#"BA 100 1000000\r" ; A: 100 (successfully executed), value 1000000"#),
        "{text}"
    );
    assert!(text.contains(r#" tx "ABIN\r""#), "{text}");
    for line in text.lines() {
        assert!(
            line.len() > 25 && line.as_bytes()[10] == b'T',
            "timestamped: {line}"
        );
    }
}

#[test]
fn binary_direct_mode_after_bin() {
    let sim = Sim::start(&["--pty"]);
    let out = on(
        &sim,
        &[
            "-c", ":bin", "-c", "136 1", "-c", "136 0", "-c", "GAP 4, 0", "-c", ":ascii", "-c",
            "GAP 4, 0",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let got = lines(&out);
    assert!(got[0].contains("binary direct mode"), "{got:?}");
    assert_eq!(got[1], "BA 100 262", "136 type 1: version 1.06 in binary");
    assert_eq!(got[2], "142V1.06");
    assert_eq!(got[3], "BA 100 1000000");
    assert_eq!(got[5], "BA 100 1000000");
}

#[test]
fn the_built_in_simulator_needs_no_port() {
    let out = run(&["--sim", "-c", "GAP 4, 0", "-c", "MVP ABS, 0, 1000"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(lines(&out), ["BA 100 1000000", "BA 100 1000"]);
}

#[test]
fn a_paced_line_delivers_echoes_byte_by_byte_without_noise() {
    let sim = Sim::start(&["--pty", "--baud", "38400"]);
    for echo in ["char", "line", "none"] {
        let out = on(
            &sim,
            &[
                "-c",
                &format!(":echo {echo}"),
                "-c",
                "GAP 4, 0",
                "-c",
                "GAP 4, 0",
            ],
        );
        assert_eq!(code(&out), 0, "{echo}: {}", stderr(&out));
        assert_eq!(
            lines(&out)[1..],
            ["BA 100 1000000", "BA 100 1000000"],
            "{echo}"
        );
        assert!(
            stderr(&out).is_empty(),
            "{echo}: an echo arriving in pieces is no noise: {}",
            stderr(&out)
        );
    }
}
