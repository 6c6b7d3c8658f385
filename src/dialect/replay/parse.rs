//! Reading a `--log` transcript back: `<time> tx|rx "<escaped bytes>" ; <meaning>` and
//! `<time> -- <note>` lines (the format of [`crate::session::transcript`]).

use crate::session::transcript::{self, Header, unescape};

use super::header::HeaderError;

/// One transcript line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Record {
    /// Bytes sent to the bus.
    Sent(Vec<u8>),
    /// Bytes received, with the session's reading of them.
    Received {
        /// The bytes.
        bytes: Vec<u8>,
        /// What the session made of them ("A: 100 (…), value 5", "… discarded").
        meaning: String,
    },
    /// A remark (mode changes, timeouts, session start and end).
    Note(String),
    /// The start of a session's part of the file: what it is a transcript of.
    Header(Header),
}

/// A transcript line with its place in the file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry {
    /// Line number, from 1.
    pub line: usize,
    /// The time stamp as written.
    pub time: String,
    /// What the line says.
    pub record: Record,
}

/// Parses a whole transcript; blank lines are skipped, anything else malformed is an error that
/// names the line — except an unfinished last line, which a full disk cuts short: it is left out.
pub fn parse(text: &str) -> Result<Vec<Entry>, ParseError> {
    let mut entries = Vec::new();
    let count = text.lines().count();
    for (i, raw) in text.lines().enumerate() {
        match parse_line(i + 1, raw) {
            Ok(Some(entry)) => entries.push(entry),
            Ok(None) => {}
            Err(_) if i + 1 == count && !text.ends_with('\n') && cut_short(raw) => break,
            Err(e) => return Err(e),
        }
    }
    Ok(entries)
}

/// Whether a malformed last line is a transcript line cut short: its time stamp and tag are there,
/// or it is the start of a time stamp.
fn cut_short(raw: &str) -> bool {
    if !raw.contains(' ')
        && raw
            .chars()
            .all(|c| c.is_ascii_digit() || "-T:.Z".contains(c))
    {
        return true;
    }
    let tag = raw.split(' ').nth(1).unwrap_or("");
    ["tx", "rx", "--", transcript::HEADER_TAG].contains(&tag)
}

/// One line: `None` when blank.
fn parse_line(line: usize, raw: &str) -> Result<Option<Entry>, ParseError> {
    if raw.trim().is_empty() {
        return Ok(None);
    }
    let bad = |what| ParseError::Line {
        line,
        what,
        excerpt: excerpt(raw),
    };
    let (time, rest) = raw.split_once(' ').ok_or_else(|| bad("no time stamp"))?;
    let (tag, rest) = rest.split_once(' ').unwrap_or((rest, ""));
    let record = match tag {
        "--" => Record::Note(rest.to_string()),
        transcript::HEADER_TAG => {
            Record::Header(Header::parse(rest).map_err(|why| ParseError::Header { line, why })?)
        }
        "tx" | "rx" => {
            let (quoted, meaning) = split_quoted(rest).ok_or_else(|| bad("no quoted bytes"))?;
            let bytes = unescape(quoted).ok_or_else(|| bad("bad escape in the bytes"))?;
            if tag == "tx" {
                Record::Sent(bytes)
            } else {
                Record::Received {
                    bytes,
                    meaning: meaning.to_string(),
                }
            }
        }
        _ => return Err(bad("not a transcript line (tx, rx, -- or ##)")),
    };
    Ok(Some(Entry {
        line,
        time: time.to_string(),
        record,
    }))
}

/// Why a transcript's text cannot be read back: the line, and what is wrong with it.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ParseError {
    /// A line that is no transcript line, and its start.
    #[error("line {line}: {what}: {excerpt}")]
    Line {
        /// The line, from 1.
        line: usize,
        /// What is missing or wrong.
        what: &'static str,
        /// The line's start, escaped.
        excerpt: String,
    },
    /// A header line that cannot be read.
    #[error("line {line}: {why}")]
    Header {
        /// The line, from 1.
        line: usize,
        /// Why.
        why: HeaderError,
    },
}

