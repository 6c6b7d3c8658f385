//! What differs between a snapshot and a module, or between two snapshots: the settings (not the
//! live values, which differ from one moment to the next), by name, with units.

use std::io::{self, Write};

use crate::commission::SnapshotRole;
use crate::json::{Value, json};
use crate::session::SessionError;

use super::device::{ParamDevice, ParamRef, Scope};
use super::snapshot::{Entry, Snapshot};
use super::value::{ParamValue, Reading, Tolerance};
use crate::progress::Progress;

/// One parameter that differs.
#[derive(Debug, Clone, PartialEq)]
pub struct Difference {
    /// Where it lives.
    pub scope: Scope,
    /// Its identifier.
    pub name: String,
    /// "axis 6", "global 0/65" (empty when unknown).
    pub place: String,
    /// Its unit.
    pub unit: String,
    /// The left side's value (the file), or what is missing instead.
    pub left: Side,
    /// The right side's value (the module or the second file).
    pub right: Side,
}

/// One side of a difference.
#[derive(Debug, Clone, PartialEq)]
pub enum Side {
    /// A value (with the name of an enumerated value, where known).
    Value(Reading),
    /// The parameter is not there.
    Missing,
    /// It could not be read (the module's answer).
    Unreadable(String),
}

impl Side {
    fn of(entry: Option<&Entry>) -> Side {
        match entry {
            Some(Entry {
                value: Ok(value),
                label,
                real,
                ..
            }) => Side::Value(Reading {
                value: value.clone(),
                real: *real,
                label: label.clone(),
            }),
            Some(Entry { value: Err(e), .. }) => Side::Unreadable(e.0.clone()),
            None => Side::Missing,
        }
    }

    /// The value, where there is one.
    pub fn value(&self) -> Option<&ParamValue> {
        match self {
            Side::Value(reading) => Some(&reading.value),
            _ => None,
        }
    }

    /// Whether two sides hold the same value of a parameter compared with `tolerance`.
    fn same(&self, other: &Side, tolerance: Tolerance) -> bool {
        match (self, other) {
            (Side::Value(a), Side::Value(b)) => tolerance.same(&a.value, &b.value),
            (Side::Missing, Side::Missing) => true,
            (Side::Unreadable(a), Side::Unreadable(b)) => a == b,
            _ => false,
        }
    }

    /// The side as JSON: `{"state": "value", "value": 5, "label": null, "real": null}`, or
    /// `{"state": "absent"}`, or `{"state": "unreadable", "error": "…"}`.
    fn json(&self) -> Value {
        match self {
            Side::Value(reading) => json!({
                "state": "value",
                "value": match &reading.value {
                    ParamValue::Int(i) => json!(i),
                    ParamValue::Float(f) => json!(f),
                    ParamValue::Text(t) => json!(t),
                },
                "label": reading.label,
                "real": reading.real,
            }),
            Side::Missing => json!({ "state": "absent" }),
            Side::Unreadable(error) => json!({ "state": "unreadable", "error": error }),
        }
    }

    fn text(&self) -> String {
        match self {
            Side::Value(reading) => reading.text(),
            Side::Missing => "(absent)".into(),
            Side::Unreadable(_) => "(unreadable)".into(),
        }
    }
}

/// The result of a comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// How many settings were compared.
    pub compared: usize,
    /// Those that differ, in table order.
    pub differences: Vec<Difference>,
}

/// Whether a parameter takes part in comparisons: settings do, live and read-only values do not.
pub fn compared(role: SnapshotRole) -> bool {
    matches!(role, SnapshotRole::Setting | SnapshotRole::Manual)
}

/// Compares `file` with the module behind `device`, reading only the settings.
pub fn with_device(
    file: &Snapshot,
    device: &mut dyn ParamDevice,
) -> Result<Comparison, SessionError> {
    let params: Vec<ParamRef> = device
        .params()
        .into_iter()
        .filter(|p| p.access.read && compared(p.role))
        .collect();
    let progress = Progress::steps(params.len(), 2, "comparing");
    let mut differences = Vec::new();
    for param in &params {
        progress.step(&param.name);
        let module = match device.read(param) {
            Ok(reading) => Side::Value(reading),
            Err(e @ SessionError::Device { .. }) => Side::Unreadable(e.to_string()),
            Err(e) => return Err(e),
        };
        let left = Side::of(file.get(param.scope, &param.name));
        if !left.same(&module, param.tolerance) {
            differences.push(difference(param, left, module));
        }
    }
    let known = |e: &Entry| {
        params
            .iter()
            .any(|p| p.scope == e.scope && p.name == e.name)
    };
    let all = device.params();
    for entry in &file.entries {
        let on_module = all
            .iter()
            .any(|p| p.scope == entry.scope && p.name == entry.name);
        if !known(entry) && !on_module {
            differences.push(Difference {
                scope: entry.scope,
                name: entry.name.clone(),
                place: String::new(),
                unit: entry.unit.clone(),
                left: Side::of(Some(entry)),
                right: Side::Missing,
            });
        }
    }
    Ok(Comparison {
        compared: params.len(),
        differences,
    })
}

