//! The state file: stored values survive a restart of the simulator.

use tmclsh::dialect::tmcl::protocol::Status;

use super::Sim;
use crate::util::{code, run, stderr, tempdir};

#[test]
fn stored_values_survive_a_restart() {
    let dir = tempdir();
    let state = dir.join("eeprom.toml");
    let state = state.to_str().unwrap();
    let sim = Sim::start(&["--pty", "--state", state]);
    let mut port = sim.pty();
    assert_eq!(port.transact(1, 5, 4, 0, 123_456).status, Status::Ok);
    assert_eq!(port.transact(1, 7, 4, 0, 0).status, Status::Ok);
    assert_eq!(port.transact(1, 5, 5, 0, 4321).status, Status::Ok); // RAM only
    assert_eq!(port.transact(1, 9, 7, 2, -70).status, Status::Ok);
    assert_eq!(port.transact(1, 11, 7, 2, 0).status, Status::Ok);
    // Start in ASCII mode, no echo, from the next power-up on (GP 67 is stored at once).
    assert_eq!(port.transact(1, 9, 67, 0, 0x21).status, Status::Ok);
    drop(port);
    drop(sim); // killed: the file was written when the values changed

    let sim = Sim::start(&["--pty", "--state", state]);
    let mut port = sim.pty();
    port.send(b"AGAP 4, 0\r");
    assert_eq!(port.read_line(), "BA 100 123456\r");
    port.send(b"AGAP 5, 0\r");
    assert_eq!(port.read_line(), "BA 100 100000\r");
    port.send(b"AGGP 7, 2\r");
    assert_eq!(port.read_line(), "BA 100 -70\r");
}

#[test]
fn a_damaged_state_file_is_refused_with_a_hint() {
    let dir = tempdir();
    let state = dir.join("bad.toml");
    std::fs::write(&state, "this is not toml = [").unwrap();
    let out = run(&["sim", "--state", state.to_str().unwrap()]);
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("delete it"), "{}", stderr(&out));
}
