//! The slcan (Lawicel serial-line CAN) text protocol, pure: frames as `tIIILDD…` CR, the open
//! sequence's commands, and an incremental decoder of what an adapter sends back — received
//! frames, the acknowledgements some firmwares give a transmit (`z`, `Z`, a bare CR), and BEL, the
//! adapter's error. The same decoder reads a host's lines on the simulator's side.

use super::frame::{CanFrame, MAX_DATA};

/// The `S0`…`S8` bit rates of the Lawicel CANUSB manual (python-can's `slcan` bus and the
/// CANable and USBtin firmwares use the same table): the code is the index.
pub const BITRATES: [u32; 9] = [
    10_000, 20_000, 50_000, 100_000, 125_000, 250_000, 500_000, 800_000, 1_000_000,
];

/// The `Sn` command setting `bps`, or `None` when slcan has no code for it.
pub fn bitrate_command(bps: u32) -> Option<String> {
    BITRATES
        .iter()
        .position(|&rate| rate == bps)
        .map(|code| format!("S{code}\r"))
}

/// The bit rate an `Sn` code stands for.
pub fn bitrate_of(code: u8) -> Option<u32> {
    BITRATES.get(usize::from(code)).copied()
}

/// Opens the channel.
pub const OPEN: &str = "O\r";
/// Closes the channel (accepted, or refused with BEL, when it is closed already).
pub const CLOSE: &str = "C\r";

/// The BEL byte: an adapter refusing a command or a frame.
pub const BEL: u8 = 0x07;

/// A standard frame as the transmit command `tIIILDD…` CR.
pub fn encode(frame: &CanFrame) -> String {
    let mut out = format!("t{:03X}{}", frame.id(), frame.data().len());
    for b in frame.data() {
        out.push_str(&format!("{b:02X}"));
    }
    out.push('\r');
    out
}

/// How an adapter acknowledged a command or a transmitted frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ack {
    /// `z` CR: a standard frame was queued (Lawicel, CANable).
    Transmit,
    /// `Z` CR: an extended frame was queued; some firmwares use it for every frame.
    TransmitExtended,
    /// A bare CR: the command was taken (the answer to `C`, `Sn`, `O`; some firmwares' transmit).
    Ok,
}

/// How an adapter acknowledges a transmitted frame: firmwares differ (the simulator plays each).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AckStyle {
    /// `z` CR (Lawicel CANUSB, CANable's slcan firmware).
    #[default]
    Lower,
    /// `Z` CR.
    Upper,
    /// A bare CR.
    Cr,
    /// Nothing at all.
    None,
}

impl AckStyle {
    /// The bytes of the acknowledgement.
    pub fn bytes(self) -> &'static [u8] {
        match self {
            AckStyle::Lower => b"z\r",
            AckStyle::Upper => b"Z\r",
            AckStyle::Cr => b"\r",
            AckStyle::None => b"",
        }
    }

    /// The style by its name on the command line: `z`, `Z`, `cr`, `none`.
    pub fn parse(name: &str) -> Option<AckStyle> {
        match name {
            "z" => Some(AckStyle::Lower),
            "Z" => Some(AckStyle::Upper),
            "cr" => Some(AckStyle::Cr),
            "none" => Some(AckStyle::None),
            _ => None,
        }
    }
}

/// One thing read from the other end.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Event {
    /// A standard data frame (`t…`, with or without the 4-digit timestamp `Z1` adds).
    Frame(CanFrame),
    /// An acknowledgement.
    Ack(Ack),
    /// BEL: the adapter refused what it was sent, or reports an error.
    Bell,
    /// Any other line: a version answer, an extended or remote frame (`T…`, `r…`, `R…`), a
    /// host's command on the simulator's side, or noise. Without its CR.
    Line(String),
}

/// The longest line kept: an extended frame with eight bytes and a timestamp is 30 characters.
const MAX_LINE: usize = 40;

/// Reads events from bytes that arrive in any pieces.
#[derive(Debug, Default)]
pub struct Decoder {
    line: Vec<u8>,
}

impl Decoder {
    /// Takes `bytes`, appending each event they complete to `out`. A line longer than any slcan
    /// line is given up as a [`Event::Line`] of what was kept; a line feed is ignored.
    pub fn push(&mut self, bytes: &[u8], out: &mut Vec<Event>) {
        for &b in bytes {
            match b {
                b'\r' => out.push(parse_line(&std::mem::take(&mut self.line))),
                BEL => {
                    if !self.line.is_empty() {
                        out.push(Event::Line(lossy(&std::mem::take(&mut self.line))));
                    }
                    out.push(Event::Bell);
                }
                b'\n' => {}
                _ if self.line.len() >= MAX_LINE => {
                    out.push(Event::Line(lossy(&std::mem::take(&mut self.line))));
                    self.line.push(b);
                }
                _ => self.line.push(b),
            }
        }
    }
}

