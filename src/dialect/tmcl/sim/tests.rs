//! Unit tests of the simulated module through its bytes-in, bytes-out interface, with time
//! stepped explicitly.

mod ascii_mode;
mod axes;
mod binary;
mod eeprom;
mod fidelity;
mod interrupts;
mod moves;
mod programs;
mod real_line;
mod two_modules;

use std::time::Duration;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::{CommandFrame, Instruction, ReplyFrame, Status};
use crate::sim::Device;

use super::{Bus, BusOptions};

/// A bus and the simulation time.
pub(super) struct Sim {
    pub bus: Bus,
    pub now: Duration,
}

impl Sim {
    pub(super) fn new() -> Sim {
        Sim::with(BusOptions::default())
    }

    /// One module of the built-in profile `name` at address 1.
    pub(super) fn of(name: &str) -> Sim {
        let profile = crate::dialect::tmcl::profile::catalogue::by_name(name).expect("built in");
        Sim {
            bus: Bus::new(profile, BusOptions::default()),
            now: Duration::ZERO,
        }
    }

    pub(super) fn with(options: BusOptions) -> Sim {
        Sim {
            bus: Bus::new(Profile::builtin(), options),
            now: Duration::ZERO,
        }
    }

    /// Lets simulated time pass.
    pub(super) fn wait(&mut self, seconds: f64) {
        self.now += Duration::from_secs_f64(seconds);
    }

    /// Sets the time (seconds since start).
    pub(super) fn at(&mut self, seconds: f64) {
        let t = Duration::from_secs_f64(seconds);
        assert!(t >= self.now, "time goes forward");
        self.now = t;
    }

    /// Sends bytes and returns what the bus answers at once.
    pub(super) fn send(&mut self, bytes: &[u8]) -> Vec<u8> {
        self.bus.receive(self.now, bytes);
        self.output()
    }

    /// What the bus has sent by now.
    pub(super) fn output(&mut self) -> Vec<u8> {
        let mut out = Vec::new();
        self.bus.poll_output(self.now, &mut out);
        out
    }

    /// Sends one command frame to `address` and decodes the single reply.
    pub(super) fn frame(
        &mut self,
        address: u8,
        command: u8,
        type_: u8,
        motor: u8,
        value: i32,
    ) -> ReplyFrame {
        let instruction = Instruction::new(command, type_, motor, value);
        let out = self.send(
            &CommandFrame {
                address,
                instruction,
            }
            .encode(),
        );
        assert_eq!(out.len(), 9, "one reply frame expected, got {out:02X?}");
        ReplyFrame::decode(out[..9].try_into().unwrap()).expect("valid reply checksum")
    }

    /// A command to module 1 that must succeed; returns the reply value.
    pub(super) fn ok(&mut self, command: u8, type_: u8, motor: u8, value: i32) -> i32 {
        let reply = self.frame(1, command, type_, motor, value);
        assert_eq!(
            reply.status,
            Status::Ok,
            "command {command} {type_} {motor} {value}"
        );
        reply.value
    }

    /// The status module 1 answers.
    pub(super) fn status(&mut self, command: u8, type_: u8, motor: u8, value: i32) -> Status {
        self.frame(1, command, type_, motor, value).status
    }

    /// GAP of module 1.
    pub(super) fn gap(&mut self, number: u8) -> i32 {
        self.ok(6, number, 0, 0)
    }

    /// SAP of module 1.
    pub(super) fn sap(&mut self, number: u8, value: i32) {
        self.ok(5, number, 0, value);
    }

    /// Stores `program` from address 0 (download mode 132 … 133).
    pub(super) fn download(&mut self, program: &[(u8, u8, u8, i32)]) {
        self.ok(132, 0, 0, 0);
        for &(c, t, m, v) in program {
            assert_eq!(self.frame(1, c, t, m, v).status, Status::Stored);
        }
        self.ok(133, 0, 0, 0);
    }

    /// Sends an ASCII line (CR appended) and returns all output as text.
    pub(super) fn line(&mut self, text: &str) -> String {
        let mut bytes = text.as_bytes().to_vec();
        bytes.push(b'\r');
        String::from_utf8(self.send(&bytes)).expect("ASCII output")
    }
}
