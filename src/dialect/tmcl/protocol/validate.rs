//! Checks a resolved line against the profile before it is sent: mode, keywords, motor, bank, I/O
//! port, parameter access and value ranges. Unknown parameter *numbers* pass with a warning (the
//! tables are incomplete; the generic profile has none, and says so once per session); everything
//! else that is wrong is refused. The rules a module's profile adds are in [`family`].

mod family;

use crate::dialect::tmcl::profile::{Param, ParamKind, Profile};

use super::error::{InputError, Warning};
use super::instruction::Instruction;
use super::line::{Line, Op, format_instruction};
use crate::dialect::tmcl::profile::commands::{
    AsciiWord, CommandSpec, Field, OperandKind, ParamUse,
};

/// Where a line is going to be used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Typed in ASCII mode (manual §6.6.3 list only).
    Ascii,
    /// Sent as a binary frame in direct mode.
    Binary,
    /// Stored in a stand-alone program.
    Program,
}

/// Validates a line for `mode`; returns the warnings of a line that may be sent.
pub fn validate(line: &Line, profile: &Profile, mode: Mode) -> Result<Vec<Warning>, InputError> {
    match line.op {
        Op::Ascii(word) => check_ascii_word(word, mode).map(|()| Vec::new()),
        Op::Command(instruction) => validate_instruction(&instruction, profile, mode),
    }
}

/// Validates one instruction for `mode`.
pub fn validate_instruction(
    instruction: &Instruction,
    profile: &Profile,
    mode: Mode,
) -> Result<Vec<Warning>, InputError> {
    let spec = profile
        .commands
        .by_number(instruction.command)
        .ok_or_else(|| InputError::UnknownCommandNumber {
            number: instruction.command.number(),
            module: profile.module.clone(),
        })?;
    check_mode(spec, mode, profile)?;
    check_keyword(spec, instruction)?;
    check_motor(spec, instruction, profile)?;
    let mut warnings = check_ranges(spec, instruction, profile)?;
    warnings.extend(check_param(spec, instruction, profile)?);
    family::check_bank(spec, instruction, profile)?;
    family::check_port(spec, instruction, profile)?;
    Ok(warnings)
}

fn check_ascii_word(word: AsciiWord, mode: Mode) -> Result<(), InputError> {
    let message = match mode {
        Mode::Ascii => return Ok(()),
        Mode::Binary => format!(
            "{} only exists in ASCII mode; in binary mode use :run, :stop or :ascii",
            word.as_str()
        ),
        Mode::Program => format!(
            "{} is an ASCII-mode word, not a program instruction",
            word.as_str()
        ),
    };
    Err(InputError::NotInMode {
        mnemonic: word.as_str().into(),
        message,
    })
}

fn check_mode(spec: &CommandSpec, mode: Mode, profile: &Profile) -> Result<(), InputError> {
    let name = spec.display_name();
    let program_only = spec.standalone && !spec.direct_mode;
    let message = match mode {
        Mode::Ascii if spec.ascii_allowed => return Ok(()),
        Mode::Binary if spec.direct_mode => return Ok(()),
        Mode::Program if spec.standalone => return Ok(()),
        Mode::Ascii | Mode::Binary if program_only => {
            format!("{name} only exists inside stand-alone TMCL programs")
        }
        // The command's name goes between dashes: some names carry brackets of their own.
        Mode::Ascii => format!(
            "{name} — {} — is not available in ASCII mode: the {}'s ASCII command list lacks \
             it; switch to binary mode with :bin to send it",
            spec.name, profile.module
        ),
        Mode::Binary => format!("{name} — {} — cannot be sent in direct mode", spec.name),
        Mode::Program => format!(
            "{name} — {} — is a direct-mode control function and cannot be stored in a program",
            spec.name
        ),
    };
    Err(InputError::NotInMode {
        mnemonic: name,
        message,
    })
}

fn check_keyword(spec: &CommandSpec, instruction: &Instruction) -> Result<(), InputError> {
    let has_keyword_operand = spec.operands.iter().any(|o| o.kind == OperandKind::Keyword);
    if !has_keyword_operand
        || spec.keywords.is_empty()
        || spec.keyword_for(instruction.type_).is_some()
    {
        return Ok(());
    }
    Err(InputError::BadKeyword {
        mnemonic: spec.display_name(),
        word: instruction.type_.to_string(),
        allowed: spec
            .keywords
            .iter()
            .map(|k| format!("{} ({})", k.name, k.value))
            .collect(),
    })
}

