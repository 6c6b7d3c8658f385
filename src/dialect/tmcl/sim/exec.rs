//! Executing one command on a module: motion, parameters, I/O and coordinates. Control
//! functions 128–139 are in [`super::control`]; program flow is the program runner's.
//!
//! Status codes follow Trinamic's firmware where the manual is silent: the reply value is the
//! request's value unless the command returns one; an unknown parameter, port, coordinate or
//! keyword number (the type byte) answers 3 (wrong type); a value out of range or a motor other
//! than 0 answers 4 (invalid value).

use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::protocol::{Instruction, Status};

use super::machine::Machine;
use super::params::{Slot, eeprom_only};

/// How the module answers a command.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Reply {
    /// The usual reply: status and value.
    Normal(Status, i32),
    /// 136 type 0: the special version-string frame.
    Version,
    /// 137: no reply at all.
    Silent,
}

/// What a command did beyond its reply, for the serial interface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Effect {
    /// Nothing.
    None,
    /// 139: switch to ASCII mode after replying.
    EnterAscii,
    /// 137: the module restarted.
    Rebooted,
}

/// A command's result.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Outcome {
    pub reply: Reply,
    pub effect: Effect,
}

impl Outcome {
    pub fn ok(value: i32) -> Outcome {
        Outcome::status(Status::Ok, value)
    }

    pub fn status(status: Status, value: i32) -> Outcome {
        Outcome {
            reply: Reply::Normal(status, value),
            effect: Effect::None,
        }
    }

    pub fn error(status: Status, instruction: &Instruction) -> Outcome {
        Outcome::status(status, instruction.value)
    }
}

/// Where a command comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Source {
    /// The serial interface, binary or ASCII (direct mode).
    Direct,
    /// A running program.
    Program,
}

const ROR: u8 = 1;
const ROL: u8 = 2;
const MST: u8 = 3;
const MVP: u8 = 4;
const SAP: u8 = 5;
const GAP: u8 = 6;
const STAP: u8 = 7;
const RSAP: u8 = 8;
const SGP: u8 = 9;
const GGP: u8 = 10;
const STGP: u8 = 11;
const RSGP: u8 = 12;
const RFS: u8 = 13;
const SIO: u8 = 14;
const GIO: u8 = 15;
const SCO: u8 = 30;
const GCO: u8 = 31;
const CCO: u8 = 32;
const AAP: u8 = 34;
const AGP: u8 = 35;
const ACO: u8 = 39;
const CALC: u8 = 19;
const CALCX: u8 = 33;

/// EEPROM lock values of GP 73 (generic TMCL reference).
const LOCK: i32 = 1234;
const UNLOCK: i32 = 4321;

impl Machine {
    /// Executes `instruction` at `t` (the machine must have been advanced to `t`). In download
    /// mode, instructions below 128 are stored instead.
    pub fn execute(&mut self, t: f64, instruction: &Instruction, source: Source) -> Outcome {
        if source == Source::Direct && self.program.downloading() && instruction.command < 128 {
            return match self.program.store(*instruction) {
                Ok(()) => Outcome::status(Status::Stored, instruction.value),
                Err(status) => Outcome::error(status, instruction),
            };
        }
        let Some(spec) = self.profile.commands.by_number(instruction.command) else {
            return Outcome::error(Status::InvalidCommand, instruction);
        };
        let allowed = match source {
            Source::Direct => spec.direct_mode,
            Source::Program => spec.standalone,
        };
        if !allowed {
            return Outcome::error(Status::InvalidCommand, instruction);
        }
        if spec.mnemonic == "SAC" || spec.mnemonic.starts_with("UF") {
            // Undocumented SPI access and customer user functions: none installed.
            return Outcome::error(Status::NotAvailable, instruction);
        }
        if let Err(status) = self.precheck(spec, instruction) {
            return Outcome::error(status, instruction);
        }
        if instruction.command >= 128 {
            return self.control(t, instruction);
        }
        match self.command(t, instruction) {
            Ok(value) => Outcome::ok(value),
            Err(status) => Outcome::error(status, instruction),
        }
    }

