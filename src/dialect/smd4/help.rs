//! `:help` on SMD4: how requests are typed, addressing, and each mnemonic of the table.

use std::io::{self, Write};

use super::protocol::{ADDRESSING_HELP, Smd4Spec, hints};

/// How SMD4 requests are typed: the first lines of `:help`.
pub fn intro(out: &mut dyn Write) -> io::Result<()> {
    writeln!(
        out,
        "Type SMD4 requests, e.g. MOTOR:VMAX (read) or MOTOR:VMAX,2000 (write); @N addresses a drive."
    )?;
    writeln!(
        out,
        "Tab completes the hierarchical mnemonics (MOTOR:, SYS:, LIMIT:, BAKE:, BOOST:, COMS:NET:, COMS:SERIAL:).\n"
    )
}

/// The topics named at the end of `:help`.
pub const MORE: &str = ":help MNEMONIC, :help addressing, :help exit, :help time";

/// `:help addressing`; false for other topics.
pub fn topic(topic: &str, out: &mut dyn Write) -> io::Result<bool> {
    if topic != "addressing" {
        return Ok(false);
    }
    writeln!(out, "{ADDRESSING_HELP}")?;
    Ok(true)
}

/// `:help MOTOR:VMAX`: the request's usage, what its argument accepts, and any doubt about it;
/// false when `word` is no mnemonic of the table.
pub fn command(spec: &Smd4Spec, word: &str, out: &mut dyn Write) -> io::Result<bool> {
    let Some(spec) = spec.commands.get(word) else {
        return Ok(false);
    };
    let usage = hints::usage(spec);
    let hint = hints::hint(spec);
    writeln!(out, "{usage}")?;
    writeln!(
        out,
        "  {}",
        hint.strip_prefix(&usage).unwrap_or(&hint).trim_start()
    )?;
    if spec.uncertain && !spec.uncertain_reason.is_empty() {
        writeln!(out, "  uncertain: {}", spec.uncertain_reason)?;
    }
    Ok(true)
}
