//! A run that fails or is interrupted while the motor it started runs sends MOTOR:STOP. The
//! simulator runs on `--manual-clock`: the motor is seen running at VMAX before, and standing
//! after time is advanced — where it would still run at VMAX had nothing stopped it.

use tmclsh::dialect::smd4::protocol::{Sflags, Smd4Spec};

use super::{BOTH, Drive, Streaming, Via, assert_exit};

fn vmax() -> f64 {
    let spec = Smd4Spec::builtin().commands.get("MOTOR:VMAX").unwrap();
    spec.default
        .as_ref()
        .and_then(|d| d.parse().ok())
        .expect("VMAX default")
}

/// Starts the motor from a streaming client and lets it reach VMAX.
fn running(drive: &mut Drive) -> Streaming {
    let mut client = Streaming::start(drive, &[]);
    client.send("MOTOR:RUNV,+");
    assert_eq!(client.line(), "0x0808,0x0000", "running, standby flag off");
    drive.console("advance 5s");
    let motor = drive.motor();
    assert!(!motor.standby);
    assert_eq!(motor.velocity, vmax());
    client
}

/// The motor, after long enough to come to rest from VMAX.
fn comes_to_rest(drive: &mut Drive) {
    drive.console("advance 5s");
    let motor = drive.motor();
    assert!(motor.standby, "{motor:?}");
    assert_eq!(motor.velocity, 0.0);
}

#[test]
fn the_motor_runs_on_when_the_run_succeeds() {
    let mut drive = Drive::start(Via::Pty, &["--manual-clock"]);
    let client = running(&mut drive);
    let (code, err) = client.finish();
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("MOTOR:STOP"), "{err}");
    drive.console("advance 5s");
    assert_eq!(drive.motor().velocity, vmax(), "nothing stopped it");
}

#[test]
fn a_failing_line_while_the_motor_runs_stops_it() {
    for via in BOTH {
        let mut drive = Drive::start(via, &["--manual-clock"]);
        let mut client = running(&mut drive);
        client.send("MOTOR:RES,16");
        // Cruising: standby off, target velocity reached on.
        let mut cruising = Sflags(0x0888);
        cruising.set(Sflags::STANDBY, false);
        cruising.set(Sflags::AT_TARGET_VELOCITY, true);
        assert_eq!(
            client.line(),
            format!("{:#06X},0x0000,-1 (Stop motor first)", cruising.0).replacen("0X", "0x", 1)
        );
        let (code, err) = client.finish();
        assert_eq!(code, 1, "{err}");
        assert!(err.contains("line 2 (MOTOR:RES,16)"), "{err}");
        assert!(
            err.contains("stopped the motor of the drive with MOTOR:STOP"),
            "{err}"
        );
        comes_to_rest(&mut drive);
    }
}

#[test]
fn a_refused_line_while_the_motor_runs_stops_it_too() {
    let mut drive = Drive::start(Via::Tcp, &["--manual-clock"]);
    let out = drive.run(&["--address", "1", "-c", "MOTOR:RUNV,-", "-c", "MOTOR:RES,7"]);
    assert_exit(&out, 2);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("stopped the motor of drive @1 with MOTOR:STOP"),
        "{err}"
    );
    comes_to_rest(&mut drive);
}

#[cfg(unix)]
#[test]
fn ctrl_c_while_the_motor_runs_stops_it() {
    for via in BOTH {
        let mut drive = Drive::start(via, &["--manual-clock"]);
        let client = running(&mut drive);
        client.interrupt();
        let (code, err) = client.exit();
        assert_eq!(code, 130, "{err}");
        assert!(err.contains("interrupted"), "{err}");
        assert!(err.contains("with MOTOR:STOP"), "{err}");
        comes_to_rest(&mut drive);
    }
}

#[test]
fn a_failing_script_while_the_motor_runs_stops_it() {
    let dir = crate::util::tempdir();
    let script = dir.join("runaway.rhai");
    std::fs::write(&script, "send(\"MOTOR:RUNV,+\");\nwait_standby(200);\n").unwrap();
    for via in BOTH {
        let mut drive = Drive::start(via, &["--manual-clock"]);
        let out = drive.script(&script, &[]);
        assert_exit(&out, 1);
        let err = String::from_utf8_lossy(&out.stderr);
        let at = format!(
            "{}:2:1: timed out after 200 ms waiting for",
            script.display()
        );
        assert!(err.contains(&at), "{err}");
        assert!(err.contains("with MOTOR:STOP"), "{err}");
        comes_to_rest(&mut drive);
    }
}

#[cfg(unix)]
#[test]
fn ctrl_c_in_a_script_while_the_motor_runs_stops_it() {
    let dir = crate::util::tempdir();
    let script = dir.join("wait.rhai");
    std::fs::write(
        &script,
        "send(\"MOTOR:RUNV,-\");\nprint(\"running\");\nwait_standby(600000);\n",
    )
    .unwrap();
    let mut drive = Drive::start(Via::Tcp, &["--manual-clock"]);
    let mut client = Streaming::script(&drive, &script);
    assert_eq!(client.line(), "running");
    drive.console("advance 5s");
    assert_eq!(drive.motor().velocity, -vmax());
    client.interrupt();
    let (code, err) = client.exit();
    assert_eq!(code, 130, "{err}");
    assert!(
        err.contains(&format!("{}:3:1: interrupted", script.display())),
        "{err}"
    );
    assert!(err.contains("with MOTOR:STOP"), "{err}");
    comes_to_rest(&mut drive);
}
