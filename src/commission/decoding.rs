//! What a value means, whatever the dialect: an enumeration of whole values (a TMCL baud-rate code
//! 0 is 9600 baud, an SMD4 MOTOR:F 2 shorts the phases), single bits (status flags) and fields of
//! several bits with their own values. Each dialect fills one from its data (a TMCL profile row,
//! the SMD4 table); this only reads a value with it, so both explain values the same way.

/// What a parameter's values mean; empty when the data says nothing.
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

    #[test]
    fn a_value_no_table_names_is_not_explained() {
        let decoding = Decoding {
            values: vec![(1, "on".into())],
            ..Decoding::default()
        };
        assert_eq!(decoding.explain(1).as_deref(), Some("on"));
        assert_eq!(decoding.explain(2), None);
        assert_eq!(Decoding::default().explain(0), None);
        let flags = Decoding {
            bits: vec![Bit {
                bit: 31,
                name: "top".into(),
                meaning: String::new(),
            }],
            ..Decoding::default()
        };
        let all = flags.explain(i64::from(u32::MAX)).unwrap();
        assert!(
            all.starts_with("bit 0, bit 1,") && all.ends_with("bit 30, top"),
            "{all}"
        );
    }
}