/// Compares two snapshot files; `params` (the profile's view) says which entries are settings.
/// Entries the profile does not know are compared too.
pub fn between(left: &Snapshot, right: &Snapshot, params: &[ParamRef]) -> Comparison {
    let is_setting = |scope: Scope, name: &str| {
        params
            .iter()
            .find(|p| p.scope == scope && p.name == name)
            .is_none_or(|p| compared(p.role))
    };
    let mut keys: Vec<(Scope, Option<u32>, String)> = Vec::new();
    for e in left.entries.iter().chain(&right.entries) {
        let key = (e.scope, e.number, e.name.clone());
        if is_setting(e.scope, &e.name) && !keys.iter().any(|k| k.0 == key.0 && k.2 == key.2) {
            keys.push(key);
        }
    }
    keys.sort();
    let mut differences = Vec::new();
    for (scope, _, name) in &keys {
        let (a, b) = (left.get(*scope, name), right.get(*scope, name));
        let (l, r) = (Side::of(a), Side::of(b));
        let param = params.iter().find(|p| p.scope == *scope && p.name == *name);
        let tolerance = param.map_or(Tolerance::Exact, |p| p.tolerance);
        if !l.same(&r, tolerance) {
            differences.push(Difference {
                scope: *scope,
                name: name.clone(),
                place: param.map(ParamRef::place).unwrap_or_default(),
                unit: a.or(b).map(|e| e.unit.clone()).unwrap_or_default(),
                left: l,
                right: r,
            });
        }
    }
    Comparison {
        compared: keys.len(),
        differences,
    }
}

fn difference(param: &ParamRef, left: Side, right: Side) -> Difference {
    Difference {
        scope: param.scope,
        name: param.name.clone(),
        place: param.place(),
        unit: param.unit.clone(),
        left,
        right,
    }
}

/// "no differences in 57 settings" or "2 of 57 settings differ".
pub fn summary(comparison: &Comparison) -> String {
    match comparison.differences.len() {
        0 => format!(
            "no differences in {}",
            crate::count::counted(comparison.compared, "setting")
        ),
        1 => format!(
            "1 of {} differs",
            crate::count::counted(comparison.compared, "setting")
        ),
        n => format!(
            "{n} of {} differ",
            crate::count::counted(comparison.compared, "setting")
        ),
    }
}

/// The comparison as one JSON document; `labels` name the two sides.
pub fn json(comparison: &Comparison, labels: [&str; 2]) -> Value {
    let differences: Vec<Value> = comparison
        .differences
        .iter()
        .map(|d| {
            json!({
                "name": d.name,
                "section": d.scope.section(),
                "place": d.place,
                "unit": d.unit,
                "left": d.left.json(),
                "right": d.right.json(),
            })
        })
        .collect();
    json!({
        "left": labels[0],
        "right": labels[1],
        "compared": comparison.compared,
        "differ": comparison.differences.len(),
        "summary": summary(comparison),
        "differences": differences,
    })
}

/// Prints the differences as a table (nothing when there are none); `labels` name the two sides.
pub fn write_table(
    comparison: &Comparison,
    labels: [&str; 2],
    out: &mut dyn Write,
) -> io::Result<()> {
    if comparison.differences.is_empty() {
        return Ok(());
    }
    let header = [
        "parameter".to_string(),
        "where".to_string(),
        labels[0].to_string(),
        labels[1].to_string(),
        "unit".to_string(),
    ];
    let rows: Vec<[String; 5]> = comparison
        .differences
        .iter()
        .map(|d| {
            [
                d.name.clone(),
                d.place.clone(),
                d.left.text(),
                d.right.text(),
                d.unit.clone(),
            ]
        })
        .collect();
    let mut widths = [0usize; 5];
    for row in std::iter::once(&header).chain(&rows) {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    // A drive's settings have no place in a numbered table: no "where" column then.
    let placed = rows.iter().any(|r| !r[1].is_empty());
    for row in std::iter::once(&header).chain(&rows) {
        let place = if placed {
            format!("{:<w$}  ", row[1], w = widths[1])
        } else {
            String::new()
        };
        let line = format!(
            "{:<w0$}  {place}{:>w2$}  {:>w3$}  {}",
            row[0],
            row[2],
            row[3],
            row[4],
            w0 = widths[0],
            w2 = widths[2],
            w3 = widths[3],
        );
        writeln!(out, "{}", line.trim_end())?;
    }
    Ok(())
}
