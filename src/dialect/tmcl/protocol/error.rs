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
        /// The operand (`the motor`).
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
    #[error("{}", param_text(.0))]
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
    /// A write or store of global parameter 67 (ASCII start bit, echo) on a module without the
    /// ASCII interface: a module that keeps bit 0 would start in a mode it lacks.
    #[error(
        "the {module} has no ASCII interface: global parameter 67 (start in ASCII mode, echo) is \
         not its own, and a module that kept it could start in a mode it lacks and be locked out \
         of binary frames; not sent"
    )]
    NoAsciiStartBit {
        /// The module type.
        module: String,
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
        in_parentheses(unit)
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
    /// A command of the TMCL table this module does not have (profile `[commands] absent`).
    #[error("{mnemonic} ({number}) is not a command of the {module}; its profile says: {reason}")]
    AbsentCommand {
        /// The command as typed.
        mnemonic: String,
        /// Its number.
        number: u8,
        /// Module name.
        module: String,
        /// Why, as the profile says.
        reason: String,
    },
    /// A bank the command does not accept on this module (STGP/RSGP: user variables only).
    #[error(
        "{mnemonic} accepts bank {accepted}, not bank {bank}{}",
        in_parentheses(note)
    )]
    BankNotAccepted {
        /// The command.
        mnemonic: String,
        /// The bank typed.
        bank: u8,
        /// The banks it accepts, and where: "2 only on the TMCM-142".
        accepted: String,
        /// The profile's note on why.
        note: String,
    },
    /// An I/O address the module's map does not have.
    #[error("the {module} has no I/O port {port} in bank {bank}; it has {known}")]
    BadPort {
        /// Port typed.
        port: u8,
        /// Bank typed.
        bank: u8,
        /// Module name.
        module: String,
        /// The ports it has, by bank.
        known: String,
    },
    /// A port number no bank of the module's map has.
    #[error("the {module} has no I/O port {port} in any bank; it has {known}")]
    NoSuchPort {
        /// Port typed.
        port: u8,
        /// Module name.
        module: String,
        /// The ports it has, by bank.
        known: String,
    },
    /// A write to an I/O port that is not an output.
    #[error("{mnemonic} sets outputs ({outputs}); port {port} of bank {bank} is {name}, an input")]
    NotAnOutput {
        /// The command.
        mnemonic: String,
        /// Port typed.
        port: u8,
        /// Bank typed.
        bank: u8,
        /// The port's name.
        name: String,
        /// The output ports.
        outputs: String,
    },
}

fn param_text(error: &LookupError) -> String {
    match error {
        LookupError::NumbersOnly { .. } => error.to_string(),
        _ => format!("{error}; list them with :params or `tmclsh params`"),
    }
}

/// ` (text)`, or nothing for no text: a note or unit after a message.
fn in_parentheses(text: &str) -> String {
    if text.is_empty() {
        String::new()
    } else {
        format!(" ({text})")
    }
}

fn plural(n: u8, word: &str) -> String {
    match n {
        1 => format!("one {word}"),
        n => format!("{n} {word}s"),
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
    /// A value valid in the usual range, outside a conditional one.
    #[error("{0}")]
    ConditionalRange(ConditionalRange),
}

/// A value outside one of its ranges that lies in another (`range_when`): sent, with this notice.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "{what}: {value} is outside {outside}; sent, as it lies in {valid} (which applies depends \
     on a setting only the module knows)"
)]
pub struct ConditionalRange {
    /// What the value is for.
    pub what: String,
    /// The value typed.
    pub value: i64,
    /// The range it misses ("0..31999999 usteps/s when axis parameter 255 = 1").
    pub outside: String,
    /// The range it lies in.
    pub valid: String,
}

fn bank_text(bank: Option<u8>) -> String {
    bank.map(|b| format!(" in bank {b}")).unwrap_or_default()
}
