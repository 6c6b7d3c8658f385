use super::*;
use proptest::prelude::*;

fn any_instruction() -> impl Strategy<Value = Instruction> {
    (any::<u8>(), any::<u8>(), any::<u8>(), any::<i32>())
        .prop_map(|(c, t, m, v)| Instruction::new(c, t, m, v))
}

proptest! {
    #[test]
    fn command_frames_round_trip(address: u8, instruction in any_instruction()) {
        let frame = CommandFrame { address, instruction };
        prop_assert_eq!(CommandFrame::decode(&frame.encode()), Ok(frame));
    }

    #[test]
    fn reply_frames_round_trip(host: u8, module: u8, status: u8, command: u8, value: i32) {
        let reply = ReplyFrame { host, module, status: Status::from_code(status), command: command.into(), value };
        prop_assert_eq!(ReplyFrame::decode(&reply.encode()), Ok(reply));
    }

    #[test]
    fn any_single_byte_corruption_is_caught(
        instruction in any_instruction(), index in 0usize..9, flip in 1u8..=255,
    ) {
        let mut bytes = CommandFrame { address: 1, instruction }.encode();
        bytes[index] ^= flip;
        prop_assert!(CommandFrame::decode(&bytes).is_err());
    }

    #[test]
    fn decoder_accepts_any_split(
        frames in proptest::collection::vec(any_instruction(), 1..6),
        cuts in proptest::collection::vec(0usize..60, 0..10),
    ) {
        let stream: Vec<u8> = frames
            .iter()
            .flat_map(|&instruction| CommandFrame { address: 3, instruction }.encode())
            .collect();
        let mut cuts: Vec<usize> = cuts.into_iter().map(|c| c % (stream.len() + 1)).collect();
        cuts.sort();
        let mut decoder = FrameDecoder::new();
        let mut decoded = Vec::new();
        let mut start = 0;
        for cut in cuts.into_iter().chain([stream.len()]) {
            decoder.push(&stream[start..cut]);
            start = cut;
            while let Some(frame) = decoder.next_frame() {
                decoded.push(CommandFrame::decode(&frame.unwrap()).unwrap().instruction);
            }
        }
        prop_assert_eq!(decoded, frames);
        prop_assert_eq!(decoder.pending(), 0);
    }
}

#[test]
fn encodes_the_manual_layout_with_a_correct_checksum() {
    // ROR 0, 350 to module 1. The manual's own example prints motor 2 and checksum 0x62, which do
    // not add up; the correct sum of 01 01 00 00 00 00 01 5E is 0x61.
    let frame = CommandFrame {
        address: 1,
        instruction: Instruction::new(1, 0, 0, 350),
    };
    assert_eq!(
        frame.encode(),
        [0x01, 0x01, 0x00, 0x00, 0x00, 0x00, 0x01, 0x5E, 0x61]
    );
}

#[test]
fn reply_layout_matches_the_manual() {
    let reply = ReplyFrame {
        host: 2,
        module: 1,
        status: Status::Ok,
        command: 6.into(),
        value: -5000,
    };
    let bytes = reply.encode();
    assert_eq!(bytes[..8], [2, 1, 100, 6, 0xFF, 0xFF, 0xEC, 0x78]);
    assert_eq!(bytes[8], checksum(&bytes[..8]));
}

#[test]
fn bad_checksum_is_reported_with_both_sums() {
    let mut decoder = FrameDecoder::new();
    decoder.push(&[1, 6, 1, 0, 0, 0, 0, 0, 0x0A]);
    let err = decoder.next_frame().unwrap().unwrap_err();
    assert_eq!(err.expected, 0x08);
    assert!(err.to_string().contains("expected 0x08, got 0x0a"), "{err}");
    assert!(decoder.next_frame().is_none());
}

#[test]
fn decoder_waits_for_the_ninth_byte() {
    let mut decoder = FrameDecoder::new();
    let bytes = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 1, 0, 0),
    }
    .encode();
    decoder.push(&bytes[..8]);
    assert!(decoder.next_frame().is_none());
    assert_eq!(decoder.pending(), 8);
    decoder.push(&bytes[8..]);
    assert!(decoder.next_frame().unwrap().is_ok());
}

#[test]
fn version_string_reply_has_no_checksum() {
    let bytes = encode_version_string(2, "142V1.06");
    assert_eq!(bytes, *b"\x02142V1.06");
    assert_eq!(decode_version_string(&bytes), (2, "142V1.06".to_string()));
}
