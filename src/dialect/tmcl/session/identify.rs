//! Identification on connect: before anything else the target module is asked for its firmware
//! version (binary command 136 type 0, one 9-byte exchange), and the session takes the built-in
//! profile of the module number it names — unless a profile was given, which then wins over the
//! answer (a mismatch is one warning). A module no profile describes gets the generic profile; a
//! boot loader's answer (`B` for `V`) ends the session before anything else is sent.
//!
//! A module that does not answer (one already in ASCII mode takes the frame as a line for
//! another module; an old firmware) costs one `--timeout`; a CR then ends the partial line, and
//! the session goes on with the profile it has, saying so once.

use std::sync::Arc;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::catalogue::{self, GENERIC_NOTICE, Identified};
use crate::dialect::tmcl::protocol::line::address_char;
use crate::dialect::tmcl::protocol::{Instruction, Opcode};
use crate::exit::{Exit, Failure};

use super::{TmclReply, TmclSession};
use crate::session::SessionError;

/// What the session knows about the module it talks to, for the banner and `-v`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Identity {
    /// Not asked (`--no-enter`, or a session opened without identification).
    NotAsked,
    /// Asked; the module named itself with this version string.
    Answered {
        /// The module type the answer names (`TMCM-6110`).
        module: String,
        /// The version string (`6110V131`).
        firmware: String,
    },
    /// Asked; no usable answer (why, in a few words).
    NoAnswer(String),
}

/// The way a profile is named in the banner: `tmcm-6110 (built in)` or `FILE (file)`.
pub fn profile_label(profile: &Profile) -> String {
    match &profile.source {
        Some(path) => format!("{} (file)", path.display()),
        None => format!("{} (built in)", profile.name),
    }
}

/// The module type a module number stands for when no profile names it.
fn module_of(number: u32) -> String {
    format!("TMCM-{number}")
}

impl TmclSession {
    /// Asks the target module for its firmware version and settles the profile: `given` says
    /// the session's profile was chosen by the user (`--profile`), so it stays whatever the
    /// module says. Fails (exit 3) when the boot loader answers: nothing else is sent then.
    pub fn identify(&mut self, given: bool) -> Result<(), SessionError> {
        if !self.core.options.enter {
            self.identity = Identity::NotAsked;
            return Ok(());
        }
        let module = self.target;
        let c = address_char(module).unwrap_or('?');
        let ask = Instruction::new(Opcode::FirmwareVersion, 0, 0, 0);
        let answer = self.exchange(module, true, |s| s.binary_exchange(module, ask));
        let text = match answer {
            // The binary exchange reads the answer to 136 type 0 as a version string.
            Ok(exchange) => match exchange.reply {
                TmclReply::Version(text) => text,
                _ => String::new(),
            },
            Err(SessionError::Timeout { timeout, .. }) => {
                self.identity = Identity::NoAnswer("no answer to 136".into());
                self.core.wire.note("not identified: no answer to 136");
                // A module in ASCII mode holds the frame as the start of a line.
                self.end_partial_line()?;
                self.core.wire.notices.push(format!(
                    "module {c} did not answer command 136 (firmware version) within {} ms: not \
                     identified (a module already in ASCII mode, or an old firmware); using the \
                     profile {}",
                    timeout.as_millis(),
                    profile_label(&self.profile)
                ));
                return Ok(());
            }
            Err(e) => return Err(e),
        };
        let identified = match catalogue::identify(&text) {
            Ok(identified) => {
                self.frames_aligned = true;
                identified
            }
            Err(e) => {
                self.identity = Identity::NoAnswer("answer not understood".into());
                self.core.wire.note("not identified: answer not understood");
                self.core.wire.notices.push(format!(
                    "module {c} answered command 136 with {e}; not identified, using the profile {}",
                    profile_label(&self.profile)
                ));
                return Ok(());
            }
        };
        let version = match &identified {
            Identified::BootLoader { .. } => {
                let message = format!("module {c}: {}", identified.banner());
                self.core.wire.note(&message);
                return Err(Failure::new(Exit::Link, message).into());
            }
            Identified::Known { version, .. } | Identified::Unknown { version, .. } => version,
        };
        let named = identified.profile().expect("firmware answered").clone();
        let module_type = if named.generic {
            module_of(version.module)
        } else {
            named.module.clone()
        };
        self.identity = Identity::Answered {
            module: module_type.clone(),
            firmware: version.text.clone(),
        };
        if given {
            self.warn_mismatch(version.module, &module_type);
        } else {
            self.take_profile(named);
        }
        let line = format!("identified: {}", self.identity_line());
        self.core.wire.note(&line);
        Ok(())
    }

    /// The given profile stays; a module it does not describe is one warning.
    fn warn_mismatch(&mut self, number: u32, module_type: &str) {
        let describes = self.profile.generic || self.profile.identity.module_number == Some(number);
        if describes {
            return;
        }
        let c = address_char(self.target).unwrap_or('?');
        let firmware = match &self.identity {
            Identity::Answered { firmware, .. } => firmware.clone(),
            _ => String::new(),
        };
        self.core.wire.notices.push(format!(
            "module {c} is a {module_type} ({firmware}), but the profile given is {} for the {}; \
             the given profile is used",
            profile_label(&self.profile),
            self.profile.module
        ));
    }

    /// Talks to the module with `profile` from now on (the generic one says so once).
    fn take_profile(&mut self, profile: Arc<Profile>) {
        if profile.generic && !self.profile.generic {
            self.core.wire.notices.push(GENERIC_NOTICE.to_string());
        }
        self.profile = profile;
    }

    /// What the session talks to: `TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)`.
    pub fn identity_line(&self) -> String {
        let label = profile_label(&self.profile);
        match &self.identity {
            Identity::Answered { module, firmware } => {
                format!("{module}, firmware {firmware}, profile {label}")
            }
            Identity::NotAsked => format!("{}, profile {label}", self.profile.module),
            Identity::NoAnswer(why) => {
                format!(
                    "{} (not identified: {why}), profile {label}",
                    self.profile.module
                )
            }
        }
    }

    /// What the session knows about its module.
    pub fn identity(&self) -> &Identity {
        &self.identity
    }
}
