//! The ASCII reply grammar (manual §6.6.2): `<host char><module char> <status> <value>`, e.g.
//! `BA 100 -5000`, tolerant of extra spaces and of CR, LF or CR LF endings.
//!
//! The host character: the manual calls it "the address character of the host" and gives the
//! rule for address characters — *A* for address 1, *B* for 2 and so on — with host address 2
//! giving `B`. Global parameter 76 takes 0..255, so a module sends the byte 0x40 + address
//! (modulo 256): `@` for 0, `[` for 27, and bytes outside the letters above that. The host
//! character is therefore any byte except the line ends, which would split the reply (host
//! addresses 202 and 205 cannot work with the ASCII interface). The module character is a letter:
//! modules reachable in ASCII mode have addresses 1..26.
//!
//! Only status codes a module sends are replies: any other number is a damaged reply.

use nom::character::complete::{digit1, one_of, satisfy, space0, space1};
use nom::combinator::{opt, recognize};
use nom::{IResult, Parser};

use super::status::Status;

/// One reply line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AsciiReply {
    /// The host's address character (from global parameter 76): the byte 0x40 + address, read
    /// as one character per byte (U+0000..U+00FF).
    pub host: char,
    /// The answering module's address character.
    pub module: char,
    /// Outcome of the command.
    pub status: Status,
    /// Returned value.
    pub value: i32,
}

impl AsciiReply {
    /// The reply as the module sends it, without line ending.
    pub fn format(&self) -> String {
        self.to_string()
    }

    /// Appends the bytes a module sends for this reply to `out`, without line ending (the host
    /// character as one byte, whatever it is; the simulator's reply path, without a buffer of its
    /// own).
    pub fn write_to(&self, out: &mut Vec<u8>) {
        use std::io::Write as _;
        out.push(host_byte(self.host));
        // Writing to a Vec cannot fail.
        let _ = write!(out, "{} {} {}", self.module, self.status.code(), self.value);
    }
}

/// The reply as the module sends it (`BA 100 -5000`), without line ending.
impl std::fmt::Display for AsciiReply {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}{} {} {}",
            self.host,
            self.module,
            self.status.code(),
            self.value
        )
    }
}

/// The host character a module with host address `address` (global parameter 76) puts first in
/// its replies: 0x40 + address, modulo 256 (`A` for 1, `B` for 2, `@` for 0).
pub fn host_char(address: u8) -> char {
    char::from(0x40u8.wrapping_add(address))
}

fn host_byte(host: char) -> u8 {
    u8::try_from(u32::from(host)).unwrap_or(b'?')
}

/// Parses a reply line (line ending optional). `None` when the text is not a reply. Nothing may
/// follow the value, not even a space: a module writes none, and a digit corrupted into a space,
/// a form feed or (read as Latin-1) a no-break space would otherwise cut the value short.
pub fn parse_reply(line: &str) -> Option<AsciiReply> {
    let text = line.trim_end_matches(['\r', '\n']);
    match reply(text) {
        Ok(("", parsed)) => Some(parsed),
        _ => None,
    }
}

/// Parses a reply line as received: each byte is one character, so a host character above 0x7F
/// is read as what it is.
pub fn parse_reply_bytes(line: &[u8]) -> Option<AsciiReply> {
    // ASCII reads the same as UTF-8 and Latin-1: only other bytes need a copy.
    if line.is_ascii() {
        return std::str::from_utf8(line).ok().and_then(parse_reply);
    }
    let text: String = line.iter().map(|&b| char::from(b)).collect();
    parse_reply(&text)
}

fn reply(input: &str) -> IResult<&str, AsciiReply> {
    // The host character may be a space (host address 224): try it as the first character, and
    // only then as leading spaces before a reply.
    match reply_at(input) {
        Ok(done) => Ok(done),
        Err(_) => {
            let (rest, _) = space0(input)?;
            reply_at(rest)
        }
    }
}

fn reply_at(input: &str) -> IResult<&str, AsciiReply> {
    let host = satisfy(|c: char| u32::from(c) <= 0xFF && c != '\r' && c != '\n');
    let letter = satisfy(|c: char| c.is_ascii_uppercase());
    let (rest, (host, module, _, status, _, value)) = (
        host,
        letter,
        space1,
        digit1,
        space1,
        recognize((opt(one_of("+-")), digit1)),
    )
        .parse(input)?;
    let fail = || nom::Err::Error(nom::error::Error::new(input, nom::error::ErrorKind::Verify));
    // A module writes numbers as printf's %d does: a `+` or a leading zero is a corrupted byte
    // (`-0163803` was `40163803`), never a value.
    if !canonical(status) || !canonical(value) {
        return Err(fail());
    }
    let status = status.parse::<u8>().map_err(|_| fail())?;
    let status = match Status::from_code(status) {
        Status::Other(_) => return Err(fail()),
        known => known,
    };
    let value = value.parse::<i32>().map_err(|_| fail())?;
    Ok((
        rest,
        AsciiReply {
            host,
            module,
            status,
            value,
        },
    ))
}

