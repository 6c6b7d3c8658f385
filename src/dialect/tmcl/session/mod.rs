//! The TMCL session: ASCII mode by default (manual §6.6), binary direct mode after `:bin`, and
//! from the start for a module whose profile says it has no ASCII interface.
//!
//! On open the target module is put into ASCII mode with the binary command 139 and its echo
//! behaviour is learnt from global parameter 67; other modules on the bus are identified and
//! entered the first time a line addresses them, each with its own profile and mode (see
//! `identify.rs`). On close every module is put back in the mode it was found in.

mod ascii;
mod barrier;
mod binary;
mod exchange;
mod faces;
mod guard;
mod identify;
mod mode;
mod prepared;
mod probe;
mod relink;
mod reset;
mod seam;
mod sniff;
mod stop;
mod unanswered;

use std::collections::BTreeMap;
use std::sync::Arc;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::AsciiWord;
use crate::dialect::tmcl::protocol::line::{
    self, Line, Op, address_char, format_instruction, format_line,
};
use crate::dialect::tmcl::protocol::syntax::parse_line;
use crate::dialect::tmcl::protocol::validate::{self, Mode};
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode, error::InputError};
use crate::link::Link;

use crate::session::core::{Addresses, SessionCore};
use crate::session::transcript::Transcript;
use crate::session::wire::Peer;
use crate::session::{SessionError, SessionOptions};

pub use exchange::{TmclExchange, TmclReply};
pub use identify::{Identity, profile_label};
pub use mode::{Echo, WireMode};

use unanswered::{Unanswered, harmless};

/// A TMCL conversation with the modules on one link.
pub struct TmclSession {
    core: SessionCore,
    /// `--no-enter`: no enter-ASCII-mode frame (see [`Connect`]).
    no_enter: bool,
    /// `--stay-ascii`: the modules are not put back at the end.
    stay_ascii: bool,
    profile: Arc<Profile>,
    target: u8,
    modules: BTreeMap<u8, mode::ModuleState>,
    /// ASCII lines that failed: their echo and reply may still come.
    unanswered: Unanswered,
    /// Binary requests that failed: their reply frames may still come (see `barrier.rs`).
    late_frames: barrier::LateFrames,
    /// What the target module said it is (command 136).
    identity: Identity,
    /// The profile the session was opened with: the given one (`--profile`), and the one of a
    /// module that was not identified.
    fallback: Arc<Profile>,
    /// Every module identified so far, with its own profile.
    known: BTreeMap<u8, identify::Known>,
    /// The profile the last answer to 136 named.
    identified: Option<Arc<Profile>>,
    /// The profile was given: it stays for every module, whatever the modules say.
    profile_given: bool,
    /// Modules are identified the first time the session turns to them (sessions the command
    /// line opens).
    identify_each: bool,
    /// Every module in binary direct mode, whatever its profile says (`--binary`).
    binary_only: bool,
    /// The link carries binary frames only (CAN): no ASCII mode, 139 never sent.
    frames_only: bool,
    /// The last exchange on the line was a complete binary one: every binary receiver is at a
    /// frame boundary, and the next frame needs no quiet line before it.
    frames_aligned: bool,
    /// The host address binary replies begin with, from the last one taken (GP 76; unknown
    /// until a module has answered, and again after it was set).
    host: Option<u8>,
    /// ASCII bytes went out since the line was last kept quiet for a frame time-out (or a shared
    /// line was just opened, holding what others left): a module in binary mode may hold some of
    /// them as the start of a frame.
    ascii_sent: bool,
    /// A binary frame went out since the last ASCII line: modules in ASCII mode hold its bytes
    /// as the start of a line, which a CR must end before the next line.
    line_dirty: bool,
    /// The echo this session set on each module (`--echo`, `:echo`), set again after a
    /// reconnect or after the module restarted.
    echo_set: BTreeMap<u8, Echo>,
    /// A binary probe for a restarted module is under way (see `reset.rs`): its own failures
    /// are not probed again.
    probing_reset: bool,
    /// The host address (first byte) of the last answer to 136 type 0.
    version_host: Option<u8>,
    /// The host address each identified module replies with (see `protocol/host_clash.rs`).
    hosts: BTreeMap<u8, u8>,
    /// The buffers of ASCII exchanges, kept between them.
    buffers: ascii::Buffers,
    /// The last ASCII request checked and spelled.
    prepared: prepared::Prepared,
}

