//! `:params --values [filter]`: the readable parameters matching `filter`, read from the module
//! now, through the commissioning seam every dialect implements (so it reads what `:snapshot`
//! reads, the same way).

use std::io::Write;

use crate::commission::ParamDevice;
use crate::escape::escape_control;
use crate::session::{SessionError, interrupt};

/// The flag that asks `:params` for live values.
pub const FLAG: &str = "--values";

/// The filter of a `:params` argument that asks for values, or `None` when it does not.
pub fn values_filter(arg: &str) -> Option<String> {
    let words: Vec<&str> = arg.split_whitespace().collect();
    words.contains(&FLAG).then(|| {
        words
            .iter()
            .filter(|w| **w != FLAG)
            .copied()
            .collect::<Vec<_>>()
            .join(" ")
    })
}

/// Reads and shows the readable parameters whose name contains `filter` (any case): one line
/// each, `place  name  value unit`; a parameter the module refuses shows why, and the rest are
/// still read. Ctrl-C ends the table.
pub fn write_values(
    device: &mut dyn ParamDevice,
    filter: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let needle = filter.to_ascii_lowercase();
    let rows: Vec<_> = device
        .params()
        .into_iter()
        .filter(|p| p.access.read && p.name.to_ascii_lowercase().contains(&needle))
        .collect();
    if rows.is_empty() {
        writeln!(out, "no readable parameter matches '{filter}'")?;
        return Ok(());
    }
    let place_width = rows.iter().map(|p| p.place().len()).max().unwrap_or(0);
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
            param.place(),
            param.name
        );
        writeln!(out, "{}", escape_control(line.trim_start()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_flag_may_stand_anywhere() {
        assert_eq!(values_filter("--values").as_deref(), Some(""));
        assert_eq!(values_filter("max --values").as_deref(), Some("max"));
        assert_eq!(values_filter("--values max").as_deref(), Some("max"));
        assert_eq!(values_filter("max"), None);
    }
}
