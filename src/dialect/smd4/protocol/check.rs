//! Whether a reply is the answer its command declares, before any of it becomes a value.
//!
//! SMD4 replies carry no checksum, so a corrupted, dropped or foreign byte is caught only where it
//! breaks the form `data/smd4.toml` declares for the command: the number of data items, each
//! item's type, written the way a drive writes it, and the address the reply comes from. A reply
//! that fails is line noise (exit 3), never a value and never a device refusal.
//!
//! What is checked:
//! - every byte is printable ASCII, on every line (all SMD4 types are text 0x20..0x7E);
//! - both flag words are `0x` and four hex digits;
//! - the `@N,` prefix, if any, is the address the request went to (none without `--address`);
//! - an error item's code fits an `i32`: `-99999999999` is no code a drive sends, and the digits
//!   of a longer number run together are more likely than a refusal (the command may well have
//!   run), so it is noise rather than an unknown error;
//! - the item count of the reply shape, and each item in its type's reply spelling: INT `-?digits`
//!   and UINT `digits` within 64 bits (no `+`, no hex: the type table's response column), BOOL
//!   `0`/`1`, FLOAT in normalised scientific notation with 4 or 5 decimals, `E` in either case or
//!   left out, a signed exponent of two or three digits, finite (and fixed point with two decimals
//!   where the command is `value_format = "fixed"`), `n (label)`, dotted decimal, UUID, `h:m:s`.
//!
//! Not checked: ranges, enum values and labels. The data's ranges are best knowledge, and the
//! document's own examples leave them (TZW echoes milliseconds, SYS:MODE labels mode 2 Remote), so
//! a value out of range is reported as the drive sent it, not as noise.
//!
//! Every spelling the document and the simulator's quirk switches use passes; a dropped digit,
//! point, `E` sign or exponent digit, a letter in a number, `NaN`, `inf`, `1e999`, a 23-digit
//! integer, an extra or missing item do not. A digit turned into another digit passes: no reply
//! grammar can see that, except in a user/real pair, whose two values may disagree only as far as
//! the drive's resolution allows (`[user_real]` in the data).

use super::commands::ReplyShape;
use super::format::{FIXED_DECIMALS, FLOAT_DECIMALS};
use super::items::{DataItem, Value, is_uuid, parse_hms, parse_named, parse_reply_float};
use super::reply::{Expectation, Smd4Reply, full_width_flags};
use super::tolerance::RealTolerance;
use super::types::{ItemType, parse_dotted};

/// Why a reply is line noise rather than the answer to the request.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Noise {
    /// A byte outside printable ASCII, in line `line` (1-based) of the reply.
    #[error("a control or non-ASCII character{}", match line {
        1 => String::new(),
        n => format!(" in line {n}"),
    })]
    NotPrintable {
        /// The line, 1 for the first.
        line: usize,
    },
    /// A flag word that lost or gained a digit.
    #[error("a flag word that is not 0x and four hex digits")]
    FlagWord,
    /// Another drive's address prefix.
    #[error("a reply from drive @{from}, {}", match to {
        Some(to) => format!("not from drive @{to}"),
        None => "but requests carry no address".to_string(),
    })]
    Foreign {
        /// The address in the reply.
        from: u32,
        /// The address the request went to.
        to: Option<u32>,
    },
    /// An error code that does not fit.
    #[error("error code {0} out of range")]
    ErrorCode(String),
    /// Too many or too few data items.
    #[error("{expected} due, {got} received")]
    Count {
        /// What the command declares (`one FLOAT item`).
        expected: String,
        /// How many came.
        got: usize,
    },
    /// A user/real pair whose values lie further apart than the drive's resolution.
    #[error("user value {user} and real value {real} disagree beyond the drive's resolution")]
    Disagree {
        /// The user value as received.
        user: String,
        /// The real value as received.
        real: String,
    },
    /// An item that is not of its declared type, or not written as a drive writes it.
    #[error("'{raw}' where {expected} is due")]
    Item {
        /// The item as received.
        raw: String,
        /// What the command declares.
        expected: String,
    },
}

