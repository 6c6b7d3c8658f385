//! Data items of replies, read leniently: the document's own examples write floats with 4 or 5
//! decimals, in fixed point, or without the `E` (`0.0000+00`), and flags in either hex case.
//! Items are typed by what the command returns when that is known, and guessed otherwise.

use std::net::Ipv4Addr;

use super::types::{ItemType, parse_int, parse_uint};

/// A decoded data item.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A signed integer (`-10`).
    Int(i64),
    /// An unsigned integer, decimal or hex (`100`, `0xA74F`).
    Uint(u64),
    /// A real number in any of the forms the document shows.
    Float(f64),
    /// `0` or `1` where the command returns a BOOL.
    Bool(bool),
    /// Text (firmware version, serial numbers, MAC, multi-line text).
    Text(String),
    /// An IPv4 address or mask.
    Dotted(Ipv4Addr),
    /// A UUID, lower case as sent.
    Uuid(String),
    /// Elapsed time `h:m:s`.
    Hms {
        /// Hours.
        hours: u64,
        /// Minutes.
        minutes: u64,
        /// Seconds.
        seconds: u64,
    },
    /// `<n> (<name>)`, e.g. SYS:MODE's `1 (Remote)`.
    Named {
        /// The number.
        number: i64,
        /// The name in brackets.
        name: String,
    },
    /// An empty item (the trailing comma of a multi-line reply's first line).
    Empty,
}

impl Value {
    /// The value as a number, where it is one.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Int(i) => Some(*i as f64),
            Value::Uint(u) => Some(*u as f64),
            Value::Float(f) => Some(*f),
            Value::Bool(b) => Some(f64::from(u8::from(*b))),
            Value::Named { number, .. } => Some(*number as f64),
            _ => None,
        }
    }
}

/// One data item: the text as received and what it decodes to.
#[derive(Debug, Clone, PartialEq)]
pub struct DataItem {
    /// Exactly as received.
    pub raw: String,
    /// Decoded.
    pub value: Value,
}

impl DataItem {
    /// Decodes `raw` as `ty`, falling back to a guess when it does not fit (the drive is always
    /// right about what it sent; the caller can compare `value` with the type it expected).
    pub fn typed(raw: &str, ty: Option<ItemType>) -> DataItem {
        let value = ty
            .and_then(|ty| as_type(raw, ty))
            .unwrap_or_else(|| guess(raw));
        DataItem {
            raw: raw.to_string(),
            value,
        }
    }
}

fn as_type(raw: &str, ty: ItemType) -> Option<Value> {
    match ty {
        ItemType::Int => parse_int(raw).map(Value::Int),
        ItemType::Uint | ItemType::Enum => parse_uint(raw).map(|u| Value::Uint(u as u64)),
        ItemType::Float => parse_reply_float(raw).map(Value::Float),
        ItemType::Bool => match raw {
            "0" => Some(Value::Bool(false)),
            "1" => Some(Value::Bool(true)),
            _ => None,
        },
        ItemType::Str => Some(Value::Text(raw.to_string())),
        ItemType::Dotted => raw.parse().ok().map(Value::Dotted),
        ItemType::Uuid => is_uuid(raw).then(|| Value::Uuid(raw.to_string())),
        ItemType::Hms => parse_hms(raw),
    }
}

/// The likeliest reading of an item of unknown type.
pub fn guess(raw: &str) -> Value {
    if raw.is_empty() {
        return Value::Empty;
    }
    if let Some(named) = parse_named(raw) {
        return named;
    }
    let guesses = [
        parse_hms(raw),
        is_uuid(raw).then(|| Value::Uuid(raw.to_string())),
        raw.parse()
            .ok()
            .filter(|_| raw.contains('.'))
            .map(Value::Dotted),
        parse_uint(raw).map(|u| Value::Uint(u as u64)),
        parse_int(raw).map(Value::Int),
        parse_reply_float(raw).map(Value::Float),
    ];
    guesses
        .into_iter()
        .flatten()
        .next()
        .unwrap_or_else(|| Value::Text(raw.to_string()))
}

/// `<n> (<name>)`.
pub fn parse_named(raw: &str) -> Option<Value> {
    let (number, rest) = raw.split_once(' ')?;
    let name = rest.trim_start().strip_prefix('(')?.strip_suffix(')')?;
    Some(Value::Named {
        number: parse_int(number)?,
        name: name.to_string(),
    })
}

pub(super) fn parse_hms(raw: &str) -> Option<Value> {
    let parts: Vec<u64> = raw
        .split(':')
        .map(|p| {
            (!p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()))
                .then(|| p.parse().ok())
                .flatten()
        })
        .collect::<Option<_>>()?;
    match parts.as_slice() {
        [hours, minutes, seconds] if *minutes < 60 && *seconds < 60 => Some(Value::Hms {
            hours: *hours,
            minutes: *minutes,
            seconds: *seconds,
        }),
        _ => None,
    }
}

