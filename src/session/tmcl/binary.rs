//! One binary exchange in direct mode: a 9-byte command frame out, a 9-byte reply frame back
//! (or the version string of 136 type 0, or nothing after 137).

use std::time::Instant;

use crate::protocol::tmcl::frame::{
    CommandFrame, FRAME_LEN, ReplyFrame, decode_version_string, hex,
};
use crate::protocol::tmcl::line::{Op, address_char};
use crate::protocol::tmcl::{Instruction, Status};

use super::super::SessionError;
use super::super::transcript::Entry;
use super::{Answer, Exchange, TmclSession};

impl TmclSession {
    /// Sends one instruction as a binary frame and reads its reply.
    pub(super) fn binary_request(
        &mut self,
        module: u8,
        instruction: Instruction,
    ) -> Result<Exchange, SessionError> {
        self.wire.drain()?;
        let sent = self.describe_instruction(&instruction);
        let frame = CommandFrame {
            address: module,
            instruction,
        }
        .encode();
        self.wire
            .send(&frame, format_args!("{sent} to module {module} (binary)"))?;
        let exchange = |answer, raw| Exchange {
            module,
            sent: sent.clone(),
            op: Some(Op::Command(instruction)),
            answer,
            raw,
        };
        if instruction.command == 137 {
            return Ok(exchange(Answer::Nothing, String::new()));
        }
        let deadline = Instant::now() + self.options.timeout;
        loop {
            while self.wire.rx.len() >= FRAME_LEN {
                let bytes = self.wire.rx.take(FRAME_LEN);
                let mut raw = [0u8; FRAME_LEN];
                raw.copy_from_slice(&bytes);
                if instruction.command == 136 && instruction.type_ == 0 {
                    let (_, text) = decode_version_string(&raw);
                    self.wire
                        .log(Entry::Received, &bytes, format_args!("version {text}"));
                    return Ok(exchange(Answer::Version(text.clone()), text));
                }
                let reply = match ReplyFrame::decode(&raw) {
                    Ok(reply) => reply,
                    Err(e) => {
                        self.wire.log(Entry::Received, &bytes, "bad checksum");
                        self.wire.rx.clear();
                        return Err(SessionError::Link(format!(
                            "corrupted reply from module {module}: {e}"
                        )));
                    }
                };
                self.wire.log(
                    Entry::Received,
                    &bytes,
                    format_args!(
                        "from module {}: {}, value {}",
                        reply.module, reply.status, reply.value
                    ),
                );
                if reply.command == 138 && reply.status == Status::PositionReachedEvent {
                    self.wire.notices.push(format!(
                        "module {}: target position reached (event)",
                        reply.module
                    ));
                    continue;
                }
                if reply.module != module || reply.command != instruction.command {
                    self.wire.notices.push(format!(
                        "ignored reply {} while waiting for module {module}",
                        hex(&bytes)
                    ));
                    continue;
                }
                let raw = binary_reply_text(&reply);
                return Ok(exchange(
                    Answer::Reply {
                        status: reply.status,
                        value: reply.value,
                    },
                    raw,
                ));
            }
            if !self.wire.fill(deadline)? {
                let partial = self.wire.rx.clear();
                if !partial.is_empty() {
                    self.wire
                        .log(Entry::Received, &partial, "incomplete frame, discarded");
                }
                return Err(SessionError::Timeout {
                    module: address_char(module).unwrap_or('?').to_string(),
                    timeout: self.options.timeout,
                    hint: if partial.is_empty() {
                        String::new()
                    } else {
                        format!(" (received only {})", hex(&partial))
                    },
                });
            }
        }
    }
}

/// A binary reply in the ASCII reply format (`BA 100 -5000`), so one-shot output looks the same in
/// both modes; addresses without a letter are shown as numbers.
pub fn binary_reply_text(reply: &ReplyFrame) -> String {
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
