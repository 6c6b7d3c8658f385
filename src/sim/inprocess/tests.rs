use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use super::*;
use crate::clock::ManualClock;
use crate::dialect::tmcl::protocol::{CommandFrame, Instruction, ReplyFrame, Status};
use crate::dialect::tmcl::sim::Bus;
use crate::sim::fault::{Faults, Faulty};
use crate::sim::pacing::Paced;

fn frame(command: u8, type_: u8, value: i32) -> [u8; 9] {
    CommandFrame {
        address: 1,
        instruction: Instruction::new(command, type_, 0, value),
    }
    .encode()
}

fn reply(link: &mut dyn Link, within: Duration) -> Result<ReplyFrame, LinkError> {
    let mut got = Vec::new();
    let deadline = Instant::now() + within;
    while got.len() < 9 {
        let mut buf = [0u8; 4]; // small on purpose: replies come in pieces
        let n = link.recv(&mut buf, deadline)?;
        got.extend_from_slice(&buf[..n]);
    }
    Ok(ReplyFrame::decode(got[..9].try_into().unwrap()).unwrap())
}

fn manual() -> (Arc<ManualClock>, Arc<dyn Clock>) {
    let clock = Arc::new(ManualClock::new());
    (clock.clone(), clock)
}

#[test]
fn a_reply_comes_at_once_without_time_passing() {
    let (manual, clock) = manual();
    let mut link = SimLink::new(Box::new(Bus::builtin()), clock);
    link.send(&frame(6, 4, 0)).unwrap();
    let r = reply(&mut link, Duration::from_secs(1)).unwrap();
    assert_eq!((r.status, r.value), (Status::Ok, 1_000_000));
    assert_eq!(manual.now(), Duration::ZERO);
}

#[test]
fn waiting_for_the_second_reply_of_138_jumps_to_the_arrival() {
    let (manual, clock) = manual();
    let mut link = SimLink::new(Box::new(Bus::builtin()), clock);
    for (command, type_, value) in [(5, 255, 1), (5, 4, 1000), (5, 5, 1000), (138, 0, 1)] {
        link.send(&frame(command, type_, value)).unwrap();
        reply(&mut link, Duration::from_secs(1)).unwrap();
    }
    link.send(&frame(4, 0, 3000)).unwrap();
    reply(&mut link, Duration::from_secs(1)).unwrap();
    let event = reply(&mut link, Duration::from_secs(60)).unwrap();
    assert_eq!(event.status, Status::PositionReachedEvent);
    let t = manual.now().as_secs_f64();
    assert!((4.0..4.000_001).contains(&t), "{t}");
}

#[test]
fn nothing_to_receive_times_out_on_the_simulation_clock() {
    let (manual, clock) = manual();
    let mut link = SimLink::new(Box::new(Bus::builtin()), clock);
    let error = reply(&mut link, Duration::from_millis(500)).unwrap_err();
    assert!(matches!(error, LinkError::Timeout));
    assert!(manual.now() >= Duration::from_millis(499));
}

#[test]
fn a_paced_reply_takes_its_wire_time() {
    let (manual, clock) = manual();
    let mut link = SimLink::new(Box::new(Paced::new(Bus::builtin(), 9600)), clock);
    link.send(&frame(6, 4, 0)).unwrap();
    reply(&mut link, Duration::from_secs(1)).unwrap();
    assert_eq!(
        manual.now(),
        Duration::from_nanos(18 * 10 * 1_000_000_000 / 9600)
    );
}

#[test]
fn a_hang_up_loses_the_link_until_it_is_reopened() {
    let (_, clock) = manual();
    let faults = Faults {
        hangup_after: Some(1),
        ..Faults::default()
    };
    let mut link = SimLink::new(Box::new(Faulty::new(Bus::builtin(), faults)), clock);
    link.send(&frame(6, 4, 0)).unwrap();
    reply(&mut link, Duration::from_secs(1)).unwrap();
    assert!(matches!(
        link.send(&frame(6, 4, 0)),
        Err(LinkError::Lost(_))
    ));
    link.reopen().unwrap();
    link.send(&frame(6, 4, 0)).unwrap();
    reply(&mut link, Duration::from_secs(1)).unwrap();
}

#[test]
fn tests_reach_the_bus_typed_or_by_control_commands() {
    let (_, clock) = manual();
    let bus = Arc::new(Mutex::new(Bus::builtin()));
    let mut link = SimLink::shared(bus.clone(), clock);
    link.control("input 4 1").unwrap();
    link.send(&frame(15, 4, 0)).unwrap();
    assert_eq!(reply(&mut link, Duration::from_secs(1)).unwrap().value, 1);
    link.send(&frame(4, 0, 777)).unwrap();
    reply(&mut link, Duration::from_secs(1)).unwrap();
    let target = bus.lock().unwrap().motor(Duration::ZERO, 1).unwrap().target;
    assert_eq!(target, 777);
    assert!(link.control("frobnicate").is_err());
    assert_eq!(link.describe(), "simulated module (in-process)");
}

#[test]
fn the_builtin_link_answers_on_the_system_clock() {
    let config = (crate::dialect::tmcl::DIALECT.configure)(None).unwrap();
    let name = format!("simulated {} (built-in)", config.simulated_module());
    let mut link = crate::sim::builtin_link(config.simulator(), name);
    assert_eq!(link.describe(), "simulated TMCM-142 (built-in)");
    link.send(&frame(6, 4, 0)).unwrap();
    assert_eq!(
        reply(link.as_mut(), Duration::from_secs(5)).unwrap().value,
        1_000_000
    );
}
