//! The `--log` transcript: every byte sent and received, timestamped, escaped so the file stays
//! readable, with the decoded meaning after `;`. Each line is written with one call and flushed,
//! so a crash loses nothing. Every session's part of the file starts with a header saying what
//! it is a transcript of, so it can be read back without guessing.
//!
//! ```text
//! 2026-11-22T10:15:02.118Z ## tmclsh transcript: dialect "tmcl", module "TMCM-142", profile "built-in", version "0.1.0"
//! 2026-11-22T10:15:02.120Z tx "AGAP 1, 0\r" ; GAP 1, 0 to module A
//! 2026-11-22T10:15:02.123Z rx "AGAP 1, 0\rBA 100 -5000\r" ; A: 100 (successfully executed), value -5000
//! ```
//!
//! A transcript that cannot be written (a full disk) stops recording at the first failed line and
//! says why ([`Transcript::failure`]); the faces decide what that means for the run.

use crate::file::{Follow, Mode};
use std::fmt::{Display, Write as _};
use std::fs::File;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

use crate::escape::escape_control;
use crate::exit::{Exit, ExitStatus};

mod header;

pub use header::{HEADER_TAG, HEADER_TITLE, Header, split_quoted};

/// Direction or kind of a transcript line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Entry {
    /// Bytes sent to the module.
    Sent,
    /// Bytes received from the module.
    Received,
    /// A remark (mode changes, line noise, safety stops).
    Note,
    /// The header that starts a session's part of the file.
    Header,
}

impl Entry {
    fn tag(self) -> &'static str {
        match self {
            Entry::Sent => "tx",
            Entry::Received => "rx",
            Entry::Note => "--",
            Entry::Header => HEADER_TAG,
        }
    }
}

/// Why a transcript could not be started.
#[derive(Debug, thiserror::Error)]
pub enum TranscriptError {
    /// The file could not be opened (a bad path, no permission, not a regular file): the
    /// request is refused.
    #[error("cannot open log file {0}")]
    Open(crate::file::FileError),
    /// The file opened, but its header could not be written (a full disk).
    #[error("cannot write the transcript {path}: {source}")]
    Write {
        /// The file.
        path: String,
        /// What the OS said.
        source: io::Error,
    },
}

impl ExitStatus for TranscriptError {
    fn exit(&self) -> Exit {
        match self {
            TranscriptError::Open(_) => Exit::Refused,
            TranscriptError::Write { .. } => Exit::Link,
        }
    }
}

/// An open transcript file.
#[derive(Debug)]
pub struct Transcript {
    path: PathBuf,
    file: File,
    line: String,
    /// Why writing failed; nothing more is written after that.
    failed: Option<String>,
}

impl Transcript {
    /// Opens `path` for appending (created if missing; a regular file, never a FIFO or a
    /// device) and writes the header of this session.
    pub fn open(path: &Path, header: &Header) -> Result<Self, TranscriptError> {
        let file =
            crate::file::open(path, Mode::Append, Follow::Yes).map_err(TranscriptError::Open)?;
        Transcript::start(path, file, header)
    }

    /// Creates `path`, which must not exist (a symlink in its place is not followed), and
    /// writes the header: a `--log` directory's new file.
    pub fn create_new(path: &Path, header: &Header) -> Result<Self, TranscriptError> {
        let file =
            crate::file::open(path, Mode::CreateNew, Follow::No).map_err(TranscriptError::Open)?;
        Transcript::start(path, file, header)
    }

    fn start(path: &Path, file: File, header: &Header) -> Result<Self, TranscriptError> {
        let shown = || path.display().to_string();
        let mut transcript = Transcript {
            path: path.to_path_buf(),
            file,
            line: String::with_capacity(128),
            failed: None,
        };
        transcript
            .record(Entry::Header, b"", header.to_text())
            .map_err(|source| TranscriptError::Write {
                path: shown(),
                source,
            })?;
        Ok(transcript)
    }

    /// The file written to.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Why the transcript stopped being written, if it did: "cannot write the transcript FILE:
    /// No space left on device".
    pub fn failure(&self) -> Option<String> {
        let error = self.failed.as_ref()?;
        Some(format!(
            "cannot write the transcript {}: {error}",
            self.path.display()
        ))
    }

    /// Records bytes or a note with its meaning. The first write error is returned, not hidden;
    /// after it nothing more is written (a partly written line would make the file unreadable).
    pub fn record(&mut self, entry: Entry, bytes: &[u8], meaning: impl Display) -> io::Result<()> {
        if self.failed.is_some() {
            return Ok(());
        }
        self.line.clear();
        // Writing into a String cannot fail.
        let _ = write!(
            self.line,
            "{} {} ",
            humantime::format_rfc3339_millis(SystemTime::now()),
            entry.tag()
        );
        // A meaning may quote device text (a note on line noise, a module's name): escaped, so
        // `cat` of the file shows it and a line feed in it cannot forge a line of its own.
        let meaning = meaning.to_string();
        let meaning = escape_control(&meaning).replace('\n', "\\n");
        if matches!(entry, Entry::Note | Entry::Header) {
            self.line.push_str(&meaning);
        } else {
            escape_into(bytes, &mut self.line);
            if !meaning.is_empty() {
                self.line.push_str(" ; ");
                self.line.push_str(&meaning);
            }
        }
        self.line.push('\n');
        let written = self.file.write_all(self.line.as_bytes());
        if let Err(e) = &written {
            self.failed = Some(e.to_string());
        }
        written
    }
}

