//! TMCL over CAN (TMCM-142 manual §6.1, §6.2): "when using CAN bus, just leave out the first byte
//! (module address) and the last byte (checksum)" of a command, and in replies "the first byte
//! (reply address) and the last byte (checksum)". The module address travels as the request's
//! CAN ID, the host's as the reply's. Command 136 type 0 is answered with all eight characters
//! of the version string in one 8-byte frame (PyTrinamic's `get_version_string` reads it so).
//! PyTrinamic sends the binary checksum as an eighth request byte: requests of 7 or 8 bytes are
//! taken. The [`TmclFramer`] carries the session's 9-byte frames over a CAN link unchanged.

use crate::link::can::{CanFrame, Framer};

use super::frame::{FRAME_LEN, checksum};

/// Data bytes of a request or reply: a serial frame without its first and last byte.
pub const CAN_DATA: usize = FRAME_LEN - 2;

/// The CAN request for a serial command frame: its module address as the ID.
pub fn request(frame: &[u8; FRAME_LEN]) -> CanFrame {
    CanFrame::new(u16::from(frame[0]), &frame[1..8]).expect("7 bytes, an 8-bit ID")
}

/// The serial command frame a CAN request stands for (7 data bytes, or 8 with a checksum byte
/// that is ignored); `None` for any other length or an ID no module address has.
pub fn command(frame: &CanFrame) -> Option<[u8; FRAME_LEN]> {
    let data = frame.data();
    let address = u8::try_from(frame.id()).ok()?;
    if !(data.len() == CAN_DATA || data.len() == CAN_DATA + 1) {
        return None;
    }
    let mut out = [0u8; FRAME_LEN];
    out[0] = address;
    out[1..8].copy_from_slice(&data[..CAN_DATA]);
    out[8] = checksum(&out[..8]);
    Some(out)
}

/// The CAN reply for a serial reply frame, sent to `reply_id`: seven bytes, or the eight
/// characters of a version string (`version`: the answer to 136 type 0).
pub fn reply(frame: &[u8; FRAME_LEN], reply_id: u16, version: bool) -> CanFrame {
    let data = if version { &frame[1..] } else { &frame[1..8] };
    CanFrame::new(reply_id, data).expect("at most 8 bytes; a reply ID of 11 bits")
}

/// The serial reply frame a CAN reply stands for, beginning with `host`: seven data bytes with
/// the checksum added, or eight (a version string) as they are; `None` for another length.
pub fn reply_frame(frame: &CanFrame, host: u8) -> Option<[u8; FRAME_LEN]> {
    let data = frame.data();
    let mut out = [0u8; FRAME_LEN];
    out[0] = host;
    match data.len() {
        CAN_DATA => {
            out[1..8].copy_from_slice(data);
            out[8] = checksum(&out[..8]);
        }
        8 => out[1..].copy_from_slice(data),
        _ => return None,
    }
    Some(out)
}

/// A TMCL session's frames over CAN: each 9-byte command goes to the CAN ID of its module
/// address; frames to the host's reply ID come back as serial replies; frames to any other ID
/// (other nodes, heartbeats, other masters' requests) are not the host's. Bytes that are not
/// whole command frames (ASCII text, a lone CR) have no CAN form: they are dropped, not cut
/// into frames that would reach modules as requests.
#[derive(Debug)]
pub struct TmclFramer {
    reply_id: u16,
}

impl TmclFramer {
    /// A framer taking replies sent to `reply_id`.
    pub fn new(reply_id: u16) -> TmclFramer {
        TmclFramer { reply_id }
    }
}

impl Framer for TmclFramer {
    fn frames(&mut self, bytes: &[u8]) -> Vec<CanFrame> {
        let whole = bytes.len() % FRAME_LEN == 0
            && bytes
                .chunks_exact(FRAME_LEN)
                .all(|c| checksum(&c[..8]) == c[8]);
        if !whole {
            return Vec::new();
        }
        bytes
            .chunks_exact(FRAME_LEN)
            .map(|c| request(c.try_into().expect("chunks of 9")))
            .collect()
    }

    /// The reply's first byte is the reply ID's low byte: a session learns the host address
    /// from the replies it takes.
    fn bytes(&mut self, frame: &CanFrame) -> Option<Vec<u8>> {
        if frame.id() != self.reply_id {
            return None;
        }
        reply_frame(frame, self.reply_id as u8).map(|f| f.to_vec())
    }

    fn describe(&self) -> String {
        format!("replies to CAN ID {}", self.reply_id)
    }
}

#[cfg(test)]
mod tests {
    use super::super::frame::{CommandFrame, ReplyFrame, encode_version_string};
    use super::super::{Instruction, Opcode, Status};
    use super::*;

    #[test]
    fn a_command_loses_its_address_and_checksum() {
        let frame = CommandFrame {
            address: 3,
            instruction: Instruction::new(Opcode::Sap, 4, 0, 1000),
        }
        .encode();
        let can = request(&frame);
        assert_eq!(can.id(), 3);
        assert_eq!(can.data(), &[5, 4, 0, 0, 0, 0x03, 0xE8]);
        assert_eq!(command(&can), Some(frame));
        let mut with_sum = can.data().to_vec();
        with_sum.push(0xAA);
        assert_eq!(command(&CanFrame::new(3, &with_sum).unwrap()), Some(frame));
        assert_eq!(command(&CanFrame::new(3, &[5, 4]).unwrap()), None);
        assert_eq!(command(&CanFrame::new(0x100, can.data()).unwrap()), None);
    }

    #[test]
    fn a_reply_loses_its_host_address_and_checksum() {
        let frame = ReplyFrame {
            host: 2,
            module: 1,
            status: Status::Ok,
            command: Opcode::Gap,
            value: -5,
        }
        .encode();
        let can = reply(&frame, 2, false);
        assert_eq!(can.id(), 2);
        assert_eq!(can.data(), &frame[1..8]);
        assert_eq!(reply_frame(&can, 2), Some(frame));
    }

    #[test]
    fn a_version_string_fills_eight_bytes() {
        let frame = encode_version_string(2, "0142V106");
        let can = reply(&frame, 2, true);
        assert_eq!(can.data(), b"0142V106");
        assert_eq!(reply_frame(&can, 2), Some(frame));
    }

    #[test]
    fn the_framer_sends_whole_frames_only_and_ignores_other_ids() {
        let frame = CommandFrame {
            address: 1,
            instruction: Instruction::new(Opcode::Gap, 1, 0, 0),
        }
        .encode();
        let mut framer = TmclFramer::new(5);
        assert!(framer.frames(&frame[..4]).is_empty());
        assert!(framer.frames(b"AGAP 1, 0\r").is_empty(), "ASCII");
        assert!(framer.frames(b"\r").is_empty());
        let sent = framer.frames(&[&frame[..], &frame[..]].concat());
        assert_eq!(sent, vec![request(&frame); 2]);
        let answer = CanFrame::new(5, &[1, 100, 6, 0, 0, 0, 9]).unwrap();
        let bytes = framer.bytes(&answer).unwrap();
        assert_eq!(bytes[0], 5);
        assert_eq!(
            ReplyFrame::decode(&bytes.try_into().unwrap())
                .unwrap()
                .value,
            9
        );
        assert_eq!(
            framer.bytes(&CanFrame::new(2, answer.data()).unwrap()),
            None
        );
        assert_eq!(framer.bytes(&CanFrame::new(5, &[1]).unwrap()), None);
    }
}
