//! Binary sessions through the real binary: a binary-only module (the TMCM-1260, identified on
//! connect) used with `-c`, snapshots, a script and the REPL, every line sent as a binary frame;
//! Ctrl-C and a crash stop its motor with MST frames; `--binary` makes a TMCM-142 session a
//! binary one, with 129/128 for `:run`/`:stop`; a module that refuses 139 is talked to in binary.

use std::path::Path;

use rexpect::process::WaitStatus;

use crate::sim::{Sim, velocity_after};
use crate::util::{code, run, stderr, stdout, tempdir, terminal};

/// `tmclsh --port PTY --log LOG ARGS`.
fn on(sim: &Sim, log: &Path, args: &[&str]) -> std::process::Output {
    let mut all = vec!["--port", sim.first.as_str(), "--log", log.to_str().unwrap()];
    all.extend_from_slice(args);
    run(&all)
}

/// What the transcript says was sent: every `tx` line.
fn sent(log: &Path) -> Vec<String> {
    std::fs::read_to_string(log)
        .unwrap()
        .lines()
        .filter(|l| l.contains(" tx "))
        .map(str::to_string)
        .collect()
}

/// Every line sent was a binary frame, and 139 was never among them.
fn all_binary(log: &Path) {
    let sent = sent(log);
    assert!(!sent.is_empty());
    for line in &sent {
        assert!(line.ends_with(" in binary"), "not a binary frame: {line}");
        assert!(!line.contains("(139)"), "139 sent: {line}");
    }
}

