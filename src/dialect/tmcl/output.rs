//! A TMCL exchange in the output modes of `-c` and piped lines: only the value (`--value`), and
//! its fields of the JSON object (`--json`).

use serde_json::{Value, json};

use crate::dialect::session::ReplyForms;

use super::session::{TmclExchange, TmclReply};

impl ReplyForms for TmclExchange {
    /// The number, or the version string of 136; empty when the module sends no reply.
    fn value(&self) -> String {
        match &self.reply {
            TmclReply::Status { value, .. } => value.to_string(),
            TmclReply::Version(version) => version.clone(),
            TmclReply::Nothing => String::new(),
        }
    }

    /// The module, the line sent, success, status and value, the reply as received.
    fn json_fields(&self) -> Vec<(&'static str, Value)> {
        let (status, value) = match &self.reply {
            TmclReply::Status { status, value } => (json!(status.code()), json!(value)),
            TmclReply::Version(version) => (Value::Null, json!(version)),
            TmclReply::Nothing => (Value::Null, Value::Null),
        };
        vec![
            ("module", json!(self.module)),
            ("sent", json!(self.sent)),
            ("ok", json!(self.ok())),
            ("status", status),
            ("value", value),
            ("raw", json!(self.raw)),
        ]
    }
}
