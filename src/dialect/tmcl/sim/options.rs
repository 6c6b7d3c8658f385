//! Behaviour the manual leaves open, switchable so the simulator can match a particular module
//! or host program. The defaults are tmclsh's best reading of the manual.

use std::fmt;
use std::str::FromStr;

/// Choices the manual does not settle.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Quirks {
    /// 139 (enter ASCII mode) sends a binary reply before switching. Default: yes.
    pub reply_to_139: bool,
    /// BIN sends an ASCII reply before switching back to binary. Default: yes.
    pub reply_to_bin: bool,
    /// Ending of ASCII reply lines. Default: CR (manual §6.6.2).
    pub reply_end: LineEnd,
    /// What follows an echoed line: in character echo mode it stands for the typed CR, in line
    /// echo mode it ends the echoed line. Default: CR.
    pub echo_end: LineEnd,
    /// How a backspace is echoed in character echo mode. Default: erase (BS, space, BS).
    pub backspace: Backspace,
    /// 139 enters ASCII mode where the profile has the command. Off: every module answers 139
    /// with invalid command, as one without the interface does (the TMCM-3110's is unconfirmed).
    pub ascii: bool,
}

impl Default for Quirks {
    fn default() -> Self {
        Quirks {
            reply_to_139: true,
            reply_to_bin: true,
            reply_end: LineEnd::Cr,
            echo_end: LineEnd::Cr,
            backspace: Backspace::Erase,
            ascii: true,
        }
    }
}

/// A line ending.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineEnd {
    /// Nothing.
    None,
    /// Carriage return.
    Cr,
    /// Line feed.
    Lf,
    /// Carriage return and line feed.
    CrLf,
}

impl LineEnd {
    /// The bytes sent.
    pub fn bytes(self) -> &'static [u8] {
        match self {
            LineEnd::None => b"",
            LineEnd::Cr => b"\r",
            LineEnd::Lf => b"\n",
            LineEnd::CrLf => b"\r\n",
        }
    }
}

impl FromStr for LineEnd {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "none" => Ok(LineEnd::None),
            "cr" => Ok(LineEnd::Cr),
            "lf" => Ok(LineEnd::Lf),
            "crlf" => Ok(LineEnd::CrLf),
            _ => Err(format!(
                "'{s}' is not a line ending; use none, cr, lf or crlf"
            )),
        }
    }
}

impl fmt::Display for LineEnd {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = match self {
            LineEnd::None => "none",
            LineEnd::Cr => "cr",
            LineEnd::Lf => "lf",
            LineEnd::CrLf => "crlf",
        };
        f.write_str(name)
    }
}

/// Echo of a backspace in character echo mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Backspace {
    /// BS, space, BS: the character disappears from a terminal.
    Erase,
    /// The BS alone.
    Plain,
}

impl Backspace {
    /// The bytes echoed.
    pub fn bytes(self) -> &'static [u8] {
        match self {
            Backspace::Erase => b"\x08 \x08",
            Backspace::Plain => b"\x08",
        }
    }
}

impl FromStr for Backspace {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "erase" => Ok(Backspace::Erase),
            "plain" | "bs" => Ok(Backspace::Plain),
            _ => Err(format!("'{s}' is not a backspace echo; use erase or plain")),
        }
    }
}
