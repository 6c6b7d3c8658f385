//! Why a command line is refused before anything is sent. Every message says what is wrong and,
//! where there is one, what to do instead.

use crate::dialect::tmcl::profile::LookupError;
use crate::suggest::did_you_mean;

use super::syntax::SyntaxError;

/// A line refused by the grammar, the command table or the validator (exit code 2).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum InputError {
    /// The line does not follow the grammar.
    #[error("{0}")]
    Syntax(#[from] SyntaxError),
    /// No command has this name.
    #[error("unknown command '{word}'{}", did_you_mean(suggestion))]
    UnknownCommand {
        /// What was typed.
        word: String,
        /// The nearest mnemonic.
        suggestion: Option<String>,
    },
    /// No command has this number.
    #[error("command {number} is not supported by the {module}")]
    UnknownCommandNumber {
        /// The number typed.
        number: u8,
        /// Module name.
        module: String,
    },
    /// Too few or too many arguments.
    #[error("{mnemonic} takes {expected}, got {got}; usage: {usage}")]
    ArgumentCount {
        /// The command.
        mnemonic: String,
        /// "2 arguments", "1 to 2 arguments".
        expected: String,
        /// How many were given.
        got: usize,
        /// The usage line.
        usage: String,
    },
    /// A keyword the command does not have.
    #[error("'{word}' is not a keyword of {mnemonic}; use {}", allowed.join(", "))]
    BadKeyword {
        /// The command.
        mnemonic: String,
        /// What was typed.
        word: String,
        /// The keywords it has.
        allowed: Vec<String>,
    },
    /// A name where only a number is possible.
    #[error("{what} of {mnemonic} must be a number, not '{found}'")]
    ExpectedNumber {
        /// The command.
        mnemonic: String,
        /// The operand (`<motor>`).
        what: String,
        /// What was typed.
        found: String,
    },
    /// A number that does not fit its field.
    #[error("{what} {value} does not fit: it must lie in {lo}..{hi}")]
    FieldOverflow {
        /// The operand.
        what: String,
        /// The number typed.
        value: i64,
        /// Lowest encodable value.
        lo: i64,
        /// Highest encodable value.
        hi: i64,
    },
    /// A parameter name that does not resolve.
    #[error("{0}; list them with :params or `tmclsh params`")]
    Param(#[from] LookupError),
    /// A global parameter named with the wrong bank.
    #[error("global parameter '{ident}' is in bank {bank}, not bank {given}")]
    BankMismatch {
        /// The parameter.
        ident: String,
        /// Its bank.
        bank: u8,
        /// The bank typed.
        given: u8,
    },
    /// A command the current mode does not accept.
    #[error("{message}")]
    NotInMode {
        /// The command.
        mnemonic: String,
        /// Why, and what to do.
        message: String,
    },
    /// A motor the module does not have.
    #[error("motor {motor} does not exist: the {module} has {} (0..{})", plural(*axes, "motor"), axes.saturating_sub(1))]
    BadMotor {
        /// The motor typed.
        motor: u8,
        /// Module name.
        module: String,
        /// Number of motors.
        axes: u8,
    },
    /// A write to a parameter that is read-only.
    #[error("{kind} parameter {number} ({ident}) is read-only; use {read} to read it")]
    ReadOnly {
        /// "axis" or "global".
        kind: &'static str,
        /// Number.
        number: u8,
        /// Identifier.
        ident: String,
        /// The command line that reads it.
        read: String,
    },
    /// A read of a parameter that cannot be read.
    #[error("{kind} parameter {number} ({ident}) cannot be read")]
    NotReadable {
        /// "axis" or "global".
        kind: &'static str,
        /// Number.
        number: u8,
        /// Identifier.
        ident: String,
    },
    /// A store or restore of a parameter without EEPROM backing.
    #[error(
        "{kind} parameter {number} ({ident}) is not stored in EEPROM, so {mnemonic} does not apply to it"
    )]
    NotStorable {
        /// "axis" or "global".
        kind: &'static str,
        /// Number.
        number: u8,
        /// Identifier.
        ident: String,
        /// The command.
        mnemonic: String,
    },
    /// A value outside the documented range.
    #[error(
        "{value} is out of range for {what}: allowed {lo}..{hi}{}",
        unit_suffix(unit)
    )]
    OutOfRange {
        /// What the value is for.
        what: String,
        /// The value typed.
        value: i64,
        /// Lowest allowed.
        lo: i64,
        /// Highest allowed.
        hi: i64,
        /// Unit, if any.
        unit: String,
    },
}

fn plural(n: u8, word: &str) -> String {
    match n {
        1 => format!("one {word}"),
        n => format!("{n} {word}s"),
    }
}

fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" ({unit})")
    }
}

/// Something worth telling the user about a line that is still sent.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Warning {
    /// A parameter number the profile does not list (the tables are incomplete).
    #[error("{kind} parameter {number}{} is not in the {module} profile; sending it anyway", bank_text(*bank))]
    UnknownParam {
        /// "axis" or "global".
        kind: &'static str,
        /// Number typed.
        number: u8,
        /// Bank, for global parameters.
        bank: Option<u8>,
        /// Module name.
        module: String,
    },
}

fn bank_text(bank: Option<u8>) -> String {
    bank.map(|b| format!(" in bank {b}")).unwrap_or_default()
}
