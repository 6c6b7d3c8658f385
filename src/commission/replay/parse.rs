//! Reading a `--log` transcript back: `<time> tx|rx "<escaped bytes>" ; <meaning>` and
//! `<time> -- <note>` lines (the format of [`crate::session::transcript`]).

use crate::session::transcript::unescape;

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
/// names the line.
pub fn parse(text: &str) -> Result<Vec<Entry>, String> {
    let mut entries = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        if raw.trim().is_empty() {
            continue;
        }
        let bad = |what: &str| format!("line {line}: {what}: {raw}");
        let (time, rest) = raw.split_once(' ').ok_or_else(|| bad("no time stamp"))?;
        let (tag, rest) = rest.split_once(' ').unwrap_or((rest, ""));
        let record = match tag {
            "--" => Record::Note(rest.to_string()),
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
            _ => return Err(bad("not tx, rx or --")),
        };
        entries.push(Entry {
            line,
            time: time.to_string(),
            record,
        });
    }
    Ok(entries)
}

/// Splits `"…" ; meaning` into the quoted part (with its quotes) and the meaning.
fn split_quoted(text: &str) -> Option<(&str, &str)> {
    let bytes = text.as_bytes();
    if bytes.first() != Some(&b'"') {
        return None;
    }
    let mut i = 1;
    while i < bytes.len() {
        match bytes[i] {
            b'\\' => i += 2,
            b'"' => {
                let rest = text[i + 1..].trim_start();
                let meaning = rest.strip_prefix(';').map(str::trim).unwrap_or("");
                return Some((&text[..=i], meaning));
            }
            _ => i += 1,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sent_received_and_notes_are_read_with_their_bytes_and_meaning() {
        let text = "2026-01-01T00:00:00.000Z -- session opened on simulator\n\
                    2026-01-01T00:00:00.001Z tx \"AGAP 1, 0\\r\" ; to module A\n\
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
        assert_eq!(parse("x\n").unwrap_err(), "line 1: no time stamp: x");
        let error = parse("t -- ok\nt zz \"a\"\n").unwrap_err();
        assert!(error.starts_with("line 2: not tx, rx or --"), "{error}");
        assert!(parse("t tx \"\\q\"").unwrap_err().contains("bad escape"));
        assert!(
            parse("t tx unquoted")
                .unwrap_err()
                .contains("no quoted bytes")
        );
    }
}
