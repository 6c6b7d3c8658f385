//! `:params --values [filter]`: the readable parameters matching `filter`, read from the module
//! now, through the commissioning seam every dialect implements (so it reads what `:snapshot`
//! reads, the same way).

use std::io::Write;

use crate::commission::{ParamDevice, ParamRef, Scope};
use crate::escape::escape_control;
use crate::session::{SessionError, interrupt};

/// The flag that asks `:params` for live values.
pub const FLAG: &str = "--values";

/// The flag that keeps one motor's parameters.
pub const MOTOR: &str = "--motor";

/// What to read: the parameters whose name contains `filter`, of one motor if given.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Wanted {
    /// Part of the name, any case ("" for all).
    pub filter: String,
    /// Only this motor's axis parameters.
    pub motor: Option<u8>,
}

/// What a `:params` argument that asks for values wants (`--values [--motor N] [filter]`, the
/// flags anywhere), `None` when it does not ask for values, or why it cannot be read.
pub fn values_filter(arg: &str) -> Option<Result<Wanted, SessionError>> {
    let words: Vec<&str> = arg.split_whitespace().collect();
    if !words.contains(&FLAG) {
        return words.contains(&MOTOR).then(|| {
            Err(SessionError::Usage(format!(
                "{MOTOR} goes with {FLAG}: :params {FLAG} {MOTOR} N [filter]"
            )))
        });
    }
    let mut wanted = Wanted::default();
    let mut rest = Vec::new();
    let mut words = words.into_iter();
    while let Some(word) = words.next() {
        match word {
            FLAG => {}
            MOTOR => match words.next().map(str::parse::<u8>) {
                Some(Ok(motor)) => wanted.motor = Some(motor),
                _ => {
                    let usage = format!("usage: :params {FLAG} {MOTOR} N [filter] (N: 0, 1 …)");
                    return Some(Err(SessionError::Usage(usage)));
                }
            },
            word => rest.push(word),
        }
    }
    wanted.filter = rest.join(" ");
    Some(Ok(wanted))
}

/// Reads and shows the readable parameters `wanted` names (name containing its filter, any case;
/// of its motor only, if it names one): one line each, `place  name  value unit`, every axis
/// parameter labelled with its motor (`axis 6 motor 0`); a parameter the module refuses shows
/// why, and the rest are still read. Ctrl-C ends the table. Returns how many matched, so that
/// each face says in its own way that none did.
pub fn write_values(
    device: &mut dyn ParamDevice,
    wanted: &Wanted,
    out: &mut dyn Write,
) -> Result<usize, SessionError> {
    let needle = wanted.filter.to_ascii_lowercase();
    let of_motor = |scope: Scope| match (wanted.motor, scope) {
        (None, _) => true,
        (Some(wanted), Scope::Axis { motor }) => motor == wanted,
        (Some(_), _) => false,
    };
    let rows: Vec<_> = device
        .params()
        .into_iter()
        .filter(|p| p.access.read && p.name.to_ascii_lowercase().contains(&needle))
        .filter(|p| of_motor(p.scope))
        .collect();
    let place = |param: &ParamRef| match param.scope {
        Scope::Axis { motor } => format!("axis {} motor {motor}", param.number.unwrap_or_default()),
        _ => param.place(),
    };
    let place_width = rows.iter().map(|p| place(p).len()).max().unwrap_or(0);
    let name_width = rows.iter().map(|p| p.name.len()).max().unwrap_or(0);
    for param in &rows {
        if interrupt::pending() {
            return Err(SessionError::Interrupted);
        }
        let shown = match device.read(param) {
            Ok(reading) => match device.explain(param, &reading.value) {
                Some(meaning) => format!("{} ({meaning})", reading.value),
                None if param.unit.is_empty() => reading.text(),
                None => format!("{} {}", reading.text(), param.unit),
            },
            Err(SessionError::Device { reason, .. }) => format!("refused: {reason}"),
            Err(e) => return Err(e),
        };
        let line = format!(
            "{:<place_width$}  {:<name_width$}  {shown}",
            place(param),
            param.name
        );
        writeln!(out, "{}", escape_control(line.trim_start()))?;
    }
    Ok(rows.len())
}

/// What to say when nothing matched `wanted`.
pub fn none_matched(wanted: &Wanted) -> String {
    match wanted.motor {
        Some(motor) => format!(
            "no readable parameter of motor {motor} matches '{}'",
            wanted.filter
        ),
        None => format!("no readable parameter matches '{}'", wanted.filter),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_flag_may_stand_anywhere() {
        let filter = |arg: &str| values_filter(arg).map(|w| w.unwrap().filter);
        assert_eq!(filter("--values").as_deref(), Some(""));
        assert_eq!(filter("max --values").as_deref(), Some("max"));
        assert_eq!(filter("--values max").as_deref(), Some("max"));
        assert!(values_filter("max").is_none());
    }

    #[test]
    fn a_motor_is_a_number_after_its_flag_and_only_with_values() {
        let wanted = values_filter("--motor 2 max --values").unwrap().unwrap();
        assert_eq!(wanted.motor, Some(2));
        assert_eq!(wanted.filter, "max");
        assert!(values_filter("--values --motor").unwrap().is_err());
        assert!(values_filter("--values --motor x max").unwrap().is_err());
        assert!(values_filter("--motor 1 max").unwrap().is_err());
    }
}
