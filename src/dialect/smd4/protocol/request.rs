//! Requests: `[@addr]MNEMONIC[,arg…]` followed by CR LF.
//!
//! The document's request template puts the address prefix straight before the mnemonic
//! (`@3MOTOR:STOP`), while its rule "all elements are comma separated" suggests `@3,MOTOR:STOP`.
//! Both are parsed; which one is written is [`PrefixStyle`], the manual's form by default.

use nom::bytes::complete::take_while;
use nom::character::complete::{char, digit1, satisfy};
use nom::combinator::{opt, recognize};
use nom::{IResult, Parser};

/// The request terminator.
pub const TERMINATOR: &str = "\r\n";

/// The addressing rules of the document, for help texts.
pub const ADDRESSING_HELP: &str = "\
Addressing (several SMD4s on one RS232/RS485 bus): a request may start with @N.
  @0        broadcast: every drive executes it, none replies
  @1..@247  only the drive whose COMS:SERIAL:SLAVEADDR is N executes and replies
  other N   ignored by every drive
The first complete packet with a prefix switches a drive into addressing mode until it restarts
(power cycle or SYS:RESET): from then on it silently ignores packets without a prefix, malformed
packets and packets for other addresses. Whether a comma follows the prefix (@3MOTOR:STOP or
@3,MOTOR:STOP) is not settled by the document; the first form is its template.";

/// Whether a comma follows the address prefix of a request.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PrefixStyle {
    /// `@3MOTOR:STOP`, the document's request template.
    #[default]
    Attached,
    /// `@3,MOTOR:STOP`, following "all elements are comma separated".
    Comma,
}

/// One request line, without its terminator.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Request {
    /// `@N` prefix: 0 broadcasts, 1..=247 address one drive; anything else is ignored by drives.
    pub address: Option<u32>,
    /// As typed; drives compare it in any case.
    pub mnemonic: String,
    /// Arguments as typed (trimmed). None reads a setting or runs an action.
    pub args: Vec<String>,
}

/// Why a line is not a request.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RequestError {
    /// Nothing but spaces.
    #[error("empty line: type a mnemonic such as SYS:FW")]
    Empty,
    /// `@` without a usable number.
    #[error("bad address prefix '{0}': write @ and a number 0..247, e.g. @3MOTOR:STOP")]
    BadAddress(String),
    /// The mnemonic is missing or has characters mnemonics never have.
    #[error(
        "{}: mnemonics are letters, digits and ':+-_' (e.g. MOTOR:VMAX), and arguments follow after commas",
        match .0.as_str() { "" => "the mnemonic is missing".to_string(), found => format!("'{found}' is not a mnemonic") }
    )]
    BadMnemonic(String),
    /// Arguments after a space or `=` instead of a comma (`MOTOR:VMAX 2000`).
    #[error("arguments follow the mnemonic after a comma; did you mean {0}?")]
    CommaMissing(String),
    /// A control or non-ASCII character.
    #[error("character {0:?} cannot be sent: requests are printable ASCII")]
    BadCharacter(char),
}

impl Request {
    /// A request without address or arguments.
    pub fn new(mnemonic: impl Into<String>) -> Request {
        Request {
            address: None,
            mnemonic: mnemonic.into(),
            args: Vec::new(),
        }
    }

    /// The same request with an argument added.
    pub fn arg(mut self, arg: impl Into<String>) -> Request {
        self.args.push(arg.into());
        self
    }

    /// The same request for drive `address` (0 broadcasts).
    pub fn to(mut self, address: u32) -> Request {
        self.address = Some(address);
        self
    }

    /// Whether this is a broadcast (`@0`), which no drive answers.
    pub fn is_broadcast(&self) -> bool {
        self.address == Some(0)
    }

    /// Parses a line (a trailing CR LF, CR or LF is ignored).
    pub fn parse(line: &str) -> Result<Request, RequestError> {
        Request::parse_styled(line).map(|(request, _)| request)
    }

