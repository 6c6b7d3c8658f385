//! Snapshot save, diff and restore as the faces run them (CLI, REPL helper, Rhai): the work, the
//! report on a sink, and the verdict as an error that carries its exit code.

use std::io::Write;
use std::path::Path;

use crate::exit::{Exit, Failure};
use crate::session::SessionError;

use super::device::{ParamDevice, ParamRef};
use super::diff::{self, Comparison};
use super::restore::{self, Outcome, Plan, check};
use super::snapshot::Snapshot;

/// A failure that is not the module's status nor the link's: differences, failed verifications.
pub fn failed(message: impl Into<String>) -> SessionError {
    Failure::new(Exit::DeviceError, message).into()
}

/// Reads the module and writes the snapshot to `path`; fails (exit 1) after saving when some
/// parameters could not be read.
pub fn save(
    device: &mut dyn ParamDevice,
    path: &Path,
    out: &mut dyn Write,
) -> Result<Snapshot, SessionError> {
    let label = path.display().to_string();
    save_with(device, &label, &mut |snapshot| snapshot.save(path), out)
}

/// [`save`], refusing (exit 2, before the module is read) to replace an existing file unless
/// `force` says so: a snapshot is often the only record of a module's working settings.
pub fn save_new(
    device: &mut dyn ParamDevice,
    path: &Path,
    force: bool,
    out: &mut dyn Write,
) -> Result<Snapshot, SessionError> {
    check_new(path, force)?;
    save(device, path, out)
}

/// Refuses an existing `path` (exit 2) unless `force` says to replace it.
pub fn check_new(path: &Path, force: bool) -> Result<(), SessionError> {
    crate::file::check_writable(path)
        .map_err(|e| SessionError::Usage(format!("cannot write snapshot {e}")))?;
    if !force && path.symlink_metadata().is_ok() {
        return Err(SessionError::Usage(format!(
            "{} exists; add --force to replace it (or save to another file)",
            path.display()
        )));
    }
    Ok(())
}

