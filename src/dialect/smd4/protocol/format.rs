//! How a drive writes values into replies, with each variant the document shows: flag words in
//! either hex case, floats with 4 or 5 decimals or without the `E`, and error items in several
//! spellings. The simulator emits them; tests use them to feed the parser every variant.

use std::ops::RangeInclusive;

use super::errors::ErrorCode;

/// Decimals a FLOAT is written with: 5 in the type table (`1.23000E+04`), 4 in every example
/// (`1.0000E+00`). Replies with other counts are line noise ([`super::check`]).
pub const FLOAT_DECIMALS: RangeInclusive<u8> = 4..=5;

/// Decimals of the fixed-point values (PACT, PREL: `1000.00`).
pub const FIXED_DECIMALS: usize = 2;

/// Case of the hex digits of SFLAGS/EFLAGS.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FlagCase {
    /// `0x088E`, as the type table says.
    #[default]
    Upper,
    /// `0x088e`, as many examples show.
    Lower,
}

/// How FLOAT values are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FloatStyle {
    /// Digits after the decimal point: 4 in every example, 5 in the type table.
    pub decimals: u8,
    /// Leave out the `E` (`1.0000+01`), as two examples do.
    pub missing_e: bool,
}

impl Default for FloatStyle {
    fn default() -> Self {
        FloatStyle {
            decimals: 4,
            missing_e: false,
        }
    }
}

/// How an error item is spelled. The document shows no error reply, only the table's
/// `-2 (Argument validation)` style.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ErrorSpelling {
    /// `-103 (Invalid Mnemonic)`.
    #[default]
    Parenthesised,
    /// `-103,Invalid Mnemonic` (two items).
    Comma,
    /// `-103`.
    Bare,
}

/// `0x%04X` or `0x%04x`.
pub fn format_flags(word: u16, case: FlagCase) -> String {
    match case {
        FlagCase::Upper => format!("0x{word:04X}"),
        FlagCase::Lower => format!("0x{word:04x}"),
    }
}

/// Scientific notation: one digit, `.`, the decimals, `E`, a sign and at least two exponent
/// digits (`1.0000E+03`). Rust's own `{:E}` writes `1E3`, hence this.
pub fn format_float(value: f64, style: FloatStyle) -> String {
    let text = format!("{:.*e}", usize::from(style.decimals), value);
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let sign = if exponent < 0 { '-' } else { '+' };
    let e = if style.missing_e { "" } else { "E" };
    format!("{mantissa}{e}{sign}{:02}", exponent.abs())
}

/// Fixed point with two decimals (`1000.00`), as the PACT/PREL examples show.
pub fn format_fixed(value: f64) -> String {
    format!("{value:.FIXED_DECIMALS$}")
}

/// The error item(s) of a failed command, without the leading comma.
pub fn format_error(code: ErrorCode, spelling: ErrorSpelling) -> String {
    match spelling {
        ErrorSpelling::Parenthesised => format!("{} ({})", code.code(), code.name()),
        ErrorSpelling::Comma => format!("{},{}", code.code(), code.name()),
        ErrorSpelling::Bare => code.code().to_string(),
    }
}

/// Elapsed time as `h:mm:ss` (BAKE:ELAPSED; the document's `2:34:12` does not show padding).
pub fn format_hms(seconds: u64) -> String {
    format!(
        "{}:{:02}:{:02}",
        seconds / 3600,
        seconds / 60 % 60,
        seconds % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_as_the_document_writes_them() {
        let four = FloatStyle::default();
        let five = FloatStyle {
            decimals: 5,
            missing_e: false,
        };
        let no_e = FloatStyle {
            decimals: 4,
            missing_e: true,
        };
        assert_eq!(format_float(1000.0, four), "1.0000E+03");
        assert_eq!(format_float(149.88, four), "1.4988E+02");
        assert_eq!(format_float(0.1, four), "1.0000E-01");
        assert_eq!(format_float(12300.0, five), "1.23000E+04");
        assert_eq!(format_float(5.76159e-10, five), "5.76159E-10");
        assert_eq!(format_float(0.0, no_e), "0.0000+00");
        assert_eq!(format_float(9.9996, no_e), "9.9996+00");
        assert_eq!(format_float(-2.5e120, four), "-2.5000E+120");
        assert_eq!(format_float(9.99996, four), "1.0000E+01");
    }

    #[test]
    fn flags_errors_and_times() {
        assert_eq!(format_flags(0x088E, FlagCase::Upper), "0x088E");
        assert_eq!(format_flags(0x088E, FlagCase::Lower), "0x088e");
        let code = ErrorCode::InvalidMnemonic;
        assert_eq!(
            format_error(code, ErrorSpelling::Parenthesised),
            "-103 (Invalid Mnemonic)"
        );
        assert_eq!(
            format_error(code, ErrorSpelling::Comma),
            "-103,Invalid Mnemonic"
        );
        assert_eq!(format_error(code, ErrorSpelling::Bare), "-103");
        assert_eq!(format_hms(2 * 3600 + 34 * 60 + 12), "2:34:12");
        assert_eq!(format_hms(5), "0:00:05");
        assert_eq!(format_fixed(1000.0), "1000.00");
        assert_eq!(format_fixed(-0.5), "-0.50");
    }
}