    /// The checks every command shares, from the command table: motor, keyword, value range,
    /// coordinate numbers.
    fn precheck(&self, spec: &CommandSpec, i: &Instruction) -> Result<(), Status> {
        let has = |kind: OperandKind| spec.operands.iter().any(|o| o.kind == kind);
        if has(OperandKind::Motor) && i.motor >= self.profile.axes {
            return Err(Status::InvalidValue);
        }
        if has(OperandKind::Keyword)
            && !spec.keywords.is_empty()
            && spec.keyword_for(i.type_).is_none()
        {
            return Err(Status::WrongType);
        }
        if spec.operand_for(Field::Type).map(|o| o.kind) == Some(OperandKind::Coord)
            && i.type_ >= self.profile.coordinates
        {
            return Err(Status::WrongType);
        }
        // Banks the profile restricts the command to (STGP/RSGP: user variables only).
        if spec
            .banks
            .as_ref()
            .is_some_and(|banks| has(OperandKind::Bank) && !banks.contains(&i.motor))
        {
            return Err(Status::InvalidValue);
        }
        // Jump targets are checked by the program runner (a bad one is a program error).
        let flow = matches!(i.command, 21..=23);
        match spec.value_range {
            Some((lo, hi)) if !flow && !(lo..=hi).contains(&i64::from(i.value)) => {
                Err(Status::InvalidValue)
            }
            _ => Ok(()),
        }
    }

    fn command(&mut self, t: f64, i: &Instruction) -> Result<i32, Status> {
        let value = i.value;
        match i.command {
            ROR | ROL => {
                let signed = if i.command == ROR { value } else { -value };
                self.params.set(Slot::Axis(2), signed);
                let accel = self.move_limits().1;
                self.axis.rotate(t, self.pps(signed), accel);
            }
            MST => {
                self.params.set(Slot::Axis(2), 0);
                let accel = self.move_limits().1;
                self.axis.rotate(t, 0.0, accel);
            }
            MVP => return self.move_to(t, i),
            SAP => self.write_axis(t, i.type_, value)?,
            AAP => self.write_axis(t, i.type_, self.vm.acc)?,
            GAP => {
                self.params.check_read(Slot::Axis(i.type_))?;
                return Ok(self.axis_value(i.type_, t));
            }
            STAP | STGP => {
                let slot = slot(i);
                self.params.check_store(slot)?;
                if self.locked() {
                    return Err(Status::EepromLocked);
                }
                self.eeprom_changed |= self.params.store(slot);
            }
            RSAP | RSGP => {
                let slot = slot(i);
                self.params.check_store(slot)?;
                self.params.restore(slot);
                if let Slot::Axis(n) = slot {
                    self.after_axis_write(t, n);
                }
            }
            SGP => self.write_global(t, i.motor, i.type_, value)?,
            AGP => self.write_global(t, i.motor, i.type_, self.vm.acc)?,
            GGP => {
                self.params.check_read(Slot::Global(i.motor, i.type_))?;
                return Ok(self.global_value(i.motor, i.type_, t));
            }
            RFS => return Ok(self.reference_search(t, i.type_)),
            SIO => self.io.write(i.type_, i.motor, value != 0)?,
            GIO => return self.io.read(i.type_, i.motor),
            SCO => self.set_coordinate(i.type_, value)?,
            ACO => self.set_coordinate(i.type_, self.vm.acc)?,
            CCO => self.set_coordinate(i.type_, self.axis.counter(t))?,
            // Only a division by zero fails here: the keyword was checked before.
            CALC | CALCX => self.calculate(i).map_err(|_| Status::InvalidValue)?,
            GCO => return Ok(self.coords[i.type_ as usize]),
            _ => return Err(Status::InvalidCommand),
        }
        Ok(value)
    }

