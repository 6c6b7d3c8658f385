//! An SMD4 exchange in the output modes of `-c` and piped lines: only the data items
//! (`--value`), and its fields of the JSON object (`--json`).

use serde_json::{Value, json};

use crate::dialect::session::ReplyForms;

use super::protocol::Smd4Spec;
use super::session::Smd4Exchange;
use super::values;

impl ReplyForms for Smd4Exchange {
    /// The data items as received, comma-separated, with any further lines of a listing after
    /// them; empty when the drive sends no reply. SYS:FLAGS reads the flag words: they are its
    /// value (`0x0888,0x0000`), not the fixed item after them.
    fn value(&self) -> String {
        let spec = Smd4Spec::builtin();
        let reads_flags = spec
            .commands
            .get(&self.request.mnemonic)
            .is_some_and(values::reads_flags);
        match &self.reply {
            None => String::new(),
            Some(r) if reads_flags && r.is_ok() => {
                format!("0x{:04X},0x{:04X}", r.sflags.0, r.eflags.0)
            }
            Some(r) => {
                let mut text = r.data_strings().join(",");
                for line in &r.lines {
                    text.push('\n');
                    text.push_str(line);
                }
                text
            }
        }
    }

    /// The address, the line sent, success, the flag words and error, the items and further
    /// lines, the reply as received.
    fn json_fields(&self) -> Vec<(&'static str, Value)> {
        let response = self.reply.as_ref();
        let error = response.and_then(|r| r.error.as_ref()).map(|e| {
            json!({
                "code": e.code.code(),
                "meaning": e.code.meaning(),
                "text": e.text,
            })
        });
        vec![
            ("module", json!(self.request.address)),
            ("sent", json!(self.sent)),
            ("ok", json!(self.ok())),
            ("sflags", json!(response.map(|r| r.sflags.0))),
            ("eflags", json!(response.map(|r| r.eflags.0))),
            ("error", error.unwrap_or(Value::Null)),
            (
                "items",
                json!(response.map(|r| r.data_strings()).unwrap_or_default()),
            ),
            (
                "lines",
                json!(response.map(|r| r.lines.clone()).unwrap_or_default()),
            ),
            ("raw", json!(self.raw())),
        ]
    }
}
