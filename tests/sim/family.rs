//! `tmclsh sim --profile …` and `--modules N:PROFILE`: other modules of the family through the
//! real binary, over the pty and TCP: every motor of a TMCM-6110 on its own, per-motor switch
//! flags beside the old forms, version strings, a binary-only module, a bus of different
//! modules, and the refusals of bad specs.

use std::time::Instant;

use tmclsh::dialect::tmcl::protocol::Status;

use super::{PATIENCE, Port, Sim, frame};
use crate::util::{code, run, stderr, stdout};

const ROR: u8 = 1;
const ROL: u8 = 2;
const MST: u8 = 3;
const MVP: u8 = 4;
const GAP: u8 = 6;

/// Polls GAP `number` of `motor` at `address` until it reads `value` (bounded by PATIENCE).
fn await_gap(port: &mut Port, address: u8, number: u8, motor: u8, value: i32) {
    let deadline = Instant::now() + PATIENCE;
    loop {
        let reply = port.transact(address, GAP, number, motor, 0);
        if reply.value == value {
            return;
        }
        assert!(
            Instant::now() < deadline,
            "GAP {number}, {motor} at module {address} never read {value} (last {})",
            reply.value
        );
    }
}

/// The 136 type-0 answer of `address`: eight characters after the host byte.
fn version(port: &mut Port, address: u8) -> String {
    port.send(&frame(address, 136, 0, 0, 0));
    let reply = port.read_n(9);
    String::from_utf8_lossy(&reply[1..9]).into_owned()
}

#[test]
fn a_tmcm_6110_moves_each_motor_on_its_own_over_the_pty() {
    let mut sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    let mut port = sim.pty();
    assert_eq!(version(&mut port, 1), "6110V131");
    assert_eq!(port.transact(1, MVP, 0, 3, 4000).status, Status::Ok);
    await_gap(&mut port, 1, 1, 3, 4000);
    for motor in [0, 1, 2, 4, 5] {
        assert_eq!(port.transact(1, GAP, 1, motor, 0).value, 0, "motor {motor}");
    }
    assert!(
        sim.console("motor 3")
            .starts_with("ok position 4000 target 4000"),
        "the console sees motor 3"
    );
    assert!(sim.console("motor").starts_with("ok position 0 target 0"));
    // Turning two motors; MST stops only the one it names.
    port.transact(1, ROR, 0, 1, 300);
    port.transact(1, ROL, 0, 2, 300);
    await_gap(&mut port, 1, 3, 1, 300);
    await_gap(&mut port, 1, 3, 2, -300);
    assert_eq!(port.transact(1, MST, 0, 1, 0).status, Status::Ok);
    await_gap(&mut port, 1, 3, 1, 0);
    assert_eq!(
        port.transact(1, GAP, 3, 2, 0).value,
        -300,
        "motor 2 turns on"
    );
    assert_eq!(
        port.transact(1, GAP, 1, 6, 0).status,
        Status::InvalidValue,
        "a TMCM-6110 has motors 0..5"
    );
    port.transact(1, MST, 0, 2, 0);
}

