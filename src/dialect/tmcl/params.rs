//! The parameter table of a TMCL module: `tmclsh params FILTER` and the shell's `:params`.

use std::io::{self, Write};

use super::profile::{Param, ParamKind, Profile};

/// The parameters of `profile` matching `filter`, as a table; when none matches, says so on
/// stderr and returns false.
pub fn write_params(profile: &Profile, filter: &str, out: &mut dyn Write) -> io::Result<bool> {
    let rows: Vec<&Param> = profile.matching(filter).collect();
    if profile.generic {
        eprintln!(
            "the {} profile knows parameters by number only (0..255): it has none to list",
            profile.module
        );
        return Ok(false);
    }
    if rows.is_empty() {
        eprintln!("no {} parameter matches '{filter}'", profile.module);
        return Ok(false);
    }
    write_table(&rows, out)?;
    Ok(true)
}

/// Prints parameters as an aligned table (shared with the REPL's `:params`).
pub fn write_table(rows: &[&Param], out: &mut dyn Write) -> io::Result<()> {
    let kind = |p: &Param| match p.kind {
        ParamKind::Axis => "axis".to_string(),
        ParamKind::Global { bank } => format!("global/{bank}"),
    };
    let ident_width = rows.iter().map(|p| p.ident.len()).max().unwrap_or(0);
    let range_width = rows
        .iter()
        .map(|p| p.range_text().len())
        .max()
        .unwrap_or(0)
        .max(5);
    writeln!(
        out,
        "{:<8} {:>3}  {:<ident_width$}  {:<3}  {:<range_width$}  unit",
        "kind", "no", "name", "acc", "range"
    )?;
    for p in rows {
        // A range that applies while another parameter has a value follows the unit.
        let when: String = p
            .range_when
            .iter()
            .map(|r| format!(" ({})", r.describe()))
            .collect();
        writeln!(
            out,
            "{:<8} {:>3}  {:<ident_width$}  {:<3}  {:<range_width$}  {}{when}",
            kind(p),
            p.number,
            p.ident,
            p.access.letters(),
            p.range_text(),
            p.unit
        )?;
    }
    Ok(())
}
