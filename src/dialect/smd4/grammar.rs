//! SMD4 requests as the line editor sees them: the hierarchical mnemonics and argument values
//! completed from the command table, hints with usage, unit and range, and the validator.

use crate::dialect::Dialect;
use crate::dialect::grammar::{Completion, Grammar};

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

    fn is_invalid(&self, text: &str) -> bool {
        match Request::parse(text) {
            Ok(request) => protocol::validate(&request, &self.spec.commands).is_err(),
            Err(_) => true,
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
        &["exit", "addressing"]
    }
}
