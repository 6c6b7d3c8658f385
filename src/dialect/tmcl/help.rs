//! `:help` on TMCL: how lines are typed, the ASCII interface, and each command of the profile.

use std::io::{self, Write};

use super::params::uncertain_mark;
use super::ports;
use super::profile::commands::{Field, OperandKind};
use super::profile::{Param, ParamKind, Profile};
use crate::dialect::UNCERTAIN;
use crate::wrap::write_fitted;

/// How TMCL lines are typed: the first lines of `:help`.
pub(super) fn intro(out: &mut dyn Write) -> io::Result<()> {
    for line in [
        "Type TMCL commands as in the TMCL-IDE, e.g. GAP actual_position, 0 or MVP ABS, 0, 1000.",
        "Parameter names work in place of numbers; Tab completes, hints show units and ranges.",
        "A leading address character reaches another module: CGAP 4, 0.",
    ] {
        write_fitted(out, line, 0)?;
    }
    writeln!(out)
}

/// The topics named at the end of `:help`.
pub(super) const MORE: &str =
    ":help COMMAND, :help params, :help io, :help exit, :help time, :help ascii";

/// `:help params`, `:help io` (or `ports`: the module's I/O ports) and `:help ascii` (the ASCII
/// commands of `profile`'s module); false for other topics.
pub(super) fn topic(profile: &Profile, topic: &str, out: &mut dyn Write) -> io::Result<bool> {
    match topic {
        "params" => {
            writeln!(
                out,
                "Parameters are listed by :params [filter] (:params --values reads them too); use their names in"
            )?;
            writeln!(out, "SAP/GAP/SGP/GGP lines; :help NAME describes one.")?;
            writeln!(
                out,
                "{UNCERTAIN} after the access letters (or the number in :help NAME): the {} manual does not confirm",
                profile.module
            )?;
            writeln!(
                out,
                "  the row (taken from sibling modules or inferred); `tmclsh profiles {}` names the sources.",
                profile.name
            )?
        }
        "io" | "ports" => ports::write_table(profile, out)?,
        "ascii" => {
            writeln!(
                out,
                "ASCII mode (manual 6.6): lines are <address char><command>, replies <host char><module char> <status> <value>."
            )?;
            let allowed: Vec<&str> = profile.commands.ascii_mnemonics();
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
pub(super) fn command(profile: &Profile, word: &str, out: &mut dyn Write) -> io::Result<bool> {
    let spec = profile.commands.by_mnemonic(word).or_else(|| {
        word.parse::<u8>()
            .ok()
            .and_then(|n| profile.commands.by_number(n))
    });
    let Some(spec) = spec else {
        return match param(profile, word) {
            Some(p) => describe_param(p, out).map(|()| true),
            None => Ok(false),
        };
    };
    let first = format!("{} — {} (command {})", spec.usage(), spec.name, spec.number);
    write_fitted(out, &first, 0)?;
    for k in &spec.keywords {
        let row = format!("  {:<8} {}", k.name, k.meaning);
        write_fitted(out, &row, 11)?;
    }
    let place = match (spec.ascii_allowed, spec.direct_mode) {
        (true, _) => "ASCII and binary direct mode",
        (false, true) => "binary direct mode only (:bin)",
        (false, false) => "stand-alone programs only",
    };
    writeln!(out, "  usable in: {place}")?;
    if spec.field_is(Field::Type, OperandKind::Port) {
        let writes = spec.operand_for(Field::Value).is_some();
        let line = format!("  {}", ports::help_line(profile, writes));
        write_fitted(out, &line, 2)?;
    }
    Ok(true)
}

/// The parameter named `word` (an identifier, axis parameters first).
fn param<'a>(profile: &'a Profile, word: &str) -> Option<&'a Param> {
    let word = word.to_ascii_lowercase();
    profile
        .axis
        .iter()
        .chain(&profile.global)
        .find(|p| p.ident == word)
}

/// `:help max_current`: what the parameter is, its number, access, range, unit and default, its
/// description and what its values mean.
fn describe_param(p: &Param, out: &mut dyn Write) -> io::Result<()> {
    let kind = match p.kind {
        ParamKind::Axis => "axis parameter".to_string(),
        ParamKind::Global { bank } => format!("global parameter, bank {bank},"),
    };
    let mark = uncertain_mark(p);
    let first = format!(
        "{} — {kind} {}{} ({})",
        p.ident,
        p.number,
        mark.trim_end(),
        p.name
    );
    write_fitted(out, &first, 0)?;
    let mut facts = vec![format!("access {}", p.access.letters())];
    if let Some((lo, hi)) = p.range {
        facts.push(format!("range {lo}..{hi}"));
    }
    if !p.unit.is_empty() {
        facts.push(format!("unit {}", p.unit));
    }
    if let Some(default) = p.default {
        facts.push(format!("default {default}"));
    }
    write_fitted(out, &format!("  {}", facts.join(", ")), 2)?;
    for when in &p.range_when {
        writeln!(out, "  {}", when.describe())?;
    }
    if !p.description.is_empty() {
        let row = format!("  {}", p.description);
        write_fitted(out, &row, 2)?;
    }
    let decoding = &p.decoding;
    for (value, meaning) in &decoding.values {
        writeln!(out, "  {value:>6}  {meaning}")?;
    }
    for bit in &decoding.bits {
        writeln!(
            out,
            "  bit {:>2}  {}",
            bit.bit,
            bit_text(&bit.name, &bit.meaning)
        )?;
    }
    for field in &decoding.fields {
        let bits = if field.low == field.high {
            format!("bit {}", field.low)
        } else {
            format!("bits {}..{}", field.high, field.low)
        };
        let values: Vec<String> = field
            .values
            .iter()
            .map(|(v, meaning)| format!("{v} {meaning}"))
            .collect();
        writeln!(out, "  {bits}  {}: {}", field.name, values.join(", "))?;
    }
    if p.uncertain {
        writeln!(out, "  ({UNCERTAIN}: see :help params)")?;
    }
    Ok(())
}

/// A bit's short name and meaning, once when they are the same.
fn bit_text(name: &str, meaning: &str) -> String {
    if name == meaning || meaning.is_empty() {
        name.to_string()
    } else {
        format!("{name}: {meaning}")
    }
}

/// The research note in a text a user reads, if it carries one: where a fact was read (`sibling`,
/// `PyTrinamic`, a page `p20`, a manual version `(V1.19`) belongs in the profile's `source`
/// fields, not in descriptions, reasons or port kinds.
#[cfg(test)]
pub(crate) fn research_note(text: &str) -> Option<String> {
    let lower = text.to_ascii_lowercase();
    let words = [
        "sibling",
        "seed",
        "retriev",
        "uncertain",
        "pytrinamic",
        "generic note",
        "header",
    ];
    if let Some(word) = words.iter().find(|w| lower.contains(*w)) {
        return Some(word.to_string());
    }
    // A page (`p20`, `p.17`, `pp.1-25`) or a manual version in brackets (`(V1.19`).
    let page = |token: &str| {
        let digits = token
            .strip_prefix("pp")
            .or_else(|| token.strip_prefix('p'))
            .map(|t| t.trim_start_matches('.'));
        digits.is_some_and(|d| d.starts_with(|c: char| c.is_ascii_digit()))
    };
    let tokens = lower.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.'));
    if let Some(token) = tokens.into_iter().find(|t| page(t)) {
        return Some(token.to_string());
    }
    let version = lower
        .match_indices("(v")
        .find(|(i, _)| lower[i + 2..].starts_with(|c: char| c.is_ascii_digit()));
    version.map(|(i, _)| lower[i..].chars().take(6).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn help(word: &str) -> String {
        let mut out = Vec::new();
        assert!(
            command(&Profile::builtin(), word, &mut out).unwrap(),
            "{word}"
        );
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn a_parameter_is_described_with_what_its_values_mean() {
        let text = help("serial_baud_rate");
        assert!(
            text.starts_with("serial_baud_rate — global parameter, bank 0, 65"),
            "{text}"
        );
        assert!(
            text.contains("range 0..7") && text.contains("default 0"),
            "{text}"
        );
        assert!(text.contains("     7  115200 baud"), "{text}");
        let text = help("STATUS_FLAGS");
        assert!(
            text.contains("bit  2  standing: motor standing (v = 0)"),
            "{text}"
        );
        let text = help("ascii_mode");
        assert!(
            text.contains("bits 5..4  echo: 0 each character, 1 line after CR, 2 none"),
            "{text}"
        );
        assert!(
            text.contains("bit 0  start-up: 0 binary, 1 ASCII"),
            "{text}"
        );
    }

    #[test]
    fn research_notes_are_told_from_what_users_read() {
        for note in [
            "SAC is not in the ASCII list (V1.19 p20)",
            "read via AP11 in siblings",
            "range from p.17",
            "front matter (pp.1-25)",
            "uncertain: 0..20",
            "numbers from PyTrinamic",
        ] {
            assert!(research_note(note).is_some(), "{note}");
        }
        for text in [
            "position in microsteps (-2^31..2^31-1)",
            "the module's manual does not list it",
            "version string 142V1.06",
            "stop motor first",
            "pps (pulses per second)",
        ] {
            assert_eq!(research_note(text), None, "{text}");
        }
    }

    #[test]
    fn no_research_note_reaches_the_help_of_any_builtin_profile() {
        let mut noted = Vec::new();
        for profile in crate::dialect::tmcl::profile::catalogue::all() {
            let mut texts: Vec<String> = Vec::new();
            for spec in profile.commands.iter() {
                let mut out = Vec::new();
                command(profile, &spec.mnemonic, &mut out).unwrap();
                texts.push(String::from_utf8(out).unwrap());
            }
            for p in profile.axis.iter().chain(&profile.global) {
                let mut out = Vec::new();
                describe_param(p, &mut out).unwrap();
                texts.push(String::from_utf8(out).unwrap());
            }
            // The reason a command the module lacks is refused with.
            for (_, reason) in profile.commands.absent_commands() {
                texts.push(reason.to_string());
            }
            for text in texts {
                if let Some(note) = research_note(&text) {
                    noted.push(format!("{}: {note}: {text}", profile.name));
                }
            }
        }
        assert!(noted.is_empty(), "{}", noted.join("\n"));
    }
}
