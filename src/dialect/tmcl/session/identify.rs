//! Identification on connect: before anything else the target module is asked for its firmware
//! version (binary command 136 type 0, one 9-byte exchange), and the session takes the built-in
//! profile of the module number it names. Every other module is identified the same way the
//! first time the session turns to it (`:target`, an address character, a script's `target()`),
//! so on a bus of different modules each keeps its own profile and its own wire mode — unless a profile was given, which then wins over the
//! answer (a mismatch is one warning). A module no profile describes gets the generic profile; a
//! boot loader's answer (`B` for `V`) ends the session before anything else is sent.
//!
//! The first frame on a shared line (a port, a TCP bridge) waits until the line has been quiet
//! for twice the module's partial-frame time-out, so whatever others sent before cannot misalign
//! its receiver. A module that does not answer usably (one already in ASCII mode takes the frame
//! as a line for another module; another module at the host address answers its reply; an old
//! firmware) is asked once more after such a quiet gap, a CR first ending any partial line. Still
//! unidentified, it is sent nothing on a guess (exit 3, naming the likely causes) unless a profile
//! or `--binary` was given: then the session goes on with that, saying so once.

use std::sync::Arc;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::catalogue::{self, GENERIC_NOTICE, Identified};
use crate::dialect::tmcl::profile::version::FirmwareVersion;
use crate::dialect::tmcl::protocol::host_clash;
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode};
use crate::exit::{Exit, Failure};

use super::{TmclReply, TmclSession};
use crate::session::{NoiseKind, SessionError};

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
    /// Asked; the module runs its boot loader (the report, `module B: TMCM-142 in its boot
    /// loader (142B1.06): …`). Nothing else is ever sent to it.
    BootLoader(String),
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

/// What the session learnt about one module on the bus: the profile its lines are checked and
/// decoded with, and what it said it is.
#[derive(Debug, Clone)]
pub(super) struct Known {
    pub profile: Arc<Profile>,
    pub identity: Identity,
}

impl TmclSession {
    /// Asks the target module for its firmware version and settles the profile: `given` says
    /// the session's profile was chosen by the user (`--profile`), so it stays whatever the
    /// module says. Fails (exit 3) when the boot loader answers: nothing else is sent then.
    pub fn identify(&mut self, given: bool) -> Result<(), SessionError> {
        self.profile_given = given;
        let module = self.target;
        self.identify_module(module)?;
        self.show_target();
        Ok(())
    }

    /// Identifies `module` the first time the session turns to it, when the session identifies
    /// modules at all (a session the command line opened, `--no-enter` off): on a bus of
    /// different modules each one is checked, decoded and talked to with its own profile.
    pub(super) fn identify_if_new(&mut self, module: u8) -> Result<(), SessionError> {
        if let Some(Known {
            identity: Identity::BootLoader(report),
            ..
        }) = self.known.get(&module)
        {
            return Err(Failure::new(Exit::Link, report.clone()).into());
        }
        let new = !self.known.contains_key(&module) && !self.modules.contains_key(&module);
        if self.identify_each && new {
            self.identify_module(module)?;
        }
        Ok(())
    }

    /// Asks `module` for its firmware version (136 type 0) and records its profile and identity.
    /// A module that does not identify itself is refused (exit 3) unless a profile or `--binary`
    /// was given: nothing is sent to it on a guess of what it is.
    pub(super) fn identify_module(&mut self, module: u8) -> Result<(), SessionError> {
        self.settle_identity(module, true)
    }

