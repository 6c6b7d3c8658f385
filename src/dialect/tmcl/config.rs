//! TMCL configured by the command line: the module profile (`--profile NAME|FILE`: a built-in
//! profile or a file; by default the TMCM-142's), from which sessions, simulators, the parameter
//! table and replays are made.

use std::io::{self, Write};
use std::path::Path;
use std::sync::Arc;

use clap::ArgMatches;

use crate::commission::ParamRef;
use crate::dialect::replay::parse::Entry;
use crate::dialect::{Dialect, DialectConfig, DialectSession, Opening, Purpose};
use crate::session::SessionError;
use crate::session::transcript::Header;
use crate::sim::Device;

use super::profile::{Profile, catalogue};
use super::session::{Echo, TmclSession};
use super::sim::{Bus, BusOptions};

/// TMCL with the profile of its modules.
pub struct TmclConfig {
    /// The module profile: tables for validation, completion, decoding and the simulator.
    pub profile: Arc<Profile>,
}

/// Loads the profile `--profile` names (a built-in name, alias or module number, or a file), or
/// the default one.
pub fn configure(profile: Option<&Path>) -> Result<Box<dyn DialectConfig>, String> {
    let profile = match profile {
        None => Profile::builtin(),
        Some(arg) => catalogue::resolve(arg).map_err(|e| e.to_string())?,
    };
    Ok(Box::new(TmclConfig { profile }))
}

/// The profile of a configured TMCL, for the subcommands that only TMCL has (`asm`, `download`).
pub fn profile(config: &dyn DialectConfig) -> Option<&Arc<Profile>> {
    config
        .as_any()
        .downcast_ref::<TmclConfig>()
        .map(|c| &c.profile)
}

/// The transcript header of a TMCL session with modules of `profile`.
pub fn header(profile: &Profile) -> Header {
    Header {
        dialect: super::DIALECT.name.to_string(),
        module: profile.module.clone(),
        profile: Some(profile.origin()),
        version: env!("CARGO_PKG_VERSION").to_string(),
    }
}

impl TmclConfig {
    /// The profile the simulator serves: the configured one, but a simulated TMCM-142 behind the
    /// generic profile (which describes no module to simulate).
    fn simulated_profile(&self) -> Arc<Profile> {
        if self.profile.generic {
            Profile::builtin()
        } else {
            self.profile.clone()
        }
    }
}

/// The echo `--echo` (or a configuration file) asks the target module to use, by its word.
fn echo_flag(flags: Option<&ArgMatches>) -> Option<Echo> {
    let mut words = flags?.try_get_raw("echo").ok().flatten()?;
    words.next().and_then(|w| Echo::parse(&w.to_string_lossy()))
}

impl DialectConfig for TmclConfig {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn header(&self) -> Header {
        header(&self.profile)
    }

    fn simulated_module(&self) -> String {
        self.simulated_profile().module.clone()
    }

    fn simulator(&self) -> Box<dyn Device> {
        Box::new(Bus::new(self.simulated_profile(), BusOptions::default()))
    }

    fn served_simulator(
        &self,
        flags: &ArgMatches,
        state: Option<&Path>,
        verbose: bool,
    ) -> Result<Box<dyn Device>, String> {
        super::sim::flags::served(&self.simulated_profile(), flags, state, verbose)
    }

    /// For a conversation, the target module is contacted and its echo set as `--echo` asks.
    fn open(&self, opening: Opening<'_>) -> Result<Box<dyn DialectSession>, SessionError> {
        let Opening {
            link,
            options,
            transcript,
            flags,
            purpose,
        } = opening;
        let profile = self.profile.clone();
        let session = match purpose {
            Purpose::Talk => {
                let mut session = TmclSession::open(link, profile, options, transcript)?;
                if let Some(echo) = echo_flag(flags) {
                    let target = session.target();
                    session.set_echo(target, echo)?;
                }
                session
            }
            Purpose::Scan => TmclSession::open_idle(link, profile, options, transcript)?,
        };
        Ok(Box::new(session))
    }

    fn write_params(&self, filter: &str, out: &mut dyn Write) -> io::Result<bool> {
        super::params::write_params(&self.profile, filter, out)
    }

    fn snapshot_params(&self) -> Vec<ParamRef> {
        super::commission::profile_params(&self.profile)
    }

    fn replay(
        &self,
        entries: &[Entry],
        header: Option<&Header>,
        name: &str,
        wait_ms: u64,
    ) -> Result<String, String> {
        super::replay::script(entries, header, &self.profile, name, wait_ms)
    }
}
