//! Every face over slcan: typed lines, piped lines, scripts, snapshots, scans, transcripts and
//! their replay; acknowledgement styles; foreign frames; absent modules and silent adapters.

use super::{over_can, slcan_sim};
use crate::sim::Sim;
use crate::util::{code, run, run_with_stdin, stderr, stdout, tempdir};

#[test]
fn lines_go_over_slcan_with_every_acknowledgement_style() {
    for ack in ["z", "Z", "cr", "none"] {
        let sim = slcan_sim(&["--slcan-ack", ack]);
        let out = over_can(&sim, &["-c", "SAP 4, 0, 1234", "-c", "GAP 4, 0"]);
        assert_eq!(code(&out), 0, "--slcan-ack {ack}: {}", stderr(&out));
        assert_eq!(
            stdout(&out).matches("1234").count(),
            2,
            "--slcan-ack {ack}: {}",
            stdout(&out)
        );
    }
}

#[test]
fn piped_lines_and_scripts_reach_two_modules_on_one_bus() {
    let sim = slcan_sim(&["--modules", "1,3"]);
    let can = format!("slcan:{}", sim.first);
    let out = run_with_stdin(
        &["--can", &can],
        "SAP 4, 0, 777\n:target 3\nGAP 4, 0\n:target 1\nGAP 4, 0\n",
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("target: module 3 (C), TMCM-142"), "{text}");
    assert!(
        text.contains("1000000"),
        "module 3 keeps its default: {text}"
    );
    assert_eq!(text.matches("777").count(), 2, "{text}");
    let dir = tempdir();
    let script = dir.join("can.rhai");
    std::fs::write(
        &script,
        "send(\"SAP 4, 0, 4321\");\nassert_eq(send(\"GAP 4, 0\"), 4321);\nprint(\"done\");\n",
    )
    .unwrap();
    let out = run(&["run", "--can", &can, script.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}{}", stdout(&out), stderr(&out));
    assert!(stdout(&out).contains("done"));
}

#[test]
fn a_transcript_shows_can_frames_never_139_and_replays() {
    let sim = slcan_sim(&[]);
    let dir = tempdir();
    let log = dir.join("can.log");
    let out = over_can(
        &sim,
        &[
            "--log",
            log.to_str().unwrap(),
            "-c",
            "SAP 4, 0, 1500",
            "-c",
            "GAP 4, 0",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(text.contains("CAN 001#050400000005DC"), "{text}");
    assert!(text.contains("CAN 002#0164060000"), "{text}");
    assert!(text.contains("binary frames only"), "{text}");
    assert!(!text.contains("139"), "no ASCII mode over CAN: {text}");
    let replay = run(&["transcript", "to-rhai", log.to_str().unwrap()]);
    assert_eq!(code(&replay), 0, "{}", stderr(&replay));
    let script = dir.join("replay.rhai");
    std::fs::write(&script, stdout(&replay)).unwrap();
    let can = format!("slcan:{}", sim.first);
    let out = run(&["run", "--can", &can, script.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}{}", stdout(&out), stderr(&out));
}

#[test]
fn scan_walks_can_ids_and_snapshots_are_saved() {
    let sim = slcan_sim(&["--modules", "1,3"]);
    let can = format!("slcan:{}", sim.first);
    let out = run(&["scan", "--can", &can, "--addresses", "1-4"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("2 modules answered at 1-4"), "{text}");
    let dir = tempdir();
    let file = dir.join("snap.toml");
    let out = run(&["snapshot", "save", "--can", &can, file.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let saved = std::fs::read_to_string(&file).unwrap();
    assert!(saved.contains("max_positioning_speed"), "{saved}");
}

#[test]
fn foreign_frames_on_the_bus_are_ignored_and_counted() {
    let sim = slcan_sim(&["--foreign-frames"]);
    let out = over_can(&sim, &["-c", "GAP 4, 0", "-c", ":line"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("1000000"), "{text}");
    let counted = text
        .lines()
        .find(|l| l.contains("not for the host ignored"))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(!counted.contains(" 0 not for the host"), "{counted}");
}

#[test]
fn an_absent_module_is_exit_3_named_and_quick() {
    let sim = slcan_sim(&[]);
    let out = over_can(
        &sim,
        &["--module", "7", "--timeout", "200", "-c", "GAP 4, 0"],
    );
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(stderr(&out).contains("module 7 (G)"), "{}", stderr(&out));
}

#[test]
fn a_device_that_is_no_slcan_adapter_is_named_as_the_problem() {
    // A serial TMCL module, not an slcan adapter: `C` gets no answer.
    let sim = Sim::start(&["--pty"]);
    let can = format!("slcan:{}", sim.first);
    let out = run(&["--can", &can, "--timeout", "200", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("did not answer the slcan command `C`"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn can_options_are_refused_where_they_cannot_apply() {
    let out = run(&["--sim", "--can-bitrate", "500000", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("give it with --can"),
        "{}",
        stderr(&out)
    );
    let out = run(&[
        "--can",
        "socketcan:vcan0",
        "--can-bitrate",
        "500000",
        "-c",
        "GAP 4, 0",
    ]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("ip link"), "{}", stderr(&out));
    let out = run(&[
        "--can",
        "slcan:/dev/null",
        "--port",
        "/dev/null",
        "-c",
        "GAP 4, 0",
    ]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let out = run(&["--can", "pcan:1", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let sim = slcan_sim(&[]);
    let out = over_can(&sim, &["-c", ":ascii"]);
    assert_ne!(code(&out), 0);
    assert!(
        stderr(&out).contains("no ASCII mode over CAN"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_console_reaches_the_modules_and_faults_behind_the_slcan_adapter() {
    let mut sim = slcan_sim(&[]);
    let read = |sim: &Sim| {
        let out = over_can(sim, &["--value", "-c", "GIO 3, 0"]);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        stdout(&out).trim().to_string()
    };
    assert_eq!(read(&sim), "0");
    let answer = sim.console("input 3 1");
    assert!(answer.starts_with("ok"), "{answer}");
    assert_eq!(
        read(&sim),
        "1",
        "the input set on the console is read over CAN"
    );
    let answer = sim.console("faults");
    assert!(answer.starts_with("ok seed"), "{answer}");
    let answer = sim.console("hangup");
    assert_eq!(answer, "ok hung up");
}
