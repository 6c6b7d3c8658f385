//! Hints while typing: the usage of the command, or — once a parameter is named — its number,
//! unit, range, access and one-line description.

use crate::dialect::tmcl::profile::commands::{Field, OperandKind};
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
    fn nothing_for_unknown_things() {
        assert_eq!(h("GAP 250, 0"), None);
        assert_eq!(h("XYZ 1"), None);
        assert_eq!(h(":help"), None);
        assert_eq!(h("ROR 0, 100"), None);
    }
}
