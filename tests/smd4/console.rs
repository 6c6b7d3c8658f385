//! The console of `tmclsh sim --protocol smd4`: each command changes what the drive reports to a
//! client, bad commands are answered with an error line, and the flags that only the TMCL bus
//! understands are refused.

use tmclsh::dialect::smd4::protocol::{Eflags, Sflags};

use super::{Drive, Via, assert_exit, lines};
use crate::util::{code, run, stderr, stdout};

/// The flag words a client reads (SYS:FLAGS).
fn flags(drive: &Drive) -> (u16, u16) {
    let out = drive.run(&["-c", "SYS:FLAGS"]);
    assert_exit(&out, 0);
    let line = lines(&out).remove(0);
    let words: Vec<u16> = line
        .split(',')
        .take(2)
        .map(|w| u16::from_str_radix(w.trim_start_matches("0x"), 16).unwrap())
        .collect();
    (words[0], words[1])
}

#[test]
fn console_commands_change_what_the_drive_reports() {
    let mut drive = Drive::start(Via::Tcp, &[]);
    let (idle, none) = flags(&drive);
    assert_eq!(none, 0);

    assert_eq!(drive.console("limit pos 1"), "limit pos = 1");
    assert_eq!(drive.console("joystick 1"), "joystick = 1");
    let (s, _) = flags(&drive);
    assert!(Sflags(s).is_set(Sflags::LIMIT_POSITIVE) && Sflags(s).is_set(Sflags::JOYSTICK));
    assert_eq!(
        s & !idle,
        (1 << Sflags::LIMIT_POSITIVE) | (1 << Sflags::JOYSTICK)
    );

    // With SYS:EXTEN on, an inactive external enable input latches EFLAGS bit 4.
    assert_exit(&drive.run(&["-c", "SYS:EXTEN,1"]), 0);
    assert_eq!(drive.console("exten 0"), "exten = 0");
    let (s, e) = flags(&drive);
    assert!(!Sflags(s).is_set(Sflags::EXTERNAL_ENABLE));
    assert_eq!(e, 1 << Eflags::EXTERNAL_DISABLE);

    assert_eq!(
        drive.console("fault 1"),
        "fault bit 1 latched, eflags 0x0012"
    );
    assert_eq!(flags(&drive).1, 0x0012);
    // Latched until SYS:CLR (with the input active again) or a power cycle.
    drive.console("exten 1");
    assert_exit(&drive.run(&["-c", "SYS:CLR"]), 0);
    assert_eq!(flags(&drive).1, 0);
    drive.console("fault TempOver");
    assert_eq!(
        drive.console("power-cycle"),
        "powered up from the stored configuration"
    );
    assert_eq!(flags(&drive).1, 0);

    assert_eq!(
        drive.console("motor"),
        "position 0.00 velocity 0.000 standby 1 at-target-velocity 0"
    );
    assert_eq!(drive.console("setting MOTOR:VMAX"), "MOTOR:VMAX = 1000");
}

#[test]
fn bad_console_commands_are_answered_with_an_error() {
    let mut drive = Drive::start(Via::Pty, &[]);
    for (command, error) in [
        ("limit up 1", "error: 'up' is not a limit; use pos or neg"),
        ("exten maybe", "error: 'maybe' is not a level; use 0 or 1"),
        ("fault 16", "error: EFLAGS has bits 0..15, not 16"),
        (
            "flash-failure sometimes",
            "error: 'sometimes' is not on or off",
        ),
        ("setting MOTOR:NOPE", "error: no setting MOTOR:NOPE"),
        ("input 1 1", "error: unknown command 'input'; try help"),
        ("advance 1s", "error: advance needs --manual-clock"),
    ] {
        assert_eq!(drive.sim.console(command), error);
    }
    let answer = drive.sim.console("fault warp");
    assert!(answer.contains("5 EmergencyStop"), "{answer}");
    let help = drive.sim.console("help");
    assert!(help.starts_with("ok commands: "), "{help}");
    assert!(help.contains(" flash-failure "), "{help}");
    // Only the SMD4 console's commands and every console's: no TMCL command, no word of a
    // description's continuation line.
    let names: Vec<&str> = help.split_whitespace().collect();
    for other in ["input", "switch", "@N", "reads", "modules"] {
        assert!(!names.contains(&other), "{other} in {help}");
    }
    assert_eq!(
        drive.sim.console("time").split(' ').next(),
        Some("ok"),
        "in step after help"
    );
}

#[test]
fn the_sim_help_documents_the_smd4_console_and_quirks() {
    let out = run(&["sim", "--protocol", "smd4", "--help"]);
    assert_eq!(code(&out), 0);
    let help = stdout(&out);
    for text in [
        "SMD4 drive (--protocol smd4)",
        "limit pos|neg 0|1",
        "power-cycle",
        "--float-missing-e",
        "--error-spelling",
        "--prefix-only",
    ] {
        assert!(help.contains(text), "{text} missing from:\n{help}");
    }
}

#[test]
fn flags_of_the_tmcl_bus_are_refused_for_the_smd4() {
    for flag in [
        &["--modules", "1,2"][..],
        &["--left-switch", "-100"],
        &["--no-reply-to-139"],
        &["--no-ascii"],
        &["--boot-loader"],
    ] {
        let mut args = vec!["sim", "--protocol", "smd4"];
        args.extend(flag);
        let out = run(&args);
        assert_eq!(code(&out), 2, "{flag:?}");
        let said = stderr(&out);
        assert!(
            said.contains(&format!(
                "{} is a flag of the TMCL simulation (--protocol tmcl); the SMD4 simulation has \
                 no such flag",
                flag[0]
            )),
            "{said}"
        );
        assert!(!said.contains("TMCM-142"), "{said}");
    }
}
