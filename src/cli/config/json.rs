//! `tmclsh config --json`: the files read and every setting with its value and where it came
//! from, as one JSON document (fields in docs/machine-output.md).

use std::io::{self, Write};

use crate::json::{Value, json};

use super::{ConfigArgs, Defaults};

/// Writes the document.
pub(super) fn write(args: &ConfigArgs, defaults: &Defaults, out: &mut dyn Write) -> io::Result<()> {
    let path = |p: &std::path::PathBuf| p.display().to_string();
    let ignored = defaults
        .ignored
        .as_ref()
        .map(|(p, why)| json!({ "path": path(p), "why": why }));
    let user = defaults.user.as_ref().filter(|p| p.is_file()).map(path);
    let settings: Vec<Value> = args
        .report
        .iter()
        .map(|line| {
            json!({
                "key": line.key.name,
                "value": line.value.as_deref().map(value),
                "origin": line.value.as_ref().map(|_| line.origin.clone()),
                "unused": line.unused,
                "unset": line.value.is_none().then_some(line.key.unset),
            })
        })
        .collect();
    let document = json!({
        "project_file": defaults.project.as_ref().map(path),
        "project_file_ignored": ignored,
        "user_file": user,
        "settings": settings,
    });
    crate::json::write(&document, out)
}

/// A value as `tmclsh config` shows it in TOML, as the JSON value it is (a number, a string, a
/// boolean); text that is not a TOML value stays the text.
fn value(toml_text: &str) -> Value {
    toml::from_str::<toml::Table>(&format!("v = {toml_text}"))
        .ok()
        .and_then(|mut table| table.remove("v"))
        .and_then(|v| serde_json::to_value(v).ok())
        .unwrap_or_else(|| json!(toml_text))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toml_values_become_json_values() {
        assert_eq!(value("\"/dev/ttyUSB0\""), json!("/dev/ttyUSB0"));
        assert_eq!(value("9600"), json!(9600));
        assert_eq!(value("true"), json!(true));
        assert_eq!(value("not toml"), json!("not toml"));
    }
}
