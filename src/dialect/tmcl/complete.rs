//! Tab completion of TMCL lines, as pure functions of the line and the profile: mnemonics
//! (keeping a typed address character), keywords, axis parameter names for SAP/GAP/STAP/RSAP,
//! global parameter names with their banks for SGP/GGP/STGP/RSGP.

use crate::dialect::grammar::{Candidate, Completion};
use crate::dialect::tmcl::profile::commands::{CommandSpec, OperandKind};
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
    let (command, operand_index) = match tokens.as_slice() {
        [addr, cmd, ..] if addr.len() == 1 && profile.commands.by_mnemonic(addr).is_none() => {
            (*cmd, operand_index(tokens.len() - 2, before))
        }
        [cmd, ..] => (*cmd, operand_index(tokens.len() - 1, before)),
        [] => return words(Vec::new()),
    };
    let Some(spec) = spec_of(command, profile) else {
        return words(Vec::new());
    };
    words(operand_candidates(spec, operand_index, word, profile))
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

fn operand_candidates(
    spec: &CommandSpec,
    index: usize,
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
        _ => Vec::new(),
    }
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
