//! SMD4 requests as the line editor sees them: the hierarchical mnemonics and argument values
//! completed from the command table, hints with usage, unit and range, and the validator.

use crate::dialect::grammar::{Check, Completion, Grammar, completes_further};
use crate::dialect::{Dialect, elsewhere};

use super::protocol::request::without_comment;
use super::protocol::{self, Request, Smd4Spec};

/// The SMD4 command table.
pub struct Smd4Grammar {
    spec: &'static Smd4Spec,
}

impl Smd4Grammar {
    /// Requests checked against `spec`.
    pub fn new(spec: &'static Smd4Spec) -> Self {
        Smd4Grammar { spec }
    }
}

impl Grammar for Smd4Grammar {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn complete(&self, line: &str, pos: usize) -> Completion {
        let found = protocol::complete(&self.spec.commands, &line[..pos]);
        Completion::Words {
            start: found.start,
            candidates: found.candidates,
        }
    }

    fn hint(&self, line: &str) -> Option<String> {
        protocol::hint_for_line(&self.spec.commands, line).map(|h| format!("  ← {h}"))
    }

    /// Still on its way: a mnemonic or value that completes further, or a comma with its
    /// argument to come.
    fn check(&self, text: &str) -> Check {
        let text = without_comment(&self.spec.commands, text);
        if text.trim().is_empty() {
            return Check::Incomplete;
        }
        let refusal = match Request::parse(text) {
            Ok(request) => match protocol::validate(&request, &self.spec.commands) {
                Ok(_) => return Check::Valid,
                Err(e) => e.to_string(),
            },
            Err(e) => e.to_string(),
        };
        if text.trim_end().ends_with(',') || completes_further(self, text) {
            return Check::Incomplete;
        }
        match elsewhere::line_dialect(&super::DIALECT, text) {
            Some(other) => Check::Invalid(elsewhere::line_message(other)),
            None => Check::Invalid(refusal),
        }
    }

    /// The mnemonics, in lower case.
    fn names(&self) -> Vec<String> {
        self.spec
            .commands
            .mnemonics()
            .map(|m| m.to_ascii_lowercase())
            .collect()
    }

    fn topics(&self) -> &'static [&'static str] {
        &["params", "exit", "addressing"]
    }
}
