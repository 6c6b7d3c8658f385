//! SMD4 replies decoded for people: error codes with their meaning, user/real pairs, enumerated
//! and named values with their labels, units, and the flags that are set.

use crate::dialect::session::Decoded;
use crate::dialect::smd4::protocol::commands::trim_number;
use crate::dialect::smd4::protocol::{ReplyShape, Smd4Spec, Value};
use crate::dialect::smd4::session::Smd4Exchange;
use crate::dialect::smd4::values;

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
    // SYS:FLAGS answers with the flags themselves; its fixed item `1` carries nothing.
    if command.is_some_and(values::reads_flags) {
        return Decoded {
            text: values::flags_reply(spec, response.sflags.0, response.eflags.0),
            ok: true,
        };
    }
    let unit = command
        .map(|c| c.unit.clone())
        .filter(|u| !u.is_empty())
        .map(|u| format!(" {u}"))
        .unwrap_or_default();
    let meanings = command.map(values::decoding).unwrap_or_default();
    // The fixed item the document's examples show (MOTOR:RUNR's `1`), which the reply check
    // has made sure of, says nothing more than "ok".
    let fixed_item = command.is_some_and(|c| matches!(c.reply, ReplyShape::Literal(_)));
    let mut text = if let Some((user, real)) = response.user_real() {
        let (user, real) = (trim_number(user), trim_number(real));
        format!("{user}{unit} requested, {real}{unit} real")
    } else if response.data.is_empty() || fixed_item {
        "ok".to_string()
    } else {
        let items: Vec<String> = response
            .data
            .iter()
            .map(|d| match &d.value {
                Value::Named { number, name } => format!("{number} ({name})"),
                // 5.0516E-01, 5.0516-01 and 0.50516 alike read 0.50516.
                Value::Float(x) => trim_number(*x),
                // An enumerated setting's number with its label, as `:params --values` shows it.
                Value::Int(_) | Value::Uint(_) | Value::Bool(_) => {
                    match whole(&d.value).and_then(|n| meanings.explain(n)) {
                        Some(meaning) => format!("{} ({meaning})", d.raw),
                        None => d.raw.clone(),
                    }
                }
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

/// A whole-number item as an integer.
fn whole(value: &Value) -> Option<i64> {
    match value {
        Value::Int(i) => Some(*i),
        Value::Uint(u) => i64::try_from(*u).ok(),
        Value::Bool(b) => Some(i64::from(*b)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::protocol::{Expectation, Request, parse_reply};

    fn shown(mnemonic: &str, line: &str) -> String {
        let spec = Smd4Spec::builtin();
        let command = spec.commands.get(mnemonic).unwrap();
        let reply = parse_reply(line, &Expectation::for_command(command)).unwrap();
        let exchange = Smd4Exchange {
            sent: mnemonic.into(),
            request: Request::new(mnemonic),
            reply: Some(reply),
        };
        decode(&exchange, spec).text
    }

    #[test]
    fn an_enumerated_value_is_shown_with_its_label_and_others_as_they_came() {
        assert_eq!(
            shown("MOTOR:F", "0x0080,0x0000,2"),
            "2 (Phases shorted to GND) [Standby]"
        );
        assert_eq!(shown("LIMIT:EN", "0x0000,0x0000,1"), "1 (Enable) [none]");
        assert_eq!(
            shown("SYS:MODE", "0x0000,0x0000,1 (Remote)"),
            "1 (Remote) [none]"
        );
        // A number the table does not name keeps no label; plain numbers keep their unit.
        assert_eq!(shown("MOTOR:F", "0x0000,0x0000,5"), "5 [none]");
        assert_eq!(
            shown("MOTOR:RES", "0x0000,0x0000,256"),
            "256 microsteps per full step [none]"
        );
        assert_eq!(
            shown("MOTOR:F", "0x0000,0x0020,2"),
            "2 (Phases shorted to GND) [none] errors: Emergency Stop"
        );
    }

    #[test]
    fn sys_flags_shows_the_two_words_it_reads_not_its_fixed_item() {
        assert_eq!(
            shown("SYS:FLAGS", "0x0888,0x0000,1"),
            "0x0888, 0x0000 (status: External Enable, Standby, Boost Operational; errors: none)"
        );
        assert_eq!(
            shown("SYS:FLAGS", "0x0000,0x0003,1"),
            "0x0000, 0x0003 (status: none; errors: Temp Short, Temp Open)"
        );
        // MOTOR:RUNR has the same fixed item: it moved, and the item says nothing more.
        assert_eq!(shown("MOTOR:RUNR", "0x0000,0x0000,1"), "ok [none]");
    }
}
