//! Two modules on one simulated line, reached over TCP.

use tmclsh::dialect::tmcl::protocol::Status;

use super::Sim;

#[test]
fn two_modules_answer_their_own_addresses_in_both_modes() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0", "--modules", "1,2"]);
    let mut port = sim.tcp();
    assert_eq!(port.transact(2, 5, 4, 0, 222).status, Status::Ok);
    let one = port.transact(1, 6, 4, 0, 0);
    let two = port.transact(2, 6, 4, 0, 0);
    assert_eq!((one.module, one.value), (1, 1_000_000));
    assert_eq!((two.module, two.value), (2, 222));
    for address in [1, 2] {
        assert_eq!(port.transact(address, 9, 67, 0, 0x20).status, Status::Ok);
        assert_eq!(port.transact(address, 139, 0, 0, 0).status, Status::Ok);
    }
    port.send(b"BGAP 4, 0\r");
    assert_eq!(port.read_line(), "BB 100 222\r");
    port.send(b"AGAP 4, 0\r");
    assert_eq!(port.read_line(), "BA 100 1000000\r");
    port.send(b"CGAP 4, 0\r"); // nobody
    port.send(b"BMST 0\r");
    assert_eq!(
        port.read_line(),
        "BB 100 0\r",
        "the line for C got no answer"
    );
}

#[test]
fn the_console_reaches_each_module() {
    let mut sim = Sim::start(&["--listen", "127.0.0.1:0", "--modules", "1,2"]);
    let mut port = sim.tcp();
    assert_eq!(sim.console("@2 input 5 1"), "ok input 5 = 1");
    assert_eq!(sim.console("analog 0 700"), "ok analog 0 = 700");
    assert_eq!(port.transact(2, 15, 5, 0, 0).value, 1);
    assert_eq!(port.transact(1, 15, 5, 0, 0).value, 0);
    assert_eq!(port.transact(1, 15, 0, 1, 0).value, 700);
    assert_eq!(port.transact(2, 14, 1, 2, 1).status, Status::Ok);
    assert_eq!(sim.console("@2 output 1"), "ok output 1 = 1");
    assert!(sim.console("@9 motor").starts_with("error: no module 9"));
}
