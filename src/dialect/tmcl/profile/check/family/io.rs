//! The checks of the I/O map: `[[io_port]]` rows, and the `[simulation]` port lists that repeat
//! them.

use std::collections::{BTreeSet, HashMap};

use super::super::{Problem, Step, check_range};
use crate::dialect::tmcl::profile::load::{IoPortRow, ProfileFile};

/// Where each addressed port (bank, port) was first defined.
type Ports = HashMap<(u8, u8), Vec<Step>>;

/// `[[io_port]]` rows, and the `[simulation]` port lists that repeat them.
pub(super) fn check_io(file: &ProfileFile, problems: &mut Vec<Problem>) {
    let mut seen = Ports::new();
    let adc_max = file.simulation.as_ref().and_then(|s| s.adc_max);
    for (i, row) in file.io_port.iter().enumerate() {
        let at = |key| vec![Step::Key("io_port"), Step::Row(i), Step::Key(key)];
        let Some((bank, port)) = port_address(row, at, problems) else {
            continue;
        };
        check_port_texts(row, bank, port, at, problems);
        check_range(row.range, at("range"), "range", problems);
        check_analog_range(row, bank, adc_max, at, problems);
        match seen.get(&(bank, port)) {
            Some(first) => problems.push(
                Problem::at(
                    at("port"),
                    format!("I/O port {port} of bank {bank} is defined twice"),
                )
                .also(first.clone()),
            ),
            None => {
                seen.insert((bank, port), at("port"));
            }
        }
    }
    check_simulated_ports(file, &seen, problems);
}

/// The bank and port a row addresses; none for a signal only documented, or a half address
/// (refused).
fn port_address(
    row: &IoPortRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) -> Option<(u8, u8)> {
    match (row.bank, row.port) {
        (Some(bank), Some(port)) => Some((bank, port)),
        (None, None) => None, // a signal documented, not addressed by GIO/SIO
        (Some(_), None) => {
            problems.push(Problem::at(
                at("bank"),
                "an I/O port with a bank needs its port",
            ));
            None
        }
        (None, Some(_)) => {
            problems.push(Problem::at(
                at("port"),
                "an I/O port with a port needs its bank",
            ));
            None
        }
    }
}

/// A port has a name, and none of its texts carries a control character.
fn check_port_texts(
    row: &IoPortRow,
    bank: u8,
    port: u8,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    let named = row.name.as_deref().or(row.signal.as_deref()).unwrap_or("");
    if named.trim().is_empty() || named.chars().any(char::is_control) {
        problems.push(Problem::at(
            at("name"),
            format!("I/O port {port} of bank {bank} needs a name"),
        ));
    }
    // Help, hints and replies print these: a control character would be obeyed.
    let pin = row.pin.as_ref().map(|p| p.text()).unwrap_or_default();
    for (key, text) in [
        ("kind", row.kind.as_str()),
        ("unit", &row.unit),
        ("pin", &pin),
    ] {
        if text.chars().any(char::is_control) {
            problems.push(Problem::at(
                at(key),
                format!("the {key} of I/O port {port} of bank {bank} has a control character"),
            ));
        }
    }
}

/// An analog port (bank 1) reads no more than the simulated ADC's `adc_max`.
fn check_analog_range(
    row: &IoPortRow,
    bank: u8,
    adc_max: Option<i32>,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    if let (Some([_, hi]), Some(max), 1) = (row.range, adc_max, bank) {
        if hi > i64::from(max) {
            problems.push(Problem::at(
                at("range"),
                format!("analog port range up to {hi} is above the ADC's adc_max {max}"),
            ));
        }
    }
}

/// The simulator's port lists are the ports of the I/O map, bank by bank.
fn check_simulated_ports(file: &ProfileFile, seen: &Ports, problems: &mut Vec<Problem>) {
    let Some(sim) = &file.simulation else { return };
    if seen.is_empty() {
        return; // no I/O map: the simulator's lists stand alone
    }
    for (bank, key, listed) in [
        (0u8, "digital_inputs", &sim.digital_inputs),
        (1, "analog_inputs", &sim.analog_inputs),
        (2, "outputs", &sim.outputs),
    ] {
        let mapped: BTreeSet<u8> = seen
            .keys()
            .filter(|(b, _)| *b == bank)
            .map(|(_, p)| *p)
            .collect();
        let simulated: BTreeSet<u8> = listed.iter().copied().collect();
        if mapped != simulated {
            problems.push(Problem::at(
                vec![Step::Key("simulation"), Step::Key(key)],
                format!(
                    "{key} {:?} are not the ports of bank {bank} in [[io_port]] {:?}",
                    simulated.iter().collect::<Vec<_>>(),
                    mapped.iter().collect::<Vec<_>>()
                ),
            ));
        }
    }
}
