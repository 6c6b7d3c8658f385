//! Motion over a pty with a manual clock: time passes only when the console says so, so
//! positions and durations are exact.

use tmclsh::dialect::tmcl::protocol::Status;

use super::{Sim, decode};

fn setup(args: &[&str]) -> (Sim, super::Port) {
    let mut all = vec!["--pty", "--manual-clock"];
    all.extend_from_slice(args);
    let sim = Sim::start(&all);
    let mut port = sim.pty();
    for (number, value) in [(255, 1), (4, 8000), (5, 16_000)] {
        assert_eq!(port.transact(1, 5, number, 0, value).status, Status::Ok);
    }
    (sim, port)
}

#[test]
fn a_move_lasts_as_long_as_its_trapezoid() {
    let (mut sim, mut port) = setup(&[]);
    // 40000 steps at 8000 pps and 16000 pps²: 0.5 s up, 4.5 s cruise, 0.5 s down.
    let (v, a, d) = (8000.0, 16_000.0, 40_000.0);
    let total: f64 = 2.0 * v / a + (d - v * v / a) / v;
    assert_eq!(port.transact(1, 4, 0, 0, d as i32).status, Status::Ok);
    assert!(sim.console("advance 0.25s").starts_with("ok"));
    assert_eq!(
        port.transact(1, 6, 1, 0, 0).value,
        500,
        "½·a·t² after 0.25 s"
    );
    let total_ms = (total * 1000.0).round() as u64;
    let almost = format!("advance {}ms", total_ms - 10 - 250);
    assert!(sim.console(&almost).starts_with("ok"));
    assert_eq!(
        port.transact(1, 6, 8, 0, 0).value,
        0,
        "not there 10 ms early"
    );
    assert!(sim.console("advance 10ms").starts_with("ok"));
    assert_eq!(port.transact(1, 6, 8, 0, 0).value, 1, "there on time");
    assert_eq!(port.transact(1, 6, 1, 0, 0).value, 40_000);
}

#[test]
fn advance_reads_a_bare_number_as_milliseconds_like_every_time() {
    let (mut sim, _port) = setup(&[]);
    assert_eq!(sim.console("advance 250"), "ok 0.250000 s");
    assert_eq!(sim.console("advance 1.5s"), "ok 1.750000 s");
    assert!(
        sim.console("advance 8days")
            .starts_with("error: '8days' is longer than 7 days")
    );
    assert_eq!(sim.console("time"), "ok 1.750000 s");
}

#[test]
fn the_second_reply_of_138_comes_on_arrival() {
    let (mut sim, mut port) = setup(&[]);
    assert_eq!(port.transact(1, 138, 0, 0, 1).status, Status::Ok);
    assert_eq!(port.transact(1, 4, 0, 0, 4000).status, Status::Ok);
    assert!(sim.console("advance 1s").starts_with("ok"));
    let event = decode(&port.read_n(9));
    assert_eq!(
        (event.status, event.command.number()),
        (Status::PositionReachedEvent, 138)
    );
}

#[test]
fn limit_switches_from_the_command_line_and_the_console() {
    let (mut sim, mut port) = setup(&["--right-switch", "3000"]);
    assert_eq!(port.transact(1, 1, 0, 0, 8000).status, Status::Ok);
    assert!(sim.console("advance 5s").starts_with("ok"));
    assert_eq!(port.transact(1, 6, 1, 0, 0).value, 3000);
    assert_eq!(port.transact(1, 6, 10, 0, 0).value, 1);
    assert_eq!(sim.console("switch right off"), "ok switch right at off");
    assert_eq!(port.transact(1, 6, 10, 0, 0).value, 0);
    assert_eq!(sim.console("switch left -1000"), "ok switch left at -1000");
    assert_eq!(port.transact(1, 2, 0, 0, 8000).status, Status::Ok);
    assert!(sim.console("advance 5s").starts_with("ok"));
    assert_eq!(port.transact(1, 6, 1, 0, 0).value, -1000);
}

#[test]
fn reference_search_against_virtual_switches() {
    let (mut sim, mut port) = setup(&["--left-switch", "-2500", "--right-switch", "9000"]);
    for (number, value) in [(193, 2), (194, 4000), (195, 500)] {
        assert_eq!(port.transact(1, 5, number, 0, value).status, Status::Ok);
    }
    assert_eq!(port.transact(1, 13, 0, 0, 0).status, Status::Ok);
    assert_ne!(port.transact(1, 13, 2, 0, 0).value, 0);
    assert!(sim.console("advance 30s").starts_with("ok"));
    assert_eq!(port.transact(1, 13, 2, 0, 0).value, 0);
    assert_eq!(port.transact(1, 6, 1, 0, 0).value, 0);
    assert_eq!(port.transact(1, 6, 196, 0, 0).value, 11_500);
}

#[test]
fn baud_pacing_takes_the_wire_time_of_request_and_reply() {
    let mut sim = Sim::start(&["--pty", "--manual-clock", "--baud", "9600"]);
    let mut port = sim.pty();
    port.send(&super::frame(1, 6, 4, 0, 0));
    // Request in and reply out take 18 byte times (18.75 ms) at 9600 baud: however soon the
    // frame reached the simulator, at least 19 steps of 1 ms must pass before the reply is whole.
    let mut got = Vec::new();
    let mut steps = 0;
    while got.len() < 9 {
        assert!(sim.console("advance 1ms").starts_with("ok"));
        steps += 1;
        assert!(steps < 5000, "no reply: {got:02X?}");
        got.extend(port.read_available());
    }
    assert!(steps >= 19, "the reply came after {steps} ms");
    assert_eq!(decode(&got).value, 1_000_000);
}