    /// Parses a line and tells which prefix style it used, if it has a prefix.
    pub fn parse_styled(line: &str) -> Result<(Request, Option<PrefixStyle>), RequestError> {
        let text = line.trim_end_matches(['\r', '\n']).trim_matches(' ');
        if let Some(c) = text.chars().find(|c| !(' '..='~').contains(c)) {
            return Err(RequestError::BadCharacter(c));
        }
        if text.is_empty() {
            return Err(RequestError::Empty);
        }
        let (rest, prefix) = prefix(text).map_err(|_| bad_prefix(text))?;
        if prefix.is_none() && text.starts_with('@') {
            return Err(bad_prefix(text));
        }
        let (rest, mnemonic) =
            mnemonic(rest).map_err(|_| RequestError::BadMnemonic(first_item(rest)))?;
        let args = match rest {
            "" => Vec::new(),
            r if r.starts_with(',') => r[1..].split(',').map(|a| a.trim().to_string()).collect(),
            r => {
                let written = &text[..text.len() - r.len()];
                return Err(comma_missing(written, r)
                    .unwrap_or_else(|| RequestError::BadMnemonic(first_item(text))));
            }
        };
        let (address, style) = match prefix {
            Some((digits, comma)) => {
                let address = digits.parse().map_err(|_| bad_prefix(text))?;
                let style = if comma {
                    PrefixStyle::Comma
                } else {
                    PrefixStyle::Attached
                };
                (Some(address), Some(style))
            }
            None => (None, None),
        };
        let request = Request {
            address,
            mnemonic: mnemonic.to_string(),
            args,
        };
        Ok((request, style))
    }

    /// The line to send, without terminator.
    pub fn format(&self, style: PrefixStyle) -> String {
        let mut line = String::new();
        if let Some(address) = self.address {
            line.push('@');
            line.push_str(&address.to_string());
            if style == PrefixStyle::Comma {
                line.push(',');
            }
        }
        line.push_str(&self.mnemonic);
        for arg in &self.args {
            line.push(',');
            line.push_str(arg);
        }
        line
    }

    /// The bytes to send, with the CR LF terminator.
    pub fn wire(&self, style: PrefixStyle) -> Vec<u8> {
        let mut bytes = self.format(style).into_bytes();
        bytes.extend_from_slice(TERMINATOR.as_bytes());
        bytes
    }
}

/// A typed line without its trailing `//` comment (as `.tmc` files and people write them), where
/// `//` cannot be part of the request: anywhere but in the free text argument of a command of
/// `table` that takes one.
pub fn without_comment<'a>(table: &super::Smd4CommandTable, line: &'a str) -> &'a str {
    let Some(at) = line.find("//") else {
        return line;
    };
    let text = line.trim_start();
    let free_text = prefix(text)
        .ok()
        .and_then(|(rest, _)| mnemonic(rest).ok())
        .and_then(|(_, word)| table.get(word))
        .and_then(|command| command.arg.as_ref())
        .is_some_and(|arg| arg.ty == super::ItemType::Str && arg.choices.is_empty());
    if free_text {
        line
    } else {
        line[..at].trim_end()
    }
}

/// Whether `line` reads as a request for a command of the built-in table, whatever follows the
/// mnemonic (for [`Dialect::recognises`](crate::dialect::Dialect::recognises)).
pub fn recognises(line: &str) -> bool {
    let text = line.trim();
    let Ok((rest, _)) = prefix(text) else {
        return false;
    };
    match mnemonic(rest) {
        Ok((_, word)) => super::Smd4Spec::builtin().commands.get(word).is_some(),
        Err(_) => false,
    }
}

/// `MOTOR:VMAX 2000` or `MOTOR:VMAX=2000` as the request meant (`MOTOR:VMAX,2000`): `head` is
/// the prefix and mnemonic, `rest` what follows them.
fn comma_missing(head: &str, rest: &str) -> Option<RequestError> {
    let args = rest.trim_start().strip_prefix('=').unwrap_or(rest).trim();
    let separated = rest.starts_with([' ', '=']) && !args.is_empty() && !head.ends_with(':');
    let items: Vec<&str> = args
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|item| !item.is_empty())
        .collect();
    separated.then(|| RequestError::CommaMissing(format!("{head},{}", items.join(","))))
}

fn bad_prefix(text: &str) -> RequestError {
    let end = text
        .find(|c: char| c.is_ascii_alphabetic())
        .unwrap_or(text.len());
    RequestError::BadAddress(text[..end].to_string())
}

fn first_item(text: &str) -> String {
    text.split(',').next().unwrap_or_default().to_string()
}

/// `@digits` and an optional comma.
fn prefix(input: &str) -> IResult<&str, Option<(&str, bool)>> {
    opt((char('@'), digit1, opt(char(','))))
        .map(|found| found.map(|(_, digits, comma)| (digits, comma.is_some())))
        .parse(input)
}

