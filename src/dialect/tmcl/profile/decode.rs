//! What a parameter's value means, as its profile row says: an enumeration of whole values
//! (`values`: `serial_baud_rate` 0 is 9600 baud), single bits (`bits`: the `status_flags`), and
//! fields of several bits with their own values (`fields`: GP67's start-up mode in bit 0, its echo
//! in bits 5..4). Data, documented in `data/profiles/README.md`; this only reads it.

use serde::Deserialize;

pub use crate::commission::decoding::{Bit, BitField, Decoding};

/// The decoding tables of one parameter row, as written in the profile.
#[derive(Debug, Clone, Default, Deserialize)]
pub(crate) struct DecodeRows {
    /// `[[value, "meaning"], …]`: what whole values mean.
    #[serde(default)]
    pub values: Vec<(i64, String)>,
    /// One bit each.
    #[serde(default)]
    pub bits: Vec<BitRow>,
    /// Groups of bits with values of their own.
    #[serde(default)]
    pub fields: Vec<FieldRow>,
}

/// One bit of a bit field.
#[derive(Debug, Clone, Deserialize)]
pub(crate) struct BitRow {
    pub bit: u8,
    /// A short name for decoded values; the meaning stands in where there is none.
    pub name: Option<String>,
    #[serde(default)]
    pub meaning: String,
}

/// Bits `low..=high` read as one number.
#[derive(Debug, Clone, Deserialize)]
pub(crate) struct FieldRow {
    pub name: String,
    /// `[low, high]`, the lowest and highest bit.
    pub bits: [u8; 2],
    #[serde(default)]
    pub values: Vec<(i64, String)>,
}

impl Decoding {
    /// The tables of a profile row (bits above 31 are not read).
    pub(crate) fn from_rows(rows: &DecodeRows) -> Decoding {
        Decoding {
            values: rows.values.clone(),
            bits: rows
                .bits
                .iter()
                .filter(|b| b.bit < 32)
                .map(|b| Bit {
                    bit: b.bit,
                    name: b.name.clone().unwrap_or_else(|| b.meaning.clone()),
                    meaning: b.meaning.clone(),
                })
                .collect(),
            fields: rows
                .fields
                .iter()
                .filter(|f| f.bits[0] <= f.bits[1] && f.bits[1] < 32)
                .map(|f| BitField {
                    name: f.name.clone(),
                    low: f.bits[0],
                    high: f.bits[1],
                    values: f.values.clone(),
                })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decoding(toml: &str) -> Decoding {
        Decoding::from_rows(&toml::from_str::<DecodeRows>(toml).unwrap())
    }

    #[test]
    fn whole_values_bits_and_fields_are_explained() {
        let baud = decoding(r#"values = [[0, "9600 baud"], [7, "115200 baud"]]"#);
        assert_eq!(baud.explain(0).as_deref(), Some("9600 baud"));
        assert_eq!(baud.explain(3), None);
        let flags = decoding(
            r#"bits = [{ bit = 0, name = "position reached", meaning = "target position reached (= AP8)" },
                       { bit = 2, meaning = "standing" }]"#,
        );
        assert_eq!(
            flags.explain(5).as_deref(),
            Some("position reached, standing")
        );
        assert_eq!(flags.explain(0).as_deref(), Some("no bit set"));
        assert_eq!(flags.explain(10).as_deref(), Some("bit 1, bit 3"));
        let ascii = decoding(
            r#"fields = [{ name = "start-up", bits = [0, 0], values = [[0, "binary"], [1, "ASCII"]] },
                         { name = "echo", bits = [4, 5], values = [[0, "each character"], [1, "line after CR"], [2, "none"]] }]"#,
        );
        assert_eq!(
            ascii.explain(17).as_deref(),
            Some("start-up: ASCII; echo: line after CR")
        );
        assert_eq!(
            ascii.explain(0x30).as_deref(),
            Some("start-up: binary; echo: 3")
        );
        assert!(decoding("").explain(1).is_none());
    }
}