fn check_motor(
    spec: &CommandSpec,
    instruction: &Instruction,
    profile: &Profile,
) -> Result<(), InputError> {
    let names_motor = spec.field_is(Field::Motor, OperandKind::Motor);
    if names_motor && !spec.motor_ignored && instruction.motor >= profile.axes {
        return Err(InputError::BadMotor {
            motor: instruction.motor,
            module: profile.module.clone(),
            axes: profile.axes,
        });
    }
    Ok(())
}

fn check_ranges(
    spec: &CommandSpec,
    instruction: &Instruction,
    profile: &Profile,
) -> Result<Vec<Warning>, InputError> {
    let coordinates = (0, i64::from(profile.coordinates) - 1);
    let out_of = |what: String, value: i64, (lo, hi): (i64, i64)| {
        if (lo..=hi).contains(&value) {
            Ok(())
        } else {
            Err(InputError::OutOfRange {
                what,
                value,
                lo,
                hi,
                unit: String::new(),
            })
        }
    };
    let warnings = if spec.value_range.is_some() || !spec.range_when.is_empty() {
        family::check_value(
            &format!("the value of {}", spec.display_name()),
            instruction.value.into(),
            spec.value_range,
            &spec.range_when,
            "",
        )?
    } else {
        Vec::new()
    };
    if spec.field_is(Field::Type, OperandKind::Coord) {
        out_of(
            "the coordinate number".into(),
            instruction.type_.into(),
            coordinates,
        )?;
    }
    let moves_to_coordinate = spec
        .keyword_for(instruction.type_)
        .is_some_and(|k| k.name == "COORD");
    if moves_to_coordinate {
        out_of(
            "the coordinate number".into(),
            instruction.value.into(),
            coordinates,
        )?;
    }
    Ok(warnings)
}

fn check_param(
    spec: &CommandSpec,
    instruction: &Instruction,
    profile: &Profile,
) -> Result<Vec<Warning>, InputError> {
    let Some(operand) = spec.operand_for(Field::Type) else {
        return Ok(Vec::new());
    };
    let (param, kind, bank) = match operand.kind {
        OperandKind::AxisParam => (profile.axis_param(instruction.type_), "axis", None),
        OperandKind::GlobalParam => (
            profile.global_param(instruction.motor, instruction.type_),
            "global",
            Some(instruction.motor),
        ),
        _ => return Ok(Vec::new()),
    };
    let Some(param) = param else {
        family::check_ascii_start_bit(spec, instruction, profile)?;
        if profile.generic {
            return Ok(Vec::new()); // numbers only: the session said so once
        }
        return Ok(vec![Warning::UnknownParam {
            kind,
            number: instruction.type_,
            bank,
            module: profile.module.clone(),
        }]);
    };
    match spec.param_use {
        Some(ParamUse::Read) if !param.access.read => Err(InputError::NotReadable {
            kind,
            number: param.number,
            ident: param.ident.clone(),
        }),
        Some(ParamUse::Write) if !param.access.write => Err(InputError::ReadOnly {
            kind,
            number: param.number,
            ident: param.ident.clone(),
            read: read_line(param, profile),
        }),
        Some(ParamUse::Write) if spec.operand_for(Field::Value).is_some() => family::check_value(
            &format!("{} ({kind} parameter {})", param.ident, param.number),
            instruction.value.into(),
            param.range,
            &param.range_when,
            &param.unit,
        ),
        Some(ParamUse::Store) if !param.access.store => Err(InputError::NotStorable {
            kind,
            number: param.number,
            ident: param.ident.clone(),
            mnemonic: spec.display_name(),
        }),
        _ => Ok(Vec::new()),
    }
}

/// The line that reads a parameter (`GAP 8, 0`, `GGP 128, 0`).
fn read_line(param: &Param, profile: &Profile) -> String {
    let (kind, motor) = match param.kind {
        ParamKind::Axis => (OperandKind::AxisParam, 0),
        ParamKind::Global { bank } => (OperandKind::GlobalParam, bank),
    };
    let reader = profile
        .commands
        .iter()
        .find(|c| c.param_use == Some(ParamUse::Read) && c.field_is(Field::Type, kind));
    match reader {
        Some(reader) => format_instruction(
            &Instruction::new(reader.number, param.number, motor, 0),
            profile,
        ),
        None => format!("the read command of parameter {}", param.number),
    }
}

#[cfg(test)]
mod tests;
