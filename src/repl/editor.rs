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
use crate::dialect::grammar::Check;
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

    /// What a typed line is so far (helper lines: whether the helper exists).
    pub fn check(&self, text: &str) -> Check {
        let text = text.trim();
        if crate::shell::words::only_remark(text) || crate::shell::words::everyday(text).is_some() {
            return Check::Valid;
        }
        if let Some(rest) = text.strip_prefix(':') {
            let name = rest.split_whitespace().next().unwrap_or("");
            let dialect = self.grammar.dialect();
            let on_its_way = !rest.contains(char::is_whitespace)
                && helpers::available(dialect).any(|h| h.name().starts_with(name));
            return match helpers::find(name, dialect) {
                Ok(_) => Check::Valid,
                Err(_) if on_its_way => Check::Incomplete,
                Err(e) => Check::Invalid(e.to_string()),
            };
        }
        self.grammar.check(text)
    }

    /// Whether a typed line would be refused.
    pub fn is_invalid(&self, text: &str) -> bool {
        matches!(self.check(text), Check::Invalid(_))
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
        // An invalid line's hint is why; a line on its way gets the command's or parameter's.
        match self.check(text) {
            Check::Invalid(reason) | Check::Assumed(reason) => Some(format!("  ← {reason}")),
            _ => self.grammar.hint(text),
        }
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