/// Whether `number` is written as a module writes it: an optional `-`, then digits without a
/// leading zero (`0` itself aside), and no `-0`.
fn canonical(number: &str) -> bool {
    let digits = number.strip_prefix('-').unwrap_or(number);
    let all_digits = !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit());
    let zero_led = digits.len() > 1 && digits.starts_with('0');
    let minus_zero = digits == "0" && number.starts_with('-');
    all_digits && !zero_led && !minus_zero
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_the_manual_example() {
        let reply = parse_reply("BA 100 -5000").unwrap();
        assert_eq!(
            reply,
            AsciiReply {
                host: 'B',
                module: 'A',
                status: Status::Ok,
                value: -5000
            }
        );
        assert_eq!(reply.format(), "BA 100 -5000");
    }

    #[test]
    fn tolerates_spaces_between_fields_and_any_line_ending() {
        for line in [
            "BA 100 -5000\r",
            "BA 100 -5000\n",
            "BA 100 -5000\r\n",
            " BA  100   -5000",
        ] {
            assert_eq!(parse_reply(line).unwrap().value, -5000, "{line:?}");
        }
    }

    #[test]
    fn decodes_every_status_a_module_sends_and_nothing_else() {
        assert_eq!(parse_reply("BC 4 0").unwrap().status, Status::InvalidValue);
        assert_eq!(parse_reply("BC 2 12").unwrap().module, 'C');
        assert_eq!(
            parse_reply("BA 128 1").unwrap().status,
            Status::PositionReachedEvent
        );
        for code in 0..=255u8 {
            let known = !matches!(Status::from_code(code), Status::Other(_));
            let parsed = parse_reply(&format!("BA {code} 0"));
            assert_eq!(parsed.is_some(), known, "status {code}");
        }
        assert!(parse_reply("BA 150 0").is_none(), "150 is a damaged reply");
    }

    #[test]
    fn nothing_may_follow_the_value() {
        // `-2` + 0xA0 was `-27`: the 7 corrupted into a byte that Latin-1 reads as a no-break
        // space, which `str::trim` removes.
        assert!(parse_reply_bytes(b"BA 100 -2\xA0\r").is_none());
        assert!(parse_reply_bytes(b"BA 100 -5227\x85\r").is_none());
        for damaged in ["BA 100 5 ", "BA 100 5\t", "BA 100 5\x0c", "BA 100 5\x0b"] {
            assert!(parse_reply(damaged).is_none(), "{damaged:?}");
        }
        assert_eq!(parse_reply("BA 100 5\r\n").map(|r| r.value), Some(5));
    }

    #[test]
    fn a_number_no_module_writes_is_a_damaged_reply() {
        // A byte corrupted into a sign, or a sign into `+`, leaves text that parses as a number.
        for damaged in [
            "BA 100 -0163803",
            "BA 100 +742783580",
            "BA 100 0042",
            "BA 100 -0",
            "BA 0100 5",
            "BA 100 +5",
        ] {
            assert!(parse_reply(damaged).is_none(), "{damaged}");
        }
        for value in [0, 7, -7, 10, -2147483648, 2147483647] {
            let line = format!("BA 100 {value}");
            assert_eq!(parse_reply(&line).map(|r| r.value), Some(value), "{line}");
        }
    }

    #[test]
    fn the_host_character_is_any_byte_but_a_line_end() {
        for address in 0..=255u8 {
            let host = host_char(address);
            let reply = AsciiReply {
                host,
                module: 'A',
                status: Status::Ok,
                value: -7,
            };
            let mut bytes = Vec::new();
            reply.write_to(&mut bytes);
            assert_eq!(bytes[0], 0x40u8.wrapping_add(address));
            let parsed = parse_reply_bytes(&bytes);
            if matches!(bytes[0], b'\r' | b'\n') {
                assert_eq!(parsed, None, "host address {address} splits the line");
            } else {
                assert_eq!(parsed, Some(reply), "host address {address}");
            }
        }
        assert_eq!(host_char(2), 'B');
        assert_eq!(host_char(0), '@');
        assert_eq!(host_char(27), '[');
    }

    #[test]
    fn leading_spaces_and_a_space_host_both_read() {
        let spaced = parse_reply(" BA 100 5").unwrap();
        assert_eq!((spaced.host, spaced.module), ('B', 'A'));
        let space_host = parse_reply_bytes(b" A 100 5").unwrap();
        assert_eq!((space_host.host, space_host.module), (' ', 'A'));
    }

    #[test]
    fn rejects_what_is_not_a_reply() {
        for line in [
            "AGAP 1, 0",
            "BA",
            "BA 100",
            "BA 100 x",
            "BA 300 0",
            "BA 100 99999999999",
            "ba 100 0",
            "",
            "BA 100 5 6",
            "BA 100 +-5000",
            "A 100 5",
            "BA 150 0",
            "BA 1",
        ] {
            assert!(parse_reply(line).is_none(), "{line:?}");
        }
    }
}
