//! The firmware version string of command 136 type 0: eight characters naming the module and its
//! firmware version. Three-digit modules send `NNNVa.bc` (`142V1.06`), four-digit ones `NNNNVabc`
//! (`6110V131`: the dot does not fit); a boot loader answers with `B` in place of `V`
//! (`6110B131`). PyTrinamic's firmware updater accepts exactly these two forms.
//!
//! Manuals also print `1141V1.17`, nine characters, which the 8-byte answer cannot carry; it is
//! read too, for versions typed by people.

/// A parsed 136 version string.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FirmwareVersion {
    /// The module number (`6110`).
    pub module: u32,
    /// Major version (`1` of 1.31).
    pub major: u8,
    /// Minor version, two digits (`31` of 1.31).
    pub minor: u8,
    /// The boot loader answered, not the firmware.
    pub bootloader: bool,
    /// The string as received (trailing NULs and spaces removed).
    pub text: String,
}

/// Why a version string was not understood.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "'{}' is not a TMCL firmware version (NNNVa.bc or NNNNVabc, B for V in the boot loader)",
    crate::escape::escape_control(text)
)]
pub struct VersionError {
    /// What was received.
    pub text: String,
}

impl FirmwareVersion {
    /// Parses `142V1.06`, `6110V131`, `6110B131` (and the 9-character `1141V1.17` of manuals).
    pub fn parse(answer: &str) -> Result<FirmwareVersion, VersionError> {
        let text = answer.trim_end_matches(['\0', ' ']);
        let error = || VersionError {
            text: text.to_string(),
        };
        let at = text.find(['V', 'B']).ok_or_else(error)?;
        let (digits, rest) = text.split_at(at);
        let (letter, release) = rest.split_at(1);
        let all_digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
        if !all_digits(digits) || !(3..=4).contains(&digits.len()) {
            return Err(error());
        }
        let (major, minor) = match (digits.len(), release.as_bytes()) {
            (3 | 4, [a, b'.', b, c]) => (*a, [*b, *c]),
            (4, [a, b, c]) => (*a, [*b, *c]),
            _ => return Err(error()),
        };
        if !all_digits(std::str::from_utf8(&[major, minor[0], minor[1]]).map_err(|_| error())?) {
            return Err(error());
        }
        Ok(FirmwareVersion {
            module: digits.parse().map_err(|_| error())?,
            major: major - b'0',
            minor: (minor[0] - b'0') * 10 + (minor[1] - b'0'),
            bootloader: letter == "B",
            text: text.to_string(),
        })
    }
}

/// Whether `text` has the 136 format `format` (`N`, `a`, `b`, `c` digits, others literal).
pub fn fits(text: &str, format: &str) -> bool {
    text.len() == format.len()
        && text.chars().zip(format.chars()).all(|(c, f)| match f {
            'N' | 'a' | 'b' | 'c' => c.is_ascii_digit(),
            other => c == other,
        })
}

/// The 136 format of a module number: `NNNVa.bc` for three digits, `NNNNVabc` for four.
pub fn format_for(module_number: u32) -> Option<&'static str> {
    match module_number {
        100..=999 => Some("NNNVa.bc"),
        1000..=9999 => Some("NNNNVabc"),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parsed(text: &str) -> (u32, u8, u8, bool) {
        let v = FirmwareVersion::parse(text).unwrap_or_else(|e| panic!("{e}"));
        (v.module, v.major, v.minor, v.bootloader)
    }

    #[test]
    fn both_forms_and_the_boot_loader() {
        assert_eq!(parsed("142V1.06"), (142, 1, 6, false));
        assert_eq!(parsed("6110V131"), (6110, 1, 31, false));
        assert_eq!(parsed("6110B131"), (6110, 1, 31, true));
        assert_eq!(parsed("142B1.06"), (142, 1, 6, true));
        assert_eq!(parsed("1141V1.17"), (1141, 1, 17, false));
        assert_eq!(parsed("1640V200\0"), (1640, 2, 0, false));
    }

    #[test]
    fn anything_else_is_refused() {
        for bad in [
            "",
            "V131",
            "61V131",
            "61101V13",
            "6110X131",
            "6110V13",
            "6110V1311",
            "142V106",
            "142V1,06",
            "14aV1.06",
            "6110Vabc",
            "6110V1.3",
            "\u{0}\u{0}",
            "6110V1 31",
            "ß110V131",
        ] {
            let e = FirmwareVersion::parse(bad).unwrap_err();
            assert!(
                e.to_string().contains("not a TMCL firmware version"),
                "{bad:?}"
            );
        }
        let e = FirmwareVersion::parse("\u{1b}[2J").unwrap_err().to_string();
        assert!(!e.contains('\u{1b}'), "escaped: {e}");
    }

    #[test]
    fn formats_of_module_numbers() {
        assert_eq!(format_for(142), Some("NNNVa.bc"));
        assert_eq!(format_for(6110), Some("NNNNVabc"));
        assert_eq!(format_for(12), None);
        assert_eq!(format_for(10000), None);
        assert!(fits("142V1.06", "NNNVa.bc"));
        assert!(fits("6110B131", "NNNNBabc"));
        assert!(!fits("6110V131", "NNNNBabc"));
        assert!(!fits("142V1.06", "NNNNVabc"));
    }
}
