//! Entering and leaving the module's ASCII mode, and its echo setting (global parameter 67).
//!
//! Entering: the binary command 139 goes to the module. A module in binary mode may answer it
//! with a binary reply (then we know it was in binary mode) or not at all; a module already in
//! ASCII mode takes the nine bytes as an unaddressed line. A CR after the frame ends that line, so
//! no garbage stays in the module's line buffer. Then `GGP 67, 0` in ASCII tells the echo mode,
//! and — when 139 got no binary reply — bit 0 (start in ASCII mode) tells whether the module was
//! already in ASCII mode when we found it.

use std::time::{Duration, Instant};

use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::protocol::ModuleName;
use crate::dialect::tmcl::protocol::frame::{CommandFrame, FRAME_LEN, ReplyFrame, hex};
use crate::dialect::tmcl::protocol::line::{Op, address_char};
use crate::dialect::tmcl::protocol::{AsciiWord, Instruction, Opcode, Status};

use super::{TmclExchange, TmclReply, TmclSession};
use crate::session::SessionError;
use crate::session::transcript::Entry;

/// How a module is being talked to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WireMode {
    /// ASCII command lines (manual §6.6).
    Ascii,
    /// Binary 9-byte frames (direct mode).
    Binary,
}

/// The echo behaviour of global parameter 67 bits 5..4.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Echo {
    /// Every character echoed as it arrives (bits 00).
    Character,
    /// The whole line echoed after CR (bit 4).
    Line,
    /// No echo, only the reply (bit 5).
    None,
}

impl Echo {
    /// The echo mode encoded in a value of global parameter 67.
    pub fn from_gp67(value: i32) -> Echo {
        match (value >> 4) & 0b11 {
            0b01 => Echo::Line,
            0b10 | 0b11 => Echo::None,
            _ => Echo::Character,
        }
    }

    /// Global parameter 67 with this echo mode, keeping the other bits of `value`.
    pub fn apply(self, value: i32) -> i32 {
        let bits = match self {
            Echo::Character => 0,
            Echo::Line => 0b01 << 4,
            Echo::None => 0b10 << 4,
        };
        (value & !0b11_0000) | bits
    }

    /// The word users type for it.
    pub fn name(self) -> &'static str {
        match self {
            Echo::Character => "char",
            Echo::Line => "line",
            Echo::None => "none",
        }
    }

    /// From the word users type.
    pub fn parse(word: &str) -> Option<Echo> {
        match word.to_ascii_lowercase().as_str() {
            "char" | "character" => Some(Echo::Character),
            "line" => Some(Echo::Line),
            "none" | "off" => Some(Echo::None),
            _ => None,
        }
    }
}

/// What the session knows about one module.
#[derive(Debug, Clone, Copy)]
pub(super) struct ModuleState {
    pub mode: WireMode,
    pub found_in: WireMode,
    pub echo: Echo,
    /// Whether an echo must precede the reply (known echo mode); off while probing.
    pub echo_known: bool,
}

/// How long a module may take to start answering 139 or BIN, which it may not answer at all. The
/// wait for such a reply adds the time its bytes need on the wire; a module that does not answer
/// costs this once per session.
const OPTIONAL_REPLY_WAIT: Duration = Duration::from_millis(200);

/// The longest reply line to BIN with its echo: `ABIN` CR, then `BA 100 0` CR LF.
const BIN_EXCHANGE_BYTES: u32 = 2 * 7 + 20;

/// Whether an instruction changes global parameter 67 (so the echo must be learnt again).
pub(super) fn changes_echo(i: &Instruction) -> bool {
    let writes_67 = matches!(i.command, Opcode::Sgp | Opcode::Rsgp | Opcode::Agp)
        && i.type_ == 67
        && i.motor == 0;
    writes_67 || i.command == Opcode::FactoryDefaults
}

