//! The one operand grammar of TMCL commands: how the operands of a command in mnemonic form —
//! keywords, parameter names, motor or bank, value, coordinate, address — fill the type,
//! motor/bank and value of an instruction, as the command table lays them out.
//!
//! Typed lines (the REPL, `-c`, stdin, scripts' `send`) and program lines both go through
//! [`encode`], so the two cannot drift. What a face writes comes in through [`OperandText`]: a
//! typed line gives numbers and names; a program adds constants, labels and expressions, which it
//! evaluates to a number itself.

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};

use super::error::InputError;
use super::instruction::Instruction;

/// A number as written; one written in hex may use the full unsigned range of the value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Number {
    /// The value.
    pub value: i64,
    /// Written in hex (`0x…`/`$…`).
    pub hex: bool,
}

/// One operand as a face wrote it.
pub trait OperandText {
    /// Why the operand has no number (a program's unknown or broken constant).
    type Error;

    /// The operand, if written as a single name; a command's keywords are matched on it.
    fn name(&self) -> Option<&str>;

    /// The name, if the tables are to read it as a keyword or parameter name: `None` for a
    /// number, and for a name the text defines itself (a program's constants and labels).
    fn table_name(&self) -> Option<&str>;

    /// The operand's number where an operand of `kind` stands; `Ok(None)` for a name there.
    fn number(&self, kind: OperandKind) -> Result<Option<Number>, Self::Error>;
}

/// Why operands make no instruction.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Refused<E> {
    /// The command table refuses them; `operand` is the index of the operand at fault, `None`
    /// when the operands as a whole are (their count).
    Table {
        /// The operand at fault.
        operand: Option<usize>,
        /// Why.
        error: InputError,
    },
    /// An operand has no number.
    Operand(E),
}

impl Refused<std::convert::Infallible> {
    /// The table's reason, for text whose operands always have a number or a name.
    pub fn into_input_error(self) -> InputError {
        match self {
            Refused::Table { error, .. } => error,
            Refused::Operand(never) => match never {},
        }
    }
}

/// One operand's problem, before it is located.
enum Fault<E> {
    Table(InputError),
    Operand(E),
}

impl<E> From<InputError> for Fault<E> {
    fn from(error: InputError) -> Self {
        Fault::Table(error)
    }
}

/// The instruction `operands` make of command `spec`.
pub fn encode<O: OperandText>(
    spec: &CommandSpec,
    operands: &[O],
    profile: &Profile,
) -> Result<Instruction, Refused<O::Error>> {
    check_count(spec, operands).map_err(|error| Refused::Table {
        operand: None,
        error,
    })?;
    let mut out = Instruction {
        command: spec.number.into(),
        ..Instruction::default()
    };
    let mut named_bank = None;
    for (index, (layout, operand)) in spec.operands.iter().zip(operands).enumerate() {
        match fill(spec, layout.kind, operand, profile, &mut out) {
            Ok(bank) => named_bank = bank.or(named_bank),
            Err(Fault::Table(error)) => {
                return Err(Refused::Table {
                    operand: Some(index),
                    error,
                });
            }
            Err(Fault::Operand(error)) => return Err(Refused::Operand(error)),
        }
    }
    if let Some((ident, bank)) = named_bank {
        let given = operands.len();
        if given > 1 && out.motor != bank {
            return Err(Refused::Table {
                operand: spec.operands[..given]
                    .iter()
                    .position(|o| o.kind.field() == Field::Motor),
                error: InputError::BankMismatch {
                    ident,
                    bank,
                    given: out.motor,
                },
            });
        }
        out.motor = bank;
    }
    Ok(out)
}

