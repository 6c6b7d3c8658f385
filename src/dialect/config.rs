//! A dialect configured by the command line: its tables loaded (TMCL: the `--profile` file),
//! ready to open sessions, start simulators, print its parameter table and replay transcripts.

use std::io::{self, Write};
use std::path::Path;

use crate::commission::ParamRef;
use crate::exit::{Exit, ExitStatus};
use crate::link::Link;
use crate::link::can::Framer;
use crate::session::transcript::{Header, Transcript};
use crate::session::{SessionError, SessionOptions};
use crate::sim::Device;
use crate::sim::slcan::CanDevice;

use super::replay::ReplayError;
use super::replay::parse::Entry;
use super::session::{AsAny, DialectSession};
use super::{CommandLine, Dialect, all};

/// What a session is opened for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Purpose {
    /// Typed lines, scripts, snapshots: the target module is contacted at once.
    Talk,
    /// A bus scan: nothing is sent until the scan finds the modules.
    Scan,
}

/// What a session is opened with.
pub struct Opening<'a> {
    /// The link to the modules.
    pub link: Box<dyn Link>,
    /// The settings every dialect has.
    pub options: SessionOptions,
    /// The transcript to write, if any (its header already written).
    pub transcript: Option<Transcript>,
    /// The command line the dialect reads its own session flags from; without one, their
    /// defaults apply.
    pub flags: Option<&'a CommandLine>,
    /// What the session is for.
    pub purpose: Purpose,
}

/// A dialect with its tables loaded.
pub trait DialectConfig: AsAny {
    /// The dialect.
    fn dialect(&self) -> &'static Dialect;

    /// The header of its sessions' transcripts.
    fn header(&self) -> Header;

    /// The module its built-in simulator simulates (`TMCM-142`, `SMD4`).
    fn simulated_module(&self) -> String;

    /// A freshly powered-up simulated module: the built-in simulator of the shell.
    fn simulator(&self) -> Box<dyn Device>;

    /// The simulator `tmclsh sim` serves, set up by its flags; `state` keeps what it stores
    /// across restarts, `verbose` logs its traffic to stderr.
    #[cfg(feature = "cli")]
    fn served_simulator(
        &self,
        flags: &CommandLine,
        state: Option<&Path>,
        verbose: bool,
    ) -> Result<Box<dyn Device>, crate::sim::error::SimStartError>;

    /// The framing that carries its sessions over CAN (`--can`), replies taken at `reply_id`;
    /// `None` for a dialect without one.
    fn can_framer(&self, reply_id: u16) -> Option<Box<dyn Framer>> {
        let _ = reply_id;
        None
    }

    /// Its simulated bus `device` on CAN (`tmclsh sim --slcan`); `None` for a dialect without
    /// a CAN framing.
    fn can_device(&self, device: Box<dyn Device>) -> Option<Box<dyn CanDevice>> {
        let _ = device;
        None
    }

    /// Opens a session.
    fn open(&self, opening: Opening<'_>) -> Result<Box<dyn DialectSession>, SessionError>;

    /// Prints its parameters matching `filter` (`tmclsh params FILTER`); when none matches, says
    /// so on stderr and returns false.
    fn write_params(&self, filter: &str, out: &mut dyn Write) -> io::Result<bool>;

    /// Its parameters matching `filter` as JSON objects (`tmclsh params --json`, fields in
    /// docs/machine-output.md); the error says why none matches.
    fn params_json(&self, filter: &str) -> Result<Vec<crate::json::Value>, DialectError>;

    /// Every parameter a snapshot of its modules holds (to compare two files offline).
    fn snapshot_params(&self) -> Vec<ParamRef>;

    /// A Rhai script replaying the transcript `entries` (whose first header, if any, is
    /// `header`), named `name` in its comments, waiting at most `wait_ms` for live values; the
    /// error says why it replays nothing.
    fn replay(
        &self,
        entries: &[Entry],
        header: Option<&Header>,
        name: &str,
        wait_ms: u64,
    ) -> Result<String, ReplayError>;
}

/// Why a dialect cannot be configured: a refusal (exit 2) of whatever command was asked, as the
/// tables are read before any command runs.
#[derive(Debug, thiserror::Error)]
pub enum DialectError {
    /// Its tables could not be read (TMCL: the `--profile` name or file); the dialect's own
    /// error says why.
    #[error("{0}")]
    Tables(Box<dyn std::error::Error + Send + Sync>),
    /// No parameter matches a filter (`tmclsh params FILTER`), or the tables name none; says
    /// which.
    #[error("{0}")]
    NoParams(String),
}

impl ExitStatus for DialectError {
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}

/// Every dialect configured, in list order: a bad `--profile` is refused whatever the command,
/// as the tables are read before any command runs.
pub struct Configured {
    configs: Vec<Box<dyn DialectConfig>>,
}

impl Configured {
    /// Configures every dialect of the list with the `--profile` file.
    pub fn load(profile: Option<&Path>) -> Result<Configured, DialectError> {
        let configs = all()
            .iter()
            .map(|d| (d.configure)(profile))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Configured { configs })
    }

    /// The configuration of `dialect`.
    pub fn of(&self, dialect: &Dialect) -> &dyn DialectConfig {
        self.configs
            .iter()
            .find(|c| c.dialect() == dialect)
            .map(|c| c.as_ref())
            .expect("every listed dialect is configured")
    }
}
