//! TMCL configured by the command line: the module profile (`--profile NAME|FILE`: a built-in
//! profile or a file; by default the TMCM-142's), from which sessions, simulators, the parameter
//! table and replays are made.

use std::io::{self, Write};
use std::path::Path;
use std::sync::Arc;

use crate::commission::ParamRef;
use crate::dialect::replay::ReplayError;
use crate::dialect::replay::parse::Entry;
use crate::dialect::{Dialect, DialectConfig, DialectError, DialectSession, Opening, Purpose};
use crate::link::can::Framer;
use crate::session::SessionError;
use crate::session::transcript::Header;
use crate::sim::Device;
use crate::sim::slcan::CanDevice;

use super::protocol::can::TmclFramer;

use super::flags::switch;
use super::profile::{Profile, catalogue};
use super::session::{Connect, TmclSession};
use super::sim::{Bus, BusOptions};

/// TMCL with the profile of its modules.
pub struct TmclConfig {
    /// The module profile: tables for validation, completion, decoding and the simulator.
    pub profile: Arc<Profile>,
    /// Whether the profile was chosen (`--profile`, its variable or a configuration file): it
    /// then stays whatever the module says it is.
    pub given: bool,
}

/// Loads the profile `--profile` names (a built-in name, alias or module number, or a file), or
/// the default one.
pub fn configure(profile: Option<&Path>) -> Result<Box<dyn DialectConfig>, DialectError> {
    let given = profile.is_some();
    let profile = match profile {
        None => Profile::builtin(),
        Some(arg) => catalogue::resolve(arg).map_err(|e| DialectError::Tables(Box::new(e)))?,
    };
    Ok(Box::new(TmclConfig { profile, given }))
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
        profiles: None,
        version: env!("CARGO_PKG_VERSION").to_string(),
    }
}

/// What the header says of a session that takes each module's profile from its answer to 136.
pub const PER_MODULE: &str = "per module, see the identification notes";

/// The transcript header of a session that starts with `profile`: unless the profile was
/// `given`, each module identified takes its own, which its identification note names.
pub fn session_header(profile: &Profile, given: bool) -> Header {
    Header {
        profiles: (!given).then(|| PER_MODULE.to_string()),
        ..header(profile)
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

impl DialectConfig for TmclConfig {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn header(&self) -> Header {
        session_header(&self.profile, self.given)
    }

    fn simulated_module(&self) -> String {
        self.simulated_profile().module.clone()
    }

    fn simulator(&self) -> Box<dyn Device> {
        Box::new(Bus::new(self.simulated_profile(), BusOptions::default()))
    }

    #[cfg(feature = "cli")]
    fn served_simulator(
        &self,
        flags: &crate::dialect::CommandLine,
        state: Option<&Path>,
        verbose: bool,
    ) -> Result<Box<dyn Device>, crate::sim::error::SimStartError> {
        super::sim::flags::served(&self.simulated_profile(), flags, state, verbose)
    }

    fn can_framer(&self, reply_id: u16) -> Option<Box<dyn Framer>> {
        Some(Box::new(TmclFramer::new(reply_id)))
    }

    fn can_device(&self, device: Box<dyn Device>) -> Option<Box<dyn CanDevice>> {
        Some(Box::new(super::sim::can::CanBus::new(device)))
    }

    /// For a conversation, the target module is identified (command 136: its profile, unless
    /// one was given), contacted, and its echo set as `--echo` asks.
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
                let connect = Connect {
                    profile_given: self.given,
                    binary: switch(flags, "binary"),
                    no_enter: switch(flags, "no_enter"),
                    stay_ascii: switch(flags, "stay_ascii"),
                };
                let mut session =
                    TmclSession::connect(link, profile, connect, options, transcript)?;
                if let Some(echo) = super::flags::echo(flags) {
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

    fn params_json(&self, filter: &str) -> Result<Vec<crate::json::Value>, DialectError> {
        super::params::params_json(&self.profile, filter)
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
    ) -> Result<String, ReplayError> {
        super::replay::script(entries, header, &self.profile, name, wait_ms)
    }
}
