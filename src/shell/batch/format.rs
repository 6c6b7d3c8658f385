//! How `-c` and piped lines show their replies on stdout: the reply line as the module sent it
//! (the default), only the value (`--value`), or one JSON object per line (`--json`).
//!
//! JSON is written by serde_json (every control character escaped as JSON requires) through a
//! formatter that also writes every non-ASCII character as `\uXXXX`: the output is plain ASCII,
//! so device text can neither move the cursor nor reorder the terminal's text (bidirectional
//! overrides), and a JSON reader gets the exact text back.

use std::io;

use serde_json::{Map, Value, json};

use crate::dialect::Reply;

/// What stdout gets for each line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Output {
    /// The reply as the module sent it (`BA 100 -5000`).
    #[default]
    Reply,
    /// Only the value (`-5000`; SMD4: the data items).
    Value,
    /// One JSON object per line.
    Json,
}

/// Only the value of a reply (the dialect says what that is: TMCL the number, SMD4 the items).
pub fn value(reply: &Reply) -> String {
    reply.forms.value()
}

/// The JSON object of a line that got a reply: its number and input, the dialect's fields (where
/// it went, whether it succeeded, status or flags, value or items, the reply as received), and
/// the exit code it means.
pub fn reply_json(number: usize, input: &str, reply: &Reply, exit: u8) -> Value {
    let mut object = head(number, input);
    for (key, value) in reply.forms.json_fields() {
        object.insert(key.into(), value);
    }
    object.insert("exit".into(), json!(exit));
    Value::Object(object)
}

/// The JSON object of a line that failed without a reply (refused, no reply, link lost).
pub fn failure_json(number: usize, input: &str, message: &str, exit: u8) -> Value {
    let mut object = head(number, input);
    object.insert("ok".into(), json!(false));
    object.insert("failure".into(), json!(message));
    object.insert("exit".into(), json!(exit));
    Value::Object(object)
}

/// The JSON object of a helper line (`:params`, `:help`): its text output.
pub fn helper_json(number: usize, input: &str, output: &str) -> Value {
    let mut object = head(number, input);
    object.insert("ok".into(), json!(true));
    object.insert("output".into(), json!(output));
    object.insert("exit".into(), json!(0));
    Value::Object(object)
}

fn head(number: usize, input: &str) -> Map<String, Value> {
    let mut object = Map::new();
    object.insert("line".into(), json!(number));
    object.insert("input".into(), json!(input));
    object
}

/// `value` as one line of ASCII JSON.
pub fn json_line(value: &Value) -> String {
    let mut bytes = Vec::new();
    let mut serializer = serde_json::Serializer::with_formatter(&mut bytes, AsciiFormatter);
    serde::Serialize::serialize(value, &mut serializer).expect("a JSON value serialises");
    String::from_utf8(bytes).expect("the formatter writes ASCII")
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
        let text = "BA 100 \u{1b}[2J \u{7f}\u{9b}2J \u{202e}evil \u{1F600} \"q\" \\";
        let line = json_line(&json!({ "raw": text }));
        assert!(line.is_ascii(), "{line}");
        assert!(!line.chars().any(|c| c.is_control()), "{line}");
        assert!(line.contains("\\u007f\\u009b2J"), "{line}");
        assert!(
            line.contains("\\u202e") && line.contains("\\ud83d\\ude00"),
            "{line}"
        );
        let back: Value = serde_json::from_str(&line).unwrap();
        assert_eq!(back["raw"], text);
    }
}
