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
use crate::protocol::tmcl::line;
use crate::protocol::tmcl::validate::{Mode, validate};
use crate::shell::helpers;

use super::complete::{Completion, complete};
use super::hint::hint;

/// Completion, hints and highlighting for the REPL.
pub struct ReplHelper {
    profile: Arc<Profile>,
    files: FilenameCompleter,
    /// The mode lines are validated for (ASCII, or binary after `:bin`).
    pub mode: Mode,
    /// Whether to colour.
    pub color: bool,
}

impl ReplHelper {
    /// A helper for this profile.
    pub fn new(profile: Arc<Profile>, color: bool) -> Self {
        ReplHelper {
            profile,
            files: FilenameCompleter::new(),
            mode: Mode::Ascii,
            color,
        }
    }

    /// Whether a typed line would be refused (helper lines: whether the helper exists).
    pub fn is_invalid(&self, text: &str) -> bool {
        let text = text.trim();
        if text.is_empty() {
            return false;
        }
        if let Some(rest) = text.strip_prefix(':') {
            let name = rest.split_whitespace().next().unwrap_or("");
            return helpers::find(name).is_err();
        }
        match line::parse(text, &self.profile) {
            Ok(parsed) => validate(&parsed, &self.profile, self.mode).is_err(),
            Err(_) => true,
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
        match complete(text, pos, &self.profile) {
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
        (pos == text.len())
            .then(|| hint(text, &self.profile))
            .flatten()
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
