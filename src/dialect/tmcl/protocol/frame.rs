//! Binary TMCL frames (manual §6.1, §6.2): 9-byte commands and replies with an 8-bit checksum,
//! and an incremental decoder that accepts bytes in any pieces.

use super::instruction::Instruction;
use super::opcode::Opcode;
use super::status::Status;

/// Length of a serial command or reply frame.
pub const FRAME_LEN: usize = 9;

/// The 8-bit sum of `bytes`.
pub fn checksum(bytes: &[u8]) -> u8 {
    bytes.iter().fold(0u8, |sum, b| sum.wrapping_add(*b))
}

/// A frame whose last byte is not the sum of the others.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("bad checksum in frame {}: expected {expected:#04x}, got {:#04x}", hex(bytes), bytes[8])]
pub struct ChecksumError {
    /// The frame as received.
    pub bytes: [u8; FRAME_LEN],
    /// The sum of its first eight bytes.
    pub expected: u8,
}

/// Bytes as space-separated hex, for messages and transcripts.
pub fn hex(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|b| format!("{b:02X}"))
        .collect::<Vec<_>>()
        .join(" ")
}

fn verified(bytes: &[u8; FRAME_LEN]) -> Result<(), ChecksumError> {
    let expected = checksum(&bytes[..8]);
    if expected == bytes[8] {
        Ok(())
    } else {
        Err(ChecksumError {
            bytes: *bytes,
            expected,
        })
    }
}

/// A command frame: module address, instruction, checksum.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CommandFrame {
    /// Module address (global parameter 66).
    pub address: u8,
    /// What to do.
    pub instruction: Instruction,
}

impl CommandFrame {
    /// The nine bytes on the wire.
    pub fn encode(&self) -> [u8; FRAME_LEN] {
        let mut out = [0u8; FRAME_LEN];
        out[0] = self.address;
        out[1..8].copy_from_slice(&self.instruction.to_bytes());
        out[8] = checksum(&out[..8]);
        out
    }

    /// Decodes nine bytes, checking the checksum.
    pub fn decode(bytes: &[u8; FRAME_LEN]) -> Result<Self, ChecksumError> {
        verified(bytes)?;
        let mut body = [0u8; 7];
        body.copy_from_slice(&bytes[1..8]);
        Ok(CommandFrame {
            address: bytes[0],
            instruction: Instruction::from_bytes(body),
        })
    }
}

/// A reply frame: host address, module address, status, command, value, checksum.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReplyFrame {
    /// Reply (host) address, global parameter 76.
    pub host: u8,
    /// Address of the module that answers.
    pub module: u8,
    /// Outcome of the command.
    pub status: Status,
    /// The command answered.
    pub command: Opcode,
    /// Returned value.
    pub value: i32,
}

impl ReplyFrame {
    /// The nine bytes on the wire.
    pub fn encode(&self) -> [u8; FRAME_LEN] {
        let v = self.value.to_be_bytes();
        let mut out = [
            self.host,
            self.module,
            self.status.code(),
            self.command.into(),
            v[0],
            v[1],
            v[2],
            v[3],
            0,
        ];
        out[8] = checksum(&out[..8]);
        out
    }

    /// Decodes nine bytes, checking the checksum.
    pub fn decode(bytes: &[u8; FRAME_LEN]) -> Result<Self, ChecksumError> {
        verified(bytes)?;
        Ok(ReplyFrame {
            host: bytes[0],
            module: bytes[1],
            status: Status::from_code(bytes[2]),
            command: bytes[3].into(),
            value: i32::from_be_bytes([bytes[4], bytes[5], bytes[6], bytes[7]]),
        })
    }
}

impl ReplyFrame {
    /// Whether this is the delayed event of command 138 (target position reached), which comes
    /// on its own and is no reply to a request.
    pub fn is_position_event(&self) -> bool {
        self.command == Opcode::PositionEvent && self.status == Status::PositionReachedEvent
    }
}

/// The special reply of command 136 type 0: host address and eight ASCII characters, no checksum
/// (manual §6.7.35).
pub fn decode_version_string(bytes: &[u8; FRAME_LEN]) -> (u8, String) {
    let text = bytes[1..]
        .iter()
        .map(|&b| {
            if b.is_ascii_graphic() || b == b' ' {
                b as char
            } else {
                '?'
            }
        })
        .collect();
    (bytes[0], text)
}

/// Encodes the special reply of command 136 type 0 (the version string is padded or cut to 8).
pub fn encode_version_string(host: u8, version: &str) -> [u8; FRAME_LEN] {
    let mut out = [b' '; FRAME_LEN];
    out[0] = host;
    for (slot, b) in out[1..].iter_mut().zip(version.bytes()) {
        *slot = b;
    }
    out
}

/// Collects bytes arriving in arbitrary pieces into 9-byte frames.
#[derive(Debug, Default, Clone)]
pub struct FrameDecoder {
    buf: Vec<u8>,
}

impl FrameDecoder {
    /// An empty decoder.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends received bytes.
    pub fn push(&mut self, bytes: &[u8]) {
        self.buf.extend_from_slice(bytes);
    }

    /// The next complete frame (with its checksum verified), if nine bytes are waiting.
    pub fn next_frame(&mut self) -> Option<Result<[u8; FRAME_LEN], ChecksumError>> {
        if self.buf.len() < FRAME_LEN {
            return None;
        }
        let mut frame = [0u8; FRAME_LEN];
        frame.copy_from_slice(&self.buf[..FRAME_LEN]);
        self.buf.drain(..FRAME_LEN);
        Some(verified(&frame).map(|()| frame))
    }

    /// Bytes of an incomplete frame still waiting.
    pub fn pending(&self) -> usize {
        self.buf.len()
    }

    /// Forgets a partial frame (resynchronisation after a gap or an error).
    pub fn clear(&mut self) {
        self.buf.clear();
    }
}

#[cfg(test)]
mod tests;