/// How the command line opens a session: what decides its profile and its mode.
#[derive(Debug, Clone, Copy, Default)]
pub struct Connect {
    /// The profile was given (`--profile`): it stays whatever the module says.
    pub profile_given: bool,
    /// Binary direct mode for every module (`--binary`).
    pub binary: bool,
    /// No enter-ASCII-mode frame: the modules are in ASCII mode already (`--no-enter`).
    pub no_enter: bool,
    /// Modules left in ASCII mode at the end instead of put back (`--stay-ascii`).
    pub stay_ascii: bool,
}

impl TmclSession {
    /// Opens a session: enters ASCII mode on the target module
    /// and learns its echo behaviour.
    pub fn open(
        link: Box<dyn Link>,
        profile: Arc<Profile>,
        options: SessionOptions,
        transcript: Option<Transcript>,
    ) -> Result<Self, SessionError> {
        let mut session = Self::open_idle(link, profile, options, transcript)?;
        session.contact(session.target)?;
        Ok(session)
    }

    /// Opens a session the way the command line does: the target module is identified (command
    /// 136, see [`TmclSession::identify`]), which may settle the profile, then contacted — in
    /// ASCII mode, or in binary direct mode when `connect` or the profile says so.
    pub fn connect(
        link: Box<dyn Link>,
        profile: Arc<Profile>,
        connect: Connect,
        options: SessionOptions,
        transcript: Option<Transcript>,
    ) -> Result<Self, SessionError> {
        let mut session = Self::open_idle(link, profile, options, transcript)?;
        session.binary_only = connect.binary || session.frames_only;
        session.no_enter = connect.no_enter;
        session.stay_ascii = connect.stay_ascii;
        session.identify(connect.profile_given)?;
        session.contact(session.target)?;
        Ok(session)
    }

    /// Opens a session without contacting any module yet (a bus scan finds them first).
    pub fn open_idle(
        link: Box<dyn Link>,
        profile: Arc<Profile>,
        options: SessionOptions,
        transcript: Option<Transcript>,
    ) -> Result<Self, SessionError> {
        if address_char(options.module).is_none() {
            return Err(SessionError::Usage(format!(
                "module address {} has no ASCII address character; use 1..26",
                options.module
            )));
        }
        let frames_only = link.frames_only();
        let mut session = TmclSession {
            target: options.module,
            no_enter: false,
            stay_ascii: false,
            core: SessionCore::new(link, options, transcript),
            fallback: profile.clone(),
            known: BTreeMap::new(),
            echo_set: BTreeMap::new(),
            identified: None,
            profile_given: false,
            identify_each: false,
            profile,
            modules: BTreeMap::new(),
            unanswered: Unanswered::default(),
            late_frames: barrier::LateFrames::default(),
            identity: Identity::NotAsked,
            binary_only: frames_only,
            frames_only,
            frames_aligned: false,
            host: None,
            ascii_sent: false,
            line_dirty: false,
            probing_reset: false,
            version_host: None,
            hosts: BTreeMap::new(),
            buffers: ascii::Buffers::default(),
            prepared: prepared::Prepared::default(),
        };
        // What another program or module sent just before may sit in a binary receiver: the
        // first frame on a shared line waits for it to fall quiet (a private one has no other).
        session.ascii_sent = !session.core.wire.link.private();
        let opened = format!("session opened on {}", session.core.wire.link.describe());
        session.core.wire.note(&opened);
        if session.profile.generic {
            let notice = crate::dialect::tmcl::profile::catalogue::GENERIC_NOTICE;
            session.core.wire.notices.push(notice.to_string());
        }
        Ok(session)
    }

    /// The target module's profile, used for completion, hints, help, snapshots and `:params`.
    pub fn profile(&self) -> &Arc<Profile> {
        &self.profile
    }

    /// Whether the link carries binary frames only (CAN): no ASCII mode, no ASCII probes.
    pub fn frames_only(&self) -> bool {
        self.frames_only
    }

    /// The module lines without an address character go to.
    pub fn target(&self) -> u8 {
        self.target
    }

