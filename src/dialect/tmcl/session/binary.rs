//! One binary exchange in direct mode: a 9-byte command frame out, a 9-byte reply frame back
//! (or the version string of 136 type 0, or nothing after 137).

use std::time::Instant;

use crate::dialect::tmcl::protocol::can;
use crate::dialect::tmcl::protocol::frame::{
    CommandFrame, FRAME_LEN, ReplyFrame, decode_version_string, hex,
};
use crate::dialect::tmcl::protocol::line::{Op, address_char};
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode, Status};
use crate::link::can::CanFrame;

use super::{TmclExchange, TmclReply, TmclSession, WireMode};

/// Global parameter 76, the serial host address binary replies begin with.
const HOST_ADDRESS: u8 = 76;
use crate::session::transcript::Entry;
use crate::session::{NoiseKind, SessionError};

impl TmclSession {
    /// Sends one instruction as a binary frame and reads its reply, after a barrier when a reply
    /// given up earlier could pass for it (see `barrier.rs`).
    pub(super) fn binary_request(
        &mut self,
        module: u8,
        instruction: Instruction,
    ) -> Result<TmclExchange, SessionError> {
        self.align_for_frame()?;
        self.binary_barriers(module, &instruction)?;
        let result = self.exchange(module, false, |s| s.binary_exchange(module, instruction));
        match &result {
            // 137 is never answered: nothing of it can come late.
            _ if instruction.command == Opcode::FactoryDefaults => {}
            Ok(_) => self.late_frames.answered(module, instruction.command),
            Err(_) => self.late_frames.failed(module, instruction.command),
        }
        result
    }

    /// On a bus where ASCII lines went out, a module in binary mode took their bytes as the
    /// start of a frame: the line stays quiet for its frame time-out first, so the next frame is
    /// read from its first byte. (ASCII text never forms a frame for a module at 1..26 but 10
    /// and 13: a frame's first byte is its address, and text bytes are printable, CR or LF.)
    pub(super) fn align_for_frame(&mut self) -> Result<(), SessionError> {
        if self.frames_aligned || !std::mem::take(&mut self.ascii_sent) {
            return Ok(());
        }
        self.core.wire.idle_for(self.resync_gap())?;
        let unanswered = &mut self.unanswered;
        self.core
            .wire
            .drain(&mut |bytes| super::unanswered::harmless(bytes, unanswered))
            .map(|_| ())
    }

    pub(super) fn binary_exchange(
        &mut self,
        module: u8,
        instruction: Instruction,
    ) -> Result<TmclExchange, SessionError> {
        if self.frames_only && instruction.command == Opcode::EnterAscii {
            return Err(SessionError::Refused(
                "command 139 is not sent over CAN: TMCL over CAN has no ASCII mode".into(),
            ));
        }
        let sent = self.describe_instruction(&instruction);
        let frame = CommandFrame {
            address: module,
            instruction,
        }
        .encode();
        // No reply frame begins like its request: the first one tells whether the adapter
        // echoes.
        self.core.wire.probe_echo();
        let can = self.can_form(|| can::request(&frame));
        let sent_at = self.core.wire.send(
            &frame,
            format_args!("{sent} to {} in binary{can}", ModuleName(module)),
        )?;
        // Modules in ASCII mode now hold the frame as the start of a line.
        self.line_dirty = self.modules.values().any(|m| m.mode == WireMode::Ascii);
        let exchange = |(reply, raw)| TmclExchange {
            module,
            sent,
            op: Some(Op::Command(instruction)),
            reply,
            raw,
        };
        if instruction.command == Opcode::FactoryDefaults {
            return Ok(exchange((TmclReply::Nothing, String::new())));
        }
        let deadline = sent_at + self.core.options.timeout;
        // When the line was last read (as in `ascii.rs`).
        let mut read_at = sent_at;
        loop {
            while let Some(raw) = self.front_frame() {
                if let Some(answer) = self.take_frame(module, instruction, &raw, deadline)? {
                    return Ok(exchange(answer));
                }
            }
            if read_at >= deadline || !self.core.wire.fill(deadline)? {
                return Err(self.binary_timeout(module));
            }
            read_at = self.core.wire.heard_at().unwrap_or(deadline);
        }
    }

    /// The CAN frame a serial frame travelled as, for the transcript (`, CAN 001#0604…`), on a
    /// CAN link; nothing on a serial one.
    fn can_form(&self, frame: impl FnOnce() -> CanFrame) -> String {
        if self.frames_only {
            format!(", CAN {}", frame())
        } else {
            String::new()
        }
    }

