//! The control functions 128–139 (manual §6.5): program control, download mode, memory read-back,
//! firmware version, factory reset, the position-reached event and the switch to ASCII mode.

use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::protocol::{Instruction, Opcode, Status};

use super::machine::Machine;
use super::outcome::{Effect, Outcome, Reply};
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
            Opcode::StopApplication => {
                self.vm.stop();
                Ok(i.value)
            }
            Opcode::RunApplication => match i.type_ {
                0 => self.vm.resume(t, &self.program).map(|()| i.value),
                1 => self
                    .vm
                    .run_from(t, &self.program, i.value)
                    .map(|()| i.value),
                _ => Err(Status::WrongType),
            },
            Opcode::StepApplication => self.vm.step(t, &self.program).map(|()| i.value),
            Opcode::ResetApplication => {
                self.vm.reset();
                Ok(i.value)
            }
            Opcode::StartDownload if protection & NO_OVERWRITE != 0 => Err(Status::NotAvailable),
            Opcode::StartDownload => {
                self.vm.stop();
                self.program.start_download(i.value).map(|()| i.value)
            }
            Opcode::QuitDownload => {
                self.eeprom_changed |= self.program.quit_download();
                Ok(i.value)
            }
            Opcode::ReadMemory if protection & NO_DISASSEMBLY != 0 => Err(Status::NotAvailable),
            Opcode::ReadMemory => self
                .program
                .get(i.value)
                .ok_or(Status::InvalidValue)
                .and_then(|stored| read_reply(stored, i.type_)),
            Opcode::ApplicationStatus => match i.type_ {
                0 => Ok(self.vm.status_code()),
                1 => Ok(self.vm.error_code()),
                _ => Err(Status::WrongType),
            },
            Opcode::FirmwareVersion => match i.type_ {
                0 => return reply(Reply::Version, Effect::None),
                1 => Ok(self.profile.sim.version_binary as i32),
                _ => Err(Status::WrongType),
            },
            Opcode::FactoryDefaults => {
                // The value was checked against 1234 (value_range); the module restarts and
                // therefore never replies.
                self.params.factory();
                self.eeprom_changed = true;
                self.boot(t);
                return reply(Reply::Silent, Effect::Rebooted);
            }
            Opcode::PositionEvent => match i.type_ {
                0 | 1 if i.value & self.motor_mask() != 0 => {
                    self.request_event(i.value, i.type_ == 1);
                    Ok(i.value)
                }
                0 | 1 => Err(Status::InvalidValue),
                _ => Err(Status::WrongType),
            },
            // A binary-only firmware does not know 139.
            Opcode::EnterAscii if self.profile.identity.ascii_interface() == AsciiInterface::No => {
                Err(Status::InvalidCommand)
            }
            Opcode::EnterAscii => {
                return reply(Reply::Normal(Status::Ok, i.value), Effect::EnterAscii);
            }
            _ => Err(Status::InvalidCommand),
        };
        match result {
            Ok(value) => Outcome::ok(value),
            Err(status) => Outcome::error(status, i),
        }
    }
}

impl Machine {
    /// The bits of a 138 motor mask that name motors this module has.
    fn motor_mask(&self) -> i32 {
        (1i32 << self.axes.len().min(30)) - 1
    }

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