    /// Changes the target module, identifying it and entering ASCII mode on it if it is new;
    /// its profile becomes the session's.
    pub fn set_target(&mut self, module: u8) -> Result<(), SessionError> {
        if address_char(module).is_none() {
            return Err(SessionError::Usage(format!(
                "module address {module} is not in 1..26"
            )));
        }
        self.contact(module)?;
        self.target = module;
        self.show_target();
        Ok(())
    }

    /// The mode lines to `module` are checked for: its wire mode, or for a module not reached
    /// yet the mode it would be reached in.
    pub fn validation_mode(&self, module: u8) -> Mode {
        let binary = match self.module_state(module) {
            Some((mode, _)) => mode == WireMode::Binary,
            None => self.binary_only || !self.has_ascii(module),
        };
        if binary { Mode::Binary } else { Mode::Ascii }
    }

    /// The wire mode and echo of a module the session has talked to.
    pub fn module_state(&self, module: u8) -> Option<(WireMode, Echo)> {
        self.modules.get(&module).map(|m| (m.mode, m.echo))
    }

    /// Parses, validates and sends one command line (a trailing `//` comment aside); returns
    /// the module's answer. An error status is an `Ok` exchange whose [`TmclExchange::ok`] is
    /// false; a refused line of another dialect says so.
    pub fn exchange_line(&mut self, text: &str) -> Result<TmclExchange, SessionError> {
        self.exchange_typed(crate::dialect::tmcl::protocol::syntax::without_comment(
            text,
        ))
        .map_err(|e| crate::dialect::elsewhere::explain(&crate::dialect::tmcl::DIALECT, text, e))
    }

    fn exchange_typed(&mut self, text: &str) -> Result<TmclExchange, SessionError> {
        // A line addressed to another module is read with that module's profile.
        let addressed = parse_line(text, |w| self.profile.commands.is_word(w))
            .ok()
            .and_then(|raw| raw.address.and_then(line::address_of));
        let profile = match addressed {
            Some(module) if module != self.target => {
                self.identify_if_new(module)?;
                self.profile_of(module)
            }
            _ => self.profile.clone(),
        };
        match line::parse(text, &profile) {
            Ok(line) => {
                let module = line.address.unwrap_or(self.target);
                self.perform(module, line.op)
            }
            Err(error) if self.core.options.validate => Err(error.into()),
            Err(error) => {
                // --no-validate: send what parses, in canonical spelling.
                let raw = parse_line(text, |w| self.profile.commands.is_word(w))
                    .map_err(|_| SessionError::Refused(error.to_string()))?;
                let module = raw
                    .address
                    .and_then(line::address_of)
                    .unwrap_or(self.target);
                self.contact(module)?;
                self.core
                    .wire
                    .notices
                    .push(format!("not validated: {error}"));
                let sent = line::format_raw(&raw, self.target);
                self.ascii_request(module, sent, None)
            }
        }
    }

    /// Sends one instruction to a module (the typed path of scripts).
    pub fn request(
        &mut self,
        module: u8,
        instruction: Instruction,
    ) -> Result<TmclExchange, SessionError> {
        self.perform(module, Op::Command(instruction))
    }

    /// One request; a link lost on the way is waited for where `--reconnect` asks for it
    /// (`relink.rs`).
    fn perform(&mut self, module: u8, op: Op) -> Result<TmclExchange, SessionError> {
        match self.perform_once(module, op) {
            Err(SessionError::Lost(why)) => self.after_loss(module, op, why),
            other => other,
        }
    }

    /// A line the profile refuses: the refusal, or under `--no-validate` a notice and on.
    fn invalid(&mut self, error: InputError) -> Result<(), SessionError> {
        if self.core.options.validate {
            return Err(error.into());
        }
        let notice = format!("not validated: {error}");
        self.core.wire.notices.push(notice);
        Ok(())
    }