/// The start of a line for a message: escaped, and cut short (the file may be anything).
fn excerpt(raw: &str) -> String {
    const SHOWN: usize = 60;
    let cut = raw.char_indices().nth(SHOWN).map_or(raw.len(), |(i, _)| i);
    let mut text = String::new();
    transcript::escape_into(&raw.as_bytes()[..cut], &mut text);
    if cut < raw.len() {
        text.push_str(" …");
    }
    text
}

/// Splits `"…" ; meaning` into the quoted part (with its quotes) and the meaning.
fn split_quoted(text: &str) -> Option<(&str, &str)> {
    let (quoted, rest) = transcript::split_quoted(text)?;
    let meaning = rest
        .trim_start()
        .strip_prefix(';')
        .map(str::trim)
        .unwrap_or("");
    Some((quoted, meaning))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sent_received_and_notes_are_read_with_their_bytes_and_meaning() {
        let text = "2026-01-01T00:00:00.000Z -- session opened on simulator\n\
                    2026-01-01T00:00:00.001Z tx \"AGAP 1, 0\\r\" ; to module 1 (A)\n\
                    \n\
                    2026-01-01T00:00:00.002Z rx \"AGAP 1, 0\\rBA 100 -5\\r\" ; A: 100 (ok), value -5\n\
                    2026-01-01T00:00:00.003Z tx \"\\x01\\x8B\\\"\\x00\"\n";
        let entries = parse(text).unwrap();
        assert_eq!(entries.len(), 4);
        assert_eq!(
            entries[0].record,
            Record::Note("session opened on simulator".into())
        );
        assert_eq!(entries[1].record, Record::Sent(b"AGAP 1, 0\r".to_vec()));
        assert_eq!(
            entries[2].record,
            Record::Received {
                bytes: b"AGAP 1, 0\rBA 100 -5\r".to_vec(),
                meaning: "A: 100 (ok), value -5".into()
            }
        );
        assert_eq!(entries[2].line, 4);
        assert_eq!(entries[3].record, Record::Sent(vec![1, 0x8B, b'"', 0]));
    }

    #[test]
    fn a_quote_inside_the_meaning_does_not_end_the_bytes_early() {
        let (quoted, meaning) = split_quoted("\"a\\\"b\" ; says \"hi\"").unwrap();
        assert_eq!(quoted, "\"a\\\"b\"");
        assert_eq!(meaning, "says \"hi\"");
    }

    #[test]
    fn malformed_lines_are_refused_with_their_number() {
        assert_eq!(
            parse("x\n").unwrap_err().to_string(),
            "line 1: no time stamp: \"x\""
        );
        // A last line cut inside its time stamp by a full disk is left out.
        let cut = "2026-01-01T00:00:00.000Z -- session opened\n2026-01-01T00:00:0";
        assert_eq!(parse(cut).unwrap().len(), 1);
        assert!(parse("2026-01-01T00:00:00.000Z -- a\nx").is_err());
        assert_eq!(parse("t -- a\nt tx \"AG").unwrap().len(), 1, "cut short");
        assert!(parse("t tx \"AG\nt -- a\n").is_err());
        assert!(parse("t tx \"AG\n").is_err(), "a whole line");
        let error = parse("t -- ok\nt zz \"a\"\n").unwrap_err().to_string();
        assert!(
            error.starts_with("line 2: not a transcript line"),
            "{error}"
        );
        let long = format!("t zz \x1b[2J{}", "x".repeat(10_000));
        let error = parse(&long).unwrap_err().to_string();
        assert!(error.len() < 200 && error.contains("\\x1B[2J"), "{error}");
        let error = parse("t ## tmclsh transcript: dialect \"x\", module \"y\"\n")
            .unwrap_err()
            .to_string();
        assert!(
            error.starts_with("line 1: a header naming the unknown dialect 'x'"),
            "{error}"
        );
        assert!(
            parse("t tx \"\\q\"\n")
                .unwrap_err()
                .to_string()
                .contains("bad escape")
        );
        assert!(
            parse("t tx unquoted\n")
                .unwrap_err()
                .to_string()
                .contains("no quoted bytes")
        );
    }
}
