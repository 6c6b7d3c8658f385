//! SMD4 replies decoded for people: error codes with their meaning, user/real pairs, named values
//! with units, and the flags that are set.

use crate::dialect::session::Decoded;
use crate::dialect::smd4::protocol::commands::trim_number;
use crate::dialect::smd4::protocol::{Smd4Spec, Value};
use crate::dialect::smd4::session::Smd4Exchange;

/// Decodes an SMD4 reply: error codes with their meaning, user/real pairs, named values with
/// units, and the flags that are set.
pub fn decode(exchange: &Smd4Exchange, spec: &Smd4Spec) -> Decoded {
    let Some(response) = &exchange.reply else {
        return Decoded {
            text: "sent (no reply for broadcasts and this command)".into(),
            ok: true,
        };
    };
    let flags = {
        let mut text = format!("[{}]", spec.sflags.describe(response.sflags.0));
        if response.eflags.0 != 0 {
            text.push_str(&format!(
                " errors: {}",
                spec.eflags.describe(response.eflags.0)
            ));
        }
        text
    };
    if let Some(error) = &response.error {
        return Decoded {
            text: format!("error {error} {flags}"),
            ok: false,
        };
    }
    let command = spec.commands.get(&exchange.request.mnemonic);
    let unit = command
        .map(|c| c.unit.clone())
        .filter(|u| !u.is_empty())
        .map(|u| format!(" {u}"))
        .unwrap_or_default();
    let mut text = if let Some((user, real)) = response.user_real() {
        let (user, real) = (trim_number(user), trim_number(real));
        format!("{user}{unit} requested, {real}{unit} real")
    } else if response.data.is_empty() {
        "ok".to_string()
    } else {
        let items: Vec<String> = response
            .data
            .iter()
            .map(|d| match &d.value {
                Value::Named { number, name } => format!("{number} ({name})"),
                // 5.0516E-01, 5.0516-01 and 0.50516 alike read 0.50516.
                Value::Float(x) => trim_number(*x),
                _ => d.raw.clone(),
            })
            .collect();
        format!("{}{unit}", items.join(", "))
    };
    // The flags belong to the first line; a listing follows as sent.
    text = format!("{text} {flags}");
    for line in &response.lines {
        text.push('\n');
        text.push_str(line);
    }
    Decoded { text, ok: true }
}
