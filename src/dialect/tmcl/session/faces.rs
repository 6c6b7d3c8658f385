//! What the faces show of a TMCL session ([`Faces`]): the prompt, the banner, the grammar,
//! helpers and help.

use std::io::{self, Write};
use std::sync::Arc;

use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::protocol::ModuleName;
use crate::dialect::tmcl::protocol::line::address_char;
use crate::dialect::tmcl::protocol::validate::Mode;
use crate::dialect::tmcl::{ModuleLines, TmclGrammar, help, helpers};
use crate::dialect::{Faces, Grammar, Helper};
use crate::session::SessionError;

use super::{TmclSession, WireMode};

impl Faces for TmclSession {
    /// The target's address character, and `[bin]` in binary mode.
    fn prompt(&self) -> String {
        let c = address_char(self.target).unwrap_or('?');
        match self.module_state(self.target) {
            Some((WireMode::Binary, _)) => format!("{c}[bin]> "),
            _ => format!("{c}> "),
        }
    }

    /// What the module said it is and the profile used (`TMCM-6110, firmware 6110V131, profile
    /// tmcm-6110 (built in)`), with the target's address when it is not the first.
    fn banner(&self) -> String {
        match self.target {
            1 => self.identity_line(),
            n => format!("{}, {}", self.identity_line(), ModuleName(n)),
        }
    }

    /// The profile and mode of the target module, and of every module a line can address.
    fn grammar(&self) -> Arc<dyn Grammar> {
        let mode = self.validation_mode(self.target);
        let grammar = TmclGrammar::new(self.profile.clone(), mode);
        let others = (1..=26).filter(|&m| m != self.target);
        Arc::new(others.fold(grammar, |g, m| g.with_module(m, self.typed_lines(m))))
    }

    fn run_helper(
        &mut self,
        helper: &Helper,
        arg: &str,
        out: &mut dyn Write,
    ) -> Result<(), SessionError> {
        helpers::run(self, helper, arg, out)
    }

    fn help_intro(&self, out: &mut dyn Write) -> io::Result<()> {
        help::intro(out)
    }

    fn help_more(&self) -> &'static str {
        help::MORE
    }

    fn help_topic(&self, topic: &str, out: &mut dyn Write) -> io::Result<bool> {
        help::topic(&self.profile, topic, out)
    }

    fn help_command(&self, word: &str, out: &mut dyn Write) -> io::Result<bool> {
        help::command(&self.profile, word, out)
    }
}

impl TmclSession {
    /// How lines to `module` are read while typed, without asking the bus: with the profile the
    /// session has for it, or — a module it will identify before the first line — with the
    /// target's, assumed until the module answers.
    fn typed_lines(&self, module: u8) -> ModuleLines {
        let unasked = !self.known.contains_key(&module) && !self.modules.contains_key(&module);
        if self.identify_each && !self.no_enter && !self.profile_given && unasked {
            // Reached the way a module of the target's type would be.
            let profile = self.profile.clone();
            let binary =
                self.binary_only || profile.identity.ascii_interface() == AsciiInterface::No;
            let mode = if binary { Mode::Binary } else { Mode::Ascii };
            return ModuleLines {
                profile,
                mode,
                assumed: true,
            };
        }
        ModuleLines::known(self.profile_of(module), self.validation_mode(module))
    }
}
