//! The module's I/O ports told from its profile's port map (`[[io_port]]`): the `:help io` table,
//! the port summary that ends `:help GIO` and `:help SIO`, the hint of a typed port, and the name
//! a GIO reply is shown under. Nothing here knows a port: every name, kind and pin is the
//! profile's.

use std::io::{self, Write};

use super::profile::Profile;
use super::profile::family::{IoPort, OUTPUT_BANK, spans};
use crate::dialect::UNCERTAIN;
use crate::wrap::{fit, terminal_width};

/// `:help io`: the ports as a table (bank/port, name, direction, pin where the profile gives
/// pins, kind), or that the profile has no port map.
pub fn write_table(profile: &Profile, out: &mut dyn Write) -> io::Result<()> {
    let width = terminal_width();
    if profile.io_ports.is_empty() {
        return writeln!(out, "{}", fit(&no_map(profile), 0, width));
    }
    let intro = format!(
        "I/O ports of the {}: GIO port, bank reads any of them; SIO port, {OUTPUT_BANK}, value \
         sets an output.",
        profile.module
    );
    writeln!(out, "{}", fit(&intro, 0, width))?;
    let ports = &profile.io_ports;
    let name_width = column_width(ports.iter().map(|p| p.name.as_str()), "name");
    let pins = ports.iter().any(|p| p.pin.is_some());
    let pin_width = column_width(ports.iter().filter_map(|p| p.pin.as_deref()), "pin");
    let pin_cell = |pin: &str| {
        if pins {
            format!("{pin:>pin_width$}  ")
        } else {
            String::new()
        }
    };
    let header = format!(
        "{:<9} {:mark$}  {:<name_width$}  {:<9}  {}",
        "bank/port",
        "",
        "name",
        "direction",
        pin_cell("pin"),
        mark = UNCERTAIN.len()
    );
    writeln!(out, "{}kind", header)?;
    for p in ports {
        let head = format!(
            "{:<9} {}  {:<name_width$}  {:<9}  {}",
            format!("{}/{}", p.bank, p.port),
            mark(p),
            p.name,
            direction(p),
            pin_cell(p.pin.as_deref().unwrap_or("")),
        );
        let row = format!("{head}{}", kind(p));
        writeln!(out, "{}", fit(row.trim_end(), head.chars().count(), width))?;
    }
    if ports.iter().any(|p| p.uncertain) {
        let note = format!(
            "{UNCERTAIN} after bank/port: the {} manual does not confirm the row (taken from \
             sibling modules or inferred); `tmclsh profiles {}` names the sources.",
            profile.module, profile.name
        );
        writeln!(out, "{}", fit(&note, 0, width))?;
    }
    Ok(())
}

/// The width of a column holding `cells` under `title`.
fn column_width<'a>(cells: impl Iterator<Item = &'a str>, title: &str) -> usize {
    cells
        .map(|c| c.chars().count())
        .max()
        .unwrap_or(0)
        .max(title.len())
}

/// The uncertain mark of a row, or as many spaces.
fn mark(port: &IoPort) -> String {
    if port.uncertain {
        UNCERTAIN.to_string()
    } else {
        " ".repeat(UNCERTAIN.len())
    }
}

/// "input" (GIO reads it) or "output" (SIO sets it, GIO reads it back).
fn direction(port: &IoPort) -> &'static str {
    if port.is_output() { "output" } else { "input" }
}

/// What the port is, with the values GIO reads there unless they are plain 0 or 1.
fn kind(port: &IoPort) -> String {
    let values = match (port.range, port.unit.as_str()) {
        (Some((0, 1)), "") | (None, "") => None,
        (Some((lo, hi)), "") => Some(format!("{lo}..{hi}")),
        (Some((lo, hi)), unit) => Some(format!("{lo}..{hi} {unit}")),
        (None, unit) => Some(unit.to_string()),
    };
    [Some(port.kind.clone()), values]
        .into_iter()
        .flatten()
        .filter(|s| !s.is_empty())
        .collect::<Vec<_>>()
        .join(", ")
}

/// That the profile has no port map, and what follows from it.
pub fn no_map(profile: &Profile) -> String {
    let name = if profile.name.is_empty() {
        profile.module.as_str()
    } else {
        profile.name.as_str()
    };
    format!(
        "The {name} profile has no port map: GIO and SIO send any port and bank unchecked, and \
         replies show port numbers only."
    )
}