impl TmclSession {
    /// Makes sure the session knows how to talk to `module`, entering ASCII mode on first contact
    /// (binary direct mode on a module without the ASCII interface).
    pub(super) fn contact(&mut self, module: u8) -> Result<WireMode, SessionError> {
        if let Some(state) = self.modules.get(&module) {
            return Ok(state.mode);
        }
        // 136 before 139: its answer decides the profile, and the profile the mode.
        self.identify_if_new(module)?;
        if self.binary_only {
            let why = if self.frames_only {
                "the link is CAN, which carries binary frames only"
            } else {
                "--binary given"
            };
            self.start_binary(module, why)?;
            return Ok(WireMode::Binary);
        }
        if !self.has_ascii(module) {
            let why = format!(
                "the {} has no ASCII interface",
                self.profile_of(module).module
            );
            self.start_binary(module, &why)?;
            return Ok(WireMode::Binary);
        }
        if !self.no_enter {
            match self.enter_ascii(module) {
                Ok(()) => {}
                // It answered 136 in binary: it is there, without (working) ASCII mode. The
                // operator asked for ASCII mode (or the profile promised it), so the change is
                // said on stderr too, not only in the transcript.
                Err(e @ (SessionError::Timeout { .. } | SessionError::Device { .. }))
                    if self.answered_binary(module) =>
                {
                    let why = format!("it answered in binary, not in ASCII mode ({e})");
                    self.start_binary(module, &why)?;
                    let notice = format!("{} in binary direct mode: {why}", ModuleName(module));
                    self.core.wire.notices.push(notice);
                    return Ok(WireMode::Binary);
                }
                Err(e) => return Err(e),
            }
        } else {
            self.assume_ascii(module)?;
        }
        Ok(WireMode::Ascii)
    }

    /// Takes `module` to be in ASCII mode without asking it into it (`--no-enter`, a module
    /// probed in ASCII), and learns its echo setting.
    pub(super) fn assume_ascii(&mut self, module: u8) -> Result<(), SessionError> {
        self.modules.insert(
            module,
            ModuleState {
                mode: WireMode::Ascii,
                found_in: WireMode::Ascii,
                echo: Echo::None,
                echo_known: false,
            },
        );
        self.learn_echo(module, Some(WireMode::Ascii))
    }

    /// Makes the next frame start where binary-mode receivers look for one (see
    /// [`TmclSession::align_frames`]), and drains what arrived meanwhile.
    fn align_and_drain(&mut self) -> Result<(), SessionError> {
        self.align_frames()?;
        let unanswered = &mut self.unanswered;
        self.core
            .wire
            .drain(&mut |bytes| super::unanswered::harmless(bytes, unanswered))?;
        Ok(())
    }

    /// Whether `module` has answered a binary frame in this session (the identification).
    fn answered_binary(&self, module: u8) -> bool {
        self.known
            .get(&module)
            .is_some_and(|k| matches!(k.identity, super::Identity::Answered { .. }))
    }

    /// Talks to `module` in binary direct mode from now on (`why` goes to the transcript). The
    /// line is first left quiet for the module's frame time-out, so whatever an attempt at ASCII
    /// mode left in its receiver is dropped.
    fn start_binary(&mut self, module: u8, why: &str) -> Result<(), SessionError> {
        self.align_and_drain()?;
        self.modules.insert(
            module,
            ModuleState {
                mode: WireMode::Binary,
                found_in: WireMode::Binary,
                echo: Echo::None,
                echo_known: false,
            },
        );
        let note = format!("{} in binary direct mode: {why}", ModuleName(module));
        self.core.wire.note(&note);
        Ok(())
    }

    /// How long the line stays quiet before a binary-mode receiver takes a new frame: long
    /// enough for the module with the longest frame time-out the session knows.
    pub(super) fn resync_gap(&self) -> Duration {
        self.known
            .values()
            .map(|k| k.profile.sim.quiet_before_frame())
            .chain([self.fallback.sim.quiet_before_frame()])
            .max()
            .unwrap_or_default()
    }

    /// Whether `module` has the ASCII interface (or may have it), as its profile says.
    pub(super) fn has_ascii(&self, module: u8) -> bool {
        self.profile_of(module).identity.ascii_interface() != AsciiInterface::No
    }

