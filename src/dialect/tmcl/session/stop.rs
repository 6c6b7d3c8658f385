//! Stopping what the session set moving: MST to motors, STOP to programs, sent at once even on a
//! line that has not settled, and confirmed within a short wait (after Ctrl-C the user hears at
//! once that the stop went out).

use std::time::Duration;

use crate::dialect::tmcl::protocol::validate::Mode;
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode};

use super::{TmclExchange, TmclSession, modules};
use crate::dialect::session::DialectSession;
use crate::session::SessionError;

impl TmclSession {
    /// Sends MST to every motor of `module` at once, even on a line that has not settled since a
    /// failure; the answer for each motor.
    pub fn stop_motors(&mut self, module: u8) -> Vec<(u8, Result<TmclExchange, SessionError>)> {
        self.urgently(|s| {
            (0..s.profile_of(module).axes)
                .map(|motor| {
                    (
                        motor,
                        s.request(module, Instruction::new(Opcode::Mst, 0, motor, 0)),
                    )
                })
                .collect()
        })
    }

    /// How long a stop waits for its confirmation: a module answers MST at once, so the wire
    /// time of the exchange and [`crate::session::STOP_CONFIRMATION`]; whoever pressed Ctrl-C hears within
    /// that that the stop went out, however slow the interrupted reply was.
    fn stop_wait(&self) -> Duration {
        let wire = self.core.wire.wire_time(32);
        self.core
            .options
            .timeout
            .min(crate::session::STOP_CONFIRMATION + wire)
    }

    /// Stops every module this session set moving or whose program it started (MST, and STOP /
    /// command 128 for programs). Returns what was done, for the user.
    pub(super) fn stop_everything(&mut self) -> Vec<String> {
        let wait = self.stop_wait();
        self.with_timeout(wait, Self::stop_each)
    }

    /// Modules in binary mode before those in ASCII mode: on a bus of both, the line is quiet
    /// for a frame time-out (see [`TmclSession::align_for_frame`]) at most once, before the
    /// first frame, and never between two ASCII stops.
    fn binary_first(&self, mut modules: Vec<u8>) -> Vec<u8> {
        modules.sort_by_key(|&m| self.validation_mode(m) != Mode::Binary);
        modules
    }

    fn stop_each(&mut self) -> Vec<String> {
        let mut report = Vec::new();
        let programs = self.binary_first(modules(&self.core.running));
        for module in programs {
            let name = ModuleName(module);
            match self.stop_program(module) {
                Ok(_) => report.push(format!("stopped the TMCL program of {name}")),
                Err(SessionError::Timeout { timeout, .. }) => report.push(format!(
                    "sent STOP to {name}; no answer within {} ms",
                    timeout.as_millis()
                )),
                Err(e) => report.push(format!("could not stop the program of {name}: {e}")),
            }
        }
        let moved = self.binary_first(modules(&self.core.moved));
        for module in moved {
            let name = ModuleName(module);
            for (motor, result) in self.stop_motors(module) {
                match result {
                    Ok(x) if x.ok() => {
                        report.push(format!("stopped motor {motor} of {name} with MST"))
                    }
                    Ok(x) => {
                        report.push(format!("MST to motor {motor} of {name} answered {}", x.raw))
                    }
                    Err(SessionError::Timeout { timeout, .. }) => report.push(format!(
                        "sent MST to motor {motor} of {name}; no answer within {} ms",
                        timeout.as_millis()
                    )),
                    Err(e) => report.push(format!("could not stop motor {motor} of {name}: {e}")),
                }
            }
        }
        self.core.moved.clear();
        for line in &report {
            self.core.wire.note(line);
        }
        report
    }
}
