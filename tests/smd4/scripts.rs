//! Rhai scripts against the simulated SMD4 (`tmclsh run SCRIPT --protocol smd4 --port PTY`):
//! `send`, `reply`, `flags`, `wait_standby`, `target`, `parse_number`, the shared helpers, the
//! exit codes with file:line:column, and the example `scripts/smd4_commission.rhai`.

use std::path::PathBuf;

use tmclsh::dialect::smd4::protocol::{ErrorCode, Smd4Spec};

use super::{BOTH, Drive, Via, assert_exit, lines};
use crate::util::{code, repo, run, stderr, stdout};

fn write(name: &str, text: &str) -> PathBuf {
    let path = crate::util::tempdir().join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// Every device function, checked from inside the script (args: the firmware version).
const API: &str = r#"
// send: the data items as strings
assert_eq(send("SYS:FW"), [args[0]]);
assert_eq(send("MOTOR:VMAX,2000"), ["2.0000E+03", "2.0000E+03"]);
assert_eq(send("MOTOR:STOP"), []);

// reply: the whole reply, an error code as a value instead of a throw
let r = reply("MOTOR:VMAX");
assert_eq(r.sflags, 0x0888);
assert_eq(r.eflags, 0);
assert_eq(r.data, ["2.0000E+03", "2.0000E+03"]);
assert_eq(r.values, [2000.0, 2000.0]);
assert_eq(r.error, ());
assert_eq(r.raw, "0x0888,0x0000,2.0000E+03,2.0000E+03");
// the lines after the first of a multi-line reply
let listing = reply("SYS:FLAGSV").lines;
assert_eq(listing.len(), 34);
assert_eq(listing[8], "[X]Standby");
send("MOTOR:ESTOP");
let e = reply("MOTOR:RUNV,+");
assert_eq(e.error, -7);
assert_eq(e.eflags, 0x0020);
assert(!e.ok);

// flags: the words and the names of the bits that are set
let f = flags();
assert(f.standby);
assert(f.errors.contains("Emergency Stop"), `errors: ${f.errors}`);
assert(f.status.contains("Standby"));
send("SYS:CLR");
assert_eq(flags().eflags, 0);

// a short move, awaited
send("MOTOR:RUNR,300");
wait_standby(10000);
assert_eq(parse_number(send("MOTOR:PACT")[0]), 300.0);
assert_eq(reply("MOTOR:PACT").values[0], 300.0);
wait_until(|| flags().standby, 1000);

// numbers in every spelling drives use
assert_eq(parse_number("1.0000+03"), 1000.0);
assert_eq(parse_number("5.05161E-01"), 0.505161);
assert_eq(parse_number("0x0888"), 2184.0);

// target: requests carry @N from now on (the drive goes into addressing mode)
target(1);
assert_eq(reply("SYS:FW").raw, "@1,0x0888,0x0000," + args[0]);
log("api checked");
print("ok");
"#;

fn firmware() -> String {
    let fw = Smd4Spec::builtin().commands.get("SYS:FW").unwrap();
    fw.sim_value.clone().unwrap()
}

#[test]
fn the_device_functions_over_pty_and_tcp() {
    let script = write("api.rhai", API);
    let fw = firmware();
    for via in BOTH {
        let mut drive = Drive::start(via, &[]);
        let out = drive.script(&script, &["--", &fw]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), ["ok"]);
        assert!(
            drive.console("flags").ends_with("addressing 1"),
            "target(1) sent @1"
        );
    }
}

#[test]
fn send_throws_on_an_error_code_with_file_line_and_column() {
    let script = write(
        "estop.rhai",
        "send(\"MOTOR:ESTOP\");\n  send(\"MOTOR:RUNV,+\");\n",
    );
    let drive = Drive::start(Via::Pty, &[]);
    let out = drive.script(&script, &[]);
    assert_exit(&out, 1);
    let disabled = ErrorCode::MotorDisabled;
    let err = String::from_utf8_lossy(&out.stderr);
    let at = format!("{}:2:3: ", script.display());
    assert!(err.contains(&at), "{err}");
    assert!(
        err.contains(&format!("error {} ({})", disabled.code(), disabled.name())),
        "{err}"
    );
}

#[test]
fn a_line_the_validator_refuses_exits_2_from_a_script() {
    let script = write("res.rhai", "let x = 1;\nsend(\"MOTOR:RES,7\");\n");
    let drive = Drive::logged(Via::Tcp, &[]);
    let out = drive.script(&script, &[]);
    assert_exit(&out, 2);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(&format!("{}:2:1: ", script.display())),
        "{err}"
    );
    assert!(err.contains("use one of 8, 16, 32, 64, 128, 256"), "{err}");
    assert!(drive.received().is_empty(), "nothing was sent");
}

#[test]
fn a_bad_target_is_refused() {
    let script = write("target.rhai", "target(300);\n");
    let out = run(&[
        "--sim",
        "run",
        script.to_str().unwrap(),
        "--protocol",
        "smd4",
    ]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("SMD4 address 300 is not in 0..247"));
}

fn commission() -> PathBuf {
    repo().join("scripts").join("smd4_commission.rhai")
}

#[test]
fn the_commissioning_example_runs_on_the_built_in_drive() {
    let script = commission();
    let out = run(&[
        "--sim",
        "run",
        script.to_str().unwrap(),
        "--protocol",
        "smd4",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("commissioned"), "{}", stdout(&out));
}

#[test]
fn the_commissioning_example_stores_what_it_set_on_a_served_drive() {
    let state = crate::util::tempdir().join("smd4.toml");
    let mut drive = Drive::start(Via::Pty, &["--state", state.to_str().unwrap()]);
    let out = drive.script(&commission(), &["--", "0.6", "1500"]);
    assert_exit(&out, 0);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("commissioned"), "{text}");
    // What the script stored is the drive's configuration after a power cycle.
    let stored_ir = drive.console("setting MOTOR:IR");
    drive.console("power-cycle");
    assert_eq!(drive.console("setting MOTOR:IR"), stored_ir);
    let ir: f64 = stored_ir.rsplit(' ').next().unwrap().parse().unwrap();
    assert_eq!(ir, super::lines::rounded_current(0.6));
    assert_eq!(drive.console("setting MOTOR:VMAX"), "MOTOR:VMAX = 1500");
}
