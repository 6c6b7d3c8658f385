//! Ranges that depend on another parameter (`range_when`): shared by the command table, which
//! keeps the ones its module has, and the family tables that load them.

use super::ParamKind;
use super::load::RangeWhenRow;

/// A parameter and the value it must have for a [`RangeWhen`] to apply.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Condition {
    /// Axis parameter (of the same motor) or global parameter of a bank.
    pub kind: ParamKind,
    /// Its number.
    pub number: u8,
    /// The value that selects the range.
    pub equals: i64,
}

impl Condition {
    /// "axis parameter 255 = 1".
    pub fn describe(&self) -> String {
        match self.kind {
            ParamKind::Axis => format!("axis parameter {} = {}", self.number, self.equals),
            ParamKind::Global { bank } => format!(
                "global parameter {} of bank {bank} = {}",
                self.number, self.equals
            ),
        }
    }
}

/// A range that applies instead of the usual one while another parameter has a value
/// (`range_when`: TMCM-142 velocities are pps in 0..31999999 while AP255 = 1).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RangeWhen {
    /// When it applies.
    pub when: Condition,
    /// The range then.
    pub range: (i64, i64),
    /// The unit then.
    pub unit: String,
}

impl RangeWhen {
    /// The rows of a file, which the checker has passed (each names one parameter).
    pub(crate) fn from_rows(rows: &[RangeWhenRow]) -> Vec<RangeWhen> {
        rows.iter()
            .filter_map(|row| {
                let (kind, number) = match (row.axis_parameter, row.global_parameter) {
                    (Some(n), None) => (ParamKind::Axis, n),
                    (None, Some(n)) => (ParamKind::Global { bank: row.bank }, n),
                    _ => return None,
                };
                Some(RangeWhen {
                    when: Condition {
                        kind,
                        number,
                        equals: row.equals,
                    },
                    range: (row.range[0], row.range[1]),
                    unit: row.unit.clone(),
                })
            })
            .collect()
    }

    /// "0..31999999 usteps/s when axis parameter 255 = 1".
    pub fn describe(&self) -> String {
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        format!(
            "{}..{}{unit} when {}",
            self.range.0,
            self.range.1,
            self.when.describe()
        )
    }
}