    /// [`TmclSession::identify_module`]; `strict` off keeps going with the profile the session
    /// has (a module identified before a reconnect, which says so itself).
    pub(super) fn settle_identity(&mut self, module: u8, strict: bool) -> Result<(), SessionError> {
        self.identify_each = true;
        if self.no_enter {
            return Ok(());
        }
        let identity = self.ask_identity(module, strict)?;
        let profile = match &identity {
            Identity::Answered { .. } if !self.profile_given => self
                .identified
                .clone()
                .unwrap_or_else(|| self.fallback.clone()),
            _ => self.fallback.clone(),
        };
        if profile.generic && !self.fallback.generic {
            let notice = generic_notice(module, &identity);
            self.core.wire.notices.push(notice);
        }
        let known = Known { profile, identity };
        if let Some(line) = identified_note(module, &known) {
            self.core.wire.note(&line);
        }
        self.known.insert(module, known);
        Ok(())
    }

    /// Repeats the identification note of every module identified so far: a transcript started
    /// mid-session (`:log FILE`) names each module's profile as one opened on connect does.
    pub(super) fn note_identifications(&mut self) {
        let notes: Vec<String> = self
            .known
            .iter()
            .filter_map(|(module, known)| identified_note(*module, known))
            .collect();
        for note in notes {
            self.core.wire.note(&note);
        }
    }

    /// Asks `module` what it is, twice if need be: an answer lost to what the line held (another
    /// module's reply, a partial line, what another program left) is asked for again once the
    /// line was quiet for the frame time-out. What it said (the profile it names in
    /// `self.identified`); no usable answer is a failure when `strict` and no profile or
    /// `--binary` was given.
    fn ask_identity(&mut self, module: u8, strict: bool) -> Result<Identity, SessionError> {
        let c = ModuleName(module);
        let why = match self.ask_identity_once(module)? {
            Ok(identity) => return Ok(identity),
            Err(why) => why,
        };
        self.core
            .wire
            .note(&format!("asking {c} again after a quiet line"));
        self.ascii_sent = true;
        self.frames_aligned = false;
        let why = match self.ask_identity_once(module)? {
            Ok(identity) => return Ok(identity),
            Err(again) => again.or(why),
        };
        self.core
            .wire
            .note(&format!("not identified: {c}, {}", why.short));
        if strict && !self.profile_given && !self.binary_only {
            if why.silent && self.answers_in_ascii(module)? {
                self.core.wire.notices.push(format!(
                    "{c} did not answer command 136 (firmware version) but answers in ASCII mode: \
                     it was left in ASCII mode; not identified, using the profile {} (name its \
                     own with --profile NAME)",
                    profile_label(&self.fallback)
                ));
                return Ok(Identity::NoAnswer("in ASCII mode, no answer to 136".into()));
            }
            return Err(
                Failure::new(Exit::Link, unidentified(module, &why, self.resync_gap())).into(),
            );
        }
        self.core.wire.notices.push(format!(
            "{}; not identified, using the profile {}",
            why.said,
            profile_label(&self.fallback)
        ));
        Ok(Identity::NoAnswer(why.short.into()))
    }

    /// Whether `module`, silent to 136, answers a read of its echo setting as an ASCII line: a
    /// module left in ASCII mode (by a program that ended without `BIN`) has the ASCII interface
    /// and needs no 139. Its state is then known (found in ASCII mode); otherwise forgotten.
    fn answers_in_ascii(&mut self, module: u8) -> Result<bool, SessionError> {
        if self.modules.contains_key(&module) {
            return Ok(false);
        }
        match self.assume_ascii(module) {
            Ok(()) => Ok(true),
            Err(
                SessionError::Timeout { .. } | SessionError::Link(_) | SessionError::Noise { .. },
            ) => {
                self.modules.remove(&module);
                // The line holds the unanswered line's bytes: quiet before the next frame.
                self.ascii_sent = true;
                self.frames_aligned = false;
                Ok(false)
            }
            Err(e) => Err(e),
        }
    }

