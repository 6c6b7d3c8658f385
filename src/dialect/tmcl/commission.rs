//! The TMCL session as a [`ParamDevice`]: GAP/SAP/STAP for axis parameters, GGP/SGP/STGP for
//! global ones, the firmware version from command 136 (binary direct mode, there and back).

use crate::dialect::session::DialectSession;
use crate::dialect::tmcl::profile::{Param, Profile};
use crate::dialect::tmcl::protocol::line::Op;
use crate::dialect::tmcl::protocol::validate::{Mode, validate_instruction};
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode};
use crate::dialect::tmcl::session::{TmclReply, TmclSession};
use crate::session::SessionError;

use crate::commission::device::{ParamDevice, ParamError, ParamRef, Scope, StoreStep};
use crate::commission::value::{ParamValue, Reading, Tolerance};

impl ParamDevice for TmclSession {
    /// From the profile's decoding tables (`values`, `bits`, `fields`).
    fn explain(&self, param: &ParamRef, value: &ParamValue) -> Option<String> {
        let ParamValue::Int(value) = value else {
            return None;
        };
        let number = u8::try_from(param.number?).ok()?;
        let row = match param.scope {
            Scope::Axis { .. } => self.profile().axis_param(number),
            Scope::Global { bank } => self.profile().global_param(bank, number),
            Scope::Drive => None,
        }?;
        row.decoding.explain(*value)
    }

    fn module_name(&self) -> String {
        self.profile().module.clone()
    }

    fn address(&self) -> Option<u32> {
        Some(self.target().into())
    }

    fn who(&self) -> String {
        ModuleName(self.target()).to_string()
    }

    fn memory(&self) -> &'static str {
        "EEPROM"
    }

    fn firmware(&mut self) -> Option<String> {
        let target = self.target();
        let exchange = self
            .in_binary(target, |s| {
                s.request(target, Instruction::new(Opcode::FirmwareVersion, 0, 0, 0))
            })
            .ok()?;
        match exchange.reply {
            TmclReply::Version(text) if !text.trim().is_empty() => Some(text.trim().to_string()),
            _ => None,
        }
    }

    fn params(&self) -> Vec<ParamRef> {
        profile_params(self.profile())
    }

    fn find(&self, name: &str) -> Result<ParamRef, ParamError> {
        let profile = self.profile();
        match (profile.find_axis(name), profile.find_global(name)) {
            (Ok(p), _) => Ok(param_ref(profile, p, Scope::Axis { motor: 0 })),
            (_, Ok(p)) => Ok(param_ref(profile, p, Scope::Global { bank: p.bank() })),
            (Err(axis), Err(_)) => {
                let all = profile.axis.iter().chain(&profile.global);
                let nearest = crate::suggest::nearest(name, all.map(|p| p.ident.as_str()));
                Err(ParamError::Unknown(match axis {
                    crate::dialect::tmcl::profile::LookupError::Ambiguous { .. } => {
                        axis.to_string()
                    }
                    _ => format!(
                        "unknown parameter '{name}' (:params lists them){}",
                        crate::suggest::did_you_mean(&nearest)
                    ),
                }))
            }
        }
    }

    fn read(&mut self, param: &ParamRef) -> Result<Reading, SessionError> {
        let instruction = instruction(param, [Opcode::Gap, Opcode::Ggp], 0);
        let exchange = self.request(self.target(), instruction)?.checked()?;
        exchange
            .value()
            .map(|v| Reading::of(i64::from(v)))
            .ok_or_else(|| SessionError::Link(format!("no value in the reply '{}'", exchange.raw)))
    }

    fn write(&mut self, param: &ParamRef, value: &ParamValue) -> Result<(), SessionError> {
        let value = word(param, value)?;
        let instruction = instruction(param, [Opcode::Sap, Opcode::Sgp], value);
        self.request(self.target(), instruction)?.checked()?;
        Ok(())
    }

    fn check_write(&self, param: &ParamRef, value: &ParamValue) -> Result<(), ParamError> {
        if !self.options().validate {
            // --no-validate: the module judges (values still have to be 32-bit integers).
            return word(param, value).map(|_| ()).map_err(refused);
        }
        let mode = self.validation_mode(self.target());
        check_write_in(self.profile(), param, value, mode)
    }

    fn write_line(&self, param: &ParamRef, value: &ParamValue) -> String {
        let value = word(param, value).unwrap_or(i32::MAX);
        let op = Op::Command(instruction(param, [Opcode::Sap, Opcode::Sgp], value));
        self.format(self.target(), op)
    }

    /// STAP/STGP per parameter; none for a global parameter in a bank STGP does not take (the
    /// TMCM-142's bank-0 settings are kept in EEPROM by SGP itself).
    fn store_steps(&self, params: &[&ParamRef]) -> Vec<StoreStep> {
        params
            .iter()
            .filter(|param| stored_by_command(self.profile(), param))
            .map(|&param| {
                let op = Op::Command(instruction(param, [Opcode::Stap, Opcode::Stgp], 0));
                StoreStep {
                    line: self.format(self.target(), op),
                    params: vec![param.clone()],
                    whole: false,
                }
            })
            .collect()
    }

    fn store(&mut self, step: &StoreStep) -> Result<(), SessionError> {
        let profile = self.profile().clone();
        for param in step
            .params
            .iter()
            .filter(|p| stored_by_command(&profile, p))
        {
            let instruction = instruction(param, [Opcode::Stap, Opcode::Stgp], 0);
            self.request(self.target(), instruction)?.checked()?;
        }
        Ok(())
    }
}

