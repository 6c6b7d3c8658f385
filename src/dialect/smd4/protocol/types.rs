//! The document's value types (INT, UINT, FLOAT, STRING, BOOL, DOTTED DECIMAL, and the ENUM, UUID
//! and h:m:s forms its commands use) and the strict grammar of arguments in requests.
//!
//! Arguments are checked strictly, as the drive does (−101 for the wrong type); replies are read
//! leniently by [`super::items`], since the document's own examples disagree on number formats.

use std::net::Ipv4Addr;

/// The type of an argument or of a reply's data item.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ItemType {
    /// Signed decimal integer (`100`, `-10`, `+7`).
    Int,
    /// Unsigned integer, decimal or `0x` hex in any case (`99`, `0xA74F`).
    Uint,
    /// Real number, plain or scientific (`10.23`, `100e-3`, `1.0000E+03`).
    Float,
    /// Printable ASCII text.
    Str,
    /// `0` or `1`.
    Bool,
    /// IPv4 address or mask (`192.168.0.1`).
    Dotted,
    /// An option number (MOTOR:SDMODE).
    Enum,
    /// 8-4-4-4-12 hex (SYS:UUID).
    Uuid,
    /// Elapsed time `h:m:s` (BAKE:ELAPSED).
    Hms,
}

impl ItemType {
    /// The type named in `data/smd4.toml`; `None` for "none" or an unknown name.
    pub fn from_name(name: &str) -> Option<ItemType> {
        Some(match name.trim().to_ascii_uppercase().as_str() {
            "INT" => ItemType::Int,
            "UINT" => ItemType::Uint,
            "FLOAT" => ItemType::Float,
            "STRING" => ItemType::Str,
            "BOOL" => ItemType::Bool,
            "DOTTED DECIMAL" | "DOTTED" => ItemType::Dotted,
            "ENUM" => ItemType::Enum,
            "UUID" => ItemType::Uuid,
            "HMS" => ItemType::Hms,
            _ => return None,
        })
    }

    /// The name the document uses.
    pub fn name(self) -> &'static str {
        match self {
            ItemType::Int => "INT",
            ItemType::Uint => "UINT",
            ItemType::Float => "FLOAT",
            ItemType::Str => "STRING",
            ItemType::Bool => "BOOL",
            ItemType::Dotted => "DOTTED DECIMAL",
            ItemType::Enum => "ENUM",
            ItemType::Uuid => "UUID",
            ItemType::Hms => "h:m:s",
        }
    }

    /// What a value of this type looks like, for error messages.
    pub fn describe(self) -> &'static str {
        match self {
            ItemType::Int => "an integer such as 100, -10 or +7",
            ItemType::Uint => "an unsigned integer such as 99 or 0xA74F",
            ItemType::Float => "a number such as 10.23, 100e-3 or 10",
            ItemType::Str => "printable ASCII text without commas",
            ItemType::Bool => "0 or 1",
            ItemType::Dotted => "a dotted decimal address such as 192.168.0.1",
            ItemType::Enum => "an option number",
            ItemType::Uuid => "a UUID",
            ItemType::Hms => "a time h:m:s",
        }
    }
}

/// An argument that passed its type's grammar.
#[derive(Debug, Clone, PartialEq)]
pub enum ArgValue {
    /// INT, UINT, BOOL and ENUM arguments.
    Int(i64),
    /// FLOAT arguments.
    Float(f64),
    /// STRING arguments.
    Text(String),
    /// DOTTED DECIMAL arguments.
    Dotted(Ipv4Addr),
}

impl ArgValue {
    /// The value as a number, for range checks.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            ArgValue::Int(i) => Some(*i as f64),
            ArgValue::Float(f) => Some(*f),
            _ => None,
        }
    }

    /// The value written the way a reply would carry it (`0x10` → `16`, `+7` → `7`).
    pub fn canonical(&self) -> String {
        match self {
            ArgValue::Int(i) => i.to_string(),
            ArgValue::Float(f) => f.to_string(),
            ArgValue::Text(t) => t.clone(),
            ArgValue::Dotted(ip) => ip.to_string(),
        }
    }
}

/// Parses an argument as `ty`; `None` when it does not follow the type's grammar.
pub fn parse_arg(ty: ItemType, text: &str) -> Option<ArgValue> {
    match ty {
        ItemType::Int => parse_int(text).map(ArgValue::Int),
        ItemType::Uint | ItemType::Enum => parse_uint(text).map(ArgValue::Int),
        ItemType::Bool => match text {
            "0" => Some(ArgValue::Int(0)),
            "1" => Some(ArgValue::Int(1)),
            _ => None,
        },
        ItemType::Float => parse_float(text).map(ArgValue::Float),
        ItemType::Str => printable(text).then(|| ArgValue::Text(text.to_string())),
        ItemType::Dotted => parse_dotted(text).map(ArgValue::Dotted),
        ItemType::Uuid | ItemType::Hms => None,
    }
}