    fn perform_once(&mut self, module: u8, op: Op) -> Result<TmclExchange, SessionError> {
        let wire = self.contact(module)?;
        let mode = match wire {
            WireMode::Ascii => Mode::Ascii,
            WireMode::Binary => Mode::Binary,
        };
        let line = Line {
            address: Some(module),
            op,
        };
        let profile = self.profile_of(module);
        // The line checked and spelled the last time, if it is this one (see `prepared.rs`).
        let known = self
            .prepared
            .text(&line, &profile, mode)
            .map(str::to_string);
        let mut clean = false;
        if known.is_none() {
            match validate::validate(&line, &profile, mode) {
                Ok(warnings) => {
                    clean = warnings.is_empty();
                    self.core
                        .wire
                        .notices
                        .extend(warnings.iter().map(ToString::to_string));
                }
                Err(error) => self.invalid(error)?,
            }
        }
        let exchange = match (wire, op) {
            (WireMode::Ascii, Op::Ascii(AsciiWord::Bin)) => self.leave_ascii(module)?,
            (WireMode::Ascii, _) => {
                let text = known.unwrap_or_else(|| {
                    let text = format_line(&line, self.target, &profile);
                    if clean {
                        self.prepared.keep(line, &profile, mode, &text);
                    }
                    text
                });
                self.ascii_request(module, text, Some(op))
                    .map_err(|e| self.after_ascii_silence(module, e))?
            }
            (WireMode::Binary, Op::Command(instruction)) => {
                self.binary_request(module, instruction)?
            }
            (WireMode::Binary, Op::Ascii(word)) => {
                return Err(SessionError::Usage(format!(
                    "{} is an ASCII-mode word and {} is in binary mode; use :ascii, :run or :stop",
                    word.as_str(),
                    ModuleName(module)
                )));
            }
        };
        self.after(&exchange);
        Ok(exchange)
    }

    /// Bookkeeping after an answer: which modules move, what echo a module now uses.
    fn after(&mut self, exchange: &TmclExchange) {
        if !exchange.ok() {
            return;
        }
        match exchange.op {
            Some(Op::Command(i)) => {
                let profile = self.profile_of(exchange.module);
                let spec = profile.commands.by_number(i.command);
                if spec.is_some_and(|s| s.starts_motion) {
                    self.core.moved.insert(Some(exchange.module.into()));
                }
                if i.command == Opcode::RunApplication {
                    self.core.running.insert(Some(exchange.module.into()));
                }
                if i.command == Opcode::StopApplication {
                    self.stopped_program(exchange.module);
                }
                if mode::changes_echo(&i) {
                    self.relearn_echo(exchange.module);
                }
            }
            Some(Op::Ascii(AsciiWord::Run)) => {
                self.core.running.insert(Some(exchange.module.into()));
            }
            Some(Op::Ascii(AsciiWord::Stop)) => {
                self.stopped_program(exchange.module);
            }
            _ => {}
        }
    }

    /// A program this session started was stopped: the motion it started goes on (STOP ends the
    /// program, not the motion), so the module counts as set moving by this session.
    fn stopped_program(&mut self, module: u8) {
        let module = Some(module.into());
        if self.core.running.remove(&module) {
            self.core.moved.insert(module);
        }
    }

    /// Stores one program instruction while the module is in download mode (binary mode, after
    /// command 132). The instruction is checked as a program instruction, not as a direct-mode
    /// command; the module answers status 101 (stored).
    pub fn store_instruction(
        &mut self,
        module: u8,
        instruction: Instruction,
    ) -> Result<TmclExchange, SessionError> {
        if self.contact(module)? != WireMode::Binary {
            return Err(SessionError::Usage(format!(
                "{} must be in binary mode to store a program",
                ModuleName(module)
            )));
        }
        let line = Line {
            address: Some(module),
            op: Op::Command(instruction),
        };
        match validate::validate(&line, &self.profile_of(module), Mode::Program) {
            Ok(_) => {}
            Err(error) => self.invalid(error)?,
        }
        self.binary_request(module, instruction)
    }

    /// Starts the module's stored TMCL program: ASCII `RUN`, or command 129 in binary mode.
    pub fn run_program(
        &mut self,
        module: u8,
        address: Option<i32>,
    ) -> Result<TmclExchange, SessionError> {
        let run_from = |address: Option<i32>| {
            Op::Command(Instruction::new(
                Opcode::RunApplication,
                u8::from(address.is_some()),
                0,
                address.unwrap_or(0),
            ))
        };
        match (self.contact(module)?, address) {
            (WireMode::Ascii, None) => self.perform(module, Op::Ascii(AsciiWord::Run)),
            // ASCII RUN has no address operand: a start address needs binary command 129.
            (WireMode::Ascii, Some(_)) => {
                self.in_binary(module, |s| s.perform(module, run_from(address)))
            }
            (WireMode::Binary, _) => self.perform(module, run_from(address)),
        }
    }

