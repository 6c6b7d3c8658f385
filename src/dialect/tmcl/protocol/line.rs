//! Typed command lines: a parsed line resolved against the command table and the profile, and
//! formatted back to the one canonical line that is sent (`AGAP 1, 0`).

use crate::dialect::tmcl::profile::Profile;
use crate::suggest;

use super::error::InputError;
use super::instruction::Instruction;
use super::operands::{self, Number, OperandText, Refused};
use super::syntax::{Arg, RawLine, Word, parse_line};
use crate::dialect::tmcl::profile::commands::{AsciiWord, Field, Operand, OperandKind};

/// What a line asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op {
    /// A TMCL command.
    Command(Instruction),
    /// BIN, RUN or STOP (ASCII mode only).
    Ascii(AsciiWord),
}

/// A resolved command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Line {
    /// The module the line names with its address character, if it names one.
    pub address: Option<u8>,
    /// What to do.
    pub op: Op,
}

/// The ASCII address character of a module address (`1` → `A`), for addresses 1..=26.
pub fn address_char(address: u8) -> Option<char> {
    (1..=26)
        .contains(&address)
        .then(|| (b'A' + address - 1) as char)
}

/// The module address of an address character (`A`/`a` → 1).
pub fn address_of(c: char) -> Option<u8> {
    let upper = c.to_ascii_uppercase();
    upper.is_ascii_uppercase().then(|| upper as u8 - b'A' + 1)
}

/// Parses and resolves one line.
pub fn parse(text: &str, profile: &Profile) -> Result<Line, InputError> {
    let raw = parse_line(text, |w| profile.commands.is_word(w))?;
    resolve(&raw, profile)
}

/// Whether `text` reads as a TMCL command of the built-in table — a known mnemonic, ASCII word
/// or command number, with or without address character — whatever its operands (for
/// [`Dialect::recognises`](crate::dialect::Dialect::recognises)).
pub fn recognises(text: &str) -> bool {
    let profile = Profile::builtin();
    let commands = &profile.commands;
    match parse_line(text, |w| commands.is_word(w)) {
        Ok(RawLine {
            word: Word::Name(word),
            ..
        }) => commands.is_word(&word),
        Ok(RawLine {
            word: Word::Number(number),
            ..
        }) => commands.by_number(number).is_some(),
        Err(_) => false,
    }
}

/// Resolves names, keywords and operand order of a parsed line.
pub fn resolve(raw: &RawLine, profile: &Profile) -> Result<Line, InputError> {
    let address = raw.address.and_then(address_of);
    let spec = match &raw.word {
        Word::Name(word) => {
            if let Some(ascii) = profile.commands.ascii_word(word) {
                if !raw.args.is_empty() {
                    return Err(InputError::ArgumentCount {
                        mnemonic: word.clone(),
                        expected: "no arguments".into(),
                        got: raw.args.len(),
                        usage: word.clone(),
                    });
                }
                return Ok(Line {
                    address,
                    op: Op::Ascii(ascii),
                });
            }
            profile
                .commands
                .by_mnemonic(word)
                .ok_or_else(|| unknown_command(word, raw.address, profile))?
        }
        Word::Number(number) => match profile.commands.by_number(*number) {
            Some(spec) => spec,
            None => {
                return Err(InputError::UnknownCommandNumber {
                    number: *number,
                    module: profile.module.clone(),
                });
            }
        },
    };
    let instruction =
        operands::encode(spec, &raw.args, profile).map_err(Refused::into_input_error)?;
    Ok(Line {
        address,
        op: Op::Command(instruction),
    })
}

fn unknown_command(word: &str, address: Option<char>, profile: &Profile) -> InputError {
    // "AGAPP" may be a typo of GAP after address A, or of a whole mnemonic: try both readings.
    let typed = match address {
        Some(a) => format!("{a}{word}"),
        None => word.to_string(),
    };
    let readings = [typed.as_str(), typed.get(1..).unwrap_or_default()];
    // A command of the TMCL table this module lacks is named as such, not as a typo.
    if let Some((spec, reason)) = readings.iter().find_map(|r| profile.commands.absent(r)) {
        return InputError::AbsentCommand {
            mnemonic: spec.mnemonic.clone(),
            number: spec.number,
            module: profile.module.clone(),
            reason: reason.to_string(),
        };
    }
    let suggestion = suggest::nearest_of(&readings, profile.commands.words());
    InputError::UnknownCommand {
        word: typed,
        suggestion,
    }
}

