//! Instructions back to source that assembles to the same instructions: keywords by name, labels
//! (`L8:`) at every jump and call target, parameter numbers with their names as comments.
//!
//! An instruction whose don't-care fields are not zero (as memory read back from a module may
//! hold) cannot be written in mnemonic form, so it is written raw, by command number
//! (`3 0, 0, 5`), which the assembler takes field by field. An instruction that is not valid in a
//! program is still written, with the reason as a comment and in [`Disassembly::problems`].

use std::collections::BTreeSet;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::protocol::validate::{Mode, validate_instruction};
use crate::dialect::tmcl::protocol::{InputError, Instruction};

/// Source text and what is wrong with the instructions it came from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Disassembly {
    /// The source, one instruction per line, labels on lines of their own.
    pub source: String,
    /// Instructions that are not valid in a program, by address; their lines will not assemble.
    pub problems: Vec<(usize, InputError)>,
}

/// Column at which end-of-line comments start.
const COMMENT_COLUMN: usize = 32;

/// Writes `instructions` (program address 0 first) as source text.
pub fn disassemble(instructions: &[Instruction], profile: &Profile) -> Disassembly {
    let specs: Vec<Option<&CommandSpec>> = instructions
        .iter()
        .map(|i| mnemonic_form(i, profile))
        .collect();
    let targets: BTreeSet<usize> = instructions
        .iter()
        .zip(&specs)
        .filter_map(|(instruction, spec)| jump_target(instruction, (*spec)?, instructions.len()))
        .collect();
    let mut source = String::new();
    let mut problems = Vec::new();
    for (address, (instruction, spec)) in instructions.iter().zip(&specs).enumerate() {
        if targets.contains(&address) {
            source.push_str(&format!("{}:\n", label(address)));
        }
        let mut notes = Vec::new();
        let text = match spec {
            Some(spec) => mnemonic_text(instruction, spec, &targets, instructions.len()),
            None => {
                if let Some(spec) = profile.commands.by_number(instruction.command) {
                    if !spec.mnemonic.is_empty() {
                        notes.push(format!("{} with non-zero unused fields", spec.mnemonic));
                    }
                }
                raw_text(instruction)
            }
        };
        notes.extend(param_name(instruction, profile));
        if let Err(error) = validate_instruction(instruction, profile, Mode::Program) {
            notes.push(format!("invalid in a program: {error}"));
            problems.push((address, error));
        }
        let line = if notes.is_empty() {
            format!("    {text}")
        } else {
            format!(
                "    {text:<width$}// {}",
                notes.join("; "),
                width = COMMENT_COLUMN - 4
            )
        };
        source.push_str(line.trim_end());
        source.push('\n');
    }
    if targets.contains(&instructions.len()) {
        source.push_str(&format!("{}:\n", label(instructions.len())));
    }
    Disassembly { source, problems }
}

fn label(address: usize) -> String {
    format!("L{address}")
}

/// The command, if the instruction can be written with its mnemonic: a known mnemonic, and zero
/// in every field its operands do not cover.
fn mnemonic_form<'p>(instruction: &Instruction, profile: &'p Profile) -> Option<&'p CommandSpec> {
    let spec = profile.commands.by_number(instruction.command)?;
    let unused_are_zero = [
        (Field::Type, i64::from(instruction.type_)),
        (Field::Motor, i64::from(instruction.motor)),
        (Field::Value, i64::from(instruction.value)),
    ]
    .iter()
    .all(|&(field, value)| value == 0 || spec.operand_for(field).is_some());
    (!spec.mnemonic.is_empty() && unused_are_zero).then_some(spec)
}

/// The address a jump or call of the program goes to, if a label can stand for it.
fn jump_target(instruction: &Instruction, spec: &CommandSpec, len: usize) -> Option<usize> {
    let jumps = spec.field_is(Field::Value, OperandKind::Address);
    let target = usize::try_from(instruction.value).ok()?;
    (jumps && target <= len).then_some(target)
}

fn mnemonic_text(
    instruction: &Instruction,
    spec: &CommandSpec,
    targets: &BTreeSet<usize>,
    len: usize,
) -> String {
    let mut parts: Vec<String> = spec
        .operands
        .iter()
        .map(|operand| match operand.kind {
            OperandKind::Keyword => match spec.keyword_for(instruction.type_) {
                Some(keyword) => keyword.name.clone(),
                None => instruction.type_.to_string(),
            },
            OperandKind::Address => match jump_target(instruction, spec, len) {
                Some(target) if targets.contains(&target) => label(target),
                _ => instruction.value.to_string(),
            },
            kind => match kind.field() {
                Field::Type => instruction.type_.to_string(),
                Field::Motor => instruction.motor.to_string(),
                Field::Value => instruction.value.to_string(),
            },
        })
        .collect();
    while parts.len() > spec.required_operands()
        && spec.operands[parts.len() - 1].optional
        && parts.last().is_some_and(|p| p == "0")
    {
        parts.pop();
    }
    if parts.is_empty() {
        spec.mnemonic.clone()
    } else {
        format!("{} {}", spec.mnemonic, parts.join(", "))
    }
}

fn raw_text(instruction: &Instruction) -> String {
    format!(
        "{} {}, {}, {}",
        instruction.command.number(),
        instruction.type_,
        instruction.motor,
        instruction.value
    )
}

/// The identifier of the parameter an instruction names, if the profile knows it.
fn param_name(instruction: &Instruction, profile: &Profile) -> Option<String> {
    let spec = profile.commands.by_number(instruction.command)?;
    let param = match spec.operand_for(Field::Type)?.kind {
        OperandKind::AxisParam => profile.axis_param(instruction.type_)?,
        OperandKind::GlobalParam => profile.global_param(instruction.motor, instruction.type_)?,
        _ => return None,
    };
    Some(param.ident.clone())
}

#[cfg(test)]
mod tests;