    /// Stops the module's running TMCL program: ASCII `STOP`, or command 128 in binary mode.
    pub fn stop_program(&mut self, module: u8) -> Result<TmclExchange, SessionError> {
        let op = match self.contact(module)? {
            WireMode::Ascii => Op::Ascii(AsciiWord::Stop),
            WireMode::Binary => Op::Command(Instruction::new(Opcode::StopApplication, 0, 0, 0)),
        };
        self.perform(module, op)
    }

    /// Runs `f` with the module in binary mode, returning it to ASCII mode afterwards if it was.
    pub fn in_binary<T>(
        &mut self,
        module: u8,
        f: impl FnOnce(&mut Self) -> Result<T, SessionError>,
    ) -> Result<T, SessionError> {
        let was_ascii = self.contact(module)? == WireMode::Ascii;
        if was_ascii {
            self.leave_ascii(module)?;
        }
        let result = f(self);
        if was_ascii {
            self.enter_ascii(module)?;
        }
        result
    }

    /// Formats an instruction the way this session would send it to `module`.
    pub fn format(&self, module: u8, op: Op) -> String {
        format_line(
            &Line {
                address: Some(module),
                op,
            },
            self.target,
            &self.profile_of(module),
        )
    }

    fn restore_modes(&mut self) -> Vec<String> {
        let mut report = Vec::new();
        let to_restore: Vec<u8> = self
            .modules
            .iter()
            .filter(|(_, m)| m.mode == WireMode::Ascii && m.found_in == WireMode::Binary)
            .map(|(&a, _)| a)
            .collect();
        for &module in &to_restore {
            if let Err(e) = self.leave_ascii(module) {
                report.push(format!(
                    "could not return {} to binary mode: {e}",
                    ModuleName(module)
                ));
            }
        }
        let back_to_ascii: Vec<u8> = self
            .modules
            .iter()
            .filter(|(_, m)| m.mode == WireMode::Binary && m.found_in == WireMode::Ascii)
            .map(|(&a, _)| a)
            .collect();
        for module in back_to_ascii {
            if let Err(e) = self.enter_ascii(module) {
                report.push(format!(
                    "could not return {} to ASCII mode: {e}",
                    ModuleName(module)
                ));
            }
        }
        self.let_frames_time_out(to_restore.last().copied());
        self.core.wire.note("session closed");
        report
    }

    /// Leaves the line quiet for the frame time-out when a module in binary mode took ASCII
    /// bytes for the start of a frame — the BIN to the next module after its own (`last_bin`,
    /// the last module returned, is the only one that did not) — so that whatever opens the
    /// port next finds every receiver empty and its first frame answered.
    fn let_frames_time_out(&mut self, last_bin: Option<u8>) {
        let holding = self
            .modules
            .iter()
            .any(|(&a, m)| m.mode == WireMode::Binary && Some(a) != last_bin);
        if self.ascii_sent && holding {
            let gap = self.resync_gap();
            let _ = self.core.wire.idle_for(gap);
        }
    }

    /// A human description of an instruction for the transcript.
    fn describe_instruction(&self, instruction: &Instruction) -> String {
        format_instruction(instruction, &self.profile)
    }

    /// Runs one exchange with `module` between the wire's begin and finish, so that any failure
    /// — whatever returns it — leaves the line suspect until it has settled. `optional` replies
    /// (BIN) may fail to come without that.
    fn exchange<T>(
        &mut self,
        module: u8,
        optional: bool,
        f: impl FnOnce(&mut Self) -> Result<T, SessionError>,
    ) -> Result<T, SessionError> {
        let timeout = self.core.options.timeout;
        let peer = Peer::Module(module.into());
        let unanswered = &mut self.unanswered;
        let result = self
            .core
            .wire
            .begin(peer, self.core.urgent, timeout, &mut |bytes| {
                harmless(bytes, unanswered)
            })
            .and_then(|()| f(self));
        let settled = match &result {
            Ok(_) => true,
            Err(SessionError::Timeout { .. }) => optional,
            Err(_) => false,
        };
        self.core.wire.finish(settled);
        result
    }
}

/// The TMCL module addresses among `addresses`.
fn modules(addresses: &Addresses) -> Vec<u8> {
    addresses
        .iter()
        .filter_map(|a| a.and_then(|a| u8::try_from(a).ok()))
        .collect()
}

#[cfg(test)]
mod tests;
