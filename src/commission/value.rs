//! Values as the commissioning tools handle them, whatever the dialect: TMCL parameters are
//! integers, SMD4 settings are integers, real numbers (currents in A, speeds in Hz) or text (a
//! dotted address, a firmware string). Two readings of a value are the same when the module
//! would not tell them apart: real numbers agree to the digits the module reports, or fall on
//! the same step where the module rounds to steps (the SMD4's motor currents).

use std::fmt;

/// A parameter's value.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamValue {
    /// An integer: every TMCL value; SMD4 INT, UINT, BOOL and enumerated values.
    Int(i64),
    /// A real number (SMD4 FLOAT).
    Float(f64),
    /// Text: addresses, strings, times, flag words.
    Text(String),
}

impl ParamValue {
    /// The value as a number, where it is one.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            ParamValue::Int(i) => Some(*i as f64),
            ParamValue::Float(f) => Some(*f),
            ParamValue::Text(_) => None,
        }
    }

    /// The value as an integer, where it is one.
    pub fn as_i64(&self) -> Option<i64> {
        match self {
            ParamValue::Int(i) => Some(*i),
            _ => None,
        }
    }

    /// The value as a TOML value (`5`, `1.0103`, `"10.0.97.70"`).
    pub fn to_toml(&self) -> String {
        match self {
            ParamValue::Int(i) => i.to_string(),
            ParamValue::Float(f) => toml::Value::Float(*f).to_string(),
            ParamValue::Text(t) => toml::Value::String(t.clone()).to_string(),
        }
    }

    /// From a TOML value of a snapshot file.
    pub fn from_toml(value: &toml::Value) -> Option<ParamValue> {
        match value {
            toml::Value::Integer(i) => Some(ParamValue::Int(*i)),
            toml::Value::Float(f) if f.is_finite() => Some(ParamValue::Float(*f)),
            toml::Value::String(s) => Some(ParamValue::Text(s.clone())),
            _ => None,
        }
    }

    /// The value as a CSV cell: integers as they are, real numbers always with a decimal point
    /// or an exponent (so they read back as real numbers), text as it is (SMD4 data items
    /// cannot contain commas).
    pub fn to_csv(&self) -> String {
        match self {
            ParamValue::Int(i) => i.to_string(),
            ParamValue::Float(f) => format!("{f:?}"),
            ParamValue::Text(t) => t.clone(),
        }
    }

    /// From a CSV cell written by [`ParamValue::to_csv`].
    pub fn from_csv(cell: &str) -> ParamValue {
        if let Ok(i) = cell.parse::<i64>() {
            return ParamValue::Int(i);
        }
        match cell.parse::<f64>() {
            Ok(f) if f.is_finite() => ParamValue::Float(f),
            _ => ParamValue::Text(cell.to_string()),
        }
    }
}

impl fmt::Display for ParamValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamValue::Int(i) => write!(f, "{i}"),
            ParamValue::Float(x) => write!(f, "{x}"),
            ParamValue::Text(t) => f.write_str(t),
        }
    }
}

impl From<i64> for ParamValue {
    fn from(value: i64) -> Self {
        ParamValue::Int(value)
    }
}

impl From<f64> for ParamValue {
    fn from(value: f64) -> Self {
        ParamValue::Float(value)
    }
}

/// One reading of a parameter: its value, and what the module said about it besides.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// The value — for a user/real pair, the user value (what was set, what a restore writes).
    pub value: ParamValue,
    /// The value the hardware produces, where the module tells it (SMD4 profile settings).
    pub real: Option<f64>,
    /// The name of an enumerated value (`Remote` for SYS:MODE 1).
    pub label: Option<String>,
}

impl Reading {
    /// A bare value.
    pub fn of(value: impl Into<ParamValue>) -> Reading {
        Reading {
            value: value.into(),
            real: None,
            label: None,
        }
    }

    /// The value with its label: `1 (Remote)`, or `5`.
    pub fn text(&self) -> String {
        match &self.label {
            Some(label) => format!("{} ({label})", self.value),
            None => self.value.to_string(),
        }
    }
}