/// The last line of `:help GIO` (`writes`: of `:help SIO`): this module's ports in short.
pub fn help_line(profile: &Profile, writes: bool) -> String {
    match summary(profile, writes) {
        Some(summary) => {
            let what = if writes { "Outputs" } else { "Ports" };
            format!(
                "{what} on this {}: {summary}; :help io has the table.",
                profile.module
            )
        }
        None if profile.io_ports.is_empty() => no_map(profile),
        None => format!("The {} has no output port.", profile.module),
    }
}

/// "bank 0 ports 3..8 (IN3..IN8, digital input) and bank 2 ports 0..2 (OUT_0..OUT_2, user
/// output)"; of the output bank only when `outputs_only`. `None` without such ports.
pub fn summary(profile: &Profile, outputs_only: bool) -> Option<String> {
    let mut banks: Vec<(u8, Vec<&IoPort>)> = Vec::new();
    for p in &profile.io_ports {
        if outputs_only && !p.is_output() {
            continue;
        }
        match banks.last_mut() {
            Some((bank, ports)) if *bank == p.bank => ports.push(p),
            _ => banks.push((p.bank, vec![p])),
        }
    }
    let parts: Vec<String> = banks
        .iter()
        .map(|(bank, ports)| {
            let numbers: Vec<u8> = ports.iter().map(|p| p.port).collect();
            let numbers = spans(&numbers);
            let word = if ports.len() == 1 { "port" } else { "ports" };
            let mut about = vec![names(ports)];
            about.extend(common_kind(ports));
            format!("bank {bank} {word} {numbers} ({})", about.join(", "))
        })
        .collect();
    match parts.as_slice() {
        [] => None,
        [one] => Some(one.clone()),
        [first @ .., last] => Some(format!("{} and {last}", first.join(", "))),
    }
}

/// The names of a bank's ports: all of a few, the first and last of a contiguous run, or the
/// first two and the last.
fn names(ports: &[&IoPort]) -> String {
    let contiguous = ports
        .windows(2)
        .all(|w| w[0].port.checked_add(1) == Some(w[1].port));
    match ports {
        [] => String::new(),
        [a, .., z] if ports.len() > 3 && contiguous => format!("{}..{}", a.name, z.name),
        [a, b, .., z] if ports.len() > 3 => format!("{}, {}, …, {}", a.name, b.name, z.name),
        _ => ports
            .iter()
            .map(|p| p.name.as_str())
            .collect::<Vec<_>>()
            .join(", "),
    }
}

/// The kind a bank's ports share, up to its first qualifier ("digital input, TTL" and "digital
/// input, opto-isolated" share "digital input"); none where they differ.
fn common_kind(ports: &[&IoPort]) -> Option<String> {
    let head = |p: &IoPort| {
        p.kind
            .split([',', '('])
            .next()
            .unwrap_or_default()
            .trim()
            .to_string()
    };
    let first = head(ports.first()?);
    (!first.is_empty() && ports.iter().all(|p| head(p) == first)).then_some(first)
}

/// The hint of a port: "IN7, digital input, opto-isolated, active low, pin 11".
pub fn describe(port: &IoPort) -> String {
    let mut parts = vec![port.name.clone(), kind(port)];
    if let Some(pin) = &port.pin {
        parts.push(format!("pin {pin}"));
    }
    parts.retain(|s| !s.is_empty());
    parts.join(", ")
}

/// The hint of a typed port whose bank is still to come: the ports with that number (only
/// outputs for `writes`), each with its bank.
pub fn describe_any_bank(profile: &Profile, port: u8, writes: bool) -> Option<String> {
    let found: Vec<&IoPort> = profile
        .io_ports
        .iter()
        .filter(|p| p.port == port && (p.is_output() || !writes))
        .collect();
    match found.as_slice() {
        [] => None,
        [one] => Some(format!("bank {}: {}", one.bank, describe(one))),
        many => Some(
            many.iter()
                .map(|p| format!("bank {}: {}", p.bank, p.name))
                .collect::<Vec<_>>()
                .join("; "),
        ),
    }
}

/// A GIO reply under the port's name (`IN7 = 1`, `AIN0 = 2048`, `TEMPERATURE = 31 degC`), where
/// the profile maps the port.
pub fn reading(profile: &Profile, bank: u8, port: u8, value: i32) -> Option<String> {
    let p = profile.io_port(bank, port)?;
    let unit = if p.unit.is_empty() {
        String::new()
    } else {
        format!(" {}", p.unit)
    };
    Some(format!("{} = {value}{unit}", p.name))
}

#[cfg(test)]
mod tests;