pub(super) fn is_uuid(raw: &str) -> bool {
    let groups: Vec<&str> = raw.split('-').collect();
    groups.len() == 5
        && groups
            .iter()
            .zip([8, 4, 4, 4, 12])
            .all(|(g, n)| g.len() == n && g.bytes().all(|b| b.is_ascii_hexdigit()))
}

/// A real number as replies write it: plain (`10`, `1000.00`), scientific with any number of
/// digits and either `e` case (`1.0000E+03`, `1.23000e4`), or without the `E` (`9.9996+00`; only
/// after a decimal point, so that a serial number like `00000-000` stays text).
pub fn parse_reply_float(raw: &str) -> Option<f64> {
    let unsigned = raw.strip_prefix(['+', '-']).unwrap_or(raw);
    let mantissa_len = unsigned
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(unsigned.len());
    let (mantissa, tail) = unsigned.split_at(mantissa_len);
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if !digits(fraction) || (whole.is_empty() && fraction.is_empty()) {
        return None;
    }
    let exponent = match tail.as_bytes().first() {
        None => "0",
        Some(b'e' | b'E') => &tail[1..],
        Some(b'+' | b'-') if mantissa.contains('.') => tail,
        Some(_) => return None,
    };
    let exponent_digits = exponent.strip_prefix(['+', '-']).unwrap_or(exponent);
    if exponent_digits.is_empty() || !digits(exponent_digits) {
        return None;
    }
    let value: f64 = format!("{}e{exponent}", &raw[..raw.len() - tail.len()])
        .parse()
        .ok()?;
    value.is_finite().then_some(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_in_every_form_the_document_shows() {
        for (raw, value) in [
            ("1.0000E+03", 1000.0),
            ("1.4988E+02", 149.88),
            ("1.23000E+04", 12300.0),
            ("5.76159E-10", 5.76159e-10),
            ("0.0000+00", 0.0),
            ("9.9996+00", 9.9996),
            ("1.0000+01", 10.0),
            ("1000.00", 1000.0),
            ("-0.50", -0.5),
            ("1e3", 1000.0),
            ("10", 10.0),
        ] {
            let got = parse_reply_float(raw).unwrap();
            assert!((got - value).abs() <= value.abs() * 1e-12, "{raw}: {got}");
        }
        for bad in [
            "",
            "E+03",
            "1.0E",
            "1.0+",
            "abc",
            "1.0E+03x",
            "inf",
            "1e999",
            "00000-000",
        ] {
            assert_eq!(parse_reply_float(bad), None, "{bad}");
        }
    }

    #[test]
    fn typed_items() {
        let item = |raw, ty| DataItem::typed(raw, Some(ty)).value;
        assert_eq!(
            item("24044.12", ItemType::Str),
            Value::Text("24044.12".into())
        );
        assert_eq!(item("1", ItemType::Bool), Value::Bool(true));
        assert_eq!(item("-10", ItemType::Int), Value::Int(-10));
        assert_eq!(item("0xA4DE", ItemType::Uint), Value::Uint(0xA4DE));
        assert_eq!(
            item("2:34:12", ItemType::Hms),
            Value::Hms {
                hours: 2,
                minutes: 34,
                seconds: 12
            }
        );
        assert_eq!(
            item("255.255.248.0", ItemType::Dotted),
            Value::Dotted(Ipv4Addr::new(255, 255, 248, 0))
        );
        // A Bool that is not 0/1 falls back to the guess rather than failing.
        assert_eq!(item("7", ItemType::Bool), Value::Uint(7));
    }

    #[test]
    fn guesses_untyped_items() {
        assert_eq!(
            guess("1 (Remote)"),
            Value::Named {
                number: 1,
                name: "Remote".into()
            }
        );
        assert_eq!(
            guess("f4562fb1-d002-11ee-b3e5-44b7d0c71675"),
            Value::Uuid("f4562fb1-d002-11ee-b3e5-44b7d0c71675".into())
        );
        assert_eq!(
            guess("44:b7:d0:c7:16:75"),
            Value::Text("44:b7:d0:c7:16:75".into())
        );
        assert_eq!(
            guess("10.0.97.70"),
            Value::Dotted(Ipv4Addr::new(10, 0, 97, 70))
        );
        assert_eq!(guess("100"), Value::Uint(100));
        assert_eq!(guess("-10"), Value::Int(-10));
        assert_eq!(guess("1.5000E+02"), Value::Float(150.0));
        assert_eq!(guess("00000-000"), Value::Text("00000-000".into()));
        assert_eq!(guess(""), Value::Empty);
        assert_eq!(guess("2:61:00"), Value::Text("2:61:00".into()));
    }
}