#[test]
fn switch_flags_take_a_motor_and_keep_their_old_form() {
    let mut sim = Sim::start(&[
        "--listen",
        "127.0.0.1:0",
        "--profile",
        "tmcm-6110",
        "--left-switch",
        "-500",
        "--left-switch",
        "2:-100",
        "--right-switch=4:800",
    ]);
    let mut port = sim.tcp();
    assert_eq!(
        sim.console("switch 3 right 1500"),
        "ok motor 3 switch right at 1500",
        "the console moves one motor's switch"
    );
    for motor in [0, 2, 4] {
        port.transact(1, ROL, 0, motor, 500);
        port.transact(1, ROR, 0, motor + 1, 500);
    }
    await_gap(&mut port, 1, 1, 0, -500);
    await_gap(&mut port, 1, 1, 2, -100);
    await_gap(&mut port, 1, 1, 4, -500);
    await_gap(&mut port, 1, 1, 3, 1500);
    assert_eq!(
        port.transact(1, GAP, 11, 2, 0).value,
        1,
        "motor 2 on its left switch"
    );
    assert_eq!(
        port.transact(1, GAP, 10, 3, 0).value,
        1,
        "motor 3 on its right switch"
    );
    // Motor 4's right switch is at 800, right of where it stopped.
    assert_eq!(port.transact(1, GAP, 10, 4, 0).value, 0);
    assert_eq!(port.transact(1, GAP, 11, 4, 0).value, 1);
    // Motors 1 and 5 have no right switch: they run on.
    await_gap(&mut port, 1, 3, 5, 500);
    assert!(
        port.transact(1, GAP, 1, 1, 0).value > 1500,
        "motor 1 runs on"
    );
    assert!(
        sim.console("switch 9 left 0")
            .starts_with("error: the TMCM-6110 has no motor 9")
    );
}

#[test]
fn a_bus_of_different_modules_each_of_its_own_profile() {
    let mut sim = Sim::start(&[
        "--listen",
        "127.0.0.1:0",
        "--modules",
        "1:tmcm-142,2:tmcm-6110,3:1260",
    ]);
    let mut port = sim.tcp();
    assert_eq!(version(&mut port, 1), "142V1.06");
    assert_eq!(version(&mut port, 2), "6110V131");
    assert_eq!(version(&mut port, 3), "1260V144");
    // Each module's own tables: axis count, defaults, ranges.
    assert_eq!(port.transact(1, GAP, 4, 5, 0).status, Status::InvalidValue);
    assert_eq!(port.transact(2, GAP, 4, 5, 0).value, 1000);
    assert_eq!(port.transact(1, GAP, 4, 0, 0).value, 1_000_000);
    assert_eq!(port.transact(2, 5, 4, 0, 2048).status, Status::InvalidValue);
    assert_eq!(port.transact(3, GAP, 4, 0, 0).value, 51_200);
    // Moving module 2's motor 5 leaves module 1's motor alone.
    port.transact(2, MVP, 0, 5, 3000);
    await_gap(&mut port, 2, 1, 5, 3000);
    assert_eq!(port.transact(1, GAP, 1, 0, 0).value, 0);
    assert!(sim.console("@2 motor 5").starts_with("ok position 3000"));
    // The binary-only module refuses 139 and stays binary; the others switch.
    assert_eq!(
        port.transact(3, 139, 0, 0, 0).status,
        Status::InvalidCommand
    );
    assert_eq!(port.transact(3, GAP, 4, 0, 0).value, 51_200);
    assert_eq!(
        port.transact(2, 9, 67, 0, 0x20).status,
        Status::Ok,
        "no echo"
    );
    assert_eq!(port.transact(2, 139, 0, 0, 0).status, Status::Ok);
    port.send(b"BGAP 4, 5\r");
    assert_eq!(port.read_line(), "BB 100 1000\r");
}

