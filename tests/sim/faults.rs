//! Each injected fault, through the real binary. Where a reply is missing on purpose, the test
//! waits for the command's effect through the console instead of waiting for silence.

use tmclsh::dialect::tmcl::protocol::{ReplyFrame, Status};

use super::{Closed, Port, Sim, frame};

/// Waits (with a deadline) until the console shows the motor's target at `target`.
fn wait_for_target(sim: &mut Sim, target: i32) {
    let deadline = std::time::Instant::now() + super::PATIENCE;
    let wanted = format!("target {target} ");
    while !sim.console("motor").contains(&wanted) {
        assert!(
            std::time::Instant::now() < deadline,
            "target never became {target}"
        );
    }
}

#[test]
fn dropped_replies() {
    let mut sim = Sim::start(&["--listen", "127.0.0.1:0", "--drop-rate", "1"]);
    let mut port = sim.tcp();
    port.send(&frame(1, 4, 0, 0, 1234)); // MVP ABS 1234, reply dropped
    wait_for_target(&mut sim, 1234);
    assert_eq!(sim.console("drop 0"), "ok drop rate 0");
    let reply = port.transact(1, 6, 0, 0, 0);
    assert_eq!(reply.value, 1234, "the first bytes are the reply to GAP 0");
}

#[test]
fn corrupted_replies() {
    let sim = Sim::start(&["--pty", "--corrupt-rate", "1", "--fault-seed", "7"]);
    let mut port = sim.pty();
    for _ in 0..5 {
        port.send(&frame(1, 6, 4, 0, 0));
        let bytes = port.read_n(9);
        assert!(ReplyFrame::decode(bytes[..].try_into().unwrap()).is_err());
    }
}

#[test]
fn delayed_replies() {
    let mut sim = Sim::start(&[
        "--pty",
        "--manual-clock",
        "--delay-rate",
        "1",
        "--delay-ms",
        "200",
    ]);
    let mut port = sim.pty();
    port.send(&frame(1, 4, 0, 0, 77));
    wait_for_target(&mut sim, 77);
    assert!(port.read_available().is_empty());
    assert!(sim.console("advance 200ms").starts_with("ok"));
    assert_eq!(super::decode(&port.read_n(9)).value, 77);
}

#[test]
fn silence_after_some_replies() {
    let mut sim = Sim::start(&["--listen", "127.0.0.1:0", "--silent-after", "1"]);
    let mut port = sim.tcp();
    assert_eq!(port.transact(1, 6, 4, 0, 0).status, Status::Ok);
    port.send(&frame(1, 4, 0, 0, 55));
    wait_for_target(&mut sim, 55);
    drop(port);
    // A new connection starts counting again.
    let mut port = sim.tcp();
    assert_eq!(port.transact(1, 6, 0, 0, 0).value, 55);
}

#[test]
fn hang_up_after_some_replies_on_tcp() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0", "--hangup-after", "2"]);
    let mut port = sim.tcp();
    for _ in 0..2 {
        assert_eq!(port.transact(1, 6, 4, 0, 0).status, Status::Ok);
    }
    assert_eq!(port.try_read_until(|_| false), Err(Closed::Yes));
    let mut again = sim.tcp();
    assert_eq!(again.transact(1, 6, 4, 0, 0).status, Status::Ok);
}

#[test]
fn hang_up_on_the_pty_brings_up_a_new_one() {
    let mut sim = Sim::start(&["--pty"]);
    let mut port = sim.pty();
    assert_eq!(port.transact(1, 5, 4, 0, 999).status, Status::Ok);
    assert_eq!(sim.console("hangup"), "ok hung up");
    let announced = sim.line();
    let path = announced
        .strip_prefix("pty ")
        .expect("the new pty is announced");
    assert_ne!(path, sim.first);
    assert_eq!(port.try_read_until(|_| false), Err(Closed::Yes));
    let mut again = Port::Serial(super::open_serial(path));
    assert_eq!(
        again.transact(1, 6, 4, 0, 0).value,
        999,
        "same module behind it"
    );
}
