//! Transcripts that replay: a session logged with --log against one simulator becomes a script
//! that passes against a fresh simulator and fails when the simulator differs.

use super::{arg, expect};
use crate::sim::Sim;
use crate::util::{stderr, stdout, tempdir};

/// Logs a short commissioning session against a simulator whose time moves only when told, so
/// the values read after the move are settled: settings written and read, a user variable, a
/// move, then (after the move) its position and flag read twice, and a refused parameter.
fn logged_session(log: &std::path::Path) {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let port = sim.first.clone();
    expect(
        &[
            "--port",
            &port,
            "--log",
            arg(log),
            "-c",
            "SAP max_current, 0, 5",
            "-c",
            "GAP max_current, 0",
            "-c",
            "GAP max_positioning_speed, 0",
            "-c",
            "SGP user_variable_3, 2, 1234",
            "-c",
            "GGP user_variable_3, 2",
            "-c",
            "MVP ABS, 0, 800",
        ],
        0,
    );
    assert!(sim.console("advance 5s").starts_with("ok"));
    expect(
        &[
            "--port",
            &port,
            "--log",
            arg(log),
            "-c",
            "GAP actual_position, 0",
            "-c",
            "GAP actual_position, 0",
            "-c",
            "GAP target_position_reached, 0",
            "-c",
            "GAP target_position_reached, 0",
            "-c",
            "SAP 100, 0, 1",
        ],
        1,
    );
}

#[test]
fn a_transcript_becomes_a_script_that_passes_on_a_fresh_module_and_fails_on_a_different_one() {
    let dir = tempdir();
    let log = dir.join("session.log");
    logged_session(&log);
    let script = dir.join("replay.rhai");
    expect(&["transcript", "to-rhai", arg(&log), "-o", arg(&script)], 0);
    let text = std::fs::read_to_string(&script).unwrap();
    let body: Vec<&str> = text
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with("//"))
        .collect();
    assert_eq!(
        body,
        [
            "assert_eq(send(\"ASAP 6, 0, 5\"), 5);  // max_current",
            "assert_eq(send(\"AGAP 6, 0\"), 5);  // max_current",
            "assert_eq(send(\"AGAP 4, 0\"), 1000000);  // max_positioning_speed",
            "assert_eq(send(\"ASGP 3, 2, 1234\"), 1234);  // user_variable_3",
            "assert_eq(send(\"AGGP 3, 2\"), 1234);  // user_variable_3",
            "assert_eq(send(\"AMVP ABS, 0, 800\"), 800);",
            "send(\"AGAP 1, 0\");  // read 800, not checked (it may have been changing), actual_position",
            "wait_until(|| send(\"AGAP 1, 0\") == 800, 10000);  // actual_position",
            "send(\"AGAP 8, 0\");  // read 1, not checked (it may have been changing), target_position_reached",
            "wait_until(|| send(\"AGAP 8, 0\") == 1, 10000);  // target_position_reached",
            "assert_eq(reply(\"ASAP 100, 0, 1\").status, 3);",
        ],
        "{text}"
    );

    let fresh = Sim::start(&["--listen", "127.0.0.1:0"]);
    expect(&["run", arg(&script), "--tcp", &fresh.first], 0);

    let different = Sim::start(&["--pty"]);
    expect(
        &[
            "--port",
            &different.first,
            "-c",
            "SAP max_positioning_speed, 0, 5000",
        ],
        0,
    );
    let out = expect(&["run", arg(&script), "--port", &different.first], 1);
    let message = stderr(&out);
    assert!(message.contains("replay.rhai:"), "{message}");
    assert!(
        message.contains("assert_eq failed: left = 5000, right = 1000000"),
        "{message}"
    );
}

#[test]
fn the_script_goes_to_stdout_and_a_broken_log_is_refused_with_its_line() {
    let dir = tempdir();
    let log = dir.join("bad.log");
    std::fs::write(&log, "2026-01-01T00:00:00Z -- ok\nnonsense\n").unwrap();
    let out = expect(&["transcript", "to-rhai", arg(&log)], 2);
    assert!(
        stderr(&out).contains("line 2: no time stamp"),
        "{}",
        stderr(&out)
    );

    std::fs::write(&log, "2026-01-01T00:00:00Z tx \"AGAP 4, 0\\r\" ; to module 1 (A)\n2026-01-01T00:00:00Z rx \"BA 100 7\\r\" ; A: 100, value 7\n").unwrap();
    let out = expect(&["transcript", "to-rhai", arg(&log)], 0);
    assert!(
        stdout(&out).contains("assert_eq(send(\"AGAP 4, 0\"), 7);  // max_positioning_speed"),
        "{}",
        stdout(&out)
    );
}
