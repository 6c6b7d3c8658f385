//! The echo dialect configured: it reads no tables, opens sessions and builds its simulator.

use std::io::{self, Write};
use std::path::Path;

use tmclsh::commission::ParamRef;
use tmclsh::dialect::replay::ReplayError;
use tmclsh::dialect::replay::parse::Entry;
use tmclsh::dialect::{CommandLine, Dialect, DialectConfig, DialectError, DialectSession, Opening};
use tmclsh::session::SessionError;
use tmclsh::session::transcript::Header;
use tmclsh::sim::Device;
use tmclsh::sim::error::SimStartError;

use super::session::{EchoSession, NO_PARAMS};
use super::sim::EchoDevice;

/// The echo dialect, ready to open sessions.
pub struct EchoConfig;

/// The echo dialect has no tables: `--profile` means nothing to it.
pub fn configure(_: Option<&Path>) -> Result<Box<dyn DialectConfig>, DialectError> {
    Ok(Box::new(EchoConfig))
}

/// The header of an echo session's transcripts.
pub fn header() -> Header {
    Header {
        dialect: super::DIALECT.name.to_string(),
        module: super::MODULE.to_string(),
        profile: None,
        profiles: None,
        version: env!("CARGO_PKG_VERSION").to_string(),
    }
}

impl DialectConfig for EchoConfig {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn header(&self) -> Header {
        header()
    }

    fn simulated_module(&self) -> String {
        super::MODULE.to_string()
    }

    fn simulator(&self) -> Box<dyn Device> {
        Box::new(EchoDevice::default())
    }

    fn served_simulator(
        &self,
        _: &CommandLine,
        _: Option<&Path>,
        _: bool,
    ) -> Result<Box<dyn Device>, SimStartError> {
        Ok(self.simulator())
    }

    fn open(&self, opening: Opening<'_>) -> Result<Box<dyn DialectSession>, SessionError> {
        Ok(Box::new(EchoSession::open(opening)))
    }

    fn write_params(&self, _: &str, _: &mut dyn Write) -> io::Result<bool> {
        eprintln!("{NO_PARAMS}");
        Ok(false)
    }

    fn params_json(&self, _: &str) -> Result<Vec<serde_json::Value>, DialectError> {
        Err(DialectError::NoParams(NO_PARAMS.to_string()))
    }

    fn snapshot_params(&self) -> Vec<ParamRef> {
        Vec::new()
    }

    fn replay(
        &self,
        _: &[Entry],
        _: Option<&Header>,
        _: &str,
        _: u64,
    ) -> Result<String, ReplayError> {
        Err(ReplayError::Nothing { dialect: "echo" })
    }
}
