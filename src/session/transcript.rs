//! The `--log` transcript: every byte sent and received, timestamped, escaped so the file stays
//! readable, with the decoded meaning after `;`. Each line is written with one call and flushed,
//! so a crash loses nothing.
//!
//! ```text
//! 2026-11-22T10:15:02.120Z tx "AGAP 1, 0\r" ; GAP 1, 0 to module A
//! 2026-11-22T10:15:02.123Z rx "AGAP 1, 0\rBA 100 -5000\r" ; A: 100 (successfully executed), value -5000
//! ```

use std::fmt::{Display, Write as _};
use std::fs::{File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// Direction or kind of a transcript line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Entry {
    /// Bytes sent to the module.
    Sent,
    /// Bytes received from the module.
    Received,
    /// A remark (mode changes, line noise, safety stops).
    Note,
}

impl Entry {
    fn tag(self) -> &'static str {
        match self {
            Entry::Sent => "tx",
            Entry::Received => "rx",
            Entry::Note => "--",
        }
    }
}

/// An open transcript file.
#[derive(Debug)]
pub struct Transcript {
    path: PathBuf,
    file: File,
    line: String,
}

impl Transcript {
    /// Opens `path` for appending (created if missing).
    pub fn open(path: &Path) -> io::Result<Self> {
        let file = OpenOptions::new().create(true).append(true).open(path)?;
        Ok(Transcript {
            path: path.to_path_buf(),
            file,
            line: String::with_capacity(128),
        })
    }

    /// The file written to.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Records bytes or a note with its meaning. Write errors are returned, not hidden.
    pub fn record(&mut self, entry: Entry, bytes: &[u8], meaning: impl Display) -> io::Result<()> {
        self.line.clear();
        // Writing into a String cannot fail.
        let _ = write!(
            self.line,
            "{} {} ",
            humantime::format_rfc3339_millis(SystemTime::now()),
            entry.tag()
        );
        if entry == Entry::Note {
            let _ = write!(self.line, "{meaning}");
        } else {
            escape_into(bytes, &mut self.line);
            let before = self.line.len();
            let _ = write!(self.line, " ; {meaning}");
            if self.line.len() == before + 3 {
                self.line.truncate(before); // no meaning
            }
        }
        self.line.push('\n');
        self.file.write_all(self.line.as_bytes())
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
        let mut t = Transcript::open(&path).unwrap();
        t.record(Entry::Sent, b"AGAP 1, 0\r", "GAP 1, 0 to module A")
            .unwrap();
        t.record(Entry::Received, b"BA 100 -5000\r", "A: 100")
            .unwrap();
        t.record(Entry::Note, b"", "entered ASCII mode").unwrap();
        drop(t);
        let mut again = Transcript::open(&path).unwrap();
        again.record(Entry::Note, b"", "second session").unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 4);
        assert!(
            lines[0].ends_with(" tx \"AGAP 1, 0\\r\" ; GAP 1, 0 to module A"),
            "{}",
            lines[0]
        );
        assert!(lines[1].contains(" rx \"BA 100 -5000\\r\" ; A: 100"));
        assert!(lines[2].ends_with(" -- entered ASCII mode"));
        assert!(lines[0].starts_with("20") && lines[0].as_bytes()[10] == b'T');
    }
}
