//! Tab completion of TMCL lines, as pure functions of the line and the profile: mnemonics
//! (keeping a typed address character), keywords, axis parameter names for SAP/GAP/STAP/RSAP,
//! global parameter names with their banks for SGP/GGP/STGP/RSGP, and the ports of the profile's
//! port map for GIO/SIO (the outputs for SIO).

use crate::dialect::grammar::{Candidate, Completion};
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::profile::{Param, Profile};

/// Completes the word ending at `pos` in the TMCL line `line`.
pub fn complete(line: &str, pos: usize, profile: &Profile) -> Completion {
    let before = &line[..pos];
    let start = before.rfind([' ', ',', '\t']).map_or(0, |i| i + 1);
    let word = &before[start..];
    complete_tmcl(before, start, word, profile)
}

fn complete_tmcl(before: &str, start: usize, word: &str, profile: &Profile) -> Completion {
    let words = |candidates| Completion::Words { start, candidates };
    let head_end = before.trim_start().len();
    let leading = before.len() - head_end;
    let tokens: Vec<&str> = before[leading..]
        .split([' ', ',', '\t'])
        .filter(|t| !t.is_empty())
        .collect();
    let at_first_word = start <= leading || tokens.len() <= 1 && !before.ends_with([' ', ',']);
    if at_first_word {
        return words(mnemonics(word, profile));
    }
    // The command word, possibly after a lone address character ("A GAP").
    let (command, typed) = match tokens.as_slice() {
        [addr, cmd, rest @ ..]
            if addr.len() == 1 && profile.commands.by_mnemonic(addr).is_none() =>
        {
            (*cmd, rest)
        }
        [cmd, rest @ ..] => (*cmd, rest),
        [] => return words(Vec::new()),
    };
    let Some(spec) = spec_of(command, profile) else {
        return words(Vec::new());
    };
    let index = operand_index(typed.len(), before);
    words(operand_candidates(spec, index, typed, word, profile))
}

/// Which operand the cursor is in, given how many tokens follow the command word.
fn operand_index(tokens_after_command: usize, before: &str) -> usize {
    if before.ends_with([' ', ',', '\t']) {
        tokens_after_command
    } else {
        tokens_after_command.saturating_sub(1)
    }
}

/// The command spec of a typed command word, which may carry an address character.
pub fn spec_of<'a>(word: &str, profile: &'a Profile) -> Option<&'a CommandSpec> {
    profile.commands.by_mnemonic(word).or_else(|| {
        word.get(1..)
            .and_then(|tail| profile.commands.by_mnemonic(tail))
    })
}

/// The mnemonics (and ASCII words) starting with `word`, keeping a leading address character.
pub fn mnemonics(word: &str, profile: &Profile) -> Vec<Candidate> {
    let upper = word.to_ascii_uppercase();
    let mut out: Vec<Candidate> = profile
        .commands
        .words()
        .filter(|m| m.starts_with(&upper))
        .map(|m| Candidate {
            display: m.to_string(),
            replacement: format!("{m} "),
        })
        .collect();
    if out.is_empty() && upper.len() >= 2 && upper.starts_with(|c: char| c.is_ascii_alphabetic()) {
        // "AG" → AGAP, AGGP …: the first letter is an address character.
        let (address, tail) = upper.split_at(1);
        out.extend(
            profile
                .commands
                .words()
                .filter(|m| m.starts_with(tail))
                .map(|m| Candidate {
                    display: format!("{address}{m}"),
                    replacement: format!("{address}{m} "),
                }),
        );
    }
    out
}

/// The candidates for operand `index` of `spec`, with the operands `typed` so far.
fn operand_candidates(
    spec: &CommandSpec,
    index: usize,
    typed: &[&str],
    word: &str,
    profile: &Profile,
) -> Vec<Candidate> {
    let Some(operand) = spec.operands.get(index) else {
        return Vec::new();
    };
    let lower = word.to_ascii_lowercase();
    match operand.kind {
        OperandKind::Keyword => spec
            .keywords
            .iter()
            .filter(|k| k.name.starts_with(&word.to_ascii_uppercase()))
            .map(|k| Candidate {
                display: k.name.clone(),
                replacement: format!("{}, ", k.name),
            })
            .collect(),
        OperandKind::AxisParam => params(&profile.axis, &lower, |p| {
            format!("{} ({})", p.ident, p.number)
        }),
        OperandKind::GlobalParam => params(&profile.global, &lower, |p| {
            format!("{} ({}, bank {})", p.ident, p.number, p.bank())
        }),
        OperandKind::Port => ports(spec, index, word, profile),
        OperandKind::IoBank => banks(spec, index, typed, word, profile),
        _ => Vec::new(),
    }
}

