//! TMCL reply status codes (manual §6.2.1).

use std::fmt;

/// The status byte of a reply. Codes outside the manual's table keep their number.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Status {
    /// 100: successfully executed, no error.
    Ok,
    /// 101: command loaded into TMCL program EEPROM (download mode).
    Stored,
    /// 1: wrong checksum.
    WrongChecksum,
    /// 2: invalid command.
    InvalidCommand,
    /// 3: wrong type.
    WrongType,
    /// 4: invalid value.
    InvalidValue,
    /// 5: configuration EEPROM locked.
    EepromLocked,
    /// 6: command not available.
    NotAvailable,
    /// 128: second, delayed reply of command 138 (target position reached event; sibling manuals).
    PositionReachedEvent,
    /// Any other code.
    Other(u8),
}

impl Status {
    /// Decodes a status byte.
    pub fn from_code(code: u8) -> Status {
        match code {
            100 => Status::Ok,
            101 => Status::Stored,
            1 => Status::WrongChecksum,
            2 => Status::InvalidCommand,
            3 => Status::WrongType,
            4 => Status::InvalidValue,
            5 => Status::EepromLocked,
            6 => Status::NotAvailable,
            128 => Status::PositionReachedEvent,
            other => Status::Other(other),
        }
    }

    /// The status byte.
    pub fn code(self) -> u8 {
        match self {
            Status::Ok => 100,
            Status::Stored => 101,
            Status::WrongChecksum => 1,
            Status::InvalidCommand => 2,
            Status::WrongType => 3,
            Status::InvalidValue => 4,
            Status::EepromLocked => 5,
            Status::NotAvailable => 6,
            Status::PositionReachedEvent => 128,
            Status::Other(code) => code,
        }
    }

    /// Whether the command was executed (or stored) without error.
    pub fn is_success(self) -> bool {
        matches!(
            self,
            Status::Ok | Status::Stored | Status::PositionReachedEvent
        )
    }

    /// The manual's meaning of the code.
    pub fn meaning(self) -> &'static str {
        match self {
            Status::Ok => "successfully executed",
            Status::Stored => "command loaded into TMCL program memory",
            Status::WrongChecksum => "wrong checksum",
            Status::InvalidCommand => "invalid command",
            Status::WrongType => "wrong type",
            Status::InvalidValue => "invalid value",
            Status::EepromLocked => "configuration EEPROM locked",
            Status::NotAvailable => "command not available",
            Status::PositionReachedEvent => "target position reached (event)",
            Status::Other(_) => "unknown status",
        }
    }
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({})", self.code(), self.meaning())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_code_round_trips() {
        for code in 0..=255u8 {
            assert_eq!(Status::from_code(code).code(), code);
        }
    }

    #[test]
    fn known_codes_have_their_meaning() {
        assert_eq!(Status::from_code(100), Status::Ok);
        assert_eq!(Status::from_code(4).to_string(), "4 (invalid value)");
        assert_eq!(Status::from_code(77), Status::Other(77));
        assert!(Status::from_code(101).is_success());
        assert!(!Status::from_code(2).is_success());
    }
}
