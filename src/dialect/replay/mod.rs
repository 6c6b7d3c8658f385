//! Transcripts turned into scripts, the part every dialect shares: reading a `--log` transcript
//! back ([`parse`]), telling what it is a transcript of ([`recognise`]), and the pieces each
//! dialect's replay builds its Rhai script from. The replays themselves live with their dialects.

mod header;
pub mod parse;
mod recognise;

use std::fmt::Write as _;

use crate::exit::{Exit, ExitStatus};

pub use header::HeaderError;
use parse::{Entry, Record};
pub use recognise::{Recognised, recognise};

/// The bytes of the reply to the line just sent: the next received bytes the session took as a
/// reply, before anything else is sent. `None` when the session noted that none came.
pub fn reply_after(rest: &[Entry]) -> Option<&[u8]> {
    for entry in rest {
        match &entry.record {
            Record::Sent(_) => return None,
            Record::Received { bytes, meaning }
                if !meaning.contains("discarded") && !meaning.contains("no reply") =>
            {
                return Some(bytes);
            }
            Record::Note(note) if note.starts_with("no reply") => return None,
            Record::Header(_) => return None, // another session starts
            _ => {}
        }
    }
    None
}

/// Text for a `//` comment, on one line whatever it holds: a transcript's bytes may carry CR,
/// LF or other line breaks, and after one of them the rest would be script code. Control
/// characters and Unicode line separators are written as escapes instead.
pub fn comment(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() || matches!(c, '\u{2028}' | '\u{2029}') {
            let _ = write!(out, "\\u{{{:x}}}", c as u32);
        } else {
            out.push(c);
        }
    }
    out
}

/// A Rhai string literal.
pub fn rhai_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 || c == '\u{7f}' => {
                let _ = write!(out, "\\x{:02x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Why a transcript replays nothing: each a refusal (exit 2), the file being read but not
/// replayable as it is.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ReplayError {
    /// Sessions with different modules in one file, or (TMCL) a bus of different modules: one
    /// script checks every line against one set of tables. Says which, and what to do.
    #[error("{0}")]
    Mixed(String),
    /// A transcript of another module than the tables in use. Says which, and what to give.
    #[error("{0}")]
    OtherModule(String),
    /// No exchange in it that a script could replay.
    #[error(
        "no {dialect} exchange to replay: no command in it got a reply that could be read \
         (a transcript of another dialect, or of a session that only failed?)"
    )]
    Nothing {
        /// The dialect the transcript was read as (`TMCL`, `SMD4`).
        dialect: &'static str,
    },
}

impl ExitStatus for ReplayError {
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}