    /// Sends 139 and learns the echo mode (see the module docs).
    pub fn enter_ascii(&mut self, module: u8) -> Result<(), SessionError> {
        if self.frames_only {
            return Err(SessionError::Refused(
                "there is no ASCII mode over CAN: the link carries binary frames only".into(),
            ));
        }
        if !self.has_ascii(module) {
            let profile = self.profile_of(module);
            return Err(SessionError::Refused(format!(
                "the {} has no ASCII interface (profile {}); it is used in binary direct mode",
                profile.module, profile.name
            )));
        }
        // A module still in binary mode has seen our ASCII traffic to others as frame bytes; it
        // finds the start of our frame only after the line was idle for its receive time-out.
        self.align_and_drain()?;
        let frame = CommandFrame {
            address: module,
            instruction: Instruction::new(Opcode::EnterAscii, 0, 0, 0),
        };
        let bytes = frame.encode();
        self.core.wire.probe_echo();
        self.core.wire.send(
            &bytes,
            format_args!("enter ASCII mode (139) to {}", ModuleName(module)),
        )?;
        let answer = self.optional_binary_reply(module)?;
        if let Some(status) = answer.filter(|s| !s.is_success()) {
            // Still in binary mode: no CR, which its receiver would take as a frame's start.
            return Err(SessionError::Device {
                module: ModuleName(module).to_string(),
                sent: "139 (enter ASCII mode)".into(),
                reason: format!("status {status}"),
            });
        }
        self.core.wire.send(
            b"\r",
            "end of line, clears any partial line in ASCII-mode modules",
        )?;
        self.ascii_sent = true;
        self.line_dirty = false;
        let previous = self.modules.get(&module).map(|m| m.found_in);
        self.modules.insert(
            module,
            ModuleState {
                mode: WireMode::Ascii,
                found_in: WireMode::Binary,
                echo: Echo::None,
                echo_known: false,
            },
        );
        let found = previous.or(answer.map(|_| WireMode::Binary));
        self.learn_echo(module, found)
    }

    /// How long to wait for an optional reply when `bytes` must pass on the wire (out and back):
    /// the module's reaction time (no longer than the timeout, so scans stay quick) plus the
    /// bytes' wire time, whatever the timeout.
    pub(super) fn optional_wait(&self, bytes: u32) -> Duration {
        let wire = self.core.wire.wire_time(bytes);
        OPTIONAL_REPLY_WAIT.min(self.core.options.timeout) + wire
    }

    /// Waits briefly for the binary reply some firmware sends to 139; its status if it came.
    fn optional_binary_reply(&mut self, module: u8) -> Result<Option<Status>, SessionError> {
        let deadline = Instant::now() + self.optional_wait(2 * FRAME_LEN as u32);
        while self.core.wire.rx.len() < FRAME_LEN && Instant::now() < deadline {
            if !self.core.wire.fill(deadline)? {
                break;
            }
        }
        if self.core.wire.rx.len() < FRAME_LEN {
            let stray = self.core.wire.rx.clear();
            if !stray.is_empty() {
                self.core
                    .wire
                    .log(Entry::Received, &stray, "partial data after 139, discarded");
            }
            return Ok(None);
        }
        let bytes = self.core.wire.rx.take(FRAME_LEN);
        let mut frame = [0u8; FRAME_LEN];
        frame.copy_from_slice(&bytes);
        match ReplyFrame::decode(&frame) {
            Ok(reply) if reply.module == module && reply.command == Opcode::EnterAscii => {
                self.core.wire.log(
                    Entry::Received,
                    &bytes,
                    format_args!("binary reply to 139: status {}", reply.status),
                );
                Ok(Some(reply.status))
            }
            _ => {
                self.core
                    .wire
                    .log(Entry::Received, &bytes, "not a reply to 139, discarded");
                self.core.wire.notices.push(format!(
                    "unexpected bytes after entering ASCII mode: {}",
                    hex(&bytes)
                ));
                Ok(None)
            }
        }
    }

    /// Reads global parameter 67 in ASCII mode to learn the echo; decides the mode the module
    /// was found in when `found` is not already known.
    pub(super) fn learn_echo(
        &mut self,
        module: u8,
        found: Option<WireMode>,
    ) -> Result<(), SessionError> {
        let c = address_char(module).unwrap_or('?');
        let probe = Instruction::new(Opcode::Ggp, 67, 0, 0);
        let text = format!("{c}{}", self.describe_instruction(&probe));
        let exchange = match self.ascii_request(module, text, Some(Op::Command(probe))) {
            Ok(x) => x,
            Err(SessionError::Timeout { timeout, .. }) => {
                self.modules.remove(&module);
                if let Some(other) = self.sniff_other_dialect() {
                    return Err(other);
                }
                return Err(SessionError::Timeout {
                    module: ModuleName(module).to_string(),
                    timeout,
                    hint:
                        ": it does not answer in ASCII mode; check --module, the port and its baud \
                           rate, and that the module's firmware has the ASCII interface (TMCL 3.21 \
                           or later)"
                            .to_string(),
                });
            }
            Err(e) => {
                self.modules.remove(&module);
                return Err(e);
            }
        };
        let value = match exchange.reply {
            TmclReply::Status { status, value } if status.is_success() => value,
            _ => 0,
        };
        let state = self
            .modules
            .get_mut(&module)
            .expect("module state inserted before probing");
        state.echo = Echo::from_gp67(value);
        state.echo_known = true;
        state.found_in = found.unwrap_or(if value & 1 == 1 {
            WireMode::Ascii
        } else {
            WireMode::Binary
        });
        let note = format!(
            "{} in ASCII mode, echo {}, found in {} mode",
            ModuleName(module),
            state.echo.name(),
            if state.found_in == WireMode::Ascii {
                "ASCII"
            } else {
                "binary"
            }
        );
        self.core.wire.note(&note);
        Ok(())
    }

