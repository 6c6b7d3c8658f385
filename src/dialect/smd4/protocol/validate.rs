//! Checks a request against the command table before it is sent, so that mistakes a drive would
//! answer with −103, −3, −102, −101 or −2 are refused locally with a message that says what to do
//! (exit code 2). What only the drive can know (standby, mode, latched errors) is left to it.

use crate::suggest::did_you_mean;

use super::commands::{ArgProblem, Smd4Command, Smd4CommandTable};
use super::hints::usage;
use super::request::Request;
use super::types::{ArgValue, ItemType};

/// Highest drive address on a bus.
pub const MAX_ADDRESS: u32 = 247;

/// What a valid request does.
#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// Reads the value.
    Read,
    /// Writes this value (or starts motion with it).
    Write(ArgValue),
    /// Runs an action that takes no argument.
    Run,
}

/// A request that passed validation.
#[derive(Debug, Clone, PartialEq)]
pub struct Checked<'a> {
    /// Its command.
    pub spec: &'a Smd4Command,
    /// What it does.
    pub action: Action,
}

/// Why a request is refused before sending.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ValidationError {
    /// No command has this mnemonic (the drive would answer −103).
    #[error("unknown mnemonic '{word}'{}", did_you_mean(suggestion))]
    UnknownMnemonic {
        /// What was typed.
        word: String,
        /// The nearest mnemonic.
        suggestion: Option<String>,
    },
    /// A read of a write-only command (−3).
    #[error(
        "{mnemonic} cannot be read (the drive answers -3): it needs an argument; usage: {usage}"
    )]
    NotReadable {
        /// The command.
        mnemonic: String,
        /// How to write it.
        usage: String,
    },
    /// A write to a read-only command.
    #[error("{mnemonic} is read-only; send {mnemonic} without arguments to read it")]
    NotWritable {
        /// The command.
        mnemonic: String,
    },
    /// Too many arguments (−102).
    #[error("{mnemonic} takes {expected}, got {got}; usage: {usage}")]
    ArgumentCount {
        /// The command.
        mnemonic: String,
        /// "no arguments" or "one argument".
        expected: &'static str,
        /// How many were given.
        got: usize,
        /// Usage line.
        usage: String,
    },
    /// An argument of the wrong type (−101).
    #[error(
        "{}: expected {}, {}; usage: {usage}",
        match found.as_str() {
            "" => format!("the argument of {mnemonic} is empty"),
            found => format!("'{found}' is not a valid argument of {mnemonic}"),
        },
        expected.name(),
        expected.describe()
    )]
    ArgumentType {
        /// The command.
        mnemonic: String,
        /// What was typed.
        found: String,
        /// The type it takes.
        expected: ItemType,
        /// Usage line.
        usage: String,
    },
    /// A value outside the range (−2).
    #[error(
        "{value} is out of range for {mnemonic}: allowed {range}{}",
        unit_suffix(unit)
    )]
    OutOfRange {
        /// The command.
        mnemonic: String,
        /// What was typed.
        value: String,
        /// `1..15000`.
        range: String,
        /// Unit, if any.
        unit: String,
    },
    /// A value not in the accepted set (−2).
    #[error("{value} is not accepted by {mnemonic}: use one of {allowed}")]
    NotAllowed {
        /// The command.
        mnemonic: String,
        /// What was typed.
        value: String,
        /// The accepted values, comma separated.
        allowed: String,
    },
    /// An address no drive can have.
    #[error("address {0} is out of range: use 0 to broadcast (no reply) or 1..247 for one drive")]
    BadAddress(u32),
}

fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}

/// Validates `request` against `table`.
pub fn validate<'a>(
    request: &Request,
    table: &'a Smd4CommandTable,
) -> Result<Checked<'a>, ValidationError> {
    if let Some(address) = request.address.filter(|a| *a > MAX_ADDRESS) {
        return Err(ValidationError::BadAddress(address));
    }
    let spec = table
        .get(&request.mnemonic)
        .ok_or_else(|| ValidationError::UnknownMnemonic {
            word: request.mnemonic.clone(),
            suggestion: table.suggest(&request.mnemonic),
        })?;
    let mnemonic = spec.mnemonic.clone();
    let count_error = |expected| ValidationError::ArgumentCount {
        mnemonic: mnemonic.clone(),
        expected,
        got: request.args.len(),
        usage: usage(spec),
    };
    let action = match (request.args.as_slice(), &spec.arg) {
        ([], Some(_)) if spec.readable => Action::Read,
        ([], Some(_)) => {
            return Err(ValidationError::NotReadable {
                mnemonic,
                usage: usage(spec),
            });
        }
        ([], None) if spec.readable => Action::Read,
        ([], None) => Action::Run,
        ([_, ..], None) if spec.readable && !spec.writable => {
            return Err(ValidationError::NotWritable { mnemonic });
        }
        ([_, ..], None) => return Err(count_error("no arguments")),
        ([text], Some(arg)) => match arg.check(text) {
            Ok(value) => Action::Write(value),
            Err(ArgProblem::Type) => {
                return Err(ValidationError::ArgumentType {
                    mnemonic,
                    found: text.clone(),
                    expected: arg.ty,
                    usage: usage(spec),
                });
            }
            Err(ArgProblem::NotAllowed) => {
                return Err(ValidationError::NotAllowed {
                    mnemonic,
                    value: text.clone(),
                    allowed: arg.choices_text(),
                });
            }
            Err(ArgProblem::OutOfRange) => {
                return Err(ValidationError::OutOfRange {
                    mnemonic,
                    value: text.clone(),
                    range: arg.range_text(),
                    unit: spec.unit.clone(),
                });
            }
        },
        (_, Some(_)) => return Err(count_error("one argument")),
    };
    Ok(Checked { spec, action })
}
