//! What a parameter's value means, as its profile row says: an enumeration of whole values
//! (`values`: `serial_baud_rate` 0 is 9600 baud), single bits (`bits`: the `status_flags`), and
//! fields of several bits with their own values (`fields`: GP67's start-up mode in bit 0, its echo
//! in bits 5..4). Data, documented in `data/profiles/README.md`; this only reads it.

use serde::Deserialize;

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

/// What a parameter's values mean; empty when the profile says nothing.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Decoding {
    /// Whole values and their meaning.
    pub values: Vec<(i64, String)>,
    /// Bit number, short name and meaning of each documented bit.
    pub bits: Vec<Bit>,
    /// Fields of several bits.
    pub fields: Vec<BitField>,
}

/// One documented bit.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Bit {
    /// Its number, 0 the lowest.
    pub bit: u8,
    /// What a decoded value calls it when set.
    pub name: String,
    /// What it means, for `:help PARAM`.
    pub meaning: String,
}

/// Bits read as one number, with what its values mean.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BitField {
    /// What the field is (`echo`).
    pub name: String,
    /// Lowest and highest bit.
    pub low: u8,
    /// Highest bit.
    pub high: u8,
    /// Its values and their meaning.
    pub values: Vec<(i64, String)>,
}

impl BitField {
    /// The field's number in `value`.
    fn of(&self, value: i64) -> i64 {
        let width = u32::from(self.high.saturating_sub(self.low)) + 1;
        (value >> self.low) & ((1i64 << width.min(62)) - 1)
    }
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

    /// Whether there is nothing to decode.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty() && self.bits.is_empty() && self.fields.is_empty()
    }

    /// What `value` means (`9600 baud`; `target position reached, motor standing`; `start-up:
    /// ASCII, echo: line after CR`), if the tables say.
    pub fn explain(&self, value: i64) -> Option<String> {
        if let Some((_, meaning)) = self.values.iter().find(|(v, _)| *v == value) {
            return Some(meaning.clone());
        }
        let mut parts: Vec<String> = self
            .fields
            .iter()
            .map(|f| {
                let number = f.of(value);
                match f.values.iter().find(|(v, _)| *v == number) {
                    Some((_, meaning)) => format!("{}: {meaning}", f.name),
                    None => format!("{}: {number}", f.name),
                }
            })
            .collect();
        if !self.bits.is_empty() {
            let in_fields = |bit: u8| self.fields.iter().any(|f| (f.low..=f.high).contains(&bit));
            let set: Vec<String> = (0..32u8)
                .filter(|bit| value >> bit & 1 == 1 && !in_fields(*bit))
                .map(|bit| match self.bits.iter().find(|b| b.bit == bit) {
                    Some(b) => b.name.clone(),
                    None => format!("bit {bit}"),
                })
                .collect();
            parts.push(if set.is_empty() {
                "no bit set".to_string()
            } else {
                set.join(", ")
            });
        }
        (!parts.is_empty()).then(|| parts.join("; "))
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
