//! The error codes a drive puts in a reply instead of data, with their meanings from the data.

use super::Smd4Spec;

/// An error code from a reply; codes the document does not list are kept as [`ErrorCode::Other`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorCode {
    /// −1: the command needs the motor stopped (standby) first.
    StopMotorFirst,
    /// −2: an argument value is not acceptable.
    ArgumentValidation,
    /// −3: the command cannot be read.
    UnableToGet,
    /// −5: internal failure (e.g. settings flash worn out).
    ActionFailed,
    /// −6: not possible in the current operating mode.
    NotPossibleInMode,
    /// −7: motion refused while the motor is disabled.
    MotorDisabled,
    /// −101: argument of the wrong type.
    ArgumentType,
    /// −102: wrong number of arguments.
    ArgumentCount,
    /// −103: unknown mnemonic.
    InvalidMnemonic,
    /// −104: malformed packet.
    PacketError,
    /// Any other code.
    Other(i32),
}

impl ErrorCode {
    /// The code for a number.
    pub fn from_code(code: i32) -> ErrorCode {
        match code {
            -1 => ErrorCode::StopMotorFirst,
            -2 => ErrorCode::ArgumentValidation,
            -3 => ErrorCode::UnableToGet,
            -5 => ErrorCode::ActionFailed,
            -6 => ErrorCode::NotPossibleInMode,
            -7 => ErrorCode::MotorDisabled,
            -101 => ErrorCode::ArgumentType,
            -102 => ErrorCode::ArgumentCount,
            -103 => ErrorCode::InvalidMnemonic,
            -104 => ErrorCode::PacketError,
            other => ErrorCode::Other(other),
        }
    }

    /// The number.
    pub fn code(self) -> i32 {
        match self {
            ErrorCode::StopMotorFirst => -1,
            ErrorCode::ArgumentValidation => -2,
            ErrorCode::UnableToGet => -3,
            ErrorCode::ActionFailed => -5,
            ErrorCode::NotPossibleInMode => -6,
            ErrorCode::MotorDisabled => -7,
            ErrorCode::ArgumentType => -101,
            ErrorCode::ArgumentCount => -102,
            ErrorCode::InvalidMnemonic => -103,
            ErrorCode::PacketError => -104,
            ErrorCode::Other(code) => code,
        }
    }

    /// Whether the document lists this code.
    pub fn is_known(self) -> bool {
        !matches!(self, ErrorCode::Other(_))
    }

    /// The short name printed in the error table (`Invalid Mnemonic`).
    pub fn name(self) -> String {
        Smd4Spec::builtin()
            .error_info(self.code())
            .map(|e| e.name.clone())
            .unwrap_or_else(|| "Unknown error".into())
    }

    /// What it means, one sentence.
    pub fn meaning(self) -> String {
        Smd4Spec::builtin()
            .error_info(self.code())
            .map(|e| e.meaning.clone())
            .unwrap_or_else(|| "Not listed in the SMD4 documentation.".into())
    }
}

/// One row of the error table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ErrorInfo {
    /// The number.
    pub code: i32,
    /// Short name.
    pub name: String,
    /// One sentence.
    pub meaning: String,
}

/// An error code a drive answered with: the reply's error item, decoded.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{} ({}){}", code.code(), text.clone().unwrap_or_else(|| code.name()), meaning_suffix(*code))]
pub struct DeviceError {
    /// The code.
    pub code: ErrorCode,
    /// The text the drive sent with it, if any.
    pub text: Option<String>,
}

fn meaning_suffix(code: ErrorCode) -> String {
    format!(": {}", code.meaning())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exit::{Exit, ExitStatus};

    #[test]
    fn codes_round_trip_and_have_names_from_the_data() {
        for code in [-1, -2, -3, -5, -6, -7, -101, -102, -103, -104] {
            let e = ErrorCode::from_code(code);
            assert!(e.is_known());
            assert_eq!(e.code(), code);
            assert!(!e.meaning().is_empty());
        }
        assert_eq!(ErrorCode::from_code(-103).name(), "Invalid Mnemonic");
        assert_eq!(ErrorCode::from_code(-4), ErrorCode::Other(-4));
        assert_eq!(ErrorCode::Other(-4).name(), "Unknown error");
    }

    #[test]
    fn device_error_message_and_exit() {
        let e = DeviceError {
            code: ErrorCode::StopMotorFirst,
            text: None,
        };
        assert!(e.to_string().starts_with("-1 (Stop motor first): "), "{e}");
        assert_eq!(e.exit(), Exit::DeviceError);
    }
}