#[test]
fn a_binary_only_module_takes_typed_lines_as_binary_frames() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-1260"]);
    let log = tempdir().join("lines.log");
    let out = on(
        &sim,
        &log,
        &[
            "-c",
            "SAP max_positioning_speed, 0, 51200",
            "-c",
            "MVP ABS, 0, 100",
            "-c",
            "GAP target_position, 0",
            "-c",
            "SGP 77, 0, 1",
        ],
    );
    // SGP 77 (auto start) is refused by the module: a device error, exit 1.
    let lines: Vec<String> = stdout(&out).lines().map(str::to_string).collect();
    assert_eq!(
        lines[..3],
        ["BA 100 51200", "BA 100 100", "BA 100 100"],
        "{}",
        stderr(&out)
    );
    all_binary(&log);
    // The profile's validation applies as in ASCII mode: nothing sent for a bad motor.
    let log2 = tempdir().join("refused.log");
    let out = on(&sim, &log2, &["-c", "GAP 1, 1"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(!sent(&log2).iter().any(|l| l.contains("GAP 1, 1")));
}

#[test]
fn snapshots_and_scripts_work_over_binary_frames() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-1260"]);
    let dir = tempdir();
    let file = dir.join("module.toml");
    let file = file.to_str().unwrap();
    let log = dir.join("snapshot.log");
    let out = on(&sim, &log, &["snapshot", "save", file]);
    // The simulated TMCM-1260 has no bank-3 interrupt settings: saved with their error, exit 1.
    assert!(
        code(&out) == 0 || (code(&out) == 1 && stderr(&out).contains("saved with their error")),
        "{}",
        stderr(&out)
    );
    let text = std::fs::read_to_string(file).unwrap();
    assert!(text.contains("firmware = \"1260V144\""), "{text}");
    all_binary(&log);
    let out = on(&sim, &log, &["-c", "SAP max_positioning_speed, 0, 4321"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let differ = on(&sim, &log, &["snapshot", "diff", file]);
    assert_eq!(code(&differ), 1, "{}", stderr(&differ));
    assert!(
        stdout(&differ).contains("max_positioning_speed"),
        "{}",
        stdout(&differ)
    );
    let restored = on(&sim, &log, &["snapshot", "restore", file]);
    assert_eq!(code(&restored), 0, "{}", stderr(&restored));
    let same = on(&sim, &log, &["snapshot", "diff", file]);
    assert_eq!(code(&same), 0, "{}", stdout(&same));
    all_binary(&log);

    let script = dir.join("move.rhai");
    std::fs::write(
        &script,
        "sap(\"max_positioning_speed\", 0, 200000);\n\
         mvp_abs(0, 2000);\n\
         wait_pos(0, 20000);\n\
         assert_eq(gap(\"actual_position\", 0), 2000);\n\
         print(\"arrived\");\n",
    )
    .unwrap();
    let script_log = dir.join("script.log");
    let out = on(&sim, &script_log, &["run", script.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("arrived"));
    all_binary(&script_log);
}

#[test]
fn the_repl_of_a_binary_only_module_and_ctrl_c_stops_its_motor_with_mst_frames() {
    let mut sim = Sim::start(&["--pty", "--manual-clock", "--profile", "tmcm-1260"]);
    let log = tempdir().join("repl.log");
    let mut p = terminal(&["--port", &sim.first, "--log", log.to_str().unwrap()], &[]);
    p.exp_string("TMCM-1260, firmware 1260V144, profile tmcm-1260 (built in)")
        .unwrap();
    p.exp_string("A[bin]> ").unwrap();
    p.send_line("GAP max_positioning_speed, 0").unwrap();
    p.exp_string("max_positioning_speed = ").unwrap();
    p.exp_string("A[bin]> ").unwrap();
    p.send_line("ROR 0, 20000").unwrap();
    p.exp_string("ok").unwrap();
    p.exp_string("A[bin]> ").unwrap();
    assert!(velocity_after(&mut sim, "1s") > 0.0, "the motor turns");
    p.send_control('c').unwrap();
    p.exp_string("stopped motor 0 of module 1 (A) with MST")
        .unwrap();
    p.exp_string("A[bin]> ").unwrap();
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
    all_binary(&log);
    assert!(
        sent(&log).iter().any(|l| l.contains("MST 0")),
        "{:?}",
        sent(&log)
    );
}

#[test]
fn a_crash_in_a_binary_session_stops_the_motor() {
    let mut sim = Sim::start(&["--pty", "--manual-clock", "--profile", "tmcm-1260"]);
    let mut p = terminal(
        &["--port", &sim.first],
        &[("TMCLSH_TEST_CRASH", "repl:crash now")],
    );
    p.exp_string("A[bin]> ").unwrap();
    p.send_line("ROR 0, 20000").unwrap();
    p.exp_string("ok").unwrap();
    p.exp_string("A[bin]> ").unwrap();
    assert!(velocity_after(&mut sim, "1s") > 0.0, "the motor turns");
    p.send_line("crash now").unwrap();
    let text = p.exp_eof().unwrap();
    assert!(
        text.contains("motors stopped: motor 0 of module 1 (A) with MST"),
        "{text}"
    );
    match p.process().wait().expect("tmclsh ends") {
        WaitStatus::Exited(_, code) => assert_eq!(code, 101),
        other => panic!("tmclsh ended with {other:?}"),
    }
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
}

#[test]
fn binary_makes_a_tmcm_142_session_a_binary_one_before_or_after_the_subcommand() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let log = dir.join("c.log");
    let out = on(
        &sim,
        &log,
        &[
            "--binary",
            "-c",
            "SAP 4, 0, 777",
            "-c",
            "GAP 4, 0",
            "-c",
            ":run",
            "-c",
            ":stop",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("BA 100 777"), "{}", stdout(&out));
    all_binary(&log);
    let text = std::fs::read_to_string(&log).unwrap();
    // :run and :stop as commands 129 and 128, not the ASCII words RUN and STOP.
    assert!(text.contains("tx \"\\x01\\x81"), "{text}");
    assert!(text.contains("tx \"\\x01\\x80"), "{text}");
    assert!(
        text.contains("module 1 (A) in binary direct mode: --binary given"),
        "{text}"
    );

    let script = dir.join("read.rhai");
    std::fs::write(&script, "print(gap(4, 0));\n").unwrap();
    for args in [
        vec!["--binary", "run", script.to_str().unwrap()],
        vec!["run", script.to_str().unwrap(), "--binary"],
    ] {
        let log = dir.join("run.log");
        let _ = std::fs::remove_file(&log);
        let out = on(&sim, &log, &args);
        assert_eq!(code(&out), 0, "{args:?}: {}", stderr(&out));
        assert_eq!(stdout(&out).trim_end(), "777", "{args:?}");
        all_binary(&log);
    }
}

#[test]
fn a_module_refusing_139_is_talked_to_in_binary() {
    // The given TMCM-3110 profile leaves ASCII mode unconfirmed: 139 is tried, and the module
    // (binary only) answers it with status 2.
    let sim = Sim::start(&["--pty", "--profile", "tmcm-1260"]);
    let log = tempdir().join("refused.log");
    let out = on(&sim, &log, &["--profile", "tmcm-3110", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out).trim_end(), "BA 100 51200");
    assert!(
        stderr(&out).contains(
            "module 1 (A) in binary direct mode: it answered in binary, not in ASCII mode"
        ),
        "the operator is told which mode the module is in: {}",
        stderr(&out)
    );
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(text.contains("binary reply to 139: status 2"), "{text}");
    assert!(
        text.contains("module 1 (A) in binary direct mode: it answered in binary"),
        "{text}"
    );
    assert!(
        text.contains("GAP 4, 0 to module 1 (A) in binary"),
        "{text}"
    );
}
