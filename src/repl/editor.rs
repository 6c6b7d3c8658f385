//! The rustyline helper: completion, hints and highlighting, each a thin wrapper over the pure
//! function in `complete` and the session's [`Grammar`].

use std::borrow::Cow;
use std::sync::Arc;

use crossterm::style::Stylize;
use rustyline::completion::{Completer, FilenameCompleter, Pair};
use rustyline::highlight::{CmdKind, Highlighter};
use rustyline::hint::Hinter;
use rustyline::validate::Validator;
use rustyline::{Context, Helper};

use crate::dialect::Grammar;
use crate::shell::helpers;

use super::complete::{Completion, complete};

/// Completion, hints and highlighting for the REPL.
pub struct ReplHelper {
    /// What typed lines mean: the session's grammar, asked for again before each prompt.
    pub grammar: Arc<dyn Grammar>,
    files: FilenameCompleter,
    /// Whether to colour.
    pub color: bool,
}

impl ReplHelper {
    /// A helper for lines of `grammar`.
    pub fn new(grammar: Arc<dyn Grammar>, color: bool) -> Self {
        ReplHelper {
            grammar,
            files: FilenameCompleter::new(),
            color,
        }
    }

    /// Whether a typed line would be refused (helper lines: whether the helper exists).
    pub fn is_invalid(&self, text: &str) -> bool {
        let text = text.trim();
        if text.is_empty() || crate::shell::words::everyday(text).is_some() {
            return false;
        }
        if let Some(rest) = text.strip_prefix(':') {
            let name = rest.split_whitespace().next().unwrap_or("");
            return helpers::find(name, self.grammar.dialect()).is_err();
        }
        self.grammar.is_invalid(text)
    }
}

impl Completer for ReplHelper {
    type Candidate = Pair;

    fn complete(
        &self,
        text: &str,
        pos: usize,
        ctx: &Context<'_>,
    ) -> rustyline::Result<(usize, Vec<Pair>)> {
        match complete(text, pos, &*self.grammar) {
            Completion::Words { start, candidates } => Ok((
                start,
                candidates
                    .into_iter()
                    .map(|c| Pair {
                        display: c.display,
                        replacement: c.replacement,
                    })
                    .collect(),
            )),
            Completion::File { .. } => self.files.complete(text, pos, ctx),
        }
    }
}

impl Hinter for ReplHelper {
    type Hint = String;

    fn hint(&self, text: &str, pos: usize, _ctx: &Context<'_>) -> Option<String> {
        if pos != text.len() {
            return None;
        }
        self.grammar.hint(text)
    }
}

impl Highlighter for ReplHelper {
    fn highlight<'l>(&self, text: &'l str, _pos: usize) -> Cow<'l, str> {
        if self.color && self.is_invalid(text) {
            Cow::Owned(text.red().to_string())
        } else {
            Cow::Borrowed(text)
        }
    }

    fn highlight_hint<'h>(&self, hint: &'h str) -> Cow<'h, str> {
        if self.color {
            Cow::Owned(hint.dark_grey().to_string())
        } else {
            Cow::Borrowed(hint)
        }
    }

    fn highlight_char(&self, _line: &str, _pos: usize, _kind: CmdKind) -> bool {
        self.color
    }
}

impl Validator for ReplHelper {}

impl Helper for ReplHelper {}
