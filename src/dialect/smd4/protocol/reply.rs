//! Replies: `[prefix,]SFLAGS,EFLAGS[,data…]` or `…,<error>` followed by CR LF.
//!
//! Flags are read in either hex case. Data items are typed by what the command returns
//! ([`Expectation`]), so `24044.12` from SYS:FW stays text while `1.4988E+02` from MOTOR:AMAX is a
//! number. The error item has no documented spelling; all plausible ones are read:
//! `-103 (Invalid Mnemonic)`, `-103,Invalid Mnemonic` and a bare `-103`. A bare negative integer
//! is only taken for an error where the command's value cannot be a negative integer (MOTOR:T can).

use nom::bytes::complete::take_while_m_n;
use nom::character::complete::{char, digit1, one_of};
use nom::combinator::opt;
use nom::{IResult, Parser};

use super::commands::{ReplyShape, Smd4Command, Smd4CommandTable};
use super::errors::{DeviceError, ErrorCode};
use super::flags::{Eflags, Sflags};
use super::items::{DataItem, Value, parse_named};
use super::request::Request;
use super::tolerance::RealTolerance;
use super::types::{ItemType, parse_int};

/// A parsed reply.
#[derive(Debug, Clone, PartialEq)]
pub struct Smd4Reply {
    /// The `@N,` prefix of a reply from an addressed drive.
    pub address: Option<u32>,
    /// Status word.
    pub sflags: Sflags,
    /// Error word.
    pub eflags: Eflags,
    /// Data items (empty on error). A single trailing empty item — the comma that ends the first
    /// line of a multi-line reply — is dropped.
    pub data: Vec<DataItem>,
    /// The error the command failed with.
    pub error: Option<DeviceError>,
    /// The text lines that followed the first line of a multi-line reply.
    pub lines: Vec<String>,
    /// The first line as received, without its line ending.
    pub raw: String,
}

impl Smd4Reply {
    /// Whether the command succeeded.
    pub fn is_ok(&self) -> bool {
        self.error.is_none()
    }

    /// The data items as received.
    pub fn data_strings(&self) -> Vec<String> {
        self.data.iter().map(|d| d.raw.clone()).collect()
    }

    /// The user and real value of a profile setting (MOTOR:AMAX, VSTART, VMAX, THIGH …).
    pub fn user_real(&self) -> Option<(f64, f64)> {
        match self.data.as_slice() {
            [user, real] => Some((user.value.as_f64()?, real.value.as_f64()?)),
            _ => None,
        }
    }

    /// The reply, or the device error it carries.
    pub fn into_result(self) -> Result<Smd4Reply, DeviceError> {
        match self.error {
            Some(error) => Err(error),
            None => Ok(self),
        }
    }
}

/// Why a line is not a reply.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("not an SMD4 reply: '{line}' ({why})")]
pub struct ReplyError {
    /// The line.
    pub line: String,
    /// What is wrong with it.
    pub why: &'static str,
}

/// What a reply to a given command should carry; [`Expectation::unknown`] guesses.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Expectation {
    pub(super) shape: Option<ReplyShape>,
    pub(super) value: Option<ItemType>,
    /// The value may come in fixed point (PACT, PREL).
    pub(super) fixed_point: bool,
    /// The data item may be missing (`reply_optional`).
    pub(super) optional: bool,
    /// How far a user/real pair may disagree; `None` leaves the pair unchecked.
    pub(super) real_tolerance: Option<RealTolerance>,
}

impl Expectation {
    /// Nothing known about the command: items are guessed.
    pub fn unknown() -> Expectation {
        Expectation::default()
    }

    /// The reply of `spec`.
    pub fn for_command(spec: &Smd4Command) -> Expectation {
        Expectation {
            shape: Some(spec.reply.clone()),
            value: spec.value_item_type(),
            fixed_point: spec.fixed_point,
            optional: spec.reply_optional,
            real_tolerance: spec.real_tolerance,
        }
    }

    /// The reply to `request`, looked up in `table`.
    pub fn for_request(table: &Smd4CommandTable, request: &Request) -> Expectation {
        table
            .get(&request.mnemonic)
            .map(Expectation::for_command)
            .unwrap_or_default()
    }

    /// Whether the command's reply spans several lines.
    pub fn multi_line(&self) -> bool {
        self.shape == Some(ReplyShape::MultiLine)
    }

    fn item_type(&self, index: usize) -> Option<ItemType> {
        match self.shape.as_ref()? {
            ReplyShape::Value if index == 0 => self.value,
            ReplyShape::UserReal if index < 2 => Some(ItemType::Float),
            _ => None,
        }
    }

    /// Whether a lone negative integer can be the command's value.
    pub(super) fn negative_int_is_data(&self) -> bool {
        self.shape == Some(ReplyShape::Value) && self.value == Some(ItemType::Int)
    }
}

