//! `tmclsh params [FILTER]`: the profile's parameters as a table, or (`--protocol smd4`) the
//! SMD4 commands with their access and arguments.

use std::io::{self, Write};

use crate::exit::Exit;
use crate::profile::{Param, ParamKind, Profile};
use crate::protocol::Dialect;
use crate::protocol::smd4::{Smd4Spec, hints};

use super::connection::DialectArgs;

/// Arguments of `params`.
#[derive(Debug, clap::Args)]
pub struct ParamsArgs {
    /// Show parameters whose identifier or name contains FILTER, or whose number is FILTER
    /// (SMD4: commands whose mnemonic contains FILTER).
    pub filter: Option<String>,
    /// Whose tables to print.
    #[command(flatten)]
    pub dialect: DialectArgs,
}

/// Prints the table; a filter that matches nothing says so on stderr and exits 1 (as `grep`
/// does), so a script can test whether a parameter exists.
pub fn run(args: &ParamsArgs, profile: &Profile, out: &mut dyn Write) -> io::Result<Exit> {
    let filter = args.filter.as_deref().unwrap_or("");
    if args.dialect.protocol == Dialect::Smd4 {
        return write_smd4(filter, out);
    }
    let rows: Vec<&Param> = profile.matching(filter).collect();
    if rows.is_empty() {
        eprintln!("no {} parameter matches '{filter}'", profile.module);
        return Ok(Exit::DeviceError);
    }
    write_table(&rows, out)?;
    Ok(Exit::Success)
}

/// The SMD4 commands matching `filter`, one row each, as the shell's `:params` shows them.
fn write_smd4(filter: &str, out: &mut dyn Write) -> io::Result<Exit> {
    let mut rows = hints::matching(&Smd4Spec::builtin().commands, filter).peekable();
    if rows.peek().is_none() {
        eprintln!("no SMD4 command matches '{filter}'");
        return Ok(Exit::DeviceError);
    }
    for spec in rows {
        writeln!(out, "{}", hints::table_row(spec))?;
    }
    Ok(Exit::Success)
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
        writeln!(
            out,
            "{:<8} {:>3}  {:<ident_width$}  {:<3}  {:<range_width$}  {}",
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
