//! The command table of the SMD4: `tmclsh --protocol smd4 params FILTER` and the shell's
//! `:params`.

use std::io::{self, Write};

use super::protocol::{Smd4Command, Smd4Spec, hints};
use crate::dialect::DialectError;
use crate::json::{Value, json};

/// The SMD4 commands matching `filter`, one row each, as the shell's `:params` shows them; when
/// none matches, says so on stderr and returns false.
pub fn write_params(filter: &str, out: &mut dyn Write) -> io::Result<bool> {
    let mut rows = hints::matching(&Smd4Spec::builtin().commands, filter).peekable();
    if rows.peek().is_none() {
        eprintln!("no SMD4 command matches '{filter}'");
        return Ok(false);
    }
    for spec in rows {
        write_row(spec, out)?;
    }
    Ok(true)
}

/// One row of the command table fitted to the terminal: what the argument accepts continues
/// under itself.
pub(super) fn write_row(spec: &Smd4Command, out: &mut dyn Write) -> io::Result<()> {
    crate::wrap::write_fitted(out, &hints::table_row(spec), 29)
}

/// The SMD4 commands matching `filter` as JSON objects (`params --json`); the error says that
/// none matches.
pub fn params_json(filter: &str) -> Result<Vec<Value>, DialectError> {
    let rows: Vec<Value> = hints::matching(&Smd4Spec::builtin().commands, filter)
        .map(|spec| {
            json!({
                "mnemonic": spec.mnemonic,
                "group": spec.group,
                "readable": spec.readable,
                "writable": spec.writable,
                "argument": spec.arg.is_some().then(|| hints::arg_summary(spec)),
                "unit": spec.unit,
                "default": spec.default,
                "uncertain": spec.uncertain,
                "description": spec.description,
            })
        })
        .collect();
    if rows.is_empty() {
        return Err(DialectError::NoParams(format!(
            "no SMD4 command matches '{filter}'"
        )));
    }
    Ok(rows)
}
