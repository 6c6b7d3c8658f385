//! Tab completion, as a pure function of the line and the profile: mnemonics (keeping a typed
//! address character), keywords, axis parameter names for SAP/GAP/STAP/RSAP, global parameter
//! names with their banks for SGP/GGP/STGP/RSGP, helper commands and their arguments.

use crate::dialect::Dialect;
use crate::dialect::smd4::protocol::Smd4Spec;
use crate::dialect::tmcl::profile::{Param, Profile};
use crate::dialect::tmcl::protocol::commands::{CommandSpec, OperandKind};
use crate::shell::helpers::{self, ArgKind};

/// A completion: what is shown in the list, and what replaces the word.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Candidate {
    /// Shown in the candidate list.
    pub display: String,
    /// Inserted in place of the word.
    pub replacement: String,
}

/// What the word at the cursor should be completed as.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Completion {
    /// Candidates replacing the word starting at byte `start`.
    Words {
        /// Where the word starts.
        start: usize,
        /// The candidates.
        candidates: Vec<Candidate>,
    },
    /// A file name starting at byte `start` (left to a filename completer).
    File {
        /// Where the word starts.
        start: usize,
    },
}

/// What typed lines mean: the TMCL tables or the SMD4 command table.
#[derive(Debug, Clone, Copy)]
pub enum Grammar<'a> {
    /// TMCL command lines.
    Tmcl(&'a Profile),
    /// SMD4 requests.
    Smd4(&'a Smd4Spec),
}

impl Grammar<'_> {
    fn dialect(&self) -> Dialect {
        match self {
            Grammar::Tmcl(_) => Dialect::Tmcl,
            Grammar::Smd4(_) => Dialect::Smd4,
        }
    }
}

/// Completes the word ending at `pos` in `line`.
pub fn complete(line: &str, pos: usize, grammar: Grammar) -> Completion {
    let before = &line[..pos];
    let start = before.rfind([' ', ',', '\t']).map_or(0, |i| i + 1);
    let word = &before[start..];
    if let Some(rest) = before.trim_start().strip_prefix(':') {
        return complete_helper(rest, start, word, grammar);
    }
    match grammar {
        Grammar::Tmcl(profile) => complete_tmcl(before, start, word, profile),
        Grammar::Smd4(spec) => {
            let found = crate::dialect::smd4::protocol::complete(&spec.commands, before);
            let candidates = found
                .candidates
                .into_iter()
                .map(|c| Candidate {
                    display: c.display,
                    replacement: c.replacement,
                })
                .collect();
            Completion::Words {
                start: found.start,
                candidates,
            }
        }
    }
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

fn mnemonics(word: &str, profile: &Profile) -> Vec<Candidate> {
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

fn complete_helper(rest: &str, start: usize, word: &str, grammar: Grammar) -> Completion {
    let dialect = grammar.dialect();
    let Some((name, _)) = rest.split_once(' ') else {
        let candidates = helpers::available(dialect)
            .filter(|h| h.name.starts_with(&rest.to_ascii_lowercase()))
            .map(|h| Candidate {
                display: format!(":{}", h.name),
                replacement: format!(":{} ", h.name),
            })
            .collect();
        return Completion::Words { start, candidates };
    };
    let Ok(helper) = helpers::find(name, dialect) else {
        return Completion::Words {
            start,
            candidates: Vec::new(),
        };
    };
    let lower = word.to_ascii_lowercase();
    let fixed = |options: &[&str]| {
        options
            .iter()
            .filter(|o| o.starts_with(&lower))
            .map(|o| Candidate {
                display: o.to_string(),
                replacement: o.to_string(),
            })
            .collect()
    };
    let candidates = match helper.arg {
        ArgKind::File => return Completion::File { start },
        ArgKind::Echo => fixed(&["char", "line", "none"]),
        ArgKind::Param => name_candidates(grammar, &lower),
        ArgKind::Topic => {
            let mut topics: Vec<&str> = match grammar {
                Grammar::Tmcl(_) => vec!["params", "exit", "ascii"],
                Grammar::Smd4(_) => vec!["exit", "addressing"],
            };
            topics.extend(helpers::available(dialect).map(|h| h.name));
            let mut out: Vec<Candidate> = fixed(&topics);
            if let Grammar::Tmcl(profile) = grammar {
                out.extend(mnemonics(word, profile));
            }
            out
        }
        ArgKind::Snapshot if first_argument(rest) => fixed(&["save", "diff", "restore"]),
        ArgKind::Record if !first_argument(rest) => name_candidates(grammar, &lower),
        ArgKind::Snapshot | ArgKind::Record => return Completion::File { start },
        ArgKind::None | ArgKind::Module | ArgKind::Address => Vec::new(),
    };
    Completion::Words { start, candidates }
}

/// The names starting with `prefix` (lower case), as candidates.
fn name_candidates(grammar: Grammar, prefix: &str) -> Vec<Candidate> {
    names(grammar)
        .into_iter()
        .filter(|n| n.to_ascii_lowercase().starts_with(prefix))
        .map(|n| Candidate {
            display: n.clone(),
            replacement: n,
        })
        .collect()
}

/// Whether the cursor is in a helper's first argument (`rest` is the line after the colon).
fn first_argument(rest: &str) -> bool {
    let args = rest.split_once(' ').map_or("", |(_, a)| a.trim_start());
    !args.contains(char::is_whitespace)
}

/// Parameter identifiers (TMCL) or mnemonics (SMD4), for `:params` completion.
fn names(grammar: Grammar) -> Vec<String> {
    match grammar {
        Grammar::Tmcl(profile) => profile
            .axis
            .iter()
            .chain(&profile.global)
            .map(|p| p.ident.clone())
            .collect(),
        Grammar::Smd4(spec) => spec
            .commands
            .mnemonics()
            .map(|m| m.to_ascii_lowercase())
            .collect(),
    }
}

#[cfg(test)]
mod tests;
