//! Parameter snapshots: every readable parameter of a module, keyed by name, in a TOML file people
//! can read, edit and keep under version control.
//!
//! ```toml
//! [module]
//! name = "TMCM-142"
//! address = 1
//! firmware = "142V1.00"
//! date = "2026-11-22T10:15:02Z"
//! tool = "tmclsh 0.1.0"
//!
//! [axis.0]
//! max_current = { number = 6, value = 128, unit = "", access = "RWE" }
//!
//! [global.2]
//! user_variable_0 = { number = 0, value = 0, unit = "", access = "RWE" }
//! ```
//!
//! `axis.N` holds motor N's axis parameters, `global.B` bank B's global parameters. A drive with
//! one motor and named settings (SMD4) has a `drive` section keyed by mnemonic, with real numbers,
//! text, the name of an enumerated value and the real value of a user/real pair:
//!
//! ```toml
//! [drive]
//! "SYS:MODE" = { value = 1, label = "Remote", unit = "", access = "RWE" }
//! "MOTOR:IR" = { value = 1.0103, unit = "A rms", access = "RWE" }
//! "MOTOR:AMAX" = { value = 150.0, real = 149.88, unit = "Hz/s", access = "RWE" }
//! ```
//!
//! A parameter the module refused to read has `error = "…"` instead of a value.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use serde::Deserialize;

use crate::session::SessionError;

use super::device::{ParamDevice, Scope};
use super::value::{ParamValue, Reading};
use crate::progress::Progress;

/// The first line of every snapshot file: how a file tmclsh wrote is recognised.
pub const HEADER: &str = "# tmclsh parameter snapshot";

/// A module's parameters at one moment.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// The module type ("TMCM-142").
    pub module: String,
    /// The bus address it was read from, where requests carried one.
    pub address: Option<u32>,
    /// The firmware version, where the module told it.
    pub firmware: Option<String>,
    /// When it was taken (RFC 3339).
    pub date: String,
    /// What took it ("tmclsh 0.1.0").
    pub tool: String,
    /// The parameters, in table order.
    pub entries: Vec<Entry>,
}

/// One parameter of a snapshot.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// Where it lives.
    pub scope: Scope,
    /// Its identifier.
    pub name: String,
    /// Its number, where the dialect numbers parameters.
    pub number: Option<u32>,
    /// The value, or why the module would not tell it.
    pub value: Result<ParamValue, Refusal>,
    /// The real value of a user/real pair (informative: the drive derives it).
    pub real: Option<f64>,
    /// The name of an enumerated value (informative).
    pub label: Option<String>,
    /// Its unit (informative).
    pub unit: String,
    /// Its access letters when it was saved (informative).
    pub access: String,
}

impl Snapshot {
    /// Reads every readable parameter of `device`. A parameter the module refuses is recorded with
    /// its error; a lost link or a timeout ends the capture.
    pub fn capture(device: &mut dyn ParamDevice) -> Result<Snapshot, SessionError> {
        let params: Vec<_> = device
            .params()
            .into_iter()
            .filter(|p| p.access.read)
            .collect();
        let firmware = device.firmware();
        let progress = Progress::steps(params.len(), 2, "reading");
        let mut entries = Vec::with_capacity(params.len());
        for param in &params {
            progress.step(&param.name);
            let (value, real, label) = match device.read(param) {
                Ok(Reading { value, real, label }) => (Ok(value), real, label),
                Err(e @ SessionError::Device { .. }) => (Err(Refusal(e.to_string())), None, None),
                Err(e) => return Err(e),
            };
            entries.push(Entry {
                scope: param.scope,
                name: param.name.clone(),
                number: param.number,
                value,
                real,
                label,
                unit: param.unit.clone(),
                access: param.access.letters(),
            });
        }
        Ok(Snapshot {
            module: device.module_name(),
            address: device.address(),
            firmware,
            date: humantime::format_rfc3339_seconds(std::time::SystemTime::now()).to_string(),
            tool: format!("tmclsh {}", env!("CARGO_PKG_VERSION")),
            entries,
        })
    }

    /// The entry for `name` in `scope`.
    pub fn get(&self, scope: Scope, name: &str) -> Option<&Entry> {
        self.entries
            .iter()
            .find(|e| e.scope == scope && e.name == name)
    }

    /// Entries the module would not read.
    pub fn unreadable(&self) -> impl Iterator<Item = &Entry> {
        self.entries.iter().filter(|e| e.value.is_err())
    }

    /// The file text.
    pub fn to_toml(&self) -> String {
        let mut out = String::new();
        out.push_str(HEADER);
        out.push_str(
            ": every readable parameter, keyed by name.\n\
             # `tmclsh snapshot diff FILE` compares it with a module, `tmclsh snapshot restore FILE`\n\
             # writes the settings back. Values may be edited; number, unit, access, label and real\n\
             # are notes.\n\n",
        );
        out.push_str("[module]\n");
        let _ = writeln!(out, "name = {}", quoted(&self.module));
        if let Some(address) = self.address {
            let _ = writeln!(out, "address = {address}");
        }
        if let Some(firmware) = &self.firmware {
            let _ = writeln!(out, "firmware = {}", quoted(firmware));
        }
        let _ = writeln!(out, "date = {}", quoted(&self.date));
        let _ = writeln!(out, "tool = {}", quoted(&self.tool));
        let mut section = None;
        for entry in &self.entries {
            if section != Some(entry.scope) {
                let _ = write!(out, "\n[{}]\n", entry.scope.section());
                section = Some(entry.scope);
            }
            let mut fields = Vec::new();
            if let Some(number) = entry.number {
                fields.push(format!("number = {number}"));
            }
            match &entry.value {
                Ok(v) => fields.push(format!("value = {}", v.to_toml())),
                Err(e) => fields.push(format!("error = {}", quoted(&e.0))),
            }
            if let Some(real) = entry.real {
                fields.push(format!("real = {}", ParamValue::Float(real).to_toml()));
            }
            if let Some(label) = &entry.label {
                fields.push(format!("label = {}", quoted(label)));
            }
            fields.push(format!("unit = {}", quoted(&entry.unit)));
            fields.push(format!("access = {}", quoted(&entry.access)));
            let _ = writeln!(out, "{} = {{ {} }}", key(&entry.name), fields.join(", "));
        }
        out
    }

