//! `:help` on TMCL: how lines are typed, the ASCII interface, and each command of the profile.

use std::io::{self, Write};

use super::profile::Profile;

/// How TMCL lines are typed: the first lines of `:help`.
pub fn intro(out: &mut dyn Write) -> io::Result<()> {
    writeln!(
        out,
        "Type TMCL commands as in the TMCL-IDE, e.g. GAP actual_position, 0 or MVP ABS, 0, 1000."
    )?;
    writeln!(
        out,
        "Parameter names work in place of numbers; Tab completes, hints show units and ranges."
    )?;
    writeln!(
        out,
        "A leading address character reaches another module: CGAP 4, 0.\n"
    )
}

/// The topics named at the end of `:help`.
pub const MORE: &str = ":help COMMAND, :help params, :help exit, :help time, :help ascii";

/// `:help params` and `:help ascii` (the ASCII commands of `profile`'s module); false for other
/// topics.
pub fn topic(profile: &Profile, topic: &str, out: &mut dyn Write) -> io::Result<bool> {
    match topic {
        "params" => writeln!(
            out,
            "Parameters are listed by :params [filter]; use their names in SAP/GAP/SGP/GGP lines."
        )?,
        "ascii" => {
            writeln!(
                out,
                "ASCII mode (manual 6.6): lines are <address char><command>, replies <host char><module char> <status> <value>."
            )?;
            let allowed: Vec<&str> = profile
                .commands
                .iter()
                .filter(|c| c.ascii_allowed)
                .map(|c| c.mnemonic.as_str())
                .collect();
            if allowed.is_empty() {
                writeln!(out, "The {} has no ASCII interface.", profile.module)?;
            } else {
                writeln!(
                    out,
                    "The {} takes only {}, plus BIN RUN STOP.",
                    profile.module,
                    allowed.join(" ")
                )?;
            }
            writeln!(
                out,
                "Echo (GP 67 bits 4/5): char, line or none (:echo). :bin switches to binary frames for the rest."
            )?
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// `:help GAP` (or `:help 6`): the command's usage, keywords and where it may be used; false
/// when `word` names no command of the profile.
pub fn command(profile: &Profile, word: &str, out: &mut dyn Write) -> io::Result<bool> {
    let spec = profile.commands.by_mnemonic(word).or_else(|| {
        word.parse::<u8>()
            .ok()
            .and_then(|n| profile.commands.by_number(n))
    });
    let Some(spec) = spec else {
        return Ok(false);
    };
    writeln!(
        out,
        "{} — {} (command {})",
        spec.usage(),
        spec.name,
        spec.number
    )?;
    for k in &spec.keywords {
        writeln!(out, "  {:<8} {}", k.name, k.meaning)?;
    }
    let place = match (spec.ascii_allowed, spec.direct_mode) {
        (true, _) => "ASCII and binary direct mode",
        (false, true) => "binary direct mode only (:bin)",
        (false, false) => "stand-alone programs only",
    };
    writeln!(out, "  usable in: {place}")?;
    Ok(true)
}
