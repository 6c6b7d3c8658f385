//! The line as a real bus has it: a partial frame dropped after the firmware's UART time-out, a
//! power cycle from the console, and modules that hear each other's replies on a shared line.

use std::time::Duration;

use crate::dialect::tmcl::profile::UART_TIMEOUT_MS;
use crate::dialect::tmcl::protocol::{CommandFrame, Instruction};
use crate::sim::Device;

use super::super::BusOptions;
use super::Sim;

fn gap4() -> [u8; 9] {
    CommandFrame {
        address: 1,
        instruction: Instruction::new(6u8, 4, 0, 0),
    }
    .encode()
}

#[test]
fn a_partial_frame_is_dropped_after_5_ms_of_quiet_and_kept_before() {
    assert_eq!(UART_TIMEOUT_MS, 5);
    let mut sim = Sim::new();
    let frame = gap4();
    // 4 ms of quiet in the middle: one frame.
    assert!(sim.send(&frame[..4]).is_empty());
    sim.wait(0.004);
    assert_eq!(sim.send(&frame[4..]).len(), 9);
    // 6 ms: the first part is gone, the rest is a partial frame of its own…
    sim.wait(0.010);
    assert!(sim.send(&frame[..4]).is_empty());
    sim.wait(0.006);
    assert!(sim.send(&frame[4..]).is_empty());
    // …dropped in turn, so the next whole frame after a quiet gap is answered.
    sim.wait(0.006);
    assert_eq!(sim.send(&frame).len(), 9);
}

#[test]
fn a_paced_lines_byte_time_is_not_quiet() {
    let mut sim = Sim::new();
    sim.bus.byte_time(Duration::from_millis(16)); // 600 baud
    let frame = gap4();
    for (i, byte) in frame.iter().enumerate() {
        let out = sim.send(&[*byte]);
        assert_eq!(out.len(), if i == 8 { 9 } else { 0 }, "byte {i}");
        sim.wait(0.0166);
    }
}

#[test]
fn reset_brings_back_stored_values_and_binary_mode() {
    let mut sim = Sim::new();
    let stored = sim.gap(4);
    sim.sap(4, 1234);
    assert_eq!(sim.gap(4), 1234);
    sim.ok(139, 0, 0, 0);
    assert_eq!(sim.bus.is_ascii(1), Some(true));
    let now = sim.now;
    let said = sim.bus.control(now, "reset").unwrap().unwrap();
    assert_eq!(said, "module 1 restarted in binary mode");
    assert_eq!(sim.bus.is_ascii(1), Some(false));
    assert_eq!(sim.gap(4), stored);
    assert!(sim.bus.control(now, "reset 7").unwrap().is_err());
}

#[test]
fn on_a_shared_line_a_module_at_the_host_address_answers_others_replies() {
    let options = |shared_line| BusOptions {
        addresses: vec![1, 2],
        shared_line,
        ..BusOptions::default()
    };
    let mut sim = Sim::with(options(false));
    assert_eq!(sim.send(&gap4()).len(), 9);
    let mut sim = Sim::with(options(true));
    // Module 1's reply starts with 2: module 2 reads it as a frame to itself and answers.
    assert_eq!(sim.send(&gap4()).len(), 18);
}
