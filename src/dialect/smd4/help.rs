//! `:help` on SMD4: how requests are typed, addressing, and each mnemonic of the table.

use std::io::{self, Write};

use super::protocol::{ADDRESSING_HELP, Smd4Spec, hints};
use crate::dialect::UNCERTAIN;
use crate::wrap::{fit, terminal_width};

/// How SMD4 requests are typed: the first lines of `:help`.
pub(super) fn intro(out: &mut dyn Write) -> io::Result<()> {
    writeln!(
        out,
        "{}",
        fit(
            "Type SMD4 requests, e.g. MOTOR:VMAX (read) or MOTOR:VMAX,2000 (write); @N addresses a drive.",
            0,
            terminal_width()
        )
    )?;
    writeln!(
        out,
        "{}\n",
        fit(
            "Tab completes the hierarchical mnemonics (MOTOR:, SYS:, LIMIT:, BAKE:, BOOST:, COMS:NET:, COMS:SERIAL:).",
            0,
            terminal_width()
        )
    )
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
                "{UNCERTAIN} after a mnemonic: the SMD4 document leaves part of it open or contradicts itself."
            )?;
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// `:help MOTOR:VMAX`: the request's usage, what its argument accepts, and any doubt about it;
/// false when `word` is no mnemonic of the table.
pub(super) fn command(spec: &Smd4Spec, word: &str, out: &mut dyn Write) -> io::Result<bool> {
    let Some(spec) = spec.commands.get(word) else {
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
    writeln!(out, "{}", fit(&text, 2, terminal_width()))?;
    if spec.uncertain {
        writeln!(out, "  ({UNCERTAIN}: see :help params)")?;
    }
    Ok(true)
}