/// Parses one reply line (line ending optional).
pub fn parse_reply(line: &str, expect: &Expectation) -> Result<Smd4Reply, ReplyError> {
    let text = line.trim_end_matches(['\r', '\n']);
    let fail = |why| ReplyError {
        line: text.to_string(),
        why,
    };
    let (rest, (address, sflags, eflags)) =
        head(text).map_err(|_| fail("expected [@N,]0xSSSS,0xEEEE"))?;
    let mut items: Vec<&str> = match rest {
        "" => Vec::new(),
        r if r.starts_with(',') => r[1..].split(',').collect(),
        _ => return Err(fail("expected a comma after the flags")),
    };
    if items.last() == Some(&"") {
        items.pop();
    }
    let address = match address {
        Some(digits) => Some(digits.parse().map_err(|_| fail("address out of range"))?),
        None => None,
    };
    let error = error_item(&items, expect);
    let data = match error {
        Some(_) => Vec::new(),
        None => items
            .iter()
            .enumerate()
            .map(|(i, raw)| typed_item(raw, i, expect))
            .collect(),
    };
    Ok(Smd4Reply {
        address,
        sflags: Sflags(sflags),
        eflags: Eflags(eflags),
        data,
        error,
        lines: Vec::new(),
        raw: text.to_string(),
    })
}

fn typed_item(raw: &str, index: usize, expect: &Expectation) -> DataItem {
    if expect.shape == Some(ReplyShape::Named) && index == 0 {
        if let Some(value) = parse_named(raw) {
            return DataItem {
                raw: raw.to_string(),
                value,
            };
        }
    }
    DataItem::typed(raw, expect.item_type(index))
}

/// The error item, in whichever spelling it came. A code that does not fit an `i32` is no error
/// code a drive sends: it stays a data item, for [`super::check`] to report as line noise.
fn error_item(items: &[&str], expect: &Expectation) -> Option<DeviceError> {
    let first = items.first()?;
    if let Some(Value::Named { number, name }) = parse_named(first) {
        let code = i32::try_from(number).ok()?;
        return (code < 0 && items.len() == 1).then(|| DeviceError {
            code: ErrorCode::from_code(code),
            text: Some(name),
        });
    }
    let number = parse_int(first).filter(|n| *n < 0 && !first.starts_with('+'))?;
    let code = ErrorCode::from_code(i32::try_from(number).ok()?);
    match items {
        [_, text] if text.starts_with(|c: char| c.is_ascii_alphabetic()) => Some(DeviceError {
            code,
            text: Some(text.to_string()),
        }),
        [_] if !expect.negative_int_is_data() => {
            let flags_only = matches!(expect.shape, Some(ReplyShape::None));
            (code.is_known() || flags_only).then_some(DeviceError { code, text: None })
        }
        _ => None,
    }
}

/// Whether both flag words of a reply line are written as the type table says: `0x` and exactly
/// four hex digits. [`parse_reply`] reads shorter words too, so that a line is still
/// recognised as a reply; a reply with a short word lost a digit on the way.
pub(super) fn full_width_flags(line: &str) -> bool {
    head_of_width(line, 4).is_ok()
}

type Head<'a> = (Option<&'a str>, u16, u16);

fn head(input: &str) -> IResult<&str, Head<'_>> {
    head_of_width(input, 1)
}

/// The prefix and flags, each flag word with `min_digits..=4` hex digits.
fn head_of_width(input: &str, min_digits: usize) -> IResult<&str, Head<'_>> {
    let (rest, address) = opt(reply_prefix).parse(input)?;
    let word = |i| flag_word(i, min_digits);
    (word, char(','), word)
        .map(|(s, _, e)| (address, s, e))
        .parse(rest)
}

/// `@N,` — or `@N` straight before the flags, where the flags' leading `0` is not the address's.
fn reply_prefix(input: &str) -> IResult<&str, &str> {
    let (rest, (_, digits)) = (char('@'), digit1).parse(input)?;
    if let Some(after) = rest.strip_prefix(',') {
        return Ok((after, digits));
    }
    match digits.strip_suffix('0') {
        Some(address) if !address.is_empty() && rest.starts_with(['x', 'X']) => {
            Ok((&input[1 + address.len()..], address))
        }
        _ => Ok((rest, digits)),
    }
}

fn flag_word(input: &str, min_digits: usize) -> IResult<&str, u16> {
    let (rest, (_, _, digits)) = (
        char('0'),
        one_of("xX"),
        take_while_m_n(min_digits, 4, |c: char| c.is_ascii_hexdigit()),
    )
        .parse(input)?;
    let word = u16::from_str_radix(digits, 16).expect("at most four hex digits fit in u16");
    Ok((rest, word))
}
