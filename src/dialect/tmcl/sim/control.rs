//! The control functions 128–139 (manual §6.5): program control, download mode, memory read-back,
//! firmware version, factory reset, the position-reached event and the switch to ASCII mode.

use crate::dialect::tmcl::protocol::{Instruction, Status};

use super::exec::{Effect, Outcome, Reply};
use super::machine::Machine;
use super::program::read_reply;

/// GP 81 (TMCL code protection) bits.
const NO_DISASSEMBLY: i32 = 1;
const NO_OVERWRITE: i32 = 2;

impl Machine {
    /// Executes a control function (the machine must have been advanced to `t`).
    pub(crate) fn control(&mut self, t: f64, i: &Instruction) -> Outcome {
        let protection = self.params.get(super::params::Slot::Global(0, 81));
        let i = &self.type_as_answered(i);
        let result = match i.command {
            128 => {
                self.vm.stop();
                Ok(i.value)
            }
            129 => match i.type_ {
                0 => self.vm.resume(t, &self.program).map(|()| i.value),
                1 => self
                    .vm
                    .run_from(t, &self.program, i.value)
                    .map(|()| i.value),
                _ => Err(Status::WrongType),
            },
            130 => self.vm.step(t, &self.program).map(|()| i.value),
            131 => {
                self.vm.reset();
                Ok(i.value)
            }
            132 if protection & NO_OVERWRITE != 0 => Err(Status::NotAvailable),
            132 => {
                self.vm.stop();
                self.program.start_download(i.value).map(|()| i.value)
            }
            133 => {
                self.eeprom_changed |= self.program.quit_download();
                Ok(i.value)
            }
            134 if protection & NO_DISASSEMBLY != 0 => Err(Status::NotAvailable),
            134 => self
                .program
                .get(i.value)
                .ok_or(Status::InvalidValue)
                .and_then(|stored| read_reply(stored, i.type_)),
            135 => match i.type_ {
                0 => Ok(self.vm.status_code()),
                1 => Ok(self.vm.error_code()),
                _ => Err(Status::WrongType),
            },
            136 => match i.type_ {
                0 => return reply(Reply::Version, Effect::None),
                1 => Ok(self.profile.sim.version_binary as i32),
                _ => Err(Status::WrongType),
            },
            137 => {
                // The value was checked against 1234 (value_range); the module restarts and
                // therefore never replies.
                self.params.factory();
                self.eeprom_changed = true;
                self.boot(t);
                return reply(Reply::Silent, Effect::Rebooted);
            }
            138 => match i.type_ {
                0 | 1 if i.value & 1 != 0 => {
                    self.request_event(i.value, i.type_ == 1);
                    Ok(i.value)
                }
                0 | 1 => Err(Status::InvalidValue),
                _ => Err(Status::WrongType),
            },
            139 => return reply(Reply::Normal(Status::Ok, i.value), Effect::EnterAscii),
            _ => Err(Status::InvalidCommand),
        };
        match result {
            Ok(value) => Outcome::ok(value),
            Err(status) => Outcome::error(status, i),
        }
    }
}

impl Machine {
    /// The instruction with the type byte a command ignores (`type_ignored`: 134, 135, "don't
    /// care" in the manual) read as 0, except type 1, this simulator's documented extension
    /// (134: the stored command, type and motor; 135: the program error).
    fn type_as_answered(&self, i: &Instruction) -> Instruction {
        let ignored = self
            .profile
            .commands
            .by_number(i.command)
            .is_some_and(|spec| spec.type_ignored);
        match i.type_ {
            0 | 1 => *i,
            _ if ignored => Instruction { type_: 0, ..*i },
            _ => *i,
        }
    }
}

fn reply(reply: Reply, effect: Effect) -> Outcome {
    Outcome { reply, effect }
}
