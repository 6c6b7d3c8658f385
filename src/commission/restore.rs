//! Writing a snapshot back: the settings in a safe order (the profile's `first` list — unit mode
//! and limits — then table order), each verified by reading it back, then optionally stored to
//! EEPROM. Read-only, live and link settings are skipped and listed, never written.

use std::io::{self, Write};

use crate::profile::SnapshotRole;
use crate::session::SessionError;

use super::device::{ParamDevice, ParamRef};
use super::progress::Progress;
use super::snapshot::Snapshot;

/// What a restore will do.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Plan {
    /// Parameters to write, in order, with their values.
    pub writes: Vec<(ParamRef, i64)>,
    /// Entries left out, and why.
    pub skipped: Vec<Skipped>,
}

/// An entry a restore leaves out.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Skipped {
    /// The parameter's identifier.
    pub name: String,
    /// Why.
    pub reason: Reason,
    /// The line to send by hand, where that makes sense.
    pub by_hand: Option<String>,
}

/// Why an entry is not written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reason {
    /// The module's parameter cannot be written.
    ReadOnly,
    /// A live value (position, speed, timer).
    Live,
    /// A link or EEPROM-protection setting: written by hand only.
    Manual,
    /// The module has no parameter of that name.
    Unknown,
    /// The snapshot holds no value (it could not be read when saved).
    NoValue,
}

impl Reason {
    fn text(self) -> &'static str {
        match self {
            Reason::ReadOnly => "read-only",
            Reason::Live => "live values, not settings",
            Reason::Manual => "change the link or the EEPROM protection; set them by hand",
            Reason::Unknown => "not parameters of this module",
            Reason::NoValue => "no value in the snapshot",
        }
    }
}

/// Plans the restore of `snapshot` onto a module with `params` (its profile's view).
pub fn plan(snapshot: &Snapshot, params: &[ParamRef], device: &dyn ParamDevice) -> Plan {
    let mut writes = Vec::new();
    let mut skipped = Vec::new();
    for entry in &snapshot.entries {
        let skip = |reason, by_hand| Skipped {
            name: entry.name.clone(),
            reason,
            by_hand,
        };
        let Some(param) = params
            .iter()
            .find(|p| p.scope == entry.scope && p.name == entry.name)
        else {
            skipped.push(skip(Reason::Unknown, None));
            continue;
        };
        let Ok(value) = entry.value else {
            skipped.push(skip(Reason::NoValue, None));
            continue;
        };
        match param.role {
            SnapshotRole::Setting => writes.push((param.clone(), value)),
            SnapshotRole::ReadOnly => skipped.push(skip(Reason::ReadOnly, None)),
            SnapshotRole::Live => skipped.push(skip(Reason::Live, None)),
            SnapshotRole::Manual => {
                skipped.push(skip(Reason::Manual, Some(device.write_line(param, value))))
            }
        }
    }
    let position = |p: &ParamRef| params.iter().position(|q| q == p).unwrap_or(usize::MAX);
    writes.sort_by_key(|(p, _)| (p.rank, position(p)));
    Plan { writes, skipped }
}

/// What a restore did.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Outcome {
    /// Parameters written and read back with the same value.
    pub verified: usize,
    /// Parameters that already had the snapshot's value (not written).
    pub unchanged: usize,
    /// Parameters the module (or the profile's range) refused or that read back differently:
    /// name and what happened.
    pub failed: Vec<(String, String)>,
    /// Parameters stored to EEPROM.
    pub stored: usize,
}

/// Whether an error concerns one parameter (the restore goes on) rather than the link.
fn per_parameter(error: &SessionError) -> bool {
    matches!(
        error,
        SessionError::Device { .. } | SessionError::Refused(_)
    )
}

