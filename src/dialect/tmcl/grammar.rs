//! TMCL lines as the line editor sees them: completion and hints from the profile, and the
//! validator of the mode the target module is in (ASCII, or binary after `:bin`).

use std::sync::Arc;

use crate::dialect::Dialect;
use crate::dialect::grammar::{Candidate, Completion, Grammar};

use super::profile::Profile;
use super::protocol::line;
use super::protocol::validate::{Mode, validate};
use super::{complete, hint};

/// The profile, and the mode lines are validated for.
pub struct TmclGrammar {
    profile: Arc<Profile>,
    mode: Mode,
}

impl TmclGrammar {
    /// Lines for modules of `profile`, checked as `mode` takes them.
    pub fn new(profile: Arc<Profile>, mode: Mode) -> Self {
        TmclGrammar { profile, mode }
    }
}

impl Grammar for TmclGrammar {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn complete(&self, line: &str, pos: usize) -> Completion {
        complete::complete(line, pos, &self.profile)
    }

    fn hint(&self, line: &str) -> Option<String> {
        hint::hint(line, &self.profile)
    }

    fn is_invalid(&self, text: &str) -> bool {
        match line::parse(text, &self.profile) {
            Ok(parsed) => validate(&parsed, &self.profile, self.mode).is_err(),
            Err(_) => true,
        }
    }

    /// Parameter identifiers, axis then global.
    fn names(&self) -> Vec<String> {
        self.profile
            .axis
            .iter()
            .chain(&self.profile.global)
            .map(|p| p.ident.clone())
            .collect()
    }

    fn topics(&self) -> &'static [&'static str] {
        &["params", "exit", "ascii"]
    }

    /// Command mnemonics.
    fn topic_words(&self, word: &str) -> Vec<Candidate> {
        complete::mnemonics(word, &self.profile)
    }
}