/// `[+-]digits`.
pub fn parse_int(text: &str) -> Option<i64> {
    let digits = text.strip_prefix(['+', '-']).unwrap_or(text);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    text.parse().ok()
}

/// `digits` or `0x` hex digits (either case).
pub fn parse_uint(text: &str) -> Option<i64> {
    let hex = text.strip_prefix("0x").or_else(|| text.strip_prefix("0X"));
    match hex {
        Some(h) if !h.is_empty() && h.bytes().all(|b| b.is_ascii_hexdigit()) => {
            i64::from_str_radix(h, 16).ok()
        }
        Some(_) => None,
        None if !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit()) => text.parse().ok(),
        None => None,
    }
}

/// `[+-](digits[.digits]|.digits)([eE][+-]digits)` — no `inf`, `nan` or hex, unlike `str::parse`.
pub fn parse_float(text: &str) -> Option<f64> {
    let unsigned = text.strip_prefix(['+', '-']).unwrap_or(text);
    let (mantissa, exponent) = match unsigned.find(['e', 'E']) {
        Some(i) => (&unsigned[..i], Some(&unsigned[i + 1..])),
        None => (unsigned, None),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    let mantissa_ok =
        digits(whole) && digits(fraction) && !(whole.is_empty() && fraction.is_empty());
    let exponent_ok = exponent.is_none_or(|e| parse_int(e).is_some());
    if !mantissa_ok || !exponent_ok {
        return None;
    }
    text.parse().ok().filter(|f: &f64| f.is_finite())
}

pub(super) fn parse_dotted(text: &str) -> Option<Ipv4Addr> {
    let parts: Vec<&str> = text.split('.').collect();
    let octets: Option<Vec<u8>> = parts
        .iter()
        .map(|p| {
            (!p.is_empty() && p.len() <= 3 && p.bytes().all(|b| b.is_ascii_digit()))
                .then(|| p.parse().ok())
                .flatten()
        })
        .collect();
    match octets?.as_slice() {
        [a, b, c, d] => Some(Ipv4Addr::new(*a, *b, *c, *d)),
        _ => None,
    }
}

/// Printable ASCII 0x20..=0x7E, non-empty, without the item separator.
fn printable(text: &str) -> bool {
    !text.is_empty()
        && text
            .bytes()
            .all(|b| (0x20..=0x7E).contains(&b) && b != b',')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers_follow_the_type_table() {
        for (text, value) in [("100", 100), ("-10", -10), ("+7", 7)] {
            assert_eq!(parse_arg(ItemType::Int, text), Some(ArgValue::Int(value)));
        }
        for (text, value) in [
            ("99", 99),
            ("1000", 1000),
            ("0xA74F", 0xA74F),
            ("0xd7", 0xD7),
        ] {
            assert_eq!(parse_arg(ItemType::Uint, text), Some(ArgValue::Int(value)));
        }
        for bad in ["", "1.5", "1e3", "0x", "abc", "+-1", "-", "0xg1"] {
            assert_eq!(parse_arg(ItemType::Int, bad), None, "{bad}");
        }
        for bad in ["-1", "+1", "0x", "1.0", " 1"] {
            assert_eq!(parse_arg(ItemType::Uint, bad), None, "{bad}");
        }
    }

    #[test]
    fn floats_follow_the_type_table() {
        for (text, value) in [
            ("10.23", 10.23),
            ("100e-3", 0.1),
            ("100E4", 1e6),
            ("10", 10.0),
            ("-.5", -0.5),
            ("+3.", 3.0),
        ] {
            assert_eq!(
                parse_arg(ItemType::Float, text),
                Some(ArgValue::Float(value))
            );
        }
        for bad in [
            "", ".", "e3", "1e", "inf", "NaN", "1,5", "0x10", "1e+", "1.2.3", "1e999",
        ] {
            assert_eq!(parse_arg(ItemType::Float, bad), None, "{bad}");
        }
    }

    #[test]
    fn other_types() {
        assert_eq!(parse_arg(ItemType::Bool, "1"), Some(ArgValue::Int(1)));
        assert_eq!(parse_arg(ItemType::Bool, "2"), None);
        assert_eq!(
            parse_arg(ItemType::Dotted, "192.168.0.1"),
            Some(ArgValue::Dotted(Ipv4Addr::new(192, 168, 0, 1)))
        );
        for bad in ["192.168.0", "256.1.1.1", "1.2.3.4.5", "a.b.c.d", "1..2.3"] {
            assert_eq!(parse_arg(ItemType::Dotted, bad), None, "{bad}");
        }
        assert_eq!(
            parse_arg(ItemType::Str, "78-%^A"),
            Some(ArgValue::Text("78-%^A".into()))
        );
        assert_eq!(parse_arg(ItemType::Str, "tab\there"), None);
        assert_eq!(ArgValue::Int(16).canonical(), "16");
    }
}