/// Whether a reply with address prefix `from` answers a request sent to `to`. A drive may leave
/// the prefix out (the document shows no addressed reply), so a reply without one is taken; a
/// prefixed reply is another drive's unless the request carried the same address.
pub fn is_reply_to(from: Option<u32>, to: Option<u32>) -> bool {
    from.is_none_or(|from| to == Some(from))
}

/// Checks `reply` to a request sent to address `to` against what its command declares.
pub fn check_reply(reply: &Smd4Reply, expect: &Expectation, to: Option<u32>) -> Result<(), Noise> {
    let printable = |line: &String| line.bytes().all(|b| (0x20..=0x7E).contains(&b));
    let mut lines = std::iter::once(&reply.raw).chain(&reply.lines);
    if let Some(index) = lines.position(|l| !printable(l)) {
        return Err(Noise::NotPrintable { line: index + 1 });
    }
    if !full_width_flags(&reply.raw) {
        return Err(Noise::FlagWord);
    }
    if let Some(from) = reply.address.filter(|&from| !is_reply_to(Some(from), to)) {
        return Err(Noise::Foreign { from, to });
    }
    if reply.error.is_some() {
        return Ok(());
    }
    if let Some(code) = unrepresentable_code(&reply.data, expect) {
        return Err(Noise::ErrorCode(code.to_string()));
    }
    let Some(shape) = &expect.shape else {
        return Ok(());
    };
    let items = &reply.data;
    if items.is_empty() && expect.optional {
        return Ok(()); // no return declared: the example's item may be left out
    }
    let expected: &[ItemType] = match shape {
        ReplyShape::None | ReplyShape::MultiLine => &[],
        ReplyShape::UserReal => &[ItemType::Float, ItemType::Float],
        ReplyShape::Value => match expect.value {
            // A STRING that is empty leaves the line ending in a comma, and no item.
            Some(ItemType::Str) if items.is_empty() && reply.raw.ends_with(',') => return Ok(()),
            Some(ref ty) => std::slice::from_ref(ty),
            None => return Ok(()),
        },
        ReplyShape::Named => return one(items, "one 'n (label)' item", is_named),
        ReplyShape::Literal(text) => {
            return one(items, &format!("the item '{text}'"), |raw| raw == text);
        }
    };
    if items.len() != expected.len() {
        return Err(Noise::Count {
            expected: describe(expected),
            got: items.len(),
        });
    }
    for (item, &ty) in items.iter().zip(expected) {
        if !well_formed(&item.raw, ty, expect.fixed_point) {
            return Err(Noise::Item {
                raw: item.raw.clone(),
                expected: describe(&[ty]),
            });
        }
    }
    match (shape, items.as_slice(), expect.real_tolerance) {
        (ReplyShape::UserReal, [user, real], Some(tolerance)) => {
            agreeing(&user.raw, &real.raw, tolerance)
        }
        _ => Ok(()),
    }
}

/// A user/real pair whose values the tolerance admits; both are well-formed FLOATs.
fn agreeing(user: &str, real: &str, tolerance: RealTolerance) -> Result<(), Noise> {
    match (parse_reply_float(user), parse_reply_float(real)) {
        (Some(u), Some(r)) if !tolerance.admits(u, r) => Err(Noise::Disagree {
            user: user.to_string(),
            real: real.to_string(),
        }),
        _ => Ok(()),
    }
}

/// Exactly one item, accepted by `fits`.
fn one(items: &[DataItem], expected: &str, fits: impl Fn(&str) -> bool) -> Result<(), Noise> {
    match items {
        [item] if fits(&item.raw) => Ok(()),
        [item] => Err(Noise::Item {
            raw: item.raw.clone(),
            expected: expected.to_string(),
        }),
        _ => Err(Noise::Count {
            expected: expected.to_string(),
            got: items.len(),
        }),
    }
}

/// `no data item`, `one FLOAT item`, `two FLOAT items`.
fn describe(types: &[ItemType]) -> String {
    match types {
        [] => "no data item".into(),
        [ty] => format!("one {} item", ty.name()),
        [ty, ..] if types.iter().all(|t| t == ty) => {
            format!("{} {} items", count_word(types.len()), ty.name())
        }
        _ => {
            let names: Vec<&str> = types.iter().map(|t| t.name()).collect();
            format!("items {}", names.join(", "))
        }
    }
}

