//! The TMCL session as the faces see every session's wire ([`DialectSession`]): replies decoded
//! with the profile, stops, the transcript, the commissioning device, scan and scripts.

use std::sync::Arc;
use std::time::Duration;

use crate::commission::ParamDevice;
use crate::dialect::Dialect;
use crate::dialect::session::{BusScan, DialectSession, Reply, run_script};
use crate::dialect::tmcl::{config, render, scan};
use crate::exit::Failure;
use crate::script::Script;
use crate::session::SessionError;
use crate::session::core::SessionCore;
use crate::session::transcript::{Header, Transcript};

use super::TmclSession;

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
        if self.stay_ascii {
            return Vec::new();
        }
        // Mode restores carry no value for anyone: they need not wait for a suspect line.
        self.urgently(Self::restore_modes)
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
        run_script(*self, script, super::super::script::register)
    }

    /// Asks every module again what it is and re-enters ASCII mode on those that were in it.
    fn reenter(&mut self) -> Result<(), SessionError> {
        self.reenter_modules()
    }
}
