//! SFLAGS and EFLAGS: the two 16-bit words at the start of every reply, decoded into the named
//! bits of `data/smd4.toml`.

use super::load::FlagRow;

/// One bit of a flag word.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FlagBit {
    /// Bit number, 0..=15.
    pub bit: u8,
    /// Name from the bit table (`Standby`).
    pub name: String,
    /// Label in the SYS:FLAGSV listing (`Standby`, `ExternalInhibit`).
    pub label: String,
    /// What it means.
    pub meaning: String,
    /// Whether the name is best knowledge.
    pub uncertain: bool,
}

impl FlagBit {
    /// `X` when the bit is set in `word`, a space otherwise (the SYS:FLAGSV listing's mark).
    pub fn mark(&self, word: u16) -> char {
        if word & (1 << self.bit) != 0 {
            'X'
        } else {
            ' '
        }
    }
}

/// The sixteen bits of one flag word.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FlagTable {
    bits: Vec<FlagBit>,
}

/// A flag row that would make a reply's flags read wrongly.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{word} bit {bit} {why}")]
pub struct FlagError {
    /// The flag word (`sflag`, `eflag`).
    pub word: String,
    /// The row's bit.
    pub bit: u8,
    /// What is wrong with it.
    pub why: &'static str,
}

impl FlagTable {
    /// The table of `rows` (`word` names them in messages); a bit beyond 15, given twice or
    /// without a name is refused, since a reply's flags would then read wrongly.
    pub(crate) fn from_rows(word: &str, rows: &[FlagRow]) -> Result<FlagTable, FlagError> {
        let mut seen = [false; 16];
        for row in rows {
            let refused = |why| FlagError {
                word: word.to_string(),
                bit: row.bit,
                why,
            };
            let Some(slot) = seen.get_mut(usize::from(row.bit)) else {
                return Err(refused("is beyond bit 15 of a flag word"));
            };
            if std::mem::replace(slot, true) {
                return Err(refused("is given twice"));
            }
            if row.name.trim().is_empty() {
                return Err(refused("has no name"));
            }
        }
        let mut bits: Vec<FlagBit> = rows
            .iter()
            .map(|r| FlagBit {
                bit: r.bit,
                name: r.name.clone(),
                label: r.flagsv_label.clone(),
                meaning: r.meaning.clone(),
                uncertain: r.uncertain,
            })
            .collect();
        bits.sort_by_key(|b| b.bit);
        Ok(FlagTable { bits })
    }

    /// All bits, lowest first.
    pub fn bits(&self) -> &[FlagBit] {
        &self.bits
    }

    /// The bits set in `word`, lowest first. Bits the table does not name appear as `bit N`.
    pub fn decode(&self, word: u16) -> Vec<FlagBit> {
        (0..16u8)
            .filter(|bit| word & (1 << bit) != 0)
            .map(|bit| {
                self.bits
                    .iter()
                    .find(|b| b.bit == bit)
                    .cloned()
                    .unwrap_or_else(|| FlagBit {
                        bit,
                        name: format!("bit {bit}"),
                        label: format!("bit{bit}"),
                        meaning: String::new(),
                        uncertain: true,
                    })
            })
            .collect()
    }

    /// The names of the bits set in `word`, comma separated, or `none`.
    pub fn describe(&self, word: u16) -> String {
        let names: Vec<String> = self.decode(word).into_iter().map(|b| b.name).collect();
        if names.is_empty() {
            "none".into()
        } else {
            names.join(", ")
        }
    }

    /// The SYS:FLAGSV listing of `word`: one `[X]Label` or `[ ]Label` per bit.
    pub fn listing(&self, word: u16) -> Vec<String> {
        self.bits
            .iter()
            .map(|b| format!("[{}]{}", b.mark(word), b.label))
            .collect()
    }
}

/// The status word (SFLAGS).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Sflags(pub u16);