/// Whether a parameter is made permanent by STAP/STGP: a global one only in a bank STGP takes.
fn stored_by_command(profile: &Profile, param: &ParamRef) -> bool {
    match param.scope {
        Scope::Global { bank } => profile
            .commands
            .by_number(11)
            .and_then(|stgp| stgp.banks.as_ref())
            .is_none_or(|banks| banks.contains(&bank)),
        _ => true,
    }
}

/// Every parameter of `profile` as the commissioning tools see it: the axis parameters of each
/// motor, then the global parameters by bank.
pub fn profile_params(profile: &Profile) -> Vec<ParamRef> {
    let axes = (0..profile.axes).flat_map(|motor| {
        profile
            .axis
            .iter()
            .map(move |p| param_ref(profile, p, Scope::Axis { motor }))
    });
    let globals = profile
        .global
        .iter()
        .map(|p| param_ref(profile, p, Scope::Global { bank: p.bank() }));
    axes.chain(globals).collect()
}

/// The commissioning view of a profile parameter.
pub(crate) fn param_ref(profile: &Profile, p: &Param, scope: Scope) -> ParamRef {
    ParamRef {
        scope,
        name: p.ident.clone(),
        number: Some(p.number.into()),
        unit: p.unit.clone(),
        access: p.access,
        role: profile.snapshot.role_of(&p.ident, p.access.write),
        rank: profile.snapshot.rank(&p.ident),
        tolerance: Tolerance::Exact,
    }
}

/// Whether the validator of `profile` lets a write of `value` to `param` through (the same check
/// a typed SAP/SGP gets: a 32-bit integer, in range, writable, on a motor the module has).
#[cfg(test)]
pub(crate) fn check_write(
    profile: &Profile,
    param: &ParamRef,
    value: &ParamValue,
) -> Result<(), ParamError> {
    check_write_in(profile, param, value, Mode::Ascii)
}

/// [`check_write`] for a module talked to in `mode` (binary direct mode has no ASCII list).
fn check_write_in(
    profile: &Profile,
    param: &ParamRef,
    value: &ParamValue,
    mode: Mode,
) -> Result<(), ParamError> {
    let value = word(param, value).map_err(refused)?;
    let instruction = instruction(param, [Opcode::Sap, Opcode::Sgp], value);
    validate_instruction(&instruction, profile, mode)
        .map(|_| ())
        .map_err(refused)
}

/// A value the validator would refuse, in its words.
fn refused(why: impl std::fmt::Display) -> ParamError {
    ParamError::Value(why.to_string())
}

/// The instruction for `param`: `commands[0]` for axis parameters, `commands[1]` for global ones.
fn instruction(param: &ParamRef, commands: [Opcode; 2], value: i32) -> Instruction {
    let number = param
        .number
        .and_then(|n| u8::try_from(n).ok())
        .unwrap_or(u8::MAX);
    match param.scope {
        Scope::Axis { motor } => Instruction::new(commands[0], number, motor, value),
        Scope::Global { bank } => Instruction::new(commands[1], number, bank, value),
        // Not a TMCL scope: global bank 0, which the module refuses unless the number exists.
        Scope::Drive => Instruction::new(commands[1], number, 0, value),
    }
}

/// The 32-bit word of a TMCL value; real numbers and text are refused (as a refusal of this
/// parameter, so a restore goes on with the others).
fn word(param: &ParamRef, value: &ParamValue) -> Result<i32, SessionError> {
    value
        .as_i64()
        .and_then(|v| i32::try_from(v).ok())
        .ok_or_else(|| {
            SessionError::Refused(format!(
                "{} = {value} is not a 32-bit integer, as TMCL values are",
                param.name
            ))
        })
}
