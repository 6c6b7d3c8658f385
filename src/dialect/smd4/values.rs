//! What an SMD4 value means, read from `data/smd4.toml` with the decoding every dialect shares:
//! an enumerated setting's number by its label (MOTOR:F 2 is `Phases shorted to GND`), and the
//! two flag words of SYS:FLAGS bit by bit with the names of the bit tables. `:params --values`,
//! the REPL's replies and `:help` show the same meaning for the same value.

use crate::commission::ParamValue;
use crate::commission::decoding::{Bit, Decoding};
use crate::dialect::smd4::protocol::flags::FlagTable;
use crate::dialect::smd4::protocol::{ReplyShape, Smd4Command, Smd4Spec};

/// The whole values of `command` and their labels (its `enum` rows with a number as value).
pub fn decoding(command: &Smd4Command) -> Decoding {
    Decoding {
        values: command
            .labels
            .iter()
            .filter(|c| !c.label.trim().is_empty())
            .filter_map(|c| Some((c.value.trim().parse::<i64>().ok()?, c.label.clone())))
            .collect(),
        ..Decoding::default()
    }
}

/// The bits of one flag word, named as its bit table names them.
fn flag_decoding(table: &FlagTable) -> Decoding {
    Decoding {
        bits: table
            .bits()
            .iter()
            .map(|b| Bit {
                bit: b.bit,
                name: b.name.clone(),
                meaning: b.meaning.clone(),
            })
            .collect(),
        ..Decoding::default()
    }
}

/// Both flag words: `status: Standby, Boost Operational; errors: none`.
pub fn explain_flags(spec: &Smd4Spec, sflags: u16, eflags: u16) -> String {
    let word = |table: &FlagTable, value: u16| {
        flag_decoding(table)
            .explain(i64::from(value))
            .filter(|text| text != "no bit set")
            .unwrap_or_else(|| "none".into())
    };
    format!(
        "status: {}; errors: {}",
        word(&spec.sflags, sflags),
        word(&spec.eflags, eflags)
    )
}

/// Whether `command` reads the two flag words (SYS:FLAGS): a query whose only data item is the
/// fixed one the document's example shows (`0x0000,0x0000,1`) and does not explain. The reply
/// check has made sure of that item; what the command answers is the flags.
pub fn reads_flags(command: &Smd4Command) -> bool {
    command.readable && matches!(command.reply, ReplyShape::Literal(_))
}

/// The flag words as a SYS:FLAGS read shows them, with what they mean:
/// `0x0888, 0x0000 (status: External Enable, Standby, Boost Operational; errors: none)`.
pub fn flags_reply(spec: &Smd4Spec, sflags: u16, eflags: u16) -> String {
    format!(
        "0x{sflags:04X}, 0x{eflags:04X} ({})",
        explain_flags(spec, sflags, eflags)
    )
}

/// What `value`, read with `command`, means where the table says: the label of an enumerated
/// value, or the flags of SYS:FLAGS (whose value is its two words, `0x0888 0x0000`).
pub fn explain(spec: &Smd4Spec, command: &Smd4Command, value: &ParamValue) -> Option<String> {
    match (&command.reply, value) {
        (ReplyShape::Literal(_), ParamValue::Text(words)) => {
            let (sflags, eflags) = flag_words(words)?;
            Some(explain_flags(spec, sflags, eflags))
        }
        (_, ParamValue::Int(number)) => decoding(command).explain(*number),
        _ => None,
    }
}

/// The two words of a SYS:FLAGS value (`0x088E 0x0000`).
fn flag_words(text: &str) -> Option<(u16, u16)> {
    let word = |w: &str| {
        let hex = w.strip_prefix("0x").or_else(|| w.strip_prefix("0X"))?;
        u16::from_str_radix(hex, 16).ok()
    };
    match text.split_whitespace().collect::<Vec<_>>().as_slice() {
        [s, e] => Some((word(s)?, word(e)?)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec() -> &'static Smd4Spec {
        Smd4Spec::builtin()
    }

    fn explained(mnemonic: &str, value: ParamValue) -> Option<String> {
        let command = spec().commands.get(mnemonic).unwrap();
        explain(spec(), command, &value)
    }

    #[test]
    fn enumerated_settings_read_as_their_labels() {
        assert_eq!(
            explained("MOTOR:F", 2.into()).as_deref(),
            Some("Phases shorted to GND")
        );
        assert_eq!(explained("SYS:MODE", 1.into()).as_deref(), Some("Remote"));
        assert_eq!(
            explained("LIMIT:POL+", 1.into()).as_deref(),
            Some("Active low")
        );
        // A number the table does not name, a real value, a plain number: nothing made up.
        assert_eq!(explained("MOTOR:F", 7.into()), None);
        assert_eq!(explained("MOTOR:VMAX", 1000.0.into()), None);
        assert_eq!(explained("MOTOR:RES", 256.into()), None);
        assert_eq!(explained("COMS:SERIAL:BAUD", 115200.into()), None);
    }

    #[test]
    fn only_sys_flags_reads_the_flag_words() {
        let reading: Vec<&str> = spec()
            .commands
            .iter()
            .filter(|c| reads_flags(c))
            .map(|c| c.mnemonic.as_str())
            .collect();
        // MOTOR:RUNR has the same fixed item, but it moves the motor and reads nothing.
        assert_eq!(reading, ["SYS:FLAGS"]);
        assert_eq!(
            flags_reply(spec(), 0x0888, 0x0020),
            "0x0888, 0x0020 (status: External Enable, Standby, Boost Operational; errors: \
             Emergency Stop)"
        );
    }

    #[test]
    fn the_flag_words_read_bit_by_bit_with_the_tables_names() {
        let flags = |text: &str| explained("SYS:FLAGS", ParamValue::Text(text.into()));
        // The SYS:FLAGSV example of the document: 0x088E.
        assert_eq!(
            flags("0x088E 0x0000").as_deref(),
            Some(
                "status: Limit Negative, Limit Positive, External Enable, Standby, Boost Operational; \
                 errors: none"
            )
        );
        assert_eq!(
            flags("0x0000 0x0022").as_deref(),
            Some("status: none; errors: Temp Open, Emergency Stop")
        );
        // Every bit of both words has a name in the table.
        let all = flags("0xFFFF 0xFFFF").unwrap();
        assert!(!all.contains("bit "), "{all}");
        for broken in [
            "0x088E",
            "0x088E 0x0000 0x1",
            "088E 0000",
            "0x1FFFF 0x0",
            "text",
        ] {
            assert_eq!(flags(broken), None, "{broken}");
        }
    }
}
