//! SMD4 configured: its command table is built in, so what the command line adds are the session
//! flags each session reads for itself.

use std::io::{self, Write};
use std::path::Path;

use crate::commission::ParamRef;
use crate::dialect::replay::ReplayError;
use crate::dialect::replay::parse::Entry;
use crate::dialect::{Dialect, DialectConfig, DialectError, DialectSession, Opening};
use crate::session::SessionError;
use crate::session::transcript::Header;
use crate::sim::Device;

use super::protocol::Smd4Spec;
use super::session::Smd4Session;
use super::sim::{Smd4Sim, Smd4SimOptions};

/// SMD4 with its built-in command table.
pub struct Smd4Config;

/// SMD4 needs no tables from the command line (`--profile` is TMCL's).
pub fn configure(_: Option<&Path>) -> Result<Box<dyn DialectConfig>, DialectError> {
    Ok(Box::new(Smd4Config))
}

/// The transcript header of an SMD4 session.
pub fn header() -> Header {
    Header {
        dialect: super::DIALECT.name.to_string(),
        module: "SMD4".to_string(),
        profile: None,
        profiles: None,
        version: env!("CARGO_PKG_VERSION").to_string(),
    }
}

impl DialectConfig for Smd4Config {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn header(&self) -> Header {
        header()
    }

    fn simulated_module(&self) -> String {
        "SMD4".to_string()
    }

    fn simulator(&self) -> Box<dyn Device> {
        Box::new(Smd4Sim::new(Smd4SimOptions::default()))
    }

    #[cfg(feature = "cli")]
    fn served_simulator(
        &self,
        flags: &crate::dialect::CommandLine,
        state: Option<&Path>,
        verbose: bool,
    ) -> Result<Box<dyn Device>, crate::sim::error::SimStartError> {
        super::sim::flags::served(flags, state, verbose)
    }

    fn open(&self, opening: Opening<'_>) -> Result<Box<dyn DialectSession>, SessionError> {
        let smd4 = super::flags::options(opening.flags);
        let session = Smd4Session::open(opening.link, opening.options, smd4, opening.transcript)?;
        Ok(Box::new(session))
    }

    fn write_params(&self, filter: &str, out: &mut dyn Write) -> io::Result<bool> {
        super::params::write_params(filter, out)
    }

    fn params_json(&self, filter: &str) -> Result<Vec<crate::json::Value>, DialectError> {
        super::params::params_json(filter)
    }

    fn snapshot_params(&self) -> Vec<ParamRef> {
        super::commission::spec_params(Smd4Spec::builtin())
    }

    fn replay(
        &self,
        entries: &[Entry],
        _: Option<&Header>,
        name: &str,
        wait_ms: u64,
    ) -> Result<String, ReplayError> {
        super::replay::script(entries, name, wait_ms)
    }
}