/// How two values of one parameter are compared.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tolerance {
    /// Equal or not: integers and text.
    Exact,
    /// Real numbers the module reports to this many significant digits: the same when they
    /// agree to half a unit of the last digit.
    Digits(u32),
    /// Real numbers the module rounds to the nearest multiple of this step: the same when they
    /// fall on the same step.
    Step(f64),
}

impl Tolerance {
    /// Whether `a` and `b` are the same value of the parameter. Numbers compare by value (an
    /// integer `150` is the real `150.0`); text only with text.
    pub fn same(self, a: &ParamValue, b: &ParamValue) -> bool {
        if let (ParamValue::Int(x), ParamValue::Int(y)) = (a, b) {
            return x == y;
        }
        let (x, y) = match (a.as_f64(), b.as_f64()) {
            (Some(x), Some(y)) => (x, y),
            _ => return a == b,
        };
        match self {
            Tolerance::Exact => x == y,
            Tolerance::Step(step) if step > 0.0 => (x / step).round() == (y / step).round(),
            Tolerance::Step(_) => x == y,
            Tolerance::Digits(digits) => {
                let largest = x.abs().max(y.abs());
                if largest == 0.0 {
                    return true;
                }
                let exponent = largest.log10().floor() as i32;
                let unit = 10f64.powi(exponent + 1 - digits.max(1) as i32);
                // Half a unit of the last digit, and a little for binary rounding.
                (x - y).abs() <= unit * 0.5 * (1.0 + 1e-9)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_trip_through_toml_and_csv_keeping_their_kind() {
        for value in [
            ParamValue::Int(-42),
            ParamValue::Float(1000.0),
            ParamValue::Float(1.0103225806451613),
            ParamValue::Float(1e-7),
            ParamValue::Text("10.0.97.70".into()),
        ] {
            let cell = value.to_csv();
            assert_eq!(ParamValue::from_csv(&cell), value, "{cell}");
            let text = format!("v = {}", value.to_toml());
            let table: toml::Table = toml::from_str(&text).unwrap();
            assert_eq!(ParamValue::from_toml(&table["v"]), Some(value), "{text}");
        }
        assert_eq!(ParamValue::Float(1000.0).to_csv(), "1000.0");
        assert_eq!(ParamValue::Float(1000.0).to_string(), "1000");
    }

    #[test]
    fn real_numbers_are_the_same_to_the_digits_the_module_reports() {
        let five = Tolerance::Digits(5);
        let same = |a: f64, b: f64| five.same(&a.into(), &b.into());
        assert!(
            same(123.456, 123.46),
            "1.2346E+02 is what the drive reports"
        );
        assert!(!same(123.456, 123.47));
        assert!(same(1.0103225806451613, 1.0103));
        assert!(!same(1.0103, 1.0104));
        assert!(same(0.0, 0.0));
        assert!(!same(0.0, 1e-9));
        assert!(same(150.0, 150.0));
        assert!(five.same(&ParamValue::Int(150), &ParamValue::Float(150.0)));
    }

    #[test]
    fn stepped_values_are_the_same_on_the_same_step() {
        let step = Tolerance::Step(1.044 / 31.0);
        let same = |a: f64, b: f64| step.same(&a.into(), &b.into());
        assert!(same(1.0, 30.0 * 1.044 / 31.0), "level 30 either way");
        assert!(same(0.5, 0.5052));
        assert!(!same(0.5, 0.54));
    }

    #[test]
    fn integers_and_text_are_compared_exactly() {
        for tolerance in [Tolerance::Exact, Tolerance::Digits(5)] {
            assert!(tolerance.same(&ParamValue::Int(7), &ParamValue::Int(7)));
            assert!(!tolerance.same(&ParamValue::Int(100000), &ParamValue::Int(100001)));
            let ip = |t: &str| ParamValue::Text(t.into());
            assert!(tolerance.same(&ip("10.0.0.1"), &ip("10.0.0.1")));
            assert!(!tolerance.same(&ip("10.0.0.1"), &ip("10.0.0.2")));
            assert!(!tolerance.same(&ip("5"), &ParamValue::Int(5)));
        }
    }

    #[test]
    fn a_reading_shows_its_label() {
        let mut reading = Reading::of(1);
        assert_eq!(reading.text(), "1");
        reading.label = Some("Remote".into());
        assert_eq!(reading.text(), "1 (Remote)");
    }
}