/// Writes the plan's values that differ from the module's, reading each back. A refusal or a
/// mismatch is recorded and the rest goes on; a lost link, a timeout or Ctrl-C ends the restore.
pub fn execute(device: &mut dyn ParamDevice, plan: &Plan) -> Result<Outcome, SessionError> {
    let mut outcome = Outcome::default();
    let progress = Progress::new(plan.writes.len(), "writing");
    for (param, value) in &plan.writes {
        progress.step(&param.name);
        match device.read(param) {
            Ok(current) if current == *value => {
                outcome.unchanged += 1;
                continue;
            }
            Ok(_) => {}
            Err(e) if per_parameter(&e) => {}
            Err(e) => return Err(e),
        }
        let checked = device
            .write(param, *value)
            .and_then(|()| device.read(param));
        match checked {
            Ok(back) if back == *value => outcome.verified += 1,
            Ok(back) => outcome.failed.push((
                param.name.clone(),
                format!("wrote {value}, reads back {back}"),
            )),
            Err(e) if per_parameter(&e) => outcome.failed.push((param.name.clone(), e.to_string())),
            Err(e) => return Err(e),
        }
    }
    Ok(outcome)
}

/// The lines a restore would send (`--dry-run`): reads the module and lists the writes of the
/// values that differ, then the stores.
pub fn dry_run(
    device: &mut dyn ParamDevice,
    plan: &Plan,
    store: bool,
) -> Result<Vec<String>, SessionError> {
    let mut lines = Vec::new();
    for (param, value) in &plan.writes {
        match device.read(param) {
            Ok(current) if current == *value => continue,
            Ok(_) => {}
            Err(e) if per_parameter(&e) => {}
            Err(e) => return Err(e),
        }
        lines.push(device.write_line(param, *value));
    }
    if store {
        lines.extend(storable(plan).map(|p| device.store_line(p)));
    }
    Ok(lines)
}

/// The parameters of the plan that can be stored to EEPROM.
pub fn storable(plan: &Plan) -> impl Iterator<Item = &ParamRef> {
    plan.writes
        .iter()
        .map(|(p, _)| p)
        .filter(|p| p.access.store)
}

/// Stores the plan's storable parameters to EEPROM (STAP/STGP).
pub fn store(
    device: &mut dyn ParamDevice,
    plan: &Plan,
    outcome: &mut Outcome,
) -> Result<(), SessionError> {
    let params: Vec<&ParamRef> = storable(plan).collect();
    let progress = Progress::new(params.len(), "storing");
    for param in params {
        progress.step(&param.name);
        match device.store(param) {
            Ok(()) => outcome.stored += 1,
            Err(e) if per_parameter(&e) => outcome.failed.push((param.name.clone(), e.to_string())),
            Err(e) => return Err(e),
        }
    }
    Ok(())
}

/// Lists the skipped entries, grouped by reason (one line per reason, names comma-separated), and
/// the lines to send by hand.
pub fn write_skipped(plan: &Plan, out: &mut dyn Write) -> io::Result<()> {
    for reason in [
        Reason::ReadOnly,
        Reason::Live,
        Reason::Manual,
        Reason::Unknown,
        Reason::NoValue,
    ] {
        let names: Vec<&str> = plan
            .skipped
            .iter()
            .filter(|s| s.reason == reason)
            .map(|s| s.name.as_str())
            .collect();
        if names.is_empty() {
            continue;
        }
        writeln!(
            out,
            "skipped {} ({}): {}",
            names.len(),
            reason.text(),
            names.join(", ")
        )?;
        for s in plan.skipped.iter().filter(|s| s.reason == reason) {
            if let Some(line) = &s.by_hand {
                writeln!(out, "  by hand: {line}")?;
            }
        }
    }
    Ok(())
}

/// Prints the outcome: verified count, failures, stored count.
pub fn write_outcome(outcome: &Outcome, out: &mut dyn Write) -> io::Result<()> {
    writeln!(
        out,
        "restored {} parameters, each read back and verified; {} already had the snapshot's value",
        outcome.verified, outcome.unchanged
    )?;
    for (name, what) in &outcome.failed {
        writeln!(out, "FAILED {name}: {what}")?;
    }
    if outcome.stored > 0 {
        writeln!(out, "stored {} parameters to EEPROM", outcome.stored)?;
    }
    Ok(())
}
