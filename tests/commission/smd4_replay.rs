//! SMD4 transcripts that replay: a session logged with `--log` against one simulated drive, turned
//! into a script that passes against a fresh drive (also one that spells its replies differently)
//! and fails, naming the line, against a drive that behaves differently.

use super::arg;
use crate::smd4::{Drive, Via, assert_exit, client};
use crate::util::tempdir;

#[test]
fn a_logged_session_replays_against_a_fresh_drive_and_fails_on_a_different_one() {
    let dir = tempdir();
    let log = dir.join("session.log");
    let script = dir.join("replay.rhai");
    {
        let drive = Drive::start(Via::Pty, &[]);
        let out = drive.run(&[
            "--log",
            arg(&log),
            "-c",
            "MOTOR:VMAX,2000",
            "-c",
            "MOTOR:IR,0.5",
            "-c",
            "SYS:MODE",
            "-c",
            "MOTOR:RES",
            "-c",
            "SYS:FLAGSV",
            "-c",
            "SYS:FW",
            "-c",
            "MOTOR:T",
            "-c",
            "MOTOR:T",
            "-c",
            "MOTOR:RUNR,50",
        ]);
        assert_exit(&out, 0);
    }
    let out = client(
        &[],
        &["transcript", "to-rhai", arg(&log), "-o", arg(&script)],
        "",
    );
    assert_exit(&out, 0);
    let text = std::fs::read_to_string(&script).unwrap();
    assert!(
        text.contains("// Replay of the SMD4 transcript session.log"),
        "{text}"
    );
    assert!(
        text.contains("assert_eq(check(\"MOTOR:VMAX,2000\", [2000.0, 2000.0]), \"\");"),
        "{text}"
    );
    let temperature = tmclsh::dialect::smd4::protocol::Smd4Spec::builtin()
        .commands
        .get("MOTOR:T")
        .and_then(|c| c.sim_value.clone())
        .unwrap();
    let settled = format!("wait_until(|| check(\"MOTOR:T\", [{temperature}]) == \"\", 10000);");
    assert!(text.contains(&settled), "{text}");

    for quirks in [
        &[][..],
        &[
            "--float-decimals",
            "5",
            "--float-missing-e",
            "--flag-case",
            "lower",
        ],
    ] {
        let drive = Drive::start(Via::Tcp, quirks);
        let out = drive.script(&script, &[]);
        assert_exit(&out, 0);
    }

    // A drive that echoes currents unrounded answers 0.5 where the transcript had the level.
    let drive = Drive::start(Via::Tcp, &["--no-current-rounding"]);
    let out = drive.script(&script, &[]);
    assert_exit(&out, 1);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("MOTOR:IR,0.5: got [0.5], the transcript had [0.505"),
        "{err}"
    );
}