/// A letter, then letters, digits and `:+-_`.
fn mnemonic(input: &str) -> IResult<&str, &str> {
    recognize((
        satisfy(|c| c.is_ascii_alphabetic()),
        take_while(|c: char| c.is_ascii_alphanumeric() || ":+-_".contains(c)),
    ))
    .parse(input)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_the_forms_of_the_document() {
        let r = Request::parse("MOTOR:RUNV,+\r\n").unwrap();
        assert_eq!(r, Request::new("MOTOR:RUNV").arg("+"));
        let r = Request::parse("LIMIT:EN+,1").unwrap();
        assert_eq!(
            (r.mnemonic.as_str(), r.args.as_slice()),
            ("LIMIT:EN+", &["1".to_string()][..])
        );
        let (r, style) = Request::parse_styled("@3MOTOR:STOP").unwrap();
        assert_eq!((r.address, style), (Some(3), Some(PrefixStyle::Attached)));
        let (r, style) = Request::parse_styled("@3,MOTOR:STOP").unwrap();
        assert_eq!((r.address, style), (Some(3), Some(PrefixStyle::Comma)));
        assert_eq!(r.mnemonic, "MOTOR:STOP");
        let r = Request::parse("coms:net:gateway, 192.168.1.1 ").unwrap();
        assert_eq!(r.args, ["192.168.1.1"]);
        assert_eq!(Request::parse("MOTOR:IR,").unwrap().args, [""]);
        assert_eq!(Request::parse("@999MOTOR:STOP").unwrap().address, Some(999));
    }

    #[test]
    fn formats_both_prefix_styles() {
        let r = Request::new("MOTOR:STOP").to(3);
        assert_eq!(r.format(PrefixStyle::default()), "@3MOTOR:STOP");
        assert_eq!(r.format(PrefixStyle::Comma), "@3,MOTOR:STOP");
        assert_eq!(
            Request::new("MOTOR:VMAX")
                .arg("1000")
                .wire(PrefixStyle::Attached),
            b"MOTOR:VMAX,1000\r\n"
        );
        assert!(Request::new("SYS:CLR").to(0).is_broadcast());
    }

    #[test]
    fn refuses_what_is_not_a_request() {
        assert_eq!(Request::parse("  \r\n"), Err(RequestError::Empty));
        assert!(matches!(
            Request::parse("@MOTOR:STOP"),
            Err(RequestError::BadAddress(_))
        ));
        assert!(matches!(
            Request::parse("@99999999999MOTOR:STOP"),
            Err(RequestError::BadAddress(_))
        ));
        for (typed, meant) in [
            ("MOTOR:VMAX 2000", "MOTOR:VMAX,2000"),
            ("motor:vmax  2000 ", "motor:vmax,2000"),
            ("MOTOR:VMAX=2000", "MOTOR:VMAX,2000"),
            ("@3MOTOR:RUNV +", "@3MOTOR:RUNV,+"),
            ("COMS:NET:IP 10.0.0.2, 24", "COMS:NET:IP,10.0.0.2,24"),
        ] {
            assert_eq!(
                Request::parse(typed),
                Err(RequestError::CommaMissing(meant.into())),
                "{typed}"
            );
        }
        let message = RequestError::CommaMissing("MOTOR:VMAX,2000".into()).to_string();
        assert!(
            message.ends_with("did you mean MOTOR:VMAX,2000?"),
            "{message}"
        );
        for bad in [",1", "1MOTOR", "MOTOR: STOP", "@3,,X", "MOTOR:VMAX.5"] {
            assert!(
                matches!(Request::parse(bad), Err(RequestError::BadMnemonic(_))),
                "{bad}"
            );
        }
        assert_eq!(
            Request::parse("SYS:FW\x07"),
            Err(RequestError::BadCharacter('\x07'))
        );
        assert_eq!(
            Request::parse("SYS:FWé"),
            Err(RequestError::BadCharacter('é'))
        );
        let message = RequestError::BadAddress("@".into()).to_string();
        assert!(message.contains("@3MOTOR:STOP"), "{message}");
    }

    #[test]
    fn round_trips() {
        for line in [
            "@7MOTOR:RUNA,-1000",
            "SYS:IDENT,1",
            "MOTOR:AMAX",
            "@0,SYS:CLR",
        ] {
            let (r, style) = Request::parse_styled(line).unwrap();
            assert_eq!(r.format(style.unwrap_or_default()), line);
        }
    }
}