impl OperandText for Arg {
    /// Typed text defines no names: every operand is a number or a name for the tables.
    type Error = std::convert::Infallible;

    fn name(&self) -> Option<&str> {
        match self {
            Arg::Name(name) => Some(name),
            Arg::Number { .. } => None,
        }
    }

    fn table_name(&self) -> Option<&str> {
        self.name()
    }

    fn number(&self, _: OperandKind) -> Result<Option<Number>, Self::Error> {
        Ok(match *self {
            Arg::Number { value, hex } => Some(Number { value, hex }),
            Arg::Name(_) => None,
        })
    }
}

/// The canonical form of an instruction, without address: `GAP 1, 0`, `MVP ABS, 0, 1000`,
/// `136 1` for control functions. Trailing optional operands that are 0 are left out.
pub fn format_instruction(instruction: &Instruction, profile: &Profile) -> String {
    let mut out = String::with_capacity(24);
    write_instruction(&mut out, instruction, profile);
    out
}

/// One operand as it is written: a keyword of the command or a number.
enum Written<'a> {
    Keyword(&'a str),
    Number(i64),
}

/// Appends the canonical form of `instruction` to `out` (one buffer, no intermediate strings:
/// every command a script sends is formatted here).
fn write_instruction(out: &mut String, instruction: &Instruction, profile: &Profile) {
    use std::fmt::Write as _;
    // Writing into a String cannot fail.
    let Some(spec) = profile.commands.by_number(instruction.command) else {
        let _ = write!(
            out,
            "{} {}, {}, {}",
            instruction.command.number(),
            instruction.type_,
            instruction.motor,
            instruction.value
        );
        return;
    };
    let written = |operand: &Operand| match operand.kind.field() {
        Field::Type => match spec.keyword_for(instruction.type_) {
            Some(k) if operand.kind == OperandKind::Keyword => Written::Keyword(&k.name),
            _ => Written::Number(instruction.type_.into()),
        },
        Field::Motor => Written::Number(instruction.motor.into()),
        Field::Value => Written::Number(instruction.value.into()),
    };
    let mut count = spec.operands.len();
    while let Some(last) = count.checked_sub(1).map(|i| &spec.operands[i]) {
        if last.optional && matches!(written(last), Written::Number(0)) {
            count -= 1;
        } else {
            break;
        }
    }
    // A mnemonic that is also an ASCII-only word (command 28 is STOP, which ASCII mode reads as
    // "stop the program") is written by number, so the line resolves to this command again.
    if spec.mnemonic.is_empty() || profile.commands.ascii_word(&spec.mnemonic).is_some() {
        let _ = write!(out, "{}", spec.number);
    } else {
        out.push_str(&spec.mnemonic);
    }
    for (i, operand) in spec.operands[..count].iter().enumerate() {
        out.push_str(if i == 0 { " " } else { ", " });
        let _ = match written(operand) {
            Written::Keyword(k) => write!(out, "{k}"),
            Written::Number(n) => write!(out, "{n}"),
        };
    }
}

/// The canonical line as sent: address character of `line.address` or of `target`, then the
/// command (`AGAP 1, 0`, `ABIN`).
pub fn format_line(line: &Line, target: u8, profile: &Profile) -> String {
    let address = address_char(line.address.unwrap_or(target)).unwrap_or('?');
    let mut out = String::with_capacity(24);
    out.push(address);
    match line.op {
        Op::Command(instruction) => write_instruction(&mut out, &instruction, profile),
        Op::Ascii(word) => out.push_str(word.as_str()),
    }
    out
}

/// A parsed line that does not resolve, in canonical spelling (for `--no-validate`).
pub fn format_raw(raw: &RawLine, target: u8) -> String {
    let address = raw.address.or_else(|| address_char(target)).unwrap_or('?');
    let word = match &raw.word {
        Word::Name(w) => w.clone(),
        Word::Number(n) => n.to_string(),
    };
    let args: Vec<String> = raw
        .args
        .iter()
        .map(|a| match a {
            Arg::Number { value, hex: true } if *value >= 0 => format!("0x{value:X}"),
            Arg::Number { value, .. } => value.to_string(),
            Arg::Name(n) => n.clone(),
        })
        .collect();
    if args.is_empty() {
        format!("{address}{word}")
    } else {
        format!("{address}{word} {}", args.join(", "))
    }
}

#[cfg(test)]
mod tests;
