//! The configuration sets of a simulated SMD4 — working, stored and factory — and where the
//! stored set lives between runs. SYS:LOAD copies stored → working, SYS:LOADFD factory → working,
//! STORE working → stored and writes it out at once (to its [`crate::sim::store::Store`]), so
//! killing the simulator loses nothing.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::dialect::smd4::protocol::{ArgValue, Smd4CommandTable};

/// One setting's value.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Setting {
    /// INT, UINT, BOOL and ENUM settings.
    Int(i64),
    /// FLOAT settings.
    Float(f64),
    /// STRING and DOTTED DECIMAL settings.
    Text(String),
}

impl Setting {
    /// From a checked argument.
    pub fn from_arg(value: &ArgValue) -> Setting {
        match value {
            ArgValue::Int(i) => Setting::Int(*i),
            ArgValue::Float(f) => Setting::Float(*f),
            ArgValue::Text(t) => Setting::Text(t.clone()),
            ArgValue::Dotted(ip) => Setting::Text(ip.to_string()),
        }
    }

    /// As a number (text that is not a number counts as 0).
    pub fn number(&self) -> f64 {
        match self {
            Setting::Int(i) => *i as f64,
            Setting::Float(f) => *f,
            Setting::Text(t) => t.parse().unwrap_or(0.0),
        }
    }

    /// As text (the stored text, or the integer).
    pub fn text(&self) -> String {
        match self {
            Setting::Int(i) => i.to_string(),
            Setting::Float(f) => f.to_string(),
            Setting::Text(t) => t.clone(),
        }
    }
}

/// One set of settings, by canonical mnemonic.
pub type Settings = BTreeMap<String, Setting>;

/// The factory defaults of every setting that has one (from `data/smd4.toml`).
pub fn factory(table: &Smd4CommandTable) -> Settings {
    table
        .iter()
        .filter(|c| c.readable && c.writable && c.arg.is_some())
        .filter_map(|c| {
            let arg = c.arg.as_ref()?;
            let value = arg.check(c.default.as_deref()?).ok()?;
            Some((c.mnemonic.clone(), Setting::from_arg(&value)))
        })
        .collect()
}

/// The settings STORE saves.
pub fn persistent(table: &Smd4CommandTable, working: &Settings) -> Settings {
    working
        .iter()
        .filter(|(name, _)| table.get(name).is_some_and(|c| c.persistent))
        .map(|(name, value)| (name.clone(), value.clone()))
        .collect()
}

#[derive(Debug, Serialize, Deserialize)]
struct StateFile {
    format: u32,
    stored: Settings,
}

/// The text of a state file.
pub fn to_text(stored: &Settings) -> String {
    let file = StateFile {
        format: 1,
        stored: stored.clone(),
    };
    let body = toml::to_string(&file).unwrap_or_default();
    format!("# Stored configuration of a simulated SMD4 (tmclsh). Written by STORE.\n{body}")
}

/// Reads a state file over `factory`: each valid stored setting replaces its default. `Err` says
/// what was wrong (the drive then reports a configuration error), with the usable rest.
pub fn from_text(
    table: &Smd4CommandTable,
    factory: &Settings,
    text: &str,
) -> Result<Settings, Settings> {
    let Ok(file) = toml::from_str::<StateFile>(text) else {
        return Err(factory.clone());
    };
    let mut settings = factory.clone();
    let mut intact = file.format == 1;
    for (name, value) in file.stored {
        let arg = table
            .get(&name)
            .filter(|c| c.persistent)
            .and_then(|c| c.arg.as_ref());
        match arg.map(|a| a.check(&value.text())) {
            Some(Ok(checked)) => {
                settings.insert(name.to_ascii_uppercase(), Setting::from_arg(&checked));
            }
            _ => intact = false,
        }
    }
    if intact { Ok(settings) } else { Err(settings) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::protocol::Smd4Spec;

    #[test]
    fn every_persistent_setting_has_a_valid_factory_default() {
        let table = &Smd4Spec::builtin().commands;
        let defaults = factory(table);
        for spec in table.iter().filter(|c| c.persistent) {
            assert!(
                defaults.contains_key(&spec.mnemonic),
                "{} has no default",
                spec.mnemonic
            );
        }
        assert_eq!(defaults["MOTOR:RES"], Setting::Int(256));
        assert_eq!(defaults["MOTOR:VMAX"], Setting::Float(1000.0));
        assert_eq!(defaults["SYS:MODE"], Setting::Int(1));
        assert_eq!(
            defaults["COMS:NET:IP"],
            Setting::Text("192.168.0.100".into())
        );
    }

    #[test]
    fn state_text_round_trips_and_flags_damage() {
        let table = &Smd4Spec::builtin().commands;
        let defaults = factory(table);
        let mut changed = defaults.clone();
        changed.insert("MOTOR:VMAX".into(), Setting::Float(2500.0));
        let text = to_text(&persistent(table, &changed));
        assert_eq!(from_text(table, &defaults, &text), Ok(changed.clone()));
        let damaged = text.replace("2500.0", "99999.0");
        assert_eq!(from_text(table, &defaults, &damaged), Err(defaults.clone()));
        assert_eq!(
            from_text(table, &defaults, "garbage ["),
            Err(defaults.clone())
        );
    }
}