impl Sflags {
    /// Bit 0: a joystick is connected.
    pub const JOYSTICK: u8 = 0;
    /// Bit 1: the negative limit input is active.
    pub const LIMIT_NEGATIVE: u8 = 1;
    /// Bit 2: the positive limit input is active.
    pub const LIMIT_POSITIVE: u8 = 2;
    /// Bit 3: the external enable input is active.
    pub const EXTERNAL_ENABLE: u8 = 3;
    /// Bit 4: identify blinking.
    pub const IDENT: u8 = 4;
    /// Bit 7: the motor is stationary.
    pub const STANDBY: u8 = 7;
    /// Bit 8: bake running.
    pub const BAKING: u8 = 8;
    /// Bit 9: at target velocity.
    pub const AT_TARGET_VELOCITY: u8 = 9;
    /// Bit 11: boost supply running.
    pub const BOOST_OPERATIONAL: u8 = 11;

    /// Whether `bit` is set.
    pub fn is_set(self, bit: u8) -> bool {
        bit < 16 && self.0 & (1 << bit) != 0
    }

    /// The motor is stationary (bit 7).
    pub fn standby(self) -> bool {
        self.is_set(Self::STANDBY)
    }

    /// Sets or clears `bit`.
    pub fn set(&mut self, bit: u8, on: bool) {
        if on {
            self.0 |= 1 << bit;
        } else {
            self.0 &= !(1 << bit);
        }
    }
}

/// The latching error word (EFLAGS). Any set bit disables the motor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Eflags(pub u16);

impl Eflags {
    /// Bit 1: temperature sensor open.
    pub const TEMP_OPEN: u8 = 1;
    /// Bit 4: disabled by the external enable input.
    pub const EXTERNAL_DISABLE: u8 = 4;
    /// Bit 5: emergency stop.
    pub const EMERGENCY_STOP: u8 = 5;
    /// Bit 6: stored configuration corrupt.
    pub const CONFIG_ERROR: u8 = 6;

    /// Whether `bit` is set.
    pub fn is_set(self, bit: u8) -> bool {
        bit < 16 && self.0 & (1 << bit) != 0
    }

    /// Whether any error is latched (the motor is then disabled).
    pub fn any(self) -> bool {
        self.0 != 0
    }

    /// Latches `bit`.
    pub fn latch(&mut self, bit: u8) {
        self.0 |= 1 << bit;
    }
}

#[cfg(test)]
mod tests {
    use crate::dialect::smd4::protocol::Smd4Spec;

    #[test]
    fn decodes_the_flagsv_example_word() {
        let spec = Smd4Spec::builtin();
        let names: Vec<String> = spec
            .sflags
            .decode(0x088E)
            .into_iter()
            .map(|b| b.label)
            .collect();
        assert_eq!(
            names,
            [
                "LimitNeg",
                "LimitPos",
                "Exten",
                "Standby",
                "BoostOperational"
            ]
        );
        assert_eq!(spec.eflags.describe(0x0002), "Temp Open");
        assert_eq!(spec.eflags.describe(0), "none");
        assert_eq!(spec.eflags.decode(1 << 5)[0].label, "EmergencyStop");
    }

    #[test]
    fn listing_marks_set_bits() {
        let spec = Smd4Spec::builtin();
        let lines = spec.sflags.listing(0x0080);
        assert_eq!(lines.len(), 16);
        assert_eq!(lines[7], "[X]Standby");
        assert_eq!(lines[0], "[ ]JsCon");
    }

    #[test]
    fn word_helpers() {
        let mut s = super::Sflags::default();
        s.set(super::Sflags::STANDBY, true);
        assert!(s.standby());
        s.set(super::Sflags::STANDBY, false);
        assert!(!s.standby());
        let mut e = super::Eflags::default();
        assert!(!e.any());
        e.latch(super::Eflags::EMERGENCY_STOP);
        assert_eq!(e.0, 0x0020);
    }
}