    /// Parses a snapshot file's text; the error may quote the text, and can also be told
    /// without quoting it.
    pub fn parse(text: &str) -> Result<Snapshot, FileError> {
        let file: File = toml::from_str(text).map_err(|e| FileError {
            message: e.to_string(),
            at: e.span().map(|span| line_and_column(text, span.start)),
        })?;
        let plain = |message: String| FileError { message, at: None };
        let mut entries = Vec::new();
        for (kind, sections) in [("axis", &file.axis), ("global", &file.global)] {
            for (index, rows) in sections {
                let n: u8 = index.parse().map_err(|_| {
                    plain(format!(
                        "[{kind}.{index}]: '{index}' is not a number 0..255"
                    ))
                })?;
                let scope = match kind {
                    "axis" => Scope::Axis { motor: n },
                    _ => Scope::Global { bank: n },
                };
                for (name, row) in rows {
                    entries.push(row.entry(scope, name, text)?);
                }
            }
        }
        for (name, row) in &file.drive {
            entries.push(row.entry(Scope::Drive, name, text)?);
        }
        entries.sort_by(|a, b| (a.scope, a.number, &a.name).cmp(&(b.scope, b.number, &b.name)));
        Ok(Snapshot {
            module: file.module.name,
            address: file.module.address,
            firmware: file.module.firmware,
            date: file.module.date,
            tool: file.module.tool,
            entries,
        })
    }

    /// Reads a snapshot file; errors are usage errors naming the file.
    pub fn load(path: &Path) -> Result<Snapshot, SessionError> {
        let text = crate::file::read_text(path, crate::file::READ_LIMIT)
            .map_err(|e| SessionError::Usage(format!("cannot read snapshot {e}")))?;
        Snapshot::parse(&text).map_err(|e| {
            SessionError::Usage(format!(
                "{} is not a tmclsh snapshot: {}",
                path.display(),
                e.message.trim_end()
            ))
        })
    }

    /// Writes the snapshot to `path` (replacing it).
    pub fn save(&self, path: &Path) -> Result<(), SessionError> {
        crate::file::write(path, self.to_toml().as_bytes())
            .map_err(|e| SessionError::Usage(format!("cannot write snapshot {e}")))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    module: ModuleRow,
    #[serde(default)]
    axis: BTreeMap<String, BTreeMap<String, Row>>,
    #[serde(default)]
    global: BTreeMap<String, BTreeMap<String, Row>>,
    #[serde(default)]
    drive: BTreeMap<String, Row>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ModuleRow {
    name: String,
    address: Option<u32>,
    firmware: Option<String>,
    #[serde(default)]
    date: String,
    #[serde(default)]
    tool: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Row {
    number: Option<u32>,
    value: Option<toml::Spanned<toml::Value>>,
    error: Option<String>,
    real: Option<f64>,
    label: Option<String>,
    #[serde(default)]
    unit: String,
    #[serde(default)]
    access: String,
}

impl Row {
    fn entry(&self, scope: Scope, name: &str, text: &str) -> Result<Entry, FileError> {
        let section = scope.section();
        let value = match (&self.value, &self.error) {
            (Some(v), _) => Ok(ParamValue::from_toml(v.get_ref()).ok_or_else(|| FileError {
                message: format!(
                    "[{section}] {name}: the value {} is not a number or a string",
                    v.get_ref()
                ),
                at: Some(line_and_column(text, v.span().start)),
            })?),
            (None, Some(e)) => Err(Refusal(e.clone())),
            (None, None) => {
                return Err(FileError {
                    message: format!("[{section}] {name}: no value"),
                    at: None,
                });
            }
        };
        Ok(Entry {
            scope,
            name: name.to_string(),
            number: self.number,
            value,
            real: self.real,
            label: self.label.clone(),
            unit: self.unit.clone(),
            access: self.access.clone(),
        })
    }
}

/// Why the module would not tell a parameter's value, as a snapshot keeps it: the module's
/// refusal when captured, the `error` field when read back.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct Refusal(pub String);

/// Why a text is not a snapshot.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct FileError {
    /// What is wrong; it may quote the text.
    pub message: String,
    /// Where (line and column, from 1), when known.
    pub at: Option<(usize, usize)>,
}

impl FileError {
    /// Where the problem is, quoting nothing of the text (for scripts, which may be pointed at
    /// files that are not theirs).
    pub fn redacted(&self) -> String {
        match self.at {
            Some((line, column)) => format!("the first problem is at line {line}, column {column}"),
            None => "its sections or entries are not a snapshot's".to_string(),
        }
    }
}

/// Line and column (from 1) of byte `offset` in `text`.
fn line_and_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text.as_bytes()[..offset.min(text.len())];
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    let start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |i| i + 1);
    let column = String::from_utf8_lossy(&before[start..]).chars().count() + 1;
    (line, column)
}

fn quoted(text: &str) -> String {
    toml::Value::String(text.to_string()).to_string()
}

/// A bare key when the name allows one, else a quoted key.
fn key(name: &str) -> String {
    let bare = !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    if bare { name.to_string() } else { quoted(name) }
}

#[cfg(test)]
mod tests;