fn lossy(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// One line without its CR.
pub fn parse_line(line: &[u8]) -> Event {
    match line {
        b"" => Event::Ack(Ack::Ok),
        b"z" => Event::Ack(Ack::Transmit),
        b"Z" => Event::Ack(Ack::TransmitExtended),
        [b't', rest @ ..] => match standard_frame(rest) {
            Some(frame) => Event::Frame(frame),
            None => Event::Line(lossy(line)),
        },
        _ => Event::Line(lossy(line)),
    }
}

/// `IIILDD…` with an optional 4-digit timestamp after the data.
fn standard_frame(text: &[u8]) -> Option<CanFrame> {
    let id = hex_value(text.get(..3)?)?;
    let len = usize::from(text.get(3)?.checked_sub(b'0')?);
    if len > MAX_DATA {
        return None;
    }
    let data_end = 4 + 2 * len;
    let rest = text.get(data_end..)?;
    if !(rest.is_empty() || (rest.len() == 4 && hex_value(rest).is_some())) {
        return None;
    }
    let mut data = [0u8; MAX_DATA];
    for (i, pair) in text[4..data_end].chunks(2).enumerate() {
        data[i] = u8::try_from(hex_value(pair)?).ok()?;
    }
    CanFrame::new(u16::try_from(id).ok()?, &data[..len]).ok()
}

/// The value of ASCII hex digits (either case).
fn hex_value(digits: &[u8]) -> Option<u32> {
    digits.iter().try_fold(0u32, |value, &d| {
        let digit = char::from(d).to_digit(16)?;
        Some(value * 16 + digit)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(bytes: &[u8]) -> Vec<Event> {
        let mut out = Vec::new();
        Decoder::default().push(bytes, &mut out);
        out
    }

    fn frame(id: u16, data: &[u8]) -> Event {
        Event::Frame(CanFrame::new(id, data).unwrap())
    }

    #[test]
    fn frames_encode_as_transmit_commands() {
        let f = CanFrame::new(1, &[6, 1, 0, 0, 0, 0x03, 0xE8]).unwrap();
        assert_eq!(encode(&f), "t0017060100000003E8\r");
        assert_eq!(encode(&CanFrame::new(0x7FF, &[]).unwrap()), "t7FF0\r");
    }

    #[test]
    fn every_encoded_frame_decodes_to_itself() {
        for len in 0..=8u8 {
            let data: Vec<u8> = (0..len).map(|i| i.wrapping_mul(37)).collect();
            let f = CanFrame::new(0x123 + u16::from(len), &data).unwrap();
            assert_eq!(decode(encode(&f).as_bytes()), vec![Event::Frame(f)]);
        }
    }

    #[test]
    fn acknowledgements_errors_and_timestamps_are_told_apart() {
        let events = decode(b"z\rZ\r\r\x07t0027020100000000001234\rt002100\rV1013\r");
        assert_eq!(
            events,
            vec![
                Event::Ack(Ack::Transmit),
                Event::Ack(Ack::TransmitExtended),
                Event::Ack(Ack::Ok),
                Event::Bell,
                frame(2, &[2, 1, 0, 0, 0, 0, 0]),
                frame(0x002, &[0]),
                Event::Line("V1013".into()),
            ]
        );
    }

    #[test]
    fn bytes_split_anywhere_give_the_same_events() {
        let wire = b"t00270201060000007B\rz\r\x07T0000000120102\r";
        let whole = decode(wire);
        for cut in 0..wire.len() {
            let mut decoder = Decoder::default();
            let mut out = Vec::new();
            decoder.push(&wire[..cut], &mut out);
            decoder.push(&wire[cut..], &mut out);
            assert_eq!(out, whole, "cut at {cut}");
        }
        assert_eq!(whole[3], Event::Line("T0000000120102".into()));
    }

    #[test]
    fn malformed_frames_are_lines_not_frames() {
        for bad in [
            &b"t0019"[..],
            b"t00130102",
            b"tXYZ0",
            b"t001201020",
            b"t0012010203",
        ] {
            assert!(matches!(parse_line(bad), Event::Line(_)), "{bad:?}");
        }
        let long = [b'x'; 100];
        let events = decode(&long);
        assert_eq!(events.len(), 2);
    }

    #[test]
    fn bit_rates_have_their_codes() {
        assert_eq!(bitrate_command(1_000_000).as_deref(), Some("S8\r"));
        assert_eq!(bitrate_command(10_000).as_deref(), Some("S0\r"));
        assert_eq!(bitrate_command(83_333), None);
        assert_eq!(bitrate_of(6), Some(500_000));
        assert_eq!(bitrate_of(9), None);
    }
}
