//! What typed lines mean, as the REPL's completion, hints, highlighting and validation need it.
//! A session hands out its grammar as an owned object ([`Grammar`] behind an `Arc`), because the
//! line editor uses it while the session is busy elsewhere; the REPL asks for a fresh one before
//! each prompt, so commands that change it (TMCL `:bin`) take effect.

use super::Dialect;

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

/// What a typed line is so far, for the highlighting and the hint.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Check {
    /// The session would send it.
    Valid,
    /// Not yet a line the session would send, but typing on can make it one (a word that
    /// completes, an argument still missing).
    Incomplete,
    /// Nothing typed after it makes it valid; the reason.
    Invalid(String),
    /// Refused by the profile a module not identified yet is taken to have, which it may not
    /// have: the module decides once the line is sent (shown neutral, with the reason).
    Assumed(String),
}

/// Whether completing the last word of `line` offers a longer word: the line is on its way.
pub fn completes_further(grammar: &dyn Grammar, line: &str) -> bool {
    let Completion::Words { start, candidates } = grammar.complete(line, line.len()) else {
        return false;
    };
    let typed = line.get(start..).unwrap_or_default().to_ascii_lowercase();
    candidates.iter().any(|c| {
        let candidate = c.replacement.trim_end().to_ascii_lowercase();
        candidate.len() > typed.len() && candidate.starts_with(&typed)
    })
}

/// A dialect's typed lines, for the line editor. Helper lines (`:…`) are the REPL's business;
/// these methods see only the dialect's own lines, except [`Grammar::hint`], which sees every
/// line and answers `None` where it has nothing to say.
pub trait Grammar {
    /// The dialect whose lines these are (its helpers are completed too).
    fn dialect(&self) -> &'static Dialect;

    /// Completes the word ending at `pos` of a typed line.
    fn complete(&self, line: &str, pos: usize) -> Completion;

    /// The hint shown after `line` with the cursor at its end (`  ← …`).
    fn hint(&self, line: &str) -> Option<String>;

    /// Whether the session would send `line`, or it is on its way to a line it would send, or
    /// nothing typed after it can make it one (and why).
    fn check(&self, line: &str) -> Check;

    /// The names `:params`, `:watch` and `:record` complete (parameter identifiers, mnemonics).
    fn names(&self) -> Vec<String>;

    /// The `:help` topics besides helper names, in the order they are offered.
    fn topics(&self) -> &'static [&'static str];

    /// More `:help` completions for `word` (TMCL: command mnemonics).
    fn topic_words(&self, word: &str) -> Vec<Candidate> {
        let _ = word;
        Vec::new()
    }
}
