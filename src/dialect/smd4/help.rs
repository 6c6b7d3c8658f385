//! `:help` on SMD4: how requests are typed, addressing, and each mnemonic of the table.

use std::io::{self, Write};

use super::protocol::flags::FlagTable;
use super::protocol::{ADDRESSING_HELP, Smd4Spec, hints};
use super::values;
use crate::dialect::UNCERTAIN;
use crate::wrap::write_fitted;

/// How SMD4 requests are typed: the first lines of `:help`.
pub(super) fn intro(out: &mut dyn Write) -> io::Result<()> {
    for line in [
        "Type SMD4 requests, e.g. MOTOR:VMAX (read) or MOTOR:VMAX,2000 (write); @N addresses a drive.",
        "Tab completes the hierarchical mnemonics (MOTOR:, SYS:, LIMIT:, BAKE:, BOOST:, COMS:NET:, COMS:SERIAL:).",
    ] {
        write_fitted(out, line, 0)?;
    }
    writeln!(out)
}

/// The topics named at the end of `:help`.
pub(super) const MORE: &str =
    ":help MNEMONIC, :help params, :help addressing, :help exit, :help time";

/// `:help addressing` and `:help params`; false for other topics.
pub(super) fn topic(topic: &str, out: &mut dyn Write) -> io::Result<bool> {
    match topic {
        "addressing" => writeln!(out, "{ADDRESSING_HELP}")?,
        "params" => {
            writeln!(
                out,
                "The commands are listed by :params [filter]; :help MNEMONIC describes one."
            )?;
            writeln!(
                out,
                "{UNCERTAIN} after a mnemonic or a flag bit: the SMD4 document leaves part of it open or contradicts itself."
            )?;
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// `:help MOTOR:VMAX`: the request's usage, what its argument accepts, and any doubt about it;
/// false when `word` is no mnemonic of the table.
pub(super) fn command(table: &Smd4Spec, word: &str, out: &mut dyn Write) -> io::Result<bool> {
    let Some(spec) = table.commands.get(word) else {
        return Ok(false);
    };
    let usage = hints::usage(spec);
    let hint = hints::hint(spec);
    let mark = if spec.uncertain {
        format!(" {UNCERTAIN}")
    } else {
        String::new()
    };
    writeln!(out, "{usage}{mark}")?;
    let text = format!(
        "  {}",
        hint.strip_prefix(&usage).unwrap_or(&hint).trim_start()
    );
    write_fitted(out, &text, 2)?;
    if spec.uncertain {
        writeln!(out, "  ({UNCERTAIN}: see :help params)")?;
    }
    if values::reads_flags(spec) {
        flag_bits(table, out)?;
    }
    Ok(true)
}

/// The bits of both flag words, for `:help SYS:FLAGS`: what the reply's two words say, and what
/// the fixed item after them is.
fn flag_bits(spec: &Smd4Spec, out: &mut dyn Write) -> io::Result<()> {
    let note = "  The reply is the two flag words every reply starts with, read bit by bit below. \
                The item 1 after them is in the protocol document's example, which does not \
                explain it: it is checked and not shown (:raw shows it).";
    write_fitted(out, note, 2)?;
    let words = [
        ("Status (SFLAGS, the first word):", &spec.sflags, "status"),
        (
            "Errors (EFLAGS, the second word; latching: SYS:CLR clears them, and any set bit \
             disables the motor):",
            &spec.eflags,
            "error",
        ),
    ];
    let mut reserved = Vec::new();
    for (title, table, word) in words {
        write_fitted(out, &format!("  {title}"), 2)?;
        for bit in table
            .bits()
            .iter()
            .filter(|b| !is_reserved(b.name.as_str()))
        {
            let mark = if bit.uncertain {
                format!(" {UNCERTAIN}")
            } else {
                String::new()
            };
            let row = format!("  {:>4}  {}{mark} — {}", bit.bit, bit.name, bit.meaning);
            write_fitted(out, &row, 8)?;
        }
        let bits = reserved_bits(table);
        if !bits.is_empty() {
            reserved.push(format!("{word} bits {bits}"));
        }
    }
    if !reserved.is_empty() {
        let row = format!("  Reserved, reading 0: {}.", reserved.join("; "));
        write_fitted(out, &row, 2)?;
    }
    Ok(())
}

/// A bit the table keeps for later use (`Reserved`).
fn is_reserved(name: &str) -> bool {
    name.eq_ignore_ascii_case("reserved")
}

/// The reserved bits of a word: `5, 6, 13, 14, 15`.
fn reserved_bits(table: &FlagTable) -> String {
    let bits: Vec<String> = table
        .bits()
        .iter()
        .filter(|b| is_reserved(&b.name))
        .map(|b| b.bit.to_string())
        .collect();
    bits.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn help(word: &str) -> String {
        let mut out = Vec::new();
        assert!(command(Smd4Spec::builtin(), word, &mut out).unwrap());
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn sys_flags_lists_every_named_bit_of_both_words() {
        let text = help("SYS:FLAGS");
        let spec = Smd4Spec::builtin();
        for bit in spec.sflags.bits().iter().chain(spec.eflags.bits()) {
            if !is_reserved(&bit.name) {
                let row = format!("{:>4}  {}", bit.bit, bit.name);
                assert!(text.contains(&row), "{row}: {text}");
            }
        }
        assert!(text.contains("  7  Standby — "), "{text}");
        assert!(text.contains("  5  Emergency Stop — "), "{text}");
        assert!(text.contains("status bits 5, 6, 13, 14, 15"), "{text}");
        assert!(text.contains("error bits 10, 11, 12, 13, 14, 15"), "{text}");
        assert!(text.contains("does not explain it"), "{text}");
        // A bit the document names two ways carries the sign `:help params` explains.
        assert!(text.contains("12  Boost Disable Jumper * — "), "{text}");
        let mut params = Vec::new();
        assert!(topic("params", &mut params).unwrap());
        let params = String::from_utf8(params).unwrap();
        assert!(
            params.contains("* after a mnemonic or a flag bit"),
            "{params}"
        );
        // Other commands have no flag table.
        assert!(!help("MOTOR:VMAX").contains("SFLAGS"));
        assert!(!help("MOTOR:RUNR").contains("SFLAGS"));
    }
}