/// Bytes as a quoted string: printable ASCII as is, `\r` `\n` `\t` `\\` `\"`, others `\xNN`.
pub fn escape_into(bytes: &[u8], out: &mut String) {
    out.push('"');
    for &b in bytes {
        match b {
            b'\r' => out.push_str("\\r"),
            b'\n' => out.push_str("\\n"),
            b'\t' => out.push_str("\\t"),
            b'\\' => out.push_str("\\\\"),
            b'"' => out.push_str("\\\""),
            0x20..=0x7E => out.push(b as char),
            _ => out.push_str(&format!("\\x{b:02X}")),
        }
    }
    out.push('"');
}

/// The bytes of a quoted, escaped string (the inverse of [`escape_into`]).
pub fn unescape(quoted: &str) -> Option<Vec<u8>> {
    let inner = quoted.strip_prefix('"')?.strip_suffix('"')?;
    let mut out = Vec::with_capacity(inner.len());
    let mut chars = inner.bytes();
    while let Some(b) = chars.next() {
        if b != b'\\' {
            out.push(b);
            continue;
        }
        match chars.next()? {
            b'r' => out.push(b'\r'),
            b'n' => out.push(b'\n'),
            b't' => out.push(b'\t'),
            b'\\' => out.push(b'\\'),
            b'"' => out.push(b'"'),
            b'x' => {
                let hex = [chars.next()?, chars.next()?];
                out.push(u8::from_str_radix(std::str::from_utf8(&hex).ok()?, 16).ok()?);
            }
            _ => return None,
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::config::header as smd4_header;
    use crate::dialect::tmcl::config::header as tmcl_header;
    use crate::dialect::tmcl::profile::Profile;

    #[cfg(target_os = "linux")]
    #[test]
    fn a_transcript_is_a_regular_file() {
        let header = tmcl_header(&Profile::builtin());
        let error = Transcript::open(Path::new("/dev/full"), &header).unwrap_err();
        assert_eq!(error.exit(), Exit::Refused);
        assert_eq!(
            error.to_string(),
            "cannot open log file /dev/full: a character device, not a regular file"
        );
        let error = Transcript::open(Path::new("/nonexistent/dir/t.log"), &header).unwrap_err();
        assert_eq!(error.exit(), Exit::Refused);
    }

    #[test]
    fn device_text_in_a_meaning_reaches_the_file_escaped_on_its_line() {
        let dir = std::env::temp_dir().join(format!("tmclsh-noise-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("t.log");
        let _ = std::fs::remove_file(&path);
        let mut t = Transcript::open(&path, &tmcl_header(&Profile::builtin())).unwrap();
        let hostile = "line noise: 'B\x1b]0;owned\x07\x7f\u{9b}2J'\n2026 tx \"forged\"";
        t.record(Entry::Note, b"", hostile).unwrap();
        t.record(Entry::Received, b"\x1b[2J", hostile).unwrap();
        drop(t);
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(text.lines().count(), 3, "{text}");
        assert!(
            !text.chars().any(|c| c.is_control() && c != '\n'),
            "{text:?}"
        );
        assert!(
            text.contains("'B\\x1B]0;owned\\x07\\x7F\\u{9b}2J'\\n2026 tx"),
            "{text}"
        );
    }

    #[test]
    fn escaping_round_trips_every_byte() {
        let bytes: Vec<u8> = (0..=255).collect();
        let mut text = String::new();
        escape_into(&bytes, &mut text);
        assert!(text.is_ascii());
        assert!(!text[1..text.len() - 1].contains('"') || text.contains("\\\""));
        assert_eq!(unescape(&text).unwrap(), bytes);
    }

    #[test]
    fn lines_are_appended_with_time_direction_bytes_and_meaning() {
        let dir = std::env::temp_dir().join(format!("tmclsh-transcript-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("t.log");
        let _ = std::fs::remove_file(&path);
        let header = tmcl_header(&Profile::builtin());
        let mut t = Transcript::open(&path, &header).unwrap();
        t.record(Entry::Sent, b"AGAP 1, 0\r", "GAP 1, 0 to module A")
            .unwrap();
        t.record(Entry::Received, b"BA 100 -5000\r", "A: 100")
            .unwrap();
        t.record(Entry::Note, b"", "entered ASCII mode").unwrap();
        drop(t);
        let smd4 = smd4_header();
        let mut again = Transcript::open(&path, &smd4).unwrap();
        again.record(Entry::Note, b"", "second session").unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 6);
        assert!(
            lines[0].ends_with(&format!(
                " ## tmclsh transcript: dialect \"tmcl\", module \"TMCM-142\", profile \"built-in\", version \"{}\"",
                env!("CARGO_PKG_VERSION")
            )),
            "{}",
            lines[0]
        );
        assert!(
            lines[1].ends_with(" tx \"AGAP 1, 0\\r\" ; GAP 1, 0 to module A"),
            "{}",
            lines[1]
        );
        assert!(lines[2].contains(" rx \"BA 100 -5000\\r\" ; A: 100"));
        assert!(lines[3].ends_with(" -- entered ASCII mode"));
        assert!(
            lines[4].contains(" ## tmclsh transcript: dialect \"smd4\", module \"SMD4\", version")
        );
        assert!(lines[1].starts_with("20") && lines[1].as_bytes()[10] == b'T');
    }
}
