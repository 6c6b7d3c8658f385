//! Executing one command on a module: motion, parameters, I/O and coordinates. Control
//! functions 128–139 are in [`super::control`]; program flow is the program runner's.
//!
//! Status codes follow Trinamic's firmware where the manual is silent: the reply value is the
//! request's value unless the command returns one; an unknown parameter, port, coordinate or
//! keyword number (the type byte) answers 3 (wrong type); a value out of range or a motor other
//! than 0 answers 4 (invalid value).

use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::protocol::{Instruction, Opcode, Status};

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

/// EEPROM lock values of GP 73 (generic TMCL reference).
const LOCK: i32 = 1234;
const UNLOCK: i32 = 4321;

impl Machine {
    /// Executes `instruction` at `t` (the machine must have been advanced to `t`). In download
    /// mode, instructions other than control functions are stored instead.
    pub fn execute(&mut self, t: f64, instruction: &Instruction, source: Source) -> Outcome {
        if source == Source::Direct
            && self.program.downloading()
            && !instruction.command.is_control()
        {
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
        if instruction.command.is_control() {
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
        let flow = matches!(i.command, Opcode::Jc | Opcode::Ja | Opcode::Csub);
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
            Opcode::Ror | Opcode::Rol => {
                let signed = if i.command == Opcode::Ror {
                    value
                } else {
                    -value
                };
                self.params.set(Slot::Axis(2), signed);
                let accel = self.move_limits().1;
                self.axis.rotate(t, self.pps(signed), accel);
            }
            Opcode::Mst => {
                self.params.set(Slot::Axis(2), 0);
                let accel = self.move_limits().1;
                self.axis.rotate(t, 0.0, accel);
            }
            Opcode::Mvp => return self.move_to(t, i),
            Opcode::Sap => self.write_axis(t, i.type_, value)?,
            Opcode::Aap => self.write_axis(t, i.type_, self.vm.acc)?,
            Opcode::Gap => {
                self.params.check_read(Slot::Axis(i.type_))?;
                return Ok(self.axis_value(i.type_, t));
            }
            Opcode::Stap | Opcode::Stgp => {
                let slot = slot(i);
                self.params.check_store(slot)?;
                if self.locked() {
                    return Err(Status::EepromLocked);
                }
                self.eeprom_changed |= self.params.store(slot);
            }
            Opcode::Rsap | Opcode::Rsgp => {
                let slot = slot(i);
                self.params.check_store(slot)?;
                self.params.restore(slot);
                if let Slot::Axis(n) = slot {
                    self.after_axis_write(t, n);
                }
            }
            Opcode::Sgp => self.write_global(t, i.motor, i.type_, value)?,
            Opcode::Agp => self.write_global(t, i.motor, i.type_, self.vm.acc)?,
            Opcode::Ggp => {
                self.params.check_read(Slot::Global(i.motor, i.type_))?;
                return Ok(self.global_value(i.motor, i.type_, t));
            }
            Opcode::Rfs => return Ok(self.reference_search(t, i.type_)),
            Opcode::Sio => self.io.write(i.type_, i.motor, value != 0)?,
            Opcode::Gio => return self.io.read(i.type_, i.motor),
            Opcode::Sco => self.set_coordinate(i.type_, value)?,
            Opcode::Aco => self.set_coordinate(i.type_, self.vm.acc)?,
            Opcode::Cco => self.set_coordinate(i.type_, self.axis.counter(t))?,
            // Only a division by zero fails here: the keyword was checked before.
            Opcode::Calc | Opcode::Calcx => self.calculate(i).map_err(|_| Status::InvalidValue)?,
            Opcode::Gco => return Ok(self.coords[i.type_ as usize]),
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
        Opcode::Stap | Opcode::Rsap => Slot::Axis(i.type_),
        _ => Slot::Global(i.motor, i.type_),
    }
}
