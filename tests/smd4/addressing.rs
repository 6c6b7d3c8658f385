//! Addressing: `--address N` reaches the drive whose COMS:SERIAL:SLAVEADDR is N (set over the
//! line, or stored in the simulator's state file), `@0` broadcasts without a reply, and a drive
//! in addressing mode ignores unprefixed packets — the client then times out with exit 3 and says
//! why.

use tmclsh::dialect::smd4::protocol::Smd4Spec;

use super::{BOTH, Drive, Via, assert_exit, lines};

fn firmware() -> String {
    Smd4Spec::builtin()
        .commands
        .get("SYS:FW")
        .unwrap()
        .sim_value
        .clone()
        .unwrap()
}

#[test]
fn address_n_reaches_the_drive_whose_slave_address_is_n() {
    for via in BOTH {
        let mut drive = Drive::logged(via, &[]);
        let out = drive.run(&["-c", "COMS:SERIAL:SLAVEADDR,5"]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), ["0x0888,0x0000,5"]);
        assert_eq!(
            drive.console("flags"),
            "sflags 0x0888 eflags 0x0000 addressing 0"
        );

        let out = drive.run(&["--address", "5", "-c", "SYS:FW"]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), [format!("@5,0x0888,0x0000,{}", firmware())]);
        assert!(drive.console("flags").ends_with("addressing 1"));

        let out = drive.run(&["--address", "1", "--timeout", "200", "-c", "SYS:FW"]);
        assert_exit(&out, 3);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("no reply from drive @1 within 200 ms"),
            "{err}"
        );
        assert!(err.contains("COMS:SERIAL:SLAVEADDR is 1"), "{err}");

        let out = drive.run(&["--address", "5", "--prefix-comma", "-c", "SYS:FW"]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), [format!("@5,0x0888,0x0000,{}", firmware())]);
        assert_eq!(
            drive.received(),
            [
                "COMS:SERIAL:SLAVEADDR,5",
                "@5SYS:FW",
                "@1SYS:FW",
                "@5,SYS:FW"
            ],
            "{via:?}"
        );
    }
}

#[test]
fn a_stored_slave_address_holds_after_a_restart() {
    let state = crate::util::tempdir().join("smd4.toml");
    let state = state.to_str().unwrap();
    let drive = Drive::start(Via::Pty, &["--state", state]);
    let out = drive.run(&["-c", "COMS:SERIAL:SLAVEADDR,9", "-c", "STORE"]);
    assert_exit(&out, 0);
    drive.sim.quit();

    let mut drive = Drive::start(Via::Tcp, &["--state", state]);
    assert_eq!(
        drive.console("setting COMS:SERIAL:SLAVEADDR"),
        "COMS:SERIAL:SLAVEADDR = 9"
    );
    let out = drive.run(&["--address", "9", "-c", "COMS:SERIAL:SLAVEADDR"]);
    assert_exit(&out, 0);
    assert_eq!(lines(&out), ["@9,0x0888,0x0000,9"]);
}

#[test]
fn a_broadcast_is_executed_by_the_drive_and_expects_no_reply() {
    for via in BOTH {
        let mut drive = Drive::start(via, &[]);
        // A reply awaited in vain would end in exit 3 after the timeout.
        let out = drive.run(&["--address", "0", "-c", "SYS:IDENT,1"]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), [""], "one (empty) line per command");
        // Ident (bit 4) comes on: the drive executed it, and it is in addressing mode now.
        // (Nothing tells the client when; the console is asked until it shows.)
        drive.console_until("flags", |a| a == "sflags 0x0898 eflags 0x0000 addressing 1");
        let out = drive.run(&["--address", "1", "-c", "SYS:IDENT"]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), ["@1,0x0898,0x0000,1"]);
    }
}

#[test]
fn addressing_mode_ignores_unprefixed_packets_until_the_drive_restarts() {
    for via in BOTH {
        let mut drive = Drive::logged(via, &[]);
        assert_exit(&drive.run(&["--address", "1", "-c", "SYS:FW"]), 0);

        let out = drive.run(&["--timeout", "200", "-c", "SYS:FW"]);
        assert_exit(&out, 3);
        assert!(lines(&out).is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("no reply from the drive within 200 ms"),
            "{err}"
        );
        assert!(
            err.contains("in addressing mode") && err.contains("use --address N"),
            "the message says why: {err}"
        );

        // An addressed request answered proves the drive has read everything before it on the
        // line, the probes included: the console's power-cycle must not overtake them.
        assert_exit(&drive.run(&["--address", "1", "-c", "SYS:FW"]), 0);
        assert_eq!(
            drive.console("power-cycle"),
            "powered up from the stored configuration"
        );
        let out = drive.run(&["-c", "SYS:FW"]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), [format!("0x0888,0x0000,{}", firmware())]);

        let log = drive.sim.quit();
        let ignored = log
            .lines()
            .filter(|l| l.contains("ignored: addressing mode"))
            .count();
        // The unprefixed SYS:FW, and the TMCL probes sent after the silence (to tell a TMCL
        // module on the line), which the drive ignores as well.
        assert_eq!(ignored, 2, "{log}");
        assert!(log.contains("AGGP 67, 0"), "{log}");
    }
}