    fn move_to(&mut self, t: f64, i: &Instruction) -> Result<i32, Status> {
        let target = match i.type_ {
            0 => i.value,
            1 => self.params.get(Slot::Axis(0)).wrapping_add(i.value),
            _ => *usize::try_from(i.value)
                .ok()
                .and_then(|n| self.coords.get(n))
                .ok_or(Status::InvalidValue)?,
        };
        self.params.set(Slot::Axis(0), target);
        let (vmax, accel) = self.move_limits();
        self.axis.move_to(t, target, vmax, accel);
        Ok(if i.type_ == 1 { target } else { i.value })
    }

    fn reference_search(&mut self, t: f64, type_: u8) -> i32 {
        match type_ {
            0 => {
                let mode = self.params.get(Slot::Axis(193)).clamp(1, 3) as u8;
                let fast = self.pps(self.params.get(Slot::Axis(194)));
                let slow = self.pps(self.params.get(Slot::Axis(195)));
                let accel = self.move_limits().1;
                self.axis.start_search(t, mode, fast, slow, accel);
                0
            }
            1 => {
                self.axis.stop_search(t);
                0
            }
            _ => self.axis.search_status(),
        }
    }

    fn locked(&self) -> bool {
        self.params.get(Slot::Global(0, 73)) == 1
    }

    fn write_axis(&mut self, t: f64, number: u8, value: i32) -> Result<(), Status> {
        self.params.check_write(Slot::Axis(number), value)?;
        match number {
            1 => self.axis.set_counter(t, value),
            3 => self.axis.set_velocity(t, self.pps(value)),
            // Any write clears the integrator sum.
            34 => self.params.set(Slot::Axis(34), 0),
            _ => {
                self.params.set(Slot::Axis(number), value);
                self.after_axis_write(t, number);
            }
        }
        Ok(())
    }

    /// Side effects of a new RAM value: SAP 0 moves, SAP 2 turns, SAP 4/5 retune a move.
    fn after_axis_write(&mut self, t: f64, number: u8) {
        let value = self.params.get(Slot::Axis(number));
        let (vmax, accel) = self.move_limits();
        match number {
            0 => self.axis.move_to(t, value, vmax, accel),
            2 => self.axis.rotate(t, self.pps(value), accel),
            4 | 5 | 255 => self.axis.retune(t, vmax, accel),
            _ => {}
        }
    }

    fn write_global(&mut self, t: f64, bank: u8, number: u8, value: i32) -> Result<(), Status> {
        let slot = Slot::Global(bank, number);
        self.params.check_write(slot, value)?;
        match (bank, number) {
            (0, 73) => {
                let locked = match value {
                    LOCK => 1,
                    UNLOCK => 0,
                    _ => return Err(Status::InvalidValue),
                };
                self.params.set(slot, locked);
                self.eeprom_changed |= self.params.set_stored(slot, locked);
            }
            (0, 132) => self.set_ticks(t, value),
            _ if eeprom_only(slot) => {
                if self.locked() {
                    return Err(Status::EepromLocked);
                }
                if number == 81 && self.params.get(slot) & 1 != 0 && value & 1 == 0 {
                    // Dropping disassembly protection erases the program.
                    self.eeprom_changed |= self.program.erase();
                }
                self.params.set(slot, value);
                self.eeprom_changed |= self.params.set_stored(slot, value);
            }
            _ => self.params.set(slot, value),
        }
        Ok(())
    }

    fn set_coordinate(&mut self, number: u8, value: i32) -> Result<(), Status> {
        let stored = self.params.get(Slot::Global(0, 84)) == 1;
        if stored && self.locked() {
            return Err(Status::EepromLocked);
        }
        let slot = self
            .coords
            .get_mut(number as usize)
            .ok_or(Status::WrongType)?;
        if stored && *slot != value {
            self.eeprom_changed = true;
        }
        *slot = value;
        Ok(())
    }
}

/// The parameter a STAP/RSAP/STGP/RSGP instruction names.
fn slot(i: &Instruction) -> Slot {
    match i.command {
        STAP | RSAP => Slot::Axis(i.type_),
        _ => Slot::Global(i.motor, i.type_),
    }
}