    /// The frame at the front of the receive buffer, once nine bytes are there.
    fn front_frame(&self) -> Option<[u8; FRAME_LEN]> {
        let bytes = self.core.wire.rx.bytes().get(..FRAME_LEN)?;
        let mut raw = [0u8; FRAME_LEN];
        raw.copy_from_slice(bytes);
        Some(raw)
    }

    /// Takes the frame at the front of the buffer: the answer to `instruction` with its text, or
    /// `None` for a frame that is no answer (an event, a reply to another request), set aside.
    fn take_frame(
        &mut self,
        module: u8,
        instruction: Instruction,
        raw: &[u8; FRAME_LEN],
        deadline: Instant,
    ) -> Result<Option<(TmclReply, String)>, SessionError> {
        if !self.may_be_reply(module, instruction, raw) {
            return Ok(None);
        }
        if instruction.command == Opcode::FirmwareVersion && instruction.type_ == 0 {
            let (host, text) = decode_version_string(raw);
            self.version_host = Some(host);
            if !raw[1..].iter().all(u8::is_ascii_graphic) {
                return Err(self.binary_noise(
                    "not a version string",
                    SessionError::noise(format!(
                        "line noise: {} answered command 136 with {}, which is not a firmware \
                         version (8 printable characters, such as 142V1.06); not taken",
                        ModuleName(module),
                        hex(raw)
                    )),
                ));
            }
            self.settle_binary(module, raw, deadline)?;
            self.host = Some(raw[0]);
            let can = self.can_form(|| can::reply(raw, u16::from(raw[0]), true));
            self.core
                .wire
                .log_received(FRAME_LEN, format_args!("version {text}{can}"));
            return Ok(Some((TmclReply::Version(text.clone()), text)));
        }
        let reply = ReplyFrame::decode(raw).map_err(|e| {
            self.binary_noise(
                "bad checksum",
                SessionError::Link(format!("corrupted reply from {}: {e}", ModuleName(module))),
            )
        })?;
        if reply.is_position_event() {
            self.note_event(reply.module);
            self.core.wire.log_received(
                FRAME_LEN,
                "target position reached event, not a reply; discarded",
            );
            return Ok(None);
        }
        if reply.module != module || reply.command != instruction.command {
            let kind = format!(
                "a reply frame not for the request to {}",
                ModuleName(module)
            );
            self.core.wire.discard(FRAME_LEN, &kind);
            return Ok(None);
        }
        if let Status::Other(code) = reply.status {
            return Err(self.binary_noise(
                "unknown status",
                SessionError::noise(format!(
                    "line noise: {} answered with status {code}, which no module sends; not taken",
                    ModuleName(module)
                )),
            ));
        }
        self.settle_binary(module, raw, deadline)?;
        self.host = Some(reply.host);
        self.forget_host(&instruction);
        let can = self.can_form(|| can::reply(raw, u16::from(raw[0]), false));
        self.core.wire.log_received(
            FRAME_LEN,
            format_args!(
                "from {}: {}, value {}{can}",
                ModuleName(reply.module),
                reply.status,
                reply.value
            ),
        );
        let answer = TmclReply::Status {
            status: reply.status,
            value: reply.value,
        };
        Ok(Some((answer, binary_reply_text(&reply))))
    }

    /// Whether the frame at the front of the buffer can be a reply: it begins with the host
    /// address (once known), and is not the request itself handed back by an adapter that
    /// echoes. Any other frame is set aside with a note: taken for the reply, the echo of `SAP
    /// 4, 5, 1000` to module 5 reads as "invalid value".
    fn may_be_reply(
        &mut self,
        module: u8,
        instruction: Instruction,
        raw: &[u8; FRAME_LEN],
    ) -> bool {
        let sent = CommandFrame {
            address: module,
            instruction,
        }
        .encode();
        let kind = match self.host {
            _ if raw[..] == sent[..] => "the request itself, handed back (an adapter that \
                                          echoes? --local-echo), not a reply"
                .to_string(),
            Some(host) if raw[0] != host => format!(
                "a frame beginning with {} where a reply begins with the host address {host}, \
                 not a reply",
                raw[0]
            ),
            _ => return true,
        };
        self.core.wire.discard(FRAME_LEN, &kind);
        false
    }

    /// A module told a new host address answers with it from now on (or already to this): the
    /// next reply says which it is.
    pub(super) fn forget_host(&mut self, instruction: &Instruction) {
        if instruction.command == Opcode::Sgp
            && instruction.type_ == HOST_ADDRESS
            && instruction.motor == 0
        {
            self.host = None;
        }
    }

