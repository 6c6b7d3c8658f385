//! Snapshot save, diff and restore as the faces run them (CLI, REPL helper, Rhai): the work, the
//! report on a sink, and the verdict as an error that carries its exit code.

use std::io::Write;
use std::path::Path;

use crate::exit::Exit;
use crate::session::SessionError;

use super::device::{ParamDevice, ParamRef};
use super::diff::{self, Comparison};
use super::restore::{self, Outcome, Plan};
use super::snapshot::Snapshot;

/// A failure that is not the module's status nor the link's: differences, failed verifications.
pub fn failed(message: impl Into<String>) -> SessionError {
    SessionError::Script {
        exit: Exit::DeviceError,
        message: message.into(),
    }
}

/// Reads the module and writes the snapshot to `path`; fails (exit 1) after saving when some
/// parameters could not be read.
pub fn save(
    device: &mut dyn ParamDevice,
    path: &Path,
    out: &mut dyn Write,
) -> Result<Snapshot, SessionError> {
    let snapshot = Snapshot::capture(device)?;
    snapshot.save(path)?;
    let firmware = snapshot
        .firmware
        .as_deref()
        .map(|f| format!(", firmware {f}"))
        .unwrap_or_default();
    let address = snapshot
        .address
        .map(|a| format!(" at address {a}"))
        .unwrap_or_default();
    writeln!(
        out,
        "saved {} parameters of the {}{address}{firmware} to {}",
        snapshot.entries.len(),
        snapshot.module,
        path.display()
    )?;
    let unreadable: Vec<&str> = snapshot.unreadable().map(|e| e.name.as_str()).collect();
    if !unreadable.is_empty() {
        return Err(failed(format!(
            "the module would not read {} parameters (saved with their error): {}",
            unreadable.len(),
            unreadable.join(", ")
        )));
    }
    Ok(snapshot)
}

/// Compares the snapshot at `path` with the module; prints the differences and fails (exit 1)
/// when there are any.
pub fn diff(
    device: &mut dyn ParamDevice,
    path: &Path,
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    let file = Snapshot::load(path)?;
    let comparison = diff::with_device(&file, device)?;
    let right = device.who();
    report(comparison, [&path.display().to_string(), &right], out)
}

/// Compares two snapshot files; `params` (the profile's view) tells settings from live values.
pub fn diff_files(
    left: &Path,
    right: &Path,
    params: &[ParamRef],
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    let (a, b) = (Snapshot::load(left)?, Snapshot::load(right)?);
    let comparison = diff::between(&a, &b, params);
    let labels = [left.display().to_string(), right.display().to_string()];
    report(comparison, [&labels[0], &labels[1]], out)
}

fn report(
    comparison: Comparison,
    labels: [&str; 2],
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    diff::write_table(&comparison, labels, out)?;
    if comparison.differences.is_empty() {
        writeln!(out, "{}", diff::summary(&comparison))?;
        Ok(comparison)
    } else {
        Err(failed(diff::summary(&comparison)))
    }
}

/// How to restore.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RestoreOptions {
    /// Make the written parameters permanent afterwards (TMCL STAP/STGP, SMD4 STORE).
    pub store: bool,
    /// Only print what would be sent.
    pub dry_run: bool,
}

/// Restores the snapshot at `path`: plans, writes and verifies, lists what was skipped, and — when
/// `options.store` and `confirm` agrees to the question it is asked — makes the values permanent.
/// Fails (exit 1) when a write was refused or read back differently; nothing is stored then.
pub fn restore(
    device: &mut dyn ParamDevice,
    path: &Path,
    options: RestoreOptions,
    confirm: &mut dyn FnMut(&str) -> Result<bool, SessionError>,
    out: &mut dyn Write,
) -> Result<Outcome, SessionError> {
    let snapshot = Snapshot::load(path)?;
    let params = device.params();
    let plan = restore::plan(&snapshot, &params, device);
    if options.dry_run {
        for line in restore::dry_run(device, &plan, options.store)? {
            writeln!(out, "{line}")?;
        }
        restore::write_skipped(&plan, out)?;
        return Ok(Outcome::default());
    }
    device.ready_to_restore()?;
    if snapshot.module != device.module_name() {
        writeln!(
            out,
            "note: the snapshot is of a {}, the module is a {}",
            snapshot.module,
            device.module_name()
        )?;
    }
    let mut outcome = restore::execute(device, &plan)?;
    restore::write_skipped(&plan, out)?;
    let memory = device.memory();
    if outcome.failed.is_empty() && options.store && confirm(&store_question(device, &plan))? {
        restore::store(device, &plan, &mut outcome)?;
    } else if options.store && !outcome.failed.is_empty() {
        writeln!(out, "not stored to {memory}: some parameters failed")?;
    }
    restore::write_outcome(&outcome, memory, out)?;
    if !outcome.failed.is_empty() {
        return Err(failed(format!(
            "{} parameters were not restored",
            outcome.failed.len()
        )));
    }
    Ok(outcome)
}

/// The confirmation asked before storing: how many parameters, where, and the line when one line
/// does it all ("… of drive @3 with STORE").
pub fn store_question(device: &dyn ParamDevice, plan: &Plan) -> String {
    let params: Vec<_> = restore::storable(plan).collect();
    let steps = device.store_steps(&params);
    let with = match steps.as_slice() {
        [one] if one.params.len() > 1 => format!(" with {}", one.line),
        _ => String::new(),
    };
    format!(
        "store {} parameters to the {} of {}{with}?",
        params.len(),
        device.memory(),
        device.who()
    )
}
