//! The TMCL session as the faces see every session ([`DialectSession`]): replies decoded with the
//! profile, the prompt, the grammar, helpers, help, scan and scripts.

use std::io::{self, Write};
use std::sync::Arc;
use std::time::Duration;

use crate::commission::ParamDevice;
use crate::dialect::session::{BusScan, DialectSession, Reply};
use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::protocol::ModuleName;
use crate::dialect::tmcl::protocol::line::address_char;
use crate::dialect::tmcl::protocol::validate::Mode;
use crate::dialect::tmcl::{ModuleLines, TmclGrammar, config, help, helpers, render, scan};
use crate::dialect::{Dialect, Grammar, Helper};
use crate::exit::Failure;
use crate::script::Script;
use crate::session::SessionError;
use crate::session::core::SessionCore;
use crate::session::transcript::{Header, Transcript};

use super::{TmclSession, WireMode};

impl DialectSession for TmclSession {
    fn dialect(&self) -> &'static Dialect {
        &super::super::DIALECT
    }

    fn core(&self) -> &SessionCore {
        &self.core
    }

    fn core_mut(&mut self) -> &mut SessionCore {
        &mut self.core
    }

    fn execute(&mut self, line: &str) -> Result<Reply, SessionError> {
        let exchange = self.exchange_line(line)?;
        Ok(Reply {
            shown: exchange.shown(),
            decoded: render::decode(&exchange, &self.profile_of(exchange.module)).text,
            refusal: exchange.refusal(),
            forms: Arc::new(exchange),
        })
    }

    fn stop_motion(&mut self) -> Vec<String> {
        self.urgently(Self::stop_everything)
    }

    fn target_address(&self) -> Option<u32> {
        Some(self.target.into())
    }

    /// Each motor of the modules this session or its programs set moving, read once.
    fn turning_at_exit(&mut self) -> Vec<String> {
        let mut modules = super::modules(&self.core.moved);
        modules.extend(super::modules(&self.core.running));
        modules.sort_unstable();
        modules.dedup();
        modules
            .into_iter()
            .flat_map(|module| crate::dialect::tmcl::program::turning_at_exit(self, module))
            .collect()
    }

    /// Every module goes back to the mode it was found in (unless `--stay-ascii`).
    fn close(&mut self) -> Vec<String> {
        if self.core.options.stay_ascii {
            return Vec::new();
        }
        // Mode restores carry no value for anyone: they need not wait for a suspect line.
        self.urgently(Self::restore_modes)
    }

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

    /// As at the start: the profile of a module that does not name itself (the given one, or
    /// the default); the identification notes name the others'.
    fn header(&self) -> Header {
        config::session_header(&self.fallback, self.profile_given)
    }

    /// A transcript started mid-session begins with what the session knows of each module.
    fn set_transcript(&mut self, transcript: Option<Transcript>) {
        self.core.wire.transcript = transcript;
        self.note_identifications();
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

    fn param_device(&mut self) -> &mut dyn ParamDevice {
        self
    }

    fn scan_bus(&mut self, addresses: &[u8], per_reply: Duration) -> Result<BusScan, SessionError> {
        scan::bus_scan(self, addresses, per_reply)
    }

    fn run_script(
        self: Box<Self>,
        script: &Script,
    ) -> (Box<dyn DialectSession>, Result<(), Failure>) {
        let (session, result) = script.run(
            *self,
            |s, text| s.annotate(text),
            |s| s.take_notices(),
            |s| s.transcript().is_some_and(|t| t.failure().is_some()),
            |engine, s, files| {
                super::super::script::register(engine, s, files);
                crate::script::commission::register(engine, s, files);
            },
        );
        (Box::new(session), result)
    }

    /// Asks every module again what it is and re-enters ASCII mode on those that were in it.
    fn reenter(&mut self) -> Result<(), SessionError> {
        self.reenter_modules()
    }
}

impl TmclSession {
    /// How lines to `module` are read while typed, without asking the bus: with the profile the
    /// session has for it, or — a module it will identify before the first line — with the
    /// target's, assumed until the module answers.
    fn typed_lines(&self, module: u8) -> ModuleLines {
        let unasked = !self.known.contains_key(&module) && !self.modules.contains_key(&module);
        if self.identify_each && self.core.options.enter && !self.profile_given && unasked {
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