    /// No whole answer before the deadline: what came is logged and named in the error.
    fn binary_timeout(&mut self, module: u8) -> SessionError {
        let partial = self.core.wire.rx.clear();
        if !partial.is_empty() {
            self.core
                .wire
                .log(Entry::Received, &partial, "incomplete frame, no reply");
        }
        SessionError::Timeout {
            module: ModuleName(module).to_string(),
            timeout: self.core.options.timeout,
            hint: if partial.is_empty() {
                String::new()
            } else {
                format!(" (received only {})", hex(&partial))
            },
        }
    }

    /// Tells the user of a position-reached event that came instead of, or after, a reply.
    fn note_event(&mut self, module: u8) {
        self.core.wire.notices.push(format!(
            "{}: target position reached (event)",
            ModuleName(module)
        ));
    }

    /// Checks what follows the reply frame at the front of the buffer: nothing, or whole event
    /// frames. Anything else — a frame that is longer than nine bytes, a second reply — is noise.
    fn settle_binary(
        &mut self,
        module: u8,
        reply: &[u8; FRAME_LEN],
        deadline: Instant,
    ) -> Result<(), SessionError> {
        let hard_end = deadline.max(Instant::now() + self.core.wire.settle_time());
        let mut pos = FRAME_LEN;
        loop {
            while self.core.wire.rx.len() >= pos + FRAME_LEN {
                let mut frame = [0u8; FRAME_LEN];
                frame.copy_from_slice(&self.core.wire.rx.bytes()[pos..pos + FRAME_LEN]);
                match ReplyFrame::decode(&frame) {
                    Ok(r) if r.is_position_event() => {
                        self.note_event(r.module);
                        pos += FRAME_LEN;
                    }
                    _ => return Err(self.trailing_noise(module, reply)),
                }
            }
            let partial = self.core.wire.rx.len() > pos;
            if Instant::now() >= hard_end || !self.core.wire.await_more(hard_end)? {
                if partial {
                    return Err(self.trailing_noise(module, reply));
                }
                return Ok(());
            }
        }
    }

    fn trailing_noise(&mut self, module: u8, reply: &[u8; FRAME_LEN]) -> SessionError {
        let rest = &self.core.wire.rx.bytes()[FRAME_LEN..];
        let after = hex(&rest[..rest.len().min(3 * FRAME_LEN)]);
        let other = answered_too(module, reply[0], rest);
        let clash = other
            .map(|other| {
                format!(
                    " — a reply from {}, which takes the replies of others for requests: its \
                     address is the host address",
                    ModuleName(other)
                )
            })
            .unwrap_or_default();
        let said = format!(
            "line noise: the reply {} from {} was followed by {after}{clash}; not taken",
            hex(reply),
            ModuleName(module)
        );
        let kind = match other {
            Some(_) => NoiseKind::HostClash,
            None => NoiseKind::Garbled,
        };
        self.binary_noise(
            "a reply followed by more data",
            SessionError::Noise { said, kind },
        )
    }

    /// Ends a binary exchange on line noise, logging what was received.
    fn binary_noise(&mut self, what: &str, error: SessionError) -> SessionError {
        let bytes = self.core.wire.rx.clear();
        self.core.wire.log(
            Entry::Received,
            &bytes,
            format_args!("{what}: line noise, discarded"),
        );
        self.core.wire.note(&error.to_string());
        error
    }
}

/// The module whose reply frame to the same host follows the reply of `module`: on a shared bus,
/// one at the host address answering that reply as if it were a request to it.
fn answered_too(module: u8, host: u8, rest: &[u8]) -> Option<u8> {
    let frame: &[u8; FRAME_LEN] = rest.get(..FRAME_LEN)?.try_into().ok()?;
    let other = ReplyFrame::decode(frame).ok()?;
    (other.host == host && other.module != module && other.module == host).then_some(other.module)
}

/// A binary reply in the ASCII reply format (`BA 100 -5000`), so one-shot output looks the same in
/// both modes; addresses without a letter are shown as numbers.
pub(super) fn binary_reply_text(reply: &ReplyFrame) -> String {
    let name = |a: u8| {
        address_char(a)
            .map(String::from)
            .unwrap_or_else(|| format!("<{a}>"))
    };
    format!(
        "{}{} {} {}",
        name(reply.host),
        name(reply.module),
        reply.status.code(),
        reply.value
    )
}