/// Reads the module and hands the snapshot to `write` (which stores it where `label` says);
/// fails (exit 1) after writing when some parameters could not be read.
pub fn save_with(
    device: &mut dyn ParamDevice,
    label: &str,
    write: &mut dyn FnMut(&Snapshot) -> Result<(), SessionError>,
    out: &mut dyn Write,
) -> Result<Snapshot, SessionError> {
    let snapshot = Snapshot::capture(device)?;
    write(&snapshot)?;
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
        "saved {} of the {}{address}{firmware} to {label}",
        crate::count::counted(snapshot.entries.len(), "parameter"),
        snapshot.module,
    )?;
    let unreadable: Vec<&str> = snapshot.unreadable().map(|e| e.name.as_str()).collect();
    if !unreadable.is_empty() {
        return Err(failed(format!(
            "the module would not read {} (saved with their error): {}",
            crate::count::counted(unreadable.len(), "parameter"),
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
    diff_snapshot(device, &file, path, out)
}

/// [`diff`] of a snapshot already read from `path`.
pub fn diff_snapshot(
    device: &mut dyn ParamDevice,
    file: &Snapshot,
    path: &Path,
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    diff_snapshot_as(device, file, path, DiffOutput::Table, out)
}

/// How a comparison is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DiffOutput {
    /// The table of differences and a summary line.
    Table,
    /// One JSON document (`snapshot diff --json`; fields in docs/machine-output.md).
    Json,
}

/// [`diff_snapshot`] shown as `output` says.
pub fn diff_snapshot_as(
    device: &mut dyn ParamDevice,
    file: &Snapshot,
    path: &Path,
    output: DiffOutput,
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    let comparison = diff::with_device(file, device)?;
    let right = device.who();
    report(
        comparison,
        [&path.display().to_string(), &right],
        output,
        out,
    )
}

/// Compares two snapshot files; `params` (the profile's view) tells settings from live values.
pub fn diff_files(
    left: &Path,
    right: &Path,
    params: &[ParamRef],
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    diff_files_as(left, right, params, DiffOutput::Table, out)
}

/// [`diff_files`] shown as `output` says.
pub fn diff_files_as(
    left: &Path,
    right: &Path,
    params: &[ParamRef],
    output: DiffOutput,
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    let (a, b) = (Snapshot::load(left)?, Snapshot::load(right)?);
    let comparison = diff::between(&a, &b, params);
    let labels = [left.display().to_string(), right.display().to_string()];
    report(comparison, [&labels[0], &labels[1]], output, out)
}

/// Shows the comparison; fails (exit 1) when something differs, after showing it.
fn report(
    comparison: Comparison,
    labels: [&str; 2],
    output: DiffOutput,
    out: &mut dyn Write,
) -> Result<Comparison, SessionError> {
    match output {
        DiffOutput::Table => diff::write_table(&comparison, labels, out)?,
        DiffOutput::Json => crate::json::write(&diff::json(&comparison, labels), out)?,
    }
    if comparison.differences.is_empty() {
        if output == DiffOutput::Table {
            writeln!(out, "{}", diff::summary(&comparison))?;
        }
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
    /// Go on despite the problems that allow it: another module type, numbers that disagree
    /// with names (written by name), names, motors and banks the module lacks (skipped).
    pub force: bool,
    /// Tell the file's problems without quoting its text (scripts: the file may not be theirs).
    pub redact: bool,
}

/// Restores the snapshot at `path`; see [`restore_snapshot`].
pub fn restore(
    device: &mut dyn ParamDevice,
    path: &Path,
    options: RestoreOptions,
    confirm: &mut dyn FnMut(&str) -> Result<bool, SessionError>,
    out: &mut dyn Write,
) -> Result<Outcome, SessionError> {
    let snapshot = Snapshot::load(path)?;
    let label = path.display().to_string();
    restore_snapshot(device, &snapshot, &label, options, confirm, out)
}

/// Restores `snapshot` (read from `label`): checks the whole file first and refuses it (exit 2,
/// every problem listed, nothing sent) unless it is sound; then writes and verifies, lists what
/// was skipped, and — when `options.store` and `confirm` agrees to the question it is asked —
/// makes the written values permanent. Fails (exit 1) when a write was refused or read back
/// differently (nothing is stored then), and with the link's exit code when the link failed
/// midway, after saying what was written and what was not.
pub fn restore_snapshot(
    device: &mut dyn ParamDevice,
    snapshot: &Snapshot,
    label: &str,
    options: RestoreOptions,
    confirm: &mut dyn FnMut(&str) -> Result<bool, SessionError>,
    out: &mut dyn Write,
) -> Result<Outcome, SessionError> {
    let params = device.params();
    let plan = restore::plan(snapshot, &params, device);
    let blocking = check::blocking(&plan.problems, options.force);
    if !blocking.is_empty() {
        let target = format!("{}, type {}", device.who(), device.module_name());
        let refusal = check::refusal(label, &target, &blocking, !options.redact);
        return Err(Failure::refused(refusal).into());
    }
    for problem in &plan.problems {
        writeln!(out, "forced: {}", problem.text(!options.redact))?;
    }
    if options.dry_run {
        let (lines, by_hand) = restore::dry_run(device, &plan, options.store)?;
        for line in lines {
            writeln!(out, "{line}")?;
        }
        restore::write_skipped(&plan, &by_hand, out)?;
        return Ok(Outcome::default());
    }
    device.ready_to_restore()?;
    let mut outcome = match restore::execute(device, &plan) {
        Ok(outcome) => outcome,
        Err(aborted) => {
            restore::write_skipped(&plan, &aborted.outcome.by_hand, out)?;
            restore::write_outcome(&aborted.outcome, device.memory(), out)?;
            return Err(aborted.error);
        }
    };
    restore::write_skipped(&plan, &outcome.by_hand, out)?;
    let memory = device.memory();
    if options.store {
        if !outcome.failed.is_empty() {
            writeln!(out, "not stored to {memory}: some parameters failed")?;
        } else if restore::storable(&plan, &outcome.verified).next().is_none() {
            writeln!(
                out,
                "not stored to {memory}: the restore wrote nothing that is kept there"
            )?;
        } else if confirm(&store_question(device, &plan, &outcome))? {
            restore::store(device, &plan, &mut outcome)?;
        }
    }
    restore::write_outcome(&outcome, memory, out)?;
    if !outcome.failed.is_empty() {
        return Err(failed(format!(
            "{} not restored: {}",
            crate::count::counted(outcome.failed.len(), "parameter"),
            outcome
                .failed
                .iter()
                .map(|(name, _)| name.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        )));
    }
    Ok(outcome)
}

/// The confirmation asked before storing: which parameters (those the restore wrote), where, and
/// the line when one line stores them all ("… of drive @3 with STORE").
pub fn store_question(device: &dyn ParamDevice, plan: &Plan, outcome: &Outcome) -> String {
    let params: Vec<_> = restore::storable(plan, &outcome.verified).collect();
    let steps = device.store_steps(&params);
    let names: Vec<&str> = params.iter().map(|p| p.name.as_str()).collect();
    let (memory, who) = (device.memory(), device.who());
    match steps.as_slice() {
        [one] if one.whole => format!(
            "store the whole working configuration of {who} to its {memory} with {}, \
             including the {} setting{} written ({})?",
            one.line,
            params.len(),
            if params.len() == 1 { "" } else { "s" },
            names.join(", ")
        ),
        _ => format!(
            "store {} parameter{} ({}) to the {memory} of {who}?",
            params.len(),
            if params.len() == 1 { "" } else { "s" },
            names.join(", ")
        ),
    }
}
