//! The simulated module bus on CAN (`tmclsh sim --slcan`): each request frame becomes the serial
//! frame the modules take (7 or 8 data bytes; the address from the CAN ID), each reply goes back
//! to the reply ID of the module's host address (GP 76), an answer to 136 type 0 as the eight
//! characters of the version string. Faults wrapped around the bus apply to whole replies, so
//! a dropped or delayed reply is a dropped or delayed frame.

use std::time::Duration;

use crate::dialect::tmcl::protocol::Opcode;
use crate::dialect::tmcl::protocol::can;
use crate::dialect::tmcl::protocol::frame::FRAME_LEN;
use crate::link::can::CanFrame;
use crate::sim::Device;
use crate::sim::error::ConsoleError;
use crate::sim::slcan::CanDevice;

/// A byte-level TMCL bus seen through the CAN framing.
pub struct CanBus {
    bus: Box<dyn Device>,
    pending: Vec<u8>,
    /// Version-string requests not answered yet: their answers have no command byte to tell.
    versions: u32,
}

impl CanBus {
    /// The bus `bus` (a [`super::Bus`], maybe with faults around it) on CAN.
    pub fn new(bus: Box<dyn Device>) -> CanBus {
        CanBus {
            bus,
            pending: Vec::new(),
            versions: 0,
        }
    }

    /// Whether a serial answer is a version string: one was asked for, and it is eight
    /// printable characters (a status reply holds a status below 128 and a command byte, never
    /// all printable for the commands a version request sits among).
    fn is_version(&self, frame: &[u8; FRAME_LEN]) -> bool {
        self.versions > 0 && frame[1..].iter().all(u8::is_ascii_graphic)
    }
}

impl CanDevice for CanBus {
    fn receive_frame(&mut self, now: Duration, frame: &CanFrame) {
        let Some(command) = can::command(frame) else {
            return;
        };
        if command[1] == u8::from(Opcode::FirmwareVersion) && command[2] == 0 {
            self.versions += 1;
        }
        self.bus.receive(now, &command);
    }

    fn poll_frames(&mut self, now: Duration, out: &mut Vec<CanFrame>) {
        self.bus.poll_output(now, &mut self.pending);
        let whole = self.pending.len() / FRAME_LEN * FRAME_LEN;
        let replies: Vec<[u8; FRAME_LEN]> = self.pending[..whole]
            .chunks_exact(FRAME_LEN)
            .map(|c| c.try_into().expect("chunks of 9"))
            .collect();
        self.pending.drain(..whole);
        for reply in replies {
            let version = self.is_version(&reply);
            if version {
                self.versions -= 1;
            }
            out.push(can::reply(&reply, u16::from(reply[0]), version));
        }
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        self.bus.next_due(now)
    }

    fn hung_up(&self) -> bool {
        self.bus.hung_up()
    }

    fn reconnect(&mut self) {
        self.pending.clear();
        self.versions = 0;
        self.bus.reconnect()
    }

    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        self.bus.control(now, command)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::tmcl::profile::Profile;
    use crate::dialect::tmcl::sim::{Bus, BusOptions};

    fn answers(bus: &mut CanBus, id: u16, data: &[u8]) -> Vec<CanFrame> {
        bus.receive_frame(Duration::ZERO, &CanFrame::new(id, data).unwrap());
        let mut out = Vec::new();
        let mut now = Duration::ZERO;
        for _ in 0..100 {
            bus.poll_frames(now, &mut out);
            match bus.next_due(now) {
                Some(due) if out.is_empty() => now = due.max(now),
                _ => break,
            }
        }
        out
    }

    #[test]
    fn requests_of_seven_or_eight_bytes_are_answered_to_the_host_address() {
        let mut bus = CanBus::new(Box::new(Bus::new(
            Profile::builtin(),
            BusOptions::default(),
        )));
        let set = answers(&mut bus, 1, &[5, 4, 0, 0, 0, 0x03, 0xE8]);
        assert_eq!(
            set,
            vec![CanFrame::new(2, &[1, 100, 5, 0, 0, 0x03, 0xE8]).unwrap()]
        );
        let get = answers(&mut bus, 1, &[6, 4, 0, 0, 0, 0, 0, 0x0B]);
        assert_eq!(
            get,
            vec![CanFrame::new(2, &[1, 100, 6, 0, 0, 0x03, 0xE8]).unwrap()]
        );
        let version = answers(&mut bus, 1, &[136, 0, 0, 0, 0, 0, 0]);
        assert_eq!(version.len(), 1);
        assert_eq!(version[0].data().len(), 8);
        assert!(version[0].data().iter().all(u8::is_ascii_graphic));
        assert!(
            answers(&mut bus, 7, &[6, 4, 0, 0, 0, 0, 0]).is_empty(),
            "no module 7"
        );
        assert!(answers(&mut bus, 1, &[6, 4]).is_empty(), "a short frame");
    }
}
