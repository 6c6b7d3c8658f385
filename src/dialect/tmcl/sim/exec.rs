//! Executing one command on a module: motion, parameters, I/O and coordinates. Control
//! functions 128–139 are in [`super::control`]; program flow is the program runner's.
//!
//! Status codes follow Trinamic's firmware where the manual is silent: the reply value is the
//! request's value unless the command returns one; an unknown parameter, port, coordinate or
//! keyword number (the type byte) answers 3 (wrong type); a value out of range or a motor the
//! module does not have answers 4 (invalid value).

use crate::dialect::tmcl::profile::Param;
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::protocol::{Instruction, Opcode, Status};

use super::machine::Machine;
use super::outcome::{Outcome, Source};
use super::params::{Slot, eeprom_only};

/// EEPROM lock values of GP 73 (generic TMCL reference).
const LOCK: i32 = 1234;
const UNLOCK: i32 = 4321;

impl Machine {
    /// Executes `instruction` at `t` (the machine must have been advanced to `t`). In download
    /// mode, instructions other than control functions are stored instead.
    pub(super) fn execute(&mut self, t: f64, instruction: &Instruction, source: Source) -> Outcome {
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
        if has(OperandKind::Motor) && !spec.motor_ignored && i.motor >= self.profile.axes {
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
        // Axis commands name their motor in the motor byte (checked against the profile).
        let m = i.motor;
        if names_a_motor(i.command) && usize::from(m) >= self.axes.len() {
            return Err(Status::InvalidValue);
        }
        match i.command {
            Opcode::Ror => self.rotate(t, m, value),
            // A signed range (later modules) lets a negative speed turn the other way.
            Opcode::Rol => self.rotate(t, m, value.saturating_neg()),
            Opcode::Mst => self.stop_motor(t, m),
            Opcode::Mvp => return self.move_to(t, i),
            Opcode::Sap => self.write_axis(t, m, i.type_, value)?,
            Opcode::Aap => self.write_axis(t, m, i.type_, self.vm.acc)?,
            Opcode::Gap => {
                self.params.check_read(Slot::Axis(m, i.type_))?;
                return Ok(self.axis_value(m, i.type_, t));
            }
            Opcode::Stap | Opcode::Stgp => self.store(slot(i))?,
            Opcode::Rsap | Opcode::Rsgp => self.restore(t, slot(i))?,
            Opcode::Sgp => self.write_global(t, i.motor, i.type_, value)?,
            Opcode::Agp => self.write_global(t, i.motor, i.type_, self.vm.acc)?,
            Opcode::Ggp => {
                self.params.check_read(Slot::Global(i.motor, i.type_))?;
                return Ok(self.global_value(i.motor, i.type_, t));
            }
            Opcode::Rfs => return self.reference_search(t, m, i.type_),
            Opcode::Sio => self.io.write(i.type_, i.motor, value != 0)?,
            Opcode::Gio => return self.io.read(i.type_, i.motor),
            Opcode::Sco => self.set_coordinate(m, i.type_, value)?,
            Opcode::Aco => self.set_coordinate(m, i.type_, self.vm.acc)?,
            Opcode::Cco => {
                let counter = self.axes[m as usize].counter(t);
                self.set_coordinate(m, i.type_, counter)?;
            }
            // Only a division by zero fails here: the keyword was checked before.
            Opcode::Calc | Opcode::Calcx => {
                self.vm.calculate(i).map_err(|_| Status::InvalidValue)?
            }
            Opcode::Gco => return Ok(self.coords[m as usize][i.type_ as usize]),
            _ => return Err(Status::InvalidCommand),
        }
        Ok(value)
    }

    /// ROR and ROL (`speed` negated): motor `m` turns at `speed` in the user's unit.
    fn rotate(&mut self, t: f64, m: u8, speed: i32) {
        self.set_role(m, self.roles.target_speed, speed);
        let accel = self.move_limits(m).1;
        let v = self.pps(m, speed);
        self.axes[m as usize].rotate(t, v, accel);
    }

    /// MST: motor `m` ramps down to a stop.
    fn stop_motor(&mut self, t: f64, m: u8) {
        self.set_role(m, self.roles.target_speed, 0);
        let accel = self.move_limits(m).1;
        self.axes[m as usize].rotate(t, 0.0, accel);
    }

    /// STAP and STGP: the parameter's value into the EEPROM, unless the EEPROM is locked.
    fn store(&mut self, slot: Slot) -> Result<(), Status> {
        self.params.check_store(slot)?;
        if self.locked() {
            return Err(Status::EepromLocked);
        }
        self.eeprom_changed |= self.params.store(slot);
        Ok(())
    }

    /// RSAP and RSGP: the parameter's value back from the EEPROM, with what an axis parameter's
    /// change sets going (a new unit or divisor rescales a running motor).
    fn restore(&mut self, t: f64, slot: Slot) -> Result<(), Status> {
        self.params.check_store(slot)?;
        match slot {
            Slot::Axis(m, n) => {
                let before = self.velocity_factor(m);
                self.params.restore(slot);
                self.after_axis_write(t, m, n, before);
            }
            Slot::Global(..) => self.params.restore(slot),
        }
        Ok(())
    }

    fn move_to(&mut self, t: f64, i: &Instruction) -> Result<i32, Status> {
        let m = i.motor;
        let target = match i.type_ {
            0 => i.value,
            1 => self
                .role(m, self.roles.target_position)
                .wrapping_add(i.value),
            _ => *usize::try_from(i.value)
                .ok()
                .and_then(|n| self.coords[m as usize].get(n))
                .ok_or(Status::InvalidValue)?,
        };
        self.set_role(m, self.roles.target_position, target);
        let (vmax, accel) = self.move_limits(m);
        self.axes[m as usize].move_to(t, target, vmax, accel);
        Ok(if i.type_ == 1 { target } else { i.value })
    }

    /// RFS START, STOP, STATUS. START refuses (4, invalid value) a search mode (AP193) the
    /// module does not have, rather than running some other mode that may never end.
    fn reference_search(&mut self, t: f64, m: u8, type_: u8) -> Result<i32, Status> {
        let axis = m as usize;
        Ok(match type_ {
            0 => {
                let mode = self.role(m, self.roles.search_mode);
                if !self.has_search_mode(mode) {
                    return Err(Status::InvalidValue);
                }
                let mode = mode as u8;
                let fast = self.pps(m, self.role(m, self.roles.search_speed));
                let slow = self.pps(m, self.role(m, self.roles.switch_speed));
                let accel = self.move_limits(m).1;
                self.axes[axis].start_search(t, mode, fast, slow, accel);
                0
            }
            1 => {
                self.axes[axis].stop_search(t);
                0
            }
            _ => self.axes[axis].search_status(),
        })
    }

    /// Whether the module has search mode `mode`: one of the values its AP193 row lists, or in
    /// its range, or (a profile that says neither) one of the modes the simulator runs.
    fn has_search_mode(&self, mode: i32) -> bool {
        let row = self
            .roles
            .search_mode
            .and_then(|n| self.profile.axis_param(n));
        let mode = i64::from(mode);
        let runs = (1..=super::motion::SEARCH_MODES).contains(&mode);
        match row {
            Some(p) if !p.decoding.values.is_empty() => {
                runs && p.decoding.values.iter().any(|(v, _)| *v == mode)
            }
            Some(Param {
                range: Some((lo, hi)),
                ..
            }) => runs && (*lo..=*hi).contains(&mode),
            _ => runs,
        }
    }

    fn locked(&self) -> bool {
        self.params.get(Slot::Global(0, 73)) == 1
    }

    fn write_axis(&mut self, t: f64, m: u8, number: u8, value: i32) -> Result<(), Status> {
        self.params.check_write(Slot::Axis(m, number), value)?;
        let r = &self.roles;
        let is = |role: Option<u8>| role == Some(number);
        if is(r.actual_position) {
            self.axes[m as usize].set_counter(t, value);
        } else if is(r.actual_speed) {
            let v = self.pps(m, value);
            self.axes[m as usize].set_velocity(t, v);
        } else if is(r.integrator_sum) {
            // Any write clears the integrator sum.
            self.params.set(Slot::Axis(m, number), 0);
        } else {
            let before = self.velocity_factor(m);
            self.params.set(Slot::Axis(m, number), value);
            self.after_axis_write(t, m, number, before);
        }
        Ok(())
    }

    /// Side effects of a new RAM value: the target position moves, the target speed turns, the
    /// maximum speed, acceleration, unit mode and divisors retune a move, and a new velocity
    /// unit (`before` was the old one, in pps per unit) changes the speed of a rotation.
    fn after_axis_write(&mut self, t: f64, m: u8, number: u8, before: f64) {
        let value = self.params.get(Slot::Axis(m, number));
        let (vmax, accel) = self.move_limits(m);
        let r = &self.roles;
        let is = |role: Option<u8>| role == Some(number);
        if is(r.target_position) {
            self.axes[m as usize].move_to(t, value, vmax, accel);
        } else if is(r.target_speed) {
            let v = self.pps(m, value);
            self.axes[m as usize].rotate(t, v, accel);
        } else if is(r.max_speed)
            || is(r.max_acceleration)
            || is(r.unit_mode)
            || is(r.pulse_divisor)
            || is(r.ramp_divisor)
        {
            let scale = self.velocity_factor(m) / before;
            let axis = &mut self.axes[m as usize];
            axis.retune(t, vmax, accel);
            axis.rescale_rotation(t, scale);
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
            _ => {
                self.params.set(slot, value);
                if bank == 3 {
                    self.configure_interrupt(t, number, value);
                }
            }
        }
        Ok(())
    }

    /// SCO, ACO, CCO: coordinate `number` of motor `m` (every axis has its own, as the
    /// multi-axis manuals say: "up to 20 position values for every axis").
    fn set_coordinate(&mut self, m: u8, number: u8, value: i32) -> Result<(), Status> {
        let stored = self.params.get(Slot::Global(0, 84)) == 1;
        if stored && self.locked() {
            return Err(Status::EepromLocked);
        }
        let slot = self.coords[m as usize]
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
/// Whether the command's motor byte names a motor, which the module must have.
fn names_a_motor(command: Opcode) -> bool {
    matches!(
        command,
        Opcode::Ror
            | Opcode::Rol
            | Opcode::Mst
            | Opcode::Mvp
            | Opcode::Sap
            | Opcode::Aap
            | Opcode::Gap
            | Opcode::Stap
            | Opcode::Rsap
            | Opcode::Rfs
            | Opcode::Sco
            | Opcode::Gco
            | Opcode::Cco
            | Opcode::Aco
    )
}

fn slot(i: &Instruction) -> Slot {
    match i.command {
        Opcode::Stap | Opcode::Rsap => Slot::Axis(i.motor, i.type_),
        _ => Slot::Global(i.motor, i.type_),
    }
}
