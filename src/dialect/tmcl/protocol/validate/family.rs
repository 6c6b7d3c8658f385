//! The checks one module's profile adds to the table checks: the banks a command accepts, the
//! I/O map, and ranges that depend on another parameter's value.
//!
//! A conditional range (`range_when`: TMCM-142 velocities are pps in 0..31999999 while AP255 = 1)
//! depends on a value only the module knows: a program, RSAP, a restart or another tool may have
//! changed it since. So the validator accepts a value that lies in the usual range or in any
//! conditional one, refuses a value that lies in none, and sends a value that one of them excludes
//! with a one-line notice that names the range it misses.

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind, ParamUse};
use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::profile::family::{OUTPUT_BANK, RangeWhen, spans};
use crate::dialect::tmcl::protocol::Instruction;

use super::super::error::{ConditionalRange, InputError, Warning};

/// Global parameter 67 (bank 0): the ASCII interface's settings, bit 0 its start in ASCII mode.
const ASCII_SETTINGS: u8 = 67;

/// The bank of a global-parameter command against the banks it accepts (STGP/RSGP: bank 2).
pub(super) fn check_bank(
    spec: &CommandSpec,
    instruction: &Instruction,
    profile: &Profile,
) -> Result<(), InputError> {
    let Some(banks) = &spec.banks else {
        return Ok(());
    };
    let names_bank = spec.field_is(Field::Motor, OperandKind::Bank);
    if !names_bank || banks.contains(&instruction.motor) {
        return Ok(());
    }
    let banks: Vec<String> = banks.iter().map(u8::to_string).collect();
    Err(InputError::BankNotAccepted {
        mnemonic: spec.display_name(),
        bank: instruction.motor,
        accepted: format!("{} only on the {}", banks.join(" or "), profile.module),
        note: spec.banks_note.clone(),
    })
}

/// Global parameter 67 of the ASCII interface (bit 0: start in ASCII mode) is never written or
/// stored on a module whose profile has none: sent "anyway" as an unknown parameter, a module that
/// kept it would start in a mode it does not have. Reads stay allowed.
pub(super) fn check_ascii_start_bit(
    spec: &CommandSpec,
    instruction: &Instruction,
    profile: &Profile,
) -> Result<(), InputError> {
    let changes = matches!(spec.param_use, Some(ParamUse::Write | ParamUse::Store));
    let gp67 = spec.field_is(Field::Type, OperandKind::GlobalParam)
        && instruction.type_ == ASCII_SETTINGS
        && instruction.motor == 0;
    if changes && gp67 && profile.identity.ascii_interface() == AsciiInterface::No {
        return Err(InputError::NoAsciiStartBit {
            module: profile.module.clone(),
        });
    }
    Ok(())
}

/// The port and bank of GIO/SIO against the module's I/O map (not checked without one); a
/// command with a value (SIO) writes, which only the output bank takes.
pub(super) fn check_port(
    spec: &CommandSpec,
    instruction: &Instruction,
    profile: &Profile,
) -> Result<(), InputError> {
    let addresses_port = spec.field_is(Field::Type, OperandKind::Port);
    if !addresses_port || profile.io_ports.is_empty() {
        return Ok(());
    }
    let (port, bank) = (instruction.type_, instruction.motor);
    let writes = spec.operand_for(Field::Value).is_some();
    let known = || ports_of(profile, writes.then_some(OUTPUT_BANK));
    match profile.io_port(bank, port) {
        // No bank has it: wrong whatever the bank, so said without one.
        None if !profile.io_ports.iter().any(|p| p.port == port) => Err(InputError::NoSuchPort {
            port,
            module: profile.module.clone(),
            known: known(),
        }),
        None => Err(InputError::BadPort {
            port,
            bank,
            module: profile.module.clone(),
            known: known(),
        }),
        Some(found) if writes && bank != OUTPUT_BANK => Err(InputError::NotAnOutput {
            mnemonic: spec.display_name(),
            port,
            bank,
            name: found.name.clone(),
            outputs: ports_of(profile, Some(OUTPUT_BANK)),
        }),
        Some(_) => Ok(()),
    }
}

/// "bank 0 ports 3..8, bank 1 ports 0..2 and bank 2 ports 0..2" (of one bank only, if given).
fn ports_of(profile: &Profile, only: Option<u8>) -> String {
    let mut banks: Vec<(u8, Vec<u8>)> = Vec::new();
    for p in &profile.io_ports {
        if only.is_some_and(|b| b != p.bank) {
            continue;
        }
        match banks.last_mut() {
            Some((bank, ports)) if *bank == p.bank => ports.push(p.port),
            _ => banks.push((p.bank, vec![p.port])),
        }
    }
    let parts: Vec<String> = banks
        .iter()
        .map(|(bank, ports)| format!("bank {bank} ports {}", spans(ports)))
        .collect();
    match parts.as_slice() {
        [] => "no ports there".to_string(),
        [one] => one.clone(),
        [first @ .., last] => format!("{} and {last}", first.join(", ")),
    }
}

/// A value against its usual range and its conditional ones (see the module docs).
pub(super) fn check_value(
    what: &str,
    value: i64,
    usual: Option<(i64, i64)>,
    conditional: &[RangeWhen],
    unit: &str,
) -> Result<Vec<Warning>, InputError> {
    let inside = |(lo, hi): (i64, i64)| (lo..=hi).contains(&value);
    let in_usual = usual.is_none_or(inside);
    let valid_in = conditional.iter().find(|r| inside(r.range));
    match (usual, in_usual, valid_in) {
        (Some((lo, hi)), false, None) => Err(InputError::OutOfRange {
            what: what.to_string(),
            value,
            lo,
            hi,
            unit: unit.to_string(),
        }),
        (Some((lo, hi)), false, Some(valid)) => {
            Ok(vec![Warning::ConditionalRange(ConditionalRange {
                what: what.to_string(),
                value,
                outside: format!("the usual range {lo}..{hi}{}", spaced(unit)),
                valid: valid.describe(),
            })])
        }
        _ => Ok(conditional
            .iter()
            .filter(|r| !inside(r.range))
            .map(|r| {
                Warning::ConditionalRange(ConditionalRange {
                    what: what.to_string(),
                    value,
                    outside: r.describe(),
                    valid: match usual {
                        Some((lo, hi)) => format!("the usual range {lo}..{hi}{}", spaced(unit)),
                        None => "the usual range".to_string(),
                    },
                })
            })
            .collect()),
    }
}

fn spaced(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}

#[cfg(test)]
mod tests;
