//! Hints while typing: the usage of the command, or — once a parameter is named — its number,
//! unit, range, access and one-line description; once an I/O port is named, its name, kind and
//! pin from the profile's port map.

use crate::dialect::tmcl::ports;
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::profile::{Param, Profile};

use super::complete::spec_of;

/// The hint for `line` with the cursor at its end.
pub fn hint(line: &str, profile: &Profile) -> Option<String> {
    let trimmed = line.trim_start();
    if trimmed.is_empty() || trimmed.starts_with(':') {
        return None;
    }
    let tokens: Vec<&str> = trimmed
        .split([' ', ',', '\t'])
        .filter(|t| !t.is_empty())
        .collect();
    let (command, args) = match tokens.as_slice() {
        [addr, cmd, rest @ ..]
            if addr.len() == 1
                && spec_of(cmd, profile).is_some()
                && profile.commands.by_mnemonic(addr).is_none() =>
        {
            (*cmd, rest)
        }
        [cmd, rest @ ..] => (*cmd, rest),
        [] => return None,
    };
    let spec = spec_of(command, profile)?;
    let Some(first) = args.first() else {
        return line.ends_with(' ').then(|| format!("  {}", spec.usage()));
    };
    if spec.field_is(Field::Type, OperandKind::Port) {
        return port(spec, args, profile).map(|text| format!("  ← {text}"));
    }
    let param = match spec.operand_for(Field::Type).map(|o| o.kind) {
        Some(OperandKind::AxisParam) => lookup(
            first,
            |n| profile.axis_param(n),
            |s| profile.find_axis(s).ok(),
        ),
        Some(OperandKind::GlobalParam) => {
            let bank = args.get(1).and_then(|b| b.parse().ok()).unwrap_or(0);
            lookup(
                first,
                |n| profile.global_param(bank, n),
                |s| profile.find_global(s).ok(),
            )
        }
        _ => None,
    }?;
    Some(format!("  ← {}", describe(param)))
}

/// The port a GIO/SIO line names, from the profile's port map: the port of the typed bank, or
/// before the bank every port of that number. Nothing for a port the map lacks: such a line is
/// invalid, and its hint is why.
fn port(spec: &CommandSpec, args: &[&str], profile: &Profile) -> Option<String> {
    let typed = |kind| {
        let at = spec.operands.iter().position(|o| o.kind == kind)?;
        args.get(at)?.parse::<u8>().ok()
    };
    let port = typed(OperandKind::Port)?;
    let writes = spec.operand_for(Field::Value).is_some();
    match typed(OperandKind::IoBank) {
        Some(bank) => profile.io_port(bank, port).map(ports::describe),
        None => ports::describe_any_bank(profile, port, writes),
    }
}

fn lookup<'a>(
    word: &str,
    by_number: impl Fn(u8) -> Option<&'a Param>,
    by_name: impl Fn(&str) -> Option<&'a Param>,
) -> Option<&'a Param> {
    match word.parse::<u8>() {
        Ok(n) => by_number(n),
        Err(_) => by_name(word),
    }
}

/// `#6 max_current [0..15, RWE] 1/15 of full scale — Coil current while the motor moves.`
pub fn describe(p: &Param) -> String {
    let mut text = format!("#{} {}", p.number, p.ident);
    let range = p.range_text();
    let facts: Vec<String> = [range, p.access.letters()]
        .into_iter()
        .filter(|s| !s.is_empty())
        .collect();
    if !facts.is_empty() {
        text.push_str(&format!(" [{}]", facts.join(", ")));
    }
    if !p.unit.is_empty() {
        text.push_str(&format!(" {}", p.unit));
    }
    let description: String = p.description.chars().take(70).collect();
    if !description.is_empty() {
        text.push_str(" — ");
        text.push_str(&description);
        if p.description.chars().count() > 70 {
            text.push('…');
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    fn h(line: &str) -> Option<String> {
        hint(line, &Profile::builtin())
    }

    #[test]
    fn usage_after_the_command_word() {
        assert_eq!(h("GAP ").as_deref(), Some("  GAP <parameter>, <motor>"));
        assert_eq!(
            h("A MVP ").as_deref(),
            Some("  MVP ABS|REL|COORD, <motor>, <value>")
        );
        assert_eq!(h("GAP"), None);
    }

    #[test]
    fn parameter_facts_once_named() {
        let text = h("SAP max_current, 0, ").unwrap();
        assert!(
            text.starts_with("  ← #6 max_current [0..15, RWE] 1/15 of full scale"),
            "{text}"
        );
        assert!(
            text.contains("Coil current while the motor moves."),
            "{text}"
        );
        assert!(
            h("GAP 4")
                .unwrap()
                .contains("max_positioning_speed [0..2147483647, RWE] usteps/t")
        );
        assert!(h("AGAP actual_po").unwrap().contains("#1 actual_position"));
        assert!(h("GGP 76, 0").unwrap().contains("#76 serial_host_address"));
        assert!(h("GGP 5, 2").unwrap().contains("user_variable_5"));
    }

    #[test]
    fn a_port_is_described_from_the_port_map() {
        assert_eq!(
            h("GIO 7,0").as_deref(),
            Some("  ← IN7, digital input, opto-isolated, active low (needs +5V on pin 15), pin 11")
        );
        assert_eq!(
            h("A SIO 1, 2, ").as_deref(),
            Some("  ← OUT_1, user output, pin 9")
        );
        assert_eq!(
            h("GIO 0").as_deref(),
            Some("  ← bank 1: IN0_A/D; bank 2: OUT_0")
        );
        // SIO sets outputs: before the bank, only the output of that number.
        assert_eq!(
            h("SIO 0, ").as_deref(),
            Some("  ← bank 2: OUT_0, user output, pin 17")
        );
        let other = crate::dialect::tmcl::profile::catalogue::by_name("tmcm-1141").unwrap();
        assert_eq!(
            hint("GIO 0, 1", &other).as_deref(),
            Some("  ← ADC0, analog input, 0..4095")
        );
        // A port the map lacks has no description (the line is invalid; its hint is why).
        assert_eq!(h("GIO 0, 0"), None);
        assert_eq!(h("GIO 9"), None);
        // Without a map, nothing is known of any port.
        let generic = crate::dialect::tmcl::profile::catalogue::generic();
        assert_eq!(hint("GIO 0, 0", &generic), None);
    }

    #[test]
    fn nothing_for_unknown_things() {
        assert_eq!(h("GAP 250, 0"), None);
        assert_eq!(h("XYZ 1"), None);
        assert_eq!(h(":help"), None);
        assert_eq!(h("ROR 0, 100"), None);
    }
}
