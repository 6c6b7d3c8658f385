//! The rustyline helper: completion, hints and highlighting, each a thin wrapper over the pure
//! functions in `complete` and `hint`.

use std::borrow::Cow;
use std::sync::Arc;

use crossterm::style::Stylize;
use rustyline::completion::{Completer, FilenameCompleter, Pair};
use rustyline::highlight::{CmdKind, Highlighter};
use rustyline::hint::Hinter;
use rustyline::validate::Validator;
use rustyline::{Context, Helper};

use crate::profile::Profile;
use crate::protocol::Dialect;
use crate::protocol::smd4::{self, Request, Smd4Spec};
use crate::protocol::tmcl::line;
use crate::protocol::tmcl::validate::{Mode, validate};
use crate::shell::helpers;

use super::complete::{Completion, Grammar, complete};
use super::hint::hint;

/// What the REPL's lines are checked against.
pub enum Tables {
    /// A TMCL module's profile.
    Tmcl(Arc<Profile>),
    /// The SMD4 command table.
    Smd4(&'static Smd4Spec),
}

/// Completion, hints and highlighting for the REPL.
pub struct ReplHelper {
    tables: Tables,
    files: FilenameCompleter,
    /// The mode lines are validated for (ASCII, or binary after `:bin`).
    pub mode: Mode,
    /// Whether to colour.
    pub color: bool,
}

impl ReplHelper {
    /// A helper for these tables.
    pub fn new(tables: Tables, color: bool) -> Self {
        ReplHelper {
            tables,
            files: FilenameCompleter::new(),
            mode: Mode::Ascii,
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
            return helpers::find(name, self.dialect()).is_err();
        }
        match &self.tables {
            Tables::Tmcl(profile) => match line::parse(text, profile) {
                Ok(parsed) => validate(&parsed, profile, self.mode).is_err(),
                Err(_) => true,
            },
            Tables::Smd4(spec) => match Request::parse(text) {
                Ok(request) => smd4::validate(&request, &spec.commands).is_err(),
                Err(_) => true,
            },
        }
    }

    fn dialect(&self) -> Dialect {
        match self.tables {
            Tables::Tmcl(_) => Dialect::Tmcl,
            Tables::Smd4(_) => Dialect::Smd4,
        }
    }

    fn grammar(&self) -> Grammar<'_> {
        match &self.tables {
            Tables::Tmcl(profile) => Grammar::Tmcl(profile),
            Tables::Smd4(spec) => Grammar::Smd4(spec),
        }
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
        match complete(text, pos, self.grammar()) {
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
        match &self.tables {
            Tables::Tmcl(profile) => hint(text, profile),
            Tables::Smd4(spec) => {
                smd4::hint_for_line(&spec.commands, text).map(|h| format!("  ← {h}"))
            }
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