/// The ports of the profile's map whose number starts with `word` (SIO: the outputs), each with
/// its bank when the bank comes next: `7, 0 (IN7)`.
fn ports(spec: &CommandSpec, index: usize, word: &str, profile: &Profile) -> Vec<Candidate> {
    let writes = spec.operand_for(Field::Value).is_some();
    let bank_next = spec
        .operands
        .get(index + 1)
        .is_some_and(|o| o.kind == OperandKind::IoBank);
    let more_after = spec.operands.len() > index + 2;
    profile
        .io_ports
        .iter()
        .filter(|p| (p.is_output() || !writes) && p.port.to_string().starts_with(word))
        .map(|p| {
            let replacement = match (bank_next, more_after) {
                (true, true) => format!("{}, {}, ", p.port, p.bank),
                (true, false) => format!("{}, {}", p.port, p.bank),
                (false, _) => format!("{}, ", p.port),
            };
            Candidate {
                display: format!("{}, {} ({})", p.port, p.bank, p.name),
                replacement,
            }
        })
        .collect()
}

/// The banks that have the typed port (SIO: the output bank): `0 (IN7)`.
fn banks(
    spec: &CommandSpec,
    index: usize,
    typed: &[&str],
    word: &str,
    profile: &Profile,
) -> Vec<Candidate> {
    let writes = spec.operand_for(Field::Value).is_some();
    let port = spec
        .operands
        .iter()
        .position(|o| o.kind == OperandKind::Port)
        .and_then(|at| typed.get(at))
        .and_then(|t| t.parse::<u8>().ok());
    let Some(port) = port else {
        return Vec::new();
    };
    let more_after = spec.operands.len() > index + 1;
    profile
        .io_ports
        .iter()
        .filter(|p| p.port == port && (p.is_output() || !writes))
        .filter(|p| p.bank.to_string().starts_with(word))
        .map(|p| Candidate {
            display: format!("{} ({})", p.bank, p.name),
            replacement: if more_after {
                format!("{}, ", p.bank)
            } else {
                p.bank.to_string()
            },
        })
        .collect()
}

fn params(list: &[Param], prefix: &str, display: impl Fn(&Param) -> String) -> Vec<Candidate> {
    list.iter()
        .filter(|p| p.ident.starts_with(prefix))
        .map(|p| Candidate {
            display: display(p),
            replacement: format!("{}, ", p.ident),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::tmcl::profile::catalogue;

    /// (display, replacement) of the candidates at the end of `line`.
    fn offered(line: &str, profile: &Profile) -> Vec<(String, String)> {
        match complete(line, line.len(), profile) {
            Completion::Words { candidates, .. } => candidates
                .into_iter()
                .map(|c| (c.display, c.replacement))
                .collect(),
            Completion::File { .. } => panic!("a file for {line:?}"),
        }
    }

    fn replacements(line: &str, profile: &Profile) -> Vec<String> {
        offered(line, profile).into_iter().map(|(_, r)| r).collect()
    }

    #[test]
    fn gio_offers_every_mapped_port_with_its_bank_and_name() {
        let p = Profile::builtin();
        let all = offered("GIO ", &p);
        assert_eq!(all.len(), p.io_ports.len());
        assert!(
            all.contains(&("7, 0 (IN7)".into(), "7, 0".into())),
            "{all:?}"
        );
        assert!(
            all.contains(&("0, 1 (IN0_A/D)".into(), "0, 1".into())),
            "{all:?}"
        );
        assert_eq!(replacements("A GIO 0", &p), ["0, 1", "0, 2"]);
        assert_eq!(replacements("GIO 9", &p), Vec::<String>::new());
        // The bank of a typed port.
        assert_eq!(
            offered("GIO 0, ", &p),
            [
                ("1 (IN0_A/D)".to_string(), "1".to_string()),
                ("2 (OUT_0)".to_string(), "2".to_string())
            ]
        );
        assert_eq!(replacements("GIO 7,", &p), ["0"]);
    }

    #[test]
    fn sio_offers_the_outputs_and_leaves_room_for_the_value() {
        let p = Profile::builtin();
        assert_eq!(replacements("SIO ", &p), ["0, 2, ", "1, 2, ", "2, 2, "]);
        assert_eq!(replacements("SIO 1, ", &p), ["2, "]);
        // Port 3 is an input: SIO has no bank for it.
        assert!(replacements("SIO 3, ", &p).is_empty());
        assert!(replacements("SIO 1, 2, ", &p).is_empty());
    }

    #[test]
    fn ports_come_from_each_profile_s_own_map() {
        let six = catalogue::by_name("tmcm-6110").unwrap();
        let gio: Vec<String> = replacements("GIO ", &six);
        assert_eq!(gio.len(), six.io_ports.len());
        assert!(gio.contains(&"8, 1".to_string()), "{gio:?}");
        assert_eq!(replacements("SIO ", &six).len(), 8);
        // Without a map there is nothing to offer.
        assert!(replacements("GIO ", &catalogue::generic()).is_empty());
    }
}
