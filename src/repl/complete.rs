//! Tab completion in the REPL, as a pure function of the line and the session's grammar: helper
//! commands and their arguments here; the dialect's own lines by its [`Grammar`].

pub use crate::dialect::grammar::{Candidate, Completion};
use crate::dialect::{ArgKind, Grammar};
use crate::shell::{helpers, values};

/// Completes the word ending at `pos` in `line`.
pub fn complete(line: &str, pos: usize, grammar: &dyn Grammar) -> Completion {
    let before = &line[..pos];
    let start = before.rfind([' ', ',', '\t']).map_or(0, |i| i + 1);
    let word = &before[start..];
    if let Some(rest) = before.trim_start().strip_prefix(':') {
        return complete_helper(rest, start, word, grammar);
    }
    grammar.complete(line, pos)
}

fn complete_helper(rest: &str, start: usize, word: &str, grammar: &dyn Grammar) -> Completion {
    let dialect = grammar.dialect();
    let Some((name, _)) = rest.split_once(' ') else {
        let candidates = helpers::available(dialect)
            .filter(|h| h.name().starts_with(&rest.to_ascii_lowercase()))
            .map(|h| Candidate {
                display: format!(":{}", h.name()),
                replacement: format!(":{} ", h.name()),
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
        // `:params --values --motor N`: its flags, then names.
        ArgKind::Param if lower.starts_with('-') => fixed(&[values::FLAG, values::MOTOR]),
        ArgKind::Param => name_candidates(grammar, &lower),
        ArgKind::Topic => {
            let mut topics: Vec<&str> = grammar.topics().to_vec();
            topics.extend(helpers::available(dialect).map(|h| h.name()));
            topics.extend(crate::dialect::functions::names(dialect));
            let mut seen = std::collections::HashSet::new();
            topics.retain(|t| seen.insert(*t));
            let mut out: Vec<Candidate> = fixed(&topics);
            out.extend(grammar.topic_words(word));
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
fn name_candidates(grammar: &dyn Grammar, prefix: &str) -> Vec<Candidate> {
    grammar
        .names()
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

#[cfg(test)]
mod tests;
