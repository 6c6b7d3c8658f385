//! The parameter table of a TMCL module: `tmclsh params FILTER` and the shell's `:params`.

use std::io::{self, Write};

use super::profile::{Param, ParamKind, Profile};
use crate::dialect::{DialectError, UNCERTAIN};
use crate::json::{Value, json};
use crate::wrap::{fit, terminal_width};

/// The parameters of `profile` matching `filter`, as a table; when none matches, says so on
/// stderr and returns false.
pub fn write_params(profile: &Profile, filter: &str, out: &mut dyn Write) -> io::Result<bool> {
    match matching(profile, filter) {
        Ok(rows) => write_table(&rows, out).map(|()| true),
        Err(message) => {
            eprintln!("{message}");
            Ok(false)
        }
    }
}

/// The parameters of `profile` matching `filter`; the error says why there are none.
fn matching<'a>(profile: &'a Profile, filter: &str) -> Result<Vec<&'a Param>, DialectError> {
    if profile.generic {
        return Err(DialectError::NoParams(format!(
            "the {} profile knows parameters by number only (0..255): it has none to list",
            profile.module
        )));
    }
    let rows: Vec<&Param> = profile.matching(filter).collect();
    if rows.is_empty() {
        return Err(DialectError::NoParams(format!(
            "no {} parameter matches '{filter}'",
            profile.module
        )));
    }
    Ok(rows)
}

/// The parameters of `profile` matching `filter` as JSON objects (`params --json`).
pub fn params_json(profile: &Profile, filter: &str) -> Result<Vec<Value>, DialectError> {
    Ok(matching(profile, filter)?
        .into_iter()
        .map(|p| {
            let (kind, bank) = match p.kind {
                ParamKind::Axis => ("axis", Value::Null),
                ParamKind::Global { bank } => ("global", json!(bank)),
            };
            json!({
                "kind": kind,
                "bank": bank,
                "number": p.number,
                "name": p.ident,
                "manual_name": p.name,
                "access": p.access.letters(),
                "range": p.range.map(|(min, max)| json!([min, max])),
                "unit": p.unit,
                "uncertain": p.uncertain,
                "description": p.description,
            })
        })
        .collect())
}

/// Prints parameters as an aligned table (shared with the REPL's `:params`).
pub fn write_table(rows: &[&Param], out: &mut dyn Write) -> io::Result<()> {
    let kind = |p: &Param| match p.kind {
        ParamKind::Axis => "axis".to_string(),
        ParamKind::Global { bank } => format!("global/{bank}"),
    };
    let width = terminal_width();
    let ident_width = rows.iter().map(|p| p.ident.len()).max().unwrap_or(0);
    let range_width = rows
        .iter()
        .map(|p| p.range_text().len())
        .max()
        .unwrap_or(0)
        .max(5);
    let header = format!(
        "{:<8} {:>3}  {:<ident_width$}  {:<3} {:mark$}  {:<range_width$}  unit",
        "kind",
        "no",
        "name",
        "acc",
        "",
        "range",
        mark = UNCERTAIN.len()
    );
    let unit_at = header.len() - "unit".len();
    writeln!(out, "{}", fit(&header, unit_at, width))?;
    for p in rows {
        // A range that applies while another parameter has a value follows the unit.
        let when: String = p
            .range_when
            .iter()
            .map(|r| format!(" ({})", r.describe()))
            .collect();
        let head = format!(
            "{:<8} {:>3}  {:<ident_width$}  {:<3} {}  {:<range_width$}  ",
            kind(p),
            p.number,
            p.ident,
            p.access.letters(),
            uncertain_mark(p),
            p.range_text(),
        );
        let row = format!("{head}{}{when}", p.unit);
        writeln!(out, "{}", fit(row.trim_end(), head.chars().count(), width))?;
    }
    Ok(())
}

/// The uncertain mark of a row, or as many spaces.
pub fn uncertain_mark(p: &Param) -> String {
    if p.uncertain {
        UNCERTAIN.to_string()
    } else {
        " ".repeat(UNCERTAIN.len())
    }
}