#[test]
fn bad_module_and_switch_specs_are_refused_before_serving() {
    let cases: [(&[&str], &str); 8] = [
        (
            &["--modules", "1:tmcm-9999"],
            "no built-in profile or file 'tmcm-9999'",
        ),
        (&["--modules", "1:tmcm-611"], "did you mean"),
        (
            &["--modules", "1,2:tmcm-6110,2"],
            "module address 2 is given twice",
        ),
        (
            &["--modules", "0"],
            "module address 0 is out of range 1..255",
        ),
        (
            &["--modules", "256:tmcm-142"],
            "module address 256 is out of range 1..255",
        ),
        (&["--modules", "x"], "'x' is not a module address"),
        (&["--modules", "1:"], "names no profile"),
        (
            &["--profile", "tmcm-6110", "--left-switch", "6:100"],
            "no module on the bus has a motor 6 (motors 0..5)",
        ),
    ];
    for (args, message) in cases {
        let mut all = vec!["sim", "--listen", "127.0.0.1:0"];
        all.extend_from_slice(args);
        let out = run(&all);
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(message), "{args:?}: {}", stderr(&out));
        assert!(stdout(&out).is_empty(), "{args:?}: nothing served");
    }
    let out = run(&["sim", "--listen", "127.0.0.1:0", "--left-switch", "1:x"]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("'x' is not a position"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_builtin_simulator_is_the_profiles_module() {
    let out = run(&[
        "--sim",
        "--profile",
        "tmcm-6110",
        "-c",
        "SAP 4, 4, 777",
        "-c",
        "GAP 4, 4",
        "-c",
        "GAP 4, 0",
        "-c",
        "GIO 8, 1",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines,
        ["BA 100 777", "BA 100 777", "BA 100 1000", "BA 100 0"]
    );
    assert!(stderr(&out).contains("built-in simulated TMCM-6110"));
    let out = run(&["--sim", "--profile", "tmcm-1160", "-c", "GIO 2, 0"]);
    assert_ne!(
        code(&out),
        0,
        "a TMCM-1160 has inputs 0..1: {}",
        stdout(&out)
    );
}

#[test]
fn a_boot_loader_names_itself_and_refuses_the_rest() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110", "--boot-loader"]);
    let mut port = sim.pty();
    assert_eq!(version(&mut port, 1), "6110B131");
    assert_eq!(
        port.transact(1, GAP, 1, 0, 0).status,
        Status::InvalidCommand
    );
    assert_eq!(
        port.transact(1, 139, 0, 0, 0).status,
        Status::InvalidCommand
    );
    assert_eq!(
        port.transact(1, 136, 1, 0, 0).value,
        (6110 << 16) | 287,
        "136 type 1 still answers: module number and version 1.31"
    );
}

#[test]
fn a_tmcm_6110_in_ascii_mode_moves_the_motor_each_line_names() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    let mut port = sim.pty();
    assert_eq!(
        port.transact(1, 9, 67, 0, 0x20).status,
        Status::Ok,
        "no echo"
    );
    assert_eq!(port.transact(1, 139, 0, 0, 0).status, Status::Ok);
    port.send(b"AMVP ABS, 5, 2500\r");
    assert_eq!(port.read_line(), "BA 100 2500\r");
    let deadline = Instant::now() + PATIENCE;
    loop {
        port.send(b"AGAP 8, 5\r");
        if port.read_line() == "BA 100 1\r" {
            break;
        }
        assert!(Instant::now() < deadline, "motor 5 never arrived");
    }
    port.send(b"AGAP 1, 5\r");
    assert_eq!(port.read_line(), "BA 100 2500\r");
    port.send(b"AGAP 1, 4\r");
    assert_eq!(port.read_line(), "BA 100 0\r");
    port.send(b"AGAP 1, 6\r");
    assert_eq!(port.read_line(), "BA 4 0\r", "motor 6: invalid value");
    // SAC is not in the TMCM-6110's ASCII list (it lacks the command altogether).
    port.send(b"ASAC 0, 0, 0\r");
    assert_eq!(port.read_line(), "BA 2 0\r");
    // A port the map lacks is the type byte's fault, as in binary.
    port.send(b"AGIO 9, 0\r");
    assert_eq!(port.read_line(), "BA 3 0\r");
}

#[test]
fn a_mixed_bus_keeps_each_modules_eeprom_in_the_state_file() {
    let dir = crate::util::tempdir();
    let state = dir.join("bus.toml");
    let state = state.to_str().unwrap();
    let args = [
        "--listen",
        "127.0.0.1:0",
        "--modules",
        "1:tmcm-142,2:tmcm-6110",
        "--state",
        state,
    ];
    let sim = Sim::start(&args);
    let mut port = sim.tcp();
    assert_eq!(port.transact(2, 5, 4, 3, 1717).status, Status::Ok);
    assert_eq!(port.transact(2, 7, 4, 3, 0).status, Status::Ok);
    assert_eq!(port.transact(1, 5, 4, 0, 123).status, Status::Ok);
    assert_eq!(port.transact(1, 7, 4, 0, 0).status, Status::Ok);
    drop(port);
    drop(sim);
    let text = std::fs::read_to_string(state).unwrap();
    assert!(
        text.contains("motors"),
        "motor 3's value is in the file:\n{text}"
    );
    let sim = Sim::start(&args);
    let mut port = sim.tcp();
    assert_eq!(port.transact(2, GAP, 4, 3, 0).value, 1717);
    assert_eq!(port.transact(2, GAP, 4, 2, 0).value, 1000);
    assert_eq!(port.transact(1, GAP, 4, 0, 0).value, 123);
}

#[test]
fn each_shipped_profiles_simulated_module_identifies_as_itself() {
    use tmclsh::dialect::tmcl::profile::catalogue::{self, Identified};
    use tmclsh::dialect::tmcl::profile::family::AsciiInterface;
    for builtin in catalogue::BUILTINS {
        let sim = Sim::start(&["--pty", "--profile", builtin.name]);
        let mut port = sim.pty();
        let answer = version(&mut port, 1);
        match catalogue::identify(&answer) {
            Ok(Identified::Known { profile, .. }) => {
                assert_eq!(profile.name, builtin.name, "{answer}")
            }
            other => panic!("{}: {answer} identified as {other:?}", builtin.name),
        }
        let ascii = port.transact(1, 139, 0, 0, 0).status;
        let profile = catalogue::by_name(builtin.name).unwrap();
        let binary_only = profile.identity.ascii == Some(AsciiInterface::No);
        let expected = if binary_only {
            Status::InvalidCommand
        } else {
            Status::Ok
        };
        assert_eq!(ascii, expected, "{}: 139", builtin.name);
    }
}

#[test]
fn a_module_without_its_own_profile_is_of_the_bus_profile() {
    let sim = Sim::start(&[
        "--listen",
        "127.0.0.1:0",
        "--profile",
        "tmcm-6110",
        "--modules",
        "1,2:pd-1141,7",
    ]);
    let mut port = sim.tcp();
    assert_eq!(version(&mut port, 1), "6110V131");
    assert_eq!(version(&mut port, 2), "1141V119", "by its alias");
    assert_eq!(version(&mut port, 7), "6110V131");
}

#[test]
fn no_ascii_makes_a_module_refuse_139() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-3110", "--no-ascii"]);
    let mut port = sim.pty();
    assert_eq!(version(&mut port, 1), "3110V111");
    assert_eq!(
        port.transact(1, 139, 0, 0, 0).status,
        Status::InvalidCommand
    );
    assert_eq!(port.transact(1, GAP, 4, 2, 0).value, 1000, "still binary");
    let out = run(&["sim", "--protocol", "smd4", "--no-ascii"]);
    assert_eq!(code(&out), 2, "a TMCL-only flag: {}", stderr(&out));
}

#[test]
fn a_module_of_the_generic_profile_answers_and_moves_on_a_bus() {
    let sim = Sim::start(&["--pty", "--modules", "1:tmcm-1140,2:generic"]);
    let mut port = sim.pty();
    assert_eq!(port.transact(2, GAP, 1, 0, 0).status, Status::Ok);
    // Six motors, each moving; a number no table names is plain memory.
    assert_eq!(port.transact(2, MVP, 0, 5, 2000).status, Status::Ok);
    await_gap(&mut port, 2, 1, 5, 2000);
    assert_eq!(port.transact(2, 5, 200, 3, 9).status, Status::Ok);
    assert_eq!(port.transact(2, GAP, 200, 3, 0).value, 9);
    assert_eq!(port.transact(2, GAP, 1, 6, 0).status, Status::InvalidValue);
}