fn count_word(n: usize) -> String {
    match n {
        2 => "two".into(),
        3 => "three".into(),
        n => n.to_string(),
    }
}

/// The code of an error item, in any of its spellings, that does not fit an `i32` (the parser
/// left such an item as data). A lone negative integer is data where the command returns an INT.
fn unrepresentable_code<'a>(items: &'a [DataItem], expect: &Expectation) -> Option<&'a str> {
    let first = items.first()?.raw.as_str();
    let named = matches!(parse_named(first), Some(Value::Named { .. }));
    let code = if named {
        first.split_once(' ')?.0
    } else {
        first
    };
    let digits = code.strip_prefix('-')?;
    if !all_digits(digits) || code.parse::<i32>().is_ok() {
        return None;
    }
    let error_shaped = match items {
        [_] => named || !expect.negative_int_is_data(),
        [_, text] => !named && text.raw.starts_with(|c: char| c.is_ascii_alphabetic()),
        _ => false,
    };
    error_shaped.then_some(code)
}

/// Whether `raw` is an item of type `ty` as a drive writes it.
fn well_formed(raw: &str, ty: ItemType, fixed_point: bool) -> bool {
    match ty {
        ItemType::Int => {
            let digits = match raw.strip_prefix('-') {
                Some(magnitude) => magnitude != "0" && decimal(magnitude),
                None => decimal(raw),
            };
            digits && raw.parse::<i64>().is_ok()
        }
        ItemType::Uint | ItemType::Enum => decimal(raw) && raw.parse::<i64>().is_ok(),
        ItemType::Bool => matches!(raw, "0" | "1"),
        ItemType::Float => {
            (is_scientific(raw) || (fixed_point && is_fixed(raw)))
                && parse_reply_float(raw).is_some()
        }
        ItemType::Str => !raw.is_empty(),
        ItemType::Dotted => parse_dotted(raw).is_some(),
        ItemType::Uuid => is_uuid(raw),
        ItemType::Hms => parse_hms(raw).is_some(),
    }
}

fn all_digits(text: &str) -> bool {
    !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit())
}

/// Digits as a drive's printf writes a whole number: no leading zero but zero itself, so a first
/// digit corrupted into `0` (`073` for `173`) is noise, not another value.
fn decimal(text: &str) -> bool {
    all_digits(text) && (text == "0" || !text.starts_with('0'))
}

/// `[-]d.dddd[d](E|e|)(+|-)dd[d]`, normalised: the leading digit is 0 only for zero itself.
fn is_scientific(raw: &str) -> bool {
    let unsigned = raw.strip_prefix('-').unwrap_or(raw);
    let Some((lead, rest)) = unsigned.split_at_checked(1) else {
        return false;
    };
    let Some(rest) = rest.strip_prefix('.') else {
        return false;
    };
    let decimals_len = rest
        .find(|c: char| !c.is_ascii_digit())
        .unwrap_or(rest.len());
    let (decimals, tail) = rest.split_at(decimals_len);
    let tail = tail.strip_prefix(['E', 'e']).unwrap_or(tail);
    let Some(exponent) = tail.strip_prefix(['+', '-']) else {
        return false;
    };
    let zero = |s: &str| s.bytes().all(|b| b == b'0');
    all_digits(lead)
        && u8::try_from(decimals.len()).is_ok_and(|n| FLOAT_DECIMALS.contains(&n))
        && all_digits(exponent)
        && (2..=3).contains(&exponent.len())
        && (lead != "0" || (zero(decimals) && zero(exponent)))
}

/// `[-]digits.dd`.
fn is_fixed(raw: &str) -> bool {
    let unsigned = raw.strip_prefix('-').unwrap_or(raw);
    unsigned.split_once('.').is_some_and(|(whole, decimals)| {
        decimal(whole) && all_digits(decimals) && decimals.len() == FIXED_DECIMALS
    })
}

/// `n (label)` with an unsigned number and a label.
fn is_named(raw: &str) -> bool {
    let number = raw.split_once(' ').map_or("", |(n, _)| n);
    matches!(parse_named(raw), Some(Value::Named { name, .. }) if !name.is_empty())
        && all_digits(number)
}
