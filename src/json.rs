//! Machine-readable output: every `--json` document (the `-c` replies, `scan`, `ports`,
//! `profiles`, `params`, `snapshot diff`, `config`) is written here, so all of them escape alike.
//!
//! serde_json builds and escapes the values (every C0 control as JSON requires); [`line`] writes
//! them as one line of ASCII, DEL and everything beyond ASCII (C1 controls, bidirectional
//! overrides) as `\uXXXX`, so device or file text in a string can never act on a terminal or a
//! CI log. The field names of each document are a contract, listed in docs/machine-output.md.

use std::io::{self, Write};

pub use serde_json::{Map, Value, json};

/// `value` as one line of ASCII JSON (no line end).
pub fn line(value: &Value) -> String {
    let mut bytes = Vec::new();
    let mut serializer = serde_json::Serializer::with_formatter(&mut bytes, AsciiFormatter);
    serde::Serialize::serialize(value, &mut serializer).expect("a JSON value serialises");
    String::from_utf8(bytes).expect("the formatter writes ASCII")
}

/// Writes `value` as one line of ASCII JSON and a line end: a command's whole `--json` output.
pub fn write(value: &Value, out: &mut dyn Write) -> io::Result<()> {
    writeln!(out, "{}", line(value))
}

/// serde_json's compact output (which escapes C0 controls), with DEL and every character beyond
/// ASCII (C1 controls among them) written as `\uXXXX`: nothing in it a terminal acts on.
struct AsciiFormatter;

impl serde_json::ser::Formatter for AsciiFormatter {
    fn write_string_fragment<W: ?Sized + io::Write>(
        &mut self,
        writer: &mut W,
        fragment: &str,
    ) -> io::Result<()> {
        for c in fragment.chars() {
            // DEL is ASCII, but a control character JSON leaves to the writer.
            if c.is_ascii() && c != '\x7f' {
                writer.write_all(&[c as u8])?;
            } else {
                let mut units = [0u16; 2];
                for unit in c.encode_utf16(&mut units) {
                    write!(writer, "\\u{unit:04x}")?;
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_is_ascii_and_round_trips() {
        let text = "BA 100 \u{1b}[2J \u{7f}\u{9b}2J \u{202e}evil \u{1F600} \"q\" \\ \t\r\n";
        let line = line(&json!({ "raw": text }));
        assert!(line.is_ascii(), "{line}");
        assert!(!line.chars().any(|c| c.is_control()), "{line}");
        assert!(line.contains("\\u007f\\u009b2J"), "{line}");
        assert!(line.contains("\\u001b[2J"), "{line}");
        assert!(
            line.contains("\\u202e") && line.contains("\\ud83d\\ude00"),
            "{line}"
        );
        let back: Value = serde_json::from_str(&line).unwrap();
        assert_eq!(back["raw"], text);
    }
}
