//! How `-c` and piped lines show their replies on stdout: the reply line as the module sent it
//! (the default), only the value (`--value`), or one JSON object per line (`--json`).
//!
//! JSON is written by serde_json (every control character escaped as JSON requires) through a
//! formatter that also writes every non-ASCII character as `\uXXXX`: the output is plain ASCII,
//! so device text can neither move the cursor nor reorder the terminal's text (bidirectional
//! overrides), and a JSON reader gets the exact text back.

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

/// `value` as one line of ASCII JSON (see [`crate::json`]).
pub fn json_line(value: &Value) -> String {
    crate::json::line(value)
}