    /// One 136 exchange with `module`; what it said, or why that is no identification.
    fn ask_identity_once(
        &mut self,
        module: u8,
    ) -> Result<Result<Identity, Unidentified>, SessionError> {
        self.identified = None;
        let c = ModuleName(module);
        let ask = Instruction::new(Opcode::FirmwareVersion, 0, 0, 0);
        self.align_for_frame()?;
        let answer = self.exchange(module, true, |s| s.binary_exchange(module, ask));
        let text = match answer {
            // The binary exchange reads the answer to 136 type 0 as a version string.
            Ok(exchange) => match exchange.reply {
                TmclReply::Version(text) => text,
                _ => String::new(),
            },
            Err(SessionError::Timeout { timeout, .. }) => {
                // A module in ASCII mode holds the frame as the start of a line.
                self.end_partial_line()?;
                return Ok(Err(Unidentified {
                    short: "no answer to 136",
                    said: format!(
                        "{c} did not answer command 136 (firmware version) within {} ms (a \
                         module already in ASCII mode, or an old firmware)",
                        timeout.as_millis()
                    ),
                    clash: false,
                    silent: true,
                }));
            }
            // Something came back that is no version string: said, and no profile is
            // picked from it.
            Err(SessionError::Noise { said, kind }) => {
                return Ok(Err(Unidentified {
                    short: "no usable answer to 136",
                    clash: kind == NoiseKind::HostClash,
                    said,
                    silent: false,
                }));
            }
            Err(e) => return Err(e),
        };
        let identified = match catalogue::identify(&text) {
            Ok(identified) => {
                self.frames_aligned = true;
                if let Some(host) = self.version_host.take() {
                    self.learn_host(module, host);
                }
                identified
            }
            Err(e) => {
                return Ok(Err(Unidentified {
                    short: "answer not understood",
                    said: format!("{c} answered command 136 with {e}"),
                    clash: false,
                    silent: false,
                }));
            }
        };
        let version = match &identified {
            Identified::BootLoader { .. } => {
                let message = format!("{c}: {}", identified.banner());
                self.core.wire.note(&message);
                // Every later line to it is refused with the same report, unsent.
                let identity = Identity::BootLoader(message.clone());
                let profile = self.fallback.clone();
                self.known.insert(module, Known { profile, identity });
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
        let identity = Identity::Answered {
            module: module_type.clone(),
            firmware: version.text.clone(),
        };
        if self.profile_given {
            self.warn_mismatch(module, version, &module_type);
        }
        self.identified = Some(named);
        Ok(Ok(identity))
    }

    /// Remembers the host address `module` replies with, and warns when it is the address of
    /// another module the session knows, or `module`'s address is another's host address.
    fn learn_host(&mut self, module: u8, host: u8) {
        self.hosts.insert(module, host);
        let mut pairs: Vec<(u8, Option<u8>)> =
            self.hosts.iter().map(|(&m, &h)| (m, Some(h))).collect();
        for &known in self.known.keys().chain([&module]) {
            if !self.hosts.contains_key(&known) {
                pairs.push((known, None));
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        let mine = |w: &String| {
            let name = ModuleName(module).to_string();
            w.starts_with(&name) || w.contains(&format!("host address of {name}"))
        };
        for warning in host_clash::warnings(&pairs).into_iter().filter(mine) {
            self.core.wire.note(&warning);
            self.core.wire.notices.push(warning);
        }
    }

    /// The given profile stays; a module it does not describe is one warning.
    fn warn_mismatch(&mut self, module: u8, version: &FirmwareVersion, module_type: &str) {
        let given = &self.fallback;
        if given.generic || given.identity.module_number == Some(version.module) {
            return;
        }
        let c = ModuleName(module);
        let warning = format!(
            "{c} is {} ({}), but the profile given is {} for the {}; \
             the given profile is used",
            crate::article::with_article(module_type),
            version.text,
            profile_label(given),
            given.module
        );
        self.core.wire.notices.push(warning);
    }

    /// Makes the target's profile and identity the session's (validation, completion, hints,
    /// snapshots, `:params`, the banner).
    pub(super) fn show_target(&mut self) {
        let known = self.known_of(self.target);
        self.profile = known.profile;
        self.identity = known.identity;
    }

    /// The profile and identity of `module`: what identification found, or the profile the
    /// session started with.
    pub(super) fn known_of(&self, module: u8) -> Known {
        self.known.get(&module).cloned().unwrap_or_else(|| Known {
            profile: self.fallback.clone(),
            identity: Identity::NotAsked,
        })
    }

    /// The profile lines to `module` are checked and decoded with.
    pub fn profile_of(&self, module: u8) -> Arc<Profile> {
        self.known
            .get(&module)
            .map_or_else(|| self.fallback.clone(), |k| k.profile.clone())
    }

    /// What the session talks to: `TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)`.
    pub fn identity_line(&self) -> String {
        describe(&Known {
            profile: self.profile.clone(),
            identity: self.identity.clone(),
        })
    }

    /// What the session knows about its module.
    pub fn identity(&self) -> &Identity {
        &self.identity
    }
}

/// Why an answer to 136 identified nothing: a few words for the banner, what happened for the
/// user, and whether another module at the host address was seen answering.
struct Unidentified {
    short: &'static str,
    said: String,
    clash: bool,
    /// Nothing came back at all (a module in ASCII mode takes a frame for a line).
    silent: bool,
}

impl Unidentified {
    /// The more telling of two attempts' reasons: one that saw a host-address clash.
    fn or(self, first: Unidentified) -> Unidentified {
        if first.clash && !self.clash {
            first
        } else {
            self
        }
    }
}

/// The refusal of a module that did not identify itself: what happened, the likely causes (the
/// clash first when it was seen) and the two ways on.
fn unidentified(module: u8, why: &Unidentified, gap: std::time::Duration) -> String {
    let c = ModuleName(module);
    let clash = "another module at the host address (GP 76) on a shared bus, which takes the \
                 replies for requests and answers them (give each a host address no module has: \
                 SGP 76, 0, N; `tmclsh scan` names it)";
    let others = "a module already in ASCII mode, a wrong address or baud rate";
    let causes = if why.clash {
        format!("{clash}; or {others}")
    } else {
        format!("{others}; or {clash}")
    };
    format!(
        "{c} is not identified (command 136 asked twice, the line quiet for {} ms before each): \
         {}. It is sent nothing on a guess of what it is (no 139 to enter ASCII mode). Likely \
         causes: {causes}. Name its profile with --profile NAME (`tmclsh profiles` lists them), \
         or talk to it in binary frames only with --binary",
        gap.as_millis(),
        why.said.trim_end_matches("; not taken"),
    )
}

/// The notice of a module no built-in profile describes, which names it, so that each such
/// module on a bus has its own: `module 2 (B), a TMCM-9999, uses the generic TMCL profile: …`.
fn generic_notice(module: u8, identity: &Identity) -> String {
    let c = ModuleName(module);
    match identity {
        Identity::Answered { module, .. } => format!(
            "{c}, {}, uses the {GENERIC_NOTICE}",
            crate::article::with_article(module)
        ),
        _ => format!("{c} uses the {GENERIC_NOTICE}"),
    }
}

/// The transcript note of a module that named itself: `identified: module 2 (B), TMCM-6110,
/// firmware 6110V131, profile tmcm-6110 (built in)`.
fn identified_note(module: u8, known: &Known) -> Option<String> {
    if !matches!(known.identity, Identity::Answered { .. }) {
        return None;
    }
    Some(format!(
        "identified: {}, {}",
        ModuleName(module),
        describe(known)
    ))
}

/// `TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)`.
fn describe(known: &Known) -> String {
    let label = profile_label(&known.profile);
    let module = &known.profile.module;
    match &known.identity {
        Identity::Answered { module, firmware } => {
            format!("{module}, firmware {firmware}, profile {label}")
        }
        Identity::NotAsked => format!("{module}, profile {label}"),
        Identity::NoAnswer(why) => format!("{module} (not identified: {why}), profile {label}"),
        Identity::BootLoader(report) => report.clone(),
    }
}