    /// Learns the echo again after a command that may have changed it.
    pub(super) fn relearn_echo(&mut self, module: u8) {
        let Some(state) = self.modules.get_mut(&module) else {
            return;
        };
        if state.mode != WireMode::Ascii {
            return;
        }
        state.echo_known = false;
        let found = Some(state.found_in);
        if let Err(e) = self.learn_echo(module, found) {
            self.core.wire.notices.push(format!(
                "could not read the echo setting of {}: {e}",
                ModuleName(module)
            ));
        }
    }

    /// Sends BIN; the module answers or not, and is in binary mode afterwards.
    pub fn leave_ascii(&mut self, module: u8) -> Result<TmclExchange, SessionError> {
        let c = address_char(module).unwrap_or('?');
        let text = format!("{c}BIN");
        let wait = self.optional_wait(BIN_EXCHANGE_BYTES);
        let result = self.ascii_request_with(
            module,
            text.clone(),
            Some(Op::Ascii(AsciiWord::Bin)),
            super::ascii::Wait::Optional(wait),
        );
        let exchange = match result {
            Ok(x) => x,
            Err(SessionError::Timeout { .. }) => TmclExchange {
                module,
                sent: text,
                op: Some(Op::Ascii(AsciiWord::Bin)),
                reply: TmclReply::Nothing,
                raw: String::new(),
            },
            Err(e) => return Err(e),
        };
        if let Some(state) = self.modules.get_mut(&module) {
            state.mode = WireMode::Binary;
        }
        self.core.wire.note(&format!(
            "{} left ASCII mode (binary direct mode)",
            ModuleName(module)
        ));
        Ok(exchange)
    }

    /// Sets the echo mode of `module` (global parameter 67 bits 5..4, keeping bit 0).
    pub fn set_echo(&mut self, module: u8, echo: Echo) -> Result<Echo, SessionError> {
        let read = self
            .request(module, Instruction::new(Opcode::Ggp, 67, 0, 0))?
            .checked()?;
        let current = read.value().unwrap_or(0);
        let write = Instruction::new(Opcode::Sgp, 67, 0, echo.apply(current));
        self.request(module, write)?.checked()?;
        self.chose_echo(module, echo);
        Ok(self.modules.get(&module).map(|m| m.echo).unwrap_or(echo))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn echo_bits_of_global_parameter_67() {
        assert_eq!(Echo::from_gp67(0x01), Echo::Character);
        assert_eq!(Echo::from_gp67(0x11), Echo::Line);
        assert_eq!(Echo::from_gp67(0x21), Echo::None);
        assert_eq!(Echo::None.apply(0x11), 0x21);
        assert_eq!(Echo::Character.apply(0x21), 0x01);
        assert_eq!(Echo::Line.apply(0), 0x10);
        assert_eq!(Echo::parse("LINE"), Some(Echo::Line));
        assert_eq!(Echo::parse("x"), None);
    }

    #[test]
    fn commands_that_change_the_echo() {
        assert!(changes_echo(&Instruction::new(9, 67, 0, 0x21)));
        assert!(changes_echo(&Instruction::new(12, 67, 0, 0)));
        assert!(changes_echo(&Instruction::new(137, 0, 0, 1234)));
        assert!(!changes_echo(&Instruction::new(9, 66, 0, 2)));
        assert!(!changes_echo(&Instruction::new(10, 67, 0, 0)));
    }
}
