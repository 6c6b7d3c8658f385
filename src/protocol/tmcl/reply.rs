//! The ASCII reply grammar (manual §6.6.2): `<host char><module char> <status> <value>`, e.g.
//! `BA 100 -5000`, tolerant of extra spaces and of CR, LF or CR LF endings.

use nom::character::complete::{digit1, one_of, satisfy, space0, space1};
use nom::combinator::{opt, recognize};
use nom::{IResult, Parser};

use super::status::Status;

/// One reply line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AsciiReply {
    /// The host's address character (from global parameter 76).
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

/// Parses a reply line (line ending optional). `None` when the text is not a reply.
pub fn parse_reply(line: &str) -> Option<AsciiReply> {
    let text = line.trim_end_matches(['\r', '\n']);
    match reply(text) {
        Ok((rest, parsed)) if rest.trim().is_empty() => Some(parsed),
        _ => None,
    }
}

fn reply(input: &str) -> IResult<&str, AsciiReply> {
    let letter = || satisfy(|c: char| c.is_ascii_uppercase());
    let (rest, (_, host, module, _, status, _, value)) = (
        space0,
        letter(),
        letter(),
        space1,
        digit1,
        space1,
        recognize((opt(one_of("+-")), digit1)),
    )
        .parse(input)?;
    let fail = || nom::Err::Error(nom::error::Error::new(input, nom::error::ErrorKind::Verify));
    let status = status.parse::<u8>().map_err(|_| fail())?;
    let value = value.parse::<i32>().map_err(|_| fail())?;
    Ok((
        rest,
        AsciiReply {
            host,
            module,
            status: Status::from_code(status),
            value,
        },
    ))
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
    fn tolerates_spaces_and_any_line_ending() {
        for line in [
            "BA 100 -5000\r",
            "BA 100 -5000\n",
            "BA 100 -5000\r\n",
            " BA  100   -5000 ",
        ] {
            assert_eq!(parse_reply(line).unwrap().value, -5000, "{line:?}");
        }
    }

    #[test]
    fn decodes_status_with_fallback() {
        assert_eq!(parse_reply("BC 4 0").unwrap().status, Status::InvalidValue);
        assert_eq!(parse_reply("BC 77 0").unwrap().status, Status::Other(77));
        assert_eq!(parse_reply("BC 2 12").unwrap().module, 'C');
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
        ] {
            assert!(parse_reply(line).is_none(), "{line:?}");
        }
    }
}
