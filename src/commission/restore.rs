//! Writing a snapshot back: the settings in a safe order (the profile's `first` list — unit mode
//! and limits, or the SMD4's coupled currents and frequencies — then table order, then its `last`
//! list), each verified by reading it back, then optionally made permanent (TMCL STAP/STGP per
//! parameter, SMD4 STORE for the whole configuration). Read-only, live and link settings are
//! skipped and listed, never written.
//!
//! A module may refuse a value because of another one not yet written (the SMD4 document leaves
//! open whether VMAX below VSTART is refused): writes the module refused are tried once more after
//! all the others. Written values are read once more at the end, so a value a later write changed
//! (a coupling) is reported rather than counted as restored.

use std::io::{self, Write};

use crate::profile::SnapshotRole;
use crate::session::SessionError;

use super::device::{ParamDevice, ParamRef};
use super::progress::Progress;
use super::snapshot::Snapshot;
use super::value::ParamValue;

/// What a restore will do.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// Parameters to write, in order, with their values.
    pub writes: Vec<(ParamRef, ParamValue)>,
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
        let Ok(value) = &entry.value else {
            skipped.push(skip(Reason::NoValue, None));
            continue;
        };
        match param.role {
            SnapshotRole::Setting => writes.push((param.clone(), value.clone())),
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
    /// Parameters stored to the module's permanent memory.
    pub stored: usize,
}

/// Whether an error concerns one parameter (the restore goes on) rather than the link.
fn per_parameter(error: &SessionError) -> bool {
    matches!(
        error,
        SessionError::Device { .. } | SessionError::Refused(_) | SessionError::Rejected(_)
    )
}

/// What became of one write.
enum Written {
    Verified,
    /// The module refused it: worth another try once the rest is written.
    Refused(String),
    /// Refused before sending, or read back differently.
    Failed(String),
}

fn write_and_verify(
    device: &mut dyn ParamDevice,
    param: &ParamRef,
    value: &ParamValue,
) -> Result<Written, SessionError> {
    if let Err(e) = device.write(param, value) {
        return match e {
            SessionError::Device { .. } => Ok(Written::Refused(e.to_string())),
            e if per_parameter(&e) => Ok(Written::Failed(e.to_string())),
            e => Err(e),
        };
    }
    match device.read(param) {
        Ok(back) if param.tolerance.same(&back.value, value) => Ok(Written::Verified),
        Ok(back) => Ok(Written::Failed(format!(
            "wrote {value}, reads back {}",
            back.value
        ))),
        Err(e) if per_parameter(&e) => Ok(Written::Failed(e.to_string())),
        Err(e) => Err(e),
    }
}

/// Whether the module already holds `value` for `param` (a refused read counts as no).
fn holds(
    device: &mut dyn ParamDevice,
    param: &ParamRef,
    value: &ParamValue,
) -> Result<bool, SessionError> {
    match device.read(param) {
        Ok(current) => Ok(param.tolerance.same(&current.value, value)),
        Err(e) if per_parameter(&e) => Ok(false),
        Err(e) => Err(e),
    }
}

/// Writes the plan's values that differ from the module's, reading each back. A refusal or a
/// mismatch is recorded and the rest goes on; refusals are tried once more at the end; a lost
/// link, a timeout or Ctrl-C ends the restore.
pub fn execute(device: &mut dyn ParamDevice, plan: &Plan) -> Result<Outcome, SessionError> {
    let mut outcome = Outcome::default();
    let progress = Progress::new(plan.writes.len(), "writing");
    let mut failures: Vec<(usize, String)> = Vec::new();
    let mut refused = Vec::new();
    let mut written = Vec::new();
    for (i, (param, value)) in plan.writes.iter().enumerate() {
        progress.step(&param.name);
        if holds(device, param, value)? {
            outcome.unchanged += 1;
            continue;
        }
        match write_and_verify(device, param, value)? {
            Written::Verified => written.push(i),
            Written::Refused(why) => refused.push((i, why)),
            Written::Failed(why) => failures.push((i, why)),
        }
    }
    for (i, why) in refused {
        let (param, value) = &plan.writes[i];
        match write_and_verify(device, param, value)? {
            Written::Verified => written.push(i),
            Written::Refused(_) => failures.push((i, why)),
            Written::Failed(again) => failures.push((i, again)),
        }
    }
    for &i in &written {
        let (param, value) = &plan.writes[i];
        match device.read(param) {
            Ok(now) if param.tolerance.same(&now.value, value) => outcome.verified += 1,
            Ok(now) => failures.push((
                i,
                format!("wrote {value}, a later write changed it to {}", now.value),
            )),
            Err(e) if per_parameter(&e) => failures.push((i, e.to_string())),
            Err(e) => return Err(e),
        }
    }
    failures.sort_by_key(|(i, _)| *i);
    outcome.failed = failures
        .into_iter()
        .map(|(i, why)| (plan.writes[i].0.name.clone(), why))
        .collect();
    Ok(outcome)
}

/// The lines a restore would send (`--dry-run`): reads the module and lists the writes of the
/// values that differ, then the store steps.
pub fn dry_run(
    device: &mut dyn ParamDevice,
    plan: &Plan,
    store: bool,
) -> Result<Vec<String>, SessionError> {
    let mut lines = Vec::new();
    for (param, value) in &plan.writes {
        if !holds(device, param, value)? {
            lines.push(device.write_line(param, value));
        }
    }
    if store {
        let params: Vec<&ParamRef> = storable(plan).collect();
        lines.extend(device.store_steps(&params).into_iter().map(|s| s.line));
    }
    Ok(lines)
}

/// The parameters of the plan that the module keeps over a power cycle once stored.
pub fn storable(plan: &Plan) -> impl Iterator<Item = &ParamRef> {
    plan.writes
        .iter()
        .map(|(p, _)| p)
        .filter(|p| p.access.store)
}

/// Makes the plan's storable parameters permanent (TMCL STAP/STGP, SMD4 STORE).
pub fn store(
    device: &mut dyn ParamDevice,
    plan: &Plan,
    outcome: &mut Outcome,
) -> Result<(), SessionError> {
    let params: Vec<&ParamRef> = storable(plan).collect();
    let steps = device.store_steps(&params);
    let progress = Progress::new(steps.len(), "storing");
    for step in &steps {
        // A step of one parameter is named by it; one for the whole configuration by its line.
        let name = match step.params.as_slice() {
            [one] => one.name.clone(),
            _ => step.line.clone(),
        };
        progress.step(&name);
        match device.store(step) {
            Ok(()) => outcome.stored += step.params.len(),
            Err(e) if per_parameter(&e) => outcome.failed.push((name, e.to_string())),
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

/// Prints the outcome: verified count, failures, stored count (to `memory`, "EEPROM").
pub fn write_outcome(outcome: &Outcome, memory: &str, out: &mut dyn Write) -> io::Result<()> {
    writeln!(
        out,
        "restored {} parameters, each read back and verified; {} already had the snapshot's value",
        outcome.verified, outcome.unchanged
    )?;
    for (name, what) in &outcome.failed {
        writeln!(out, "FAILED {name}: {what}")?;
    }
    if outcome.stored > 0 {
        writeln!(out, "stored {} parameters to {memory}", outcome.stored)?;
    }
    Ok(())
}