/// Refuses too few or too many operands. A global parameter given by name implies its bank,
/// which may then be left out.
fn check_count<O: OperandText>(spec: &CommandSpec, operands: &[O]) -> Result<(), InputError> {
    let given = operands.len();
    let bank_implied = spec
        .operands
        .first()
        .is_some_and(|o| o.kind == OperandKind::GlobalParam)
        && operands.first().is_some_and(|o| o.table_name().is_some());
    let required = spec
        .required_operands()
        .saturating_sub(usize::from(bank_implied && given == 1));
    if given >= required && given <= spec.operands.len() {
        return Ok(());
    }
    let expected = if required == spec.operands.len() {
        count_text(required)
    } else {
        format!("{} to {}", required, count_text(spec.operands.len()))
    };
    Err(InputError::ArgumentCount {
        mnemonic: spec.display_name(),
        expected,
        got: given,
        usage: spec.usage(),
    })
}

/// Puts one operand of `kind` into `out`; a global parameter given by name returns its
/// identifier and bank.
fn fill<O: OperandText>(
    spec: &CommandSpec,
    kind: OperandKind,
    operand: &O,
    profile: &Profile,
    out: &mut Instruction,
) -> Result<Option<(String, u8)>, Fault<O::Error>> {
    match (kind, operand.table_name()) {
        (OperandKind::Keyword, table_name) if !spec.keywords.is_empty() => {
            if let Some(keyword) = operand.name().and_then(|n| spec.keyword(n)) {
                out.type_ = keyword.value;
                return Ok(None);
            }
            if let Some(word) = table_name {
                return Err(InputError::BadKeyword {
                    mnemonic: spec.display_name(),
                    word: word.to_string(),
                    allowed: spec.keywords.iter().map(|k| k.name.clone()).collect(),
                }
                .into());
            }
        }
        (OperandKind::AxisParam, Some(name)) => {
            out.type_ = profile.find_axis(name).map_err(InputError::from)?.number;
            return Ok(None);
        }
        (OperandKind::GlobalParam, Some(name)) => {
            let param = profile.find_global(name).map_err(InputError::from)?;
            out.type_ = param.number;
            return Ok(Some((param.ident.clone(), param.bank())));
        }
        _ => {}
    }
    let what = kind.noun();
    let number = operand
        .number(kind)
        .map_err(Fault::Operand)?
        .ok_or_else(|| InputError::ExpectedNumber {
            mnemonic: spec.display_name(),
            what: what.clone(),
            found: operand.name().unwrap_or_default().to_string(),
        })?;
    store(out, kind.field(), &what, number)?;
    Ok(None)
}

/// Puts `number` into `field` of `out`, refusing what does not fit; `what` names it.
pub fn store(
    out: &mut Instruction,
    field: Field,
    what: &str,
    number: Number,
) -> Result<(), InputError> {
    match field {
        Field::Type => out.type_ = byte(what, number.value)?,
        Field::Motor => out.motor = byte(what, number.value)?,
        Field::Value => out.value = word32(what, number.value, number.hex)?,
    }
    Ok(())
}

/// "no arguments", "1 argument", "3 arguments".
pub fn count_text(n: usize) -> String {
    match n {
        0 => "no arguments".into(),
        1 => "1 argument".into(),
        n => format!("{n} arguments"),
    }
}

/// A number for a byte field (type, motor/bank, command number).
pub fn byte(what: &str, value: i64) -> Result<u8, InputError> {
    u8::try_from(value).map_err(|_| InputError::FieldOverflow {
        what: what.into(),
        value,
        lo: 0,
        hi: 255,
    })
}

/// A 32-bit value; a number written in hex may use the unsigned range (`0xFFFFFFFF` is -1).
pub fn word32(what: &str, value: i64, hex: bool) -> Result<i32, InputError> {
    if let Ok(v) = i32::try_from(value) {
        return Ok(v);
    }
    if hex && (0..=u32::MAX as i64).contains(&value) {
        return Ok(value as u32 as i32);
    }
    Err(InputError::FieldOverflow {
        what: what.into(),
        value,
        lo: i32::MIN as i64,
        hi: i32::MAX as i64,
    })
}

#[cfg(test)]
mod tests;
