//! Writing a snapshot back: the settings in a safe order (the profile's `first` list — unit mode
//! and limits, or the SMD4's coupled currents and frequencies — then table order, then its `last`
//! list), each verified by reading it back, then optionally made permanent (TMCL STAP/STGP per
//! parameter, SMD4 STORE for the whole configuration). Read-only, live and link settings are
//! skipped and listed, never written.
//!
//! Nothing is sent before the whole file has been checked ([`check`]): every value through the
//! module's own validator, every name and number against the module's tables, the module type and
//! the dialect. A file with any problem is refused whole.
//!
//! A module may refuse a value because of another one not yet written (the SMD4 document leaves
//! open whether VMAX below VSTART is refused): writes the module refused are tried once more after
//! all the others. Written values are read once more at the end, so a value a later write changed
//! (a coupling) is reported rather than counted as restored. When the link fails midway, the
//! outcome says exactly which values were written, which one was in flight and which were not
//! sent.

pub mod check;

use std::collections::BTreeSet;
use std::io::{self, Write};

use crate::article::with_article;
use crate::commission::SnapshotRole;
use crate::session::SessionError;

use super::device::{ParamDevice, ParamRef, Scope};
use super::snapshot::{Entry, Snapshot};
use super::value::ParamValue;
use crate::progress::Progress;
use check::{Problem, Subject};

/// What a restore will do.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// Parameters to write, in order, with their values.
    pub writes: Vec<(ParamRef, ParamValue)>,
    /// Settings to set by hand (link, EEPROM protection), with the snapshot's values.
    pub manual: Vec<(ParamRef, ParamValue)>,
    /// Entries left out, and why.
    pub skipped: Vec<Skipped>,
    /// What is wrong with the file (a restore goes on only without them, or with `--force` when
    /// each may be forced).
    pub problems: Vec<Problem>,
}

/// An entry a restore leaves out.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Skipped {
    /// The parameter's identifier.
    pub name: String,
    /// Why.
    pub reason: Reason,
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
    /// The module has no parameter of that name (left out under `--force`).
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

/// Plans the restore of `snapshot` onto `device`, whose parameters are `params` (its profile's
/// view), and finds every problem of the file on the way.
pub fn plan(snapshot: &Snapshot, params: &[ParamRef], device: &dyn ParamDevice) -> Plan {
    let mut plan = Plan {
        writes: Vec::new(),
        manual: Vec::new(),
        skipped: Vec::new(),
        problems: file_problems(snapshot, params, device),
    };
    let mut missing_sections = BTreeSet::new();
    for entry in &snapshot.entries {
        let skip = |reason| Skipped {
            name: entry.name.clone(),
            reason,
        };
        let Some(param) = params
            .iter()
            .find(|p| p.scope == entry.scope && p.name == entry.name)
        else {
            if let Some(problem) = unknown(entry, params, device, &mut missing_sections) {
                plan.problems.push(problem);
            }
            plan.skipped.push(skip(Reason::Unknown));
            continue;
        };
        if let Some(problem) = number_problem(entry, param) {
            plan.problems.push(problem);
        }
        let Ok(value) = &entry.value else {
            plan.skipped.push(skip(Reason::NoValue));
            continue;
        };
        match param.role {
            SnapshotRole::Setting | SnapshotRole::Manual => {
                if let Err(why) = device.check_write(param, value) {
                    plan.problems.push(Problem::fatal(
                        Subject::Param(param.name.clone()),
                        "the module would refuse this value (its type, range or access)",
                        Some(why.to_string()),
                    ));
                    continue;
                }
                if param.role == SnapshotRole::Setting {
                    plan.writes.push((param.clone(), value.clone()));
                } else {
                    plan.manual.push((param.clone(), value.clone()));
                    plan.skipped.push(skip(Reason::Manual));
                }
            }
            SnapshotRole::ReadOnly => plan.skipped.push(skip(Reason::ReadOnly)),
            SnapshotRole::Live => plan.skipped.push(skip(Reason::Live)),
        }
    }
    if plan.writes.is_empty() && plan.manual.is_empty() {
        plan.problems.push(Problem::fatal(
            Subject::File,
            format!(
                "nothing in it is a setting of the {} that a restore could write",
                device.module_name()
            ),
            None,
        ));
    }
    let position = |p: &ParamRef| params.iter().position(|q| q == p).unwrap_or(usize::MAX);
    plan.writes.sort_by_key(|(p, _)| (p.rank, position(p)));
    plan
}

/// Problems of the file as a whole: another module type, another dialect.
fn file_problems(
    snapshot: &Snapshot,
    params: &[ParamRef],
    device: &dyn ParamDevice,
) -> Vec<Problem> {
    let mut problems = Vec::new();
    let module = device.module_name();
    let drive = |scope: &Scope| *scope == Scope::Drive;
    let file_is_drive = snapshot.entries.iter().any(|e| drive(&e.scope));
    let file_has_motors_or_banks = snapshot.entries.iter().any(|e| !drive(&e.scope));
    let device_is_drive = params.iter().any(|p| drive(&p.scope));
    if (device_is_drive && file_has_motors_or_banks) || (!device_is_drive && file_is_drive) {
        let (file, target) = if device_is_drive {
            ("TMCL axis and global parameters", "an SMD4 drive")
        } else {
            ("SMD4 drive settings", "a TMCL module")
        };
        problems.push(Problem::forceable(
            Subject::File,
            format!("it holds {file}, and {} is {target}", device.who()),
            None,
        ));
    }
    if snapshot.module != module {
        problems.push(Problem::forceable(
            Subject::File,
            format!(
                "it is a snapshot of another module type, not of {}",
                with_article(&module)
            ),
            Some(format!(
                "it is a snapshot of {}, and {} is {}",
                with_article(&snapshot.module),
                device.who(),
                with_article(&module)
            )),
        ));
    }
    problems
}

/// The problem with an entry the module has no parameter for: a motor or bank it lacks (once per
/// section), or a name it does not know. Entries of another dialect are the file's problem.
fn unknown(
    entry: &Entry,
    params: &[ParamRef],
    device: &dyn ParamDevice,
    missing_sections: &mut BTreeSet<Scope>,
) -> Option<Problem> {
    let module = device.module_name();
    let section = entry.scope.section();
    let device_is_drive = params.iter().any(|p| p.scope == Scope::Drive);
    if (entry.scope == Scope::Drive) != device_is_drive {
        return None;
    }
    if !params.iter().any(|p| p.scope == entry.scope) {
        if !missing_sections.insert(entry.scope) {
            return None;
        }
        let what = match entry.scope {
            Scope::Axis { motor } => {
                let motors = params
                    .iter()
                    .filter_map(|p| match p.scope {
                        Scope::Axis { motor } => Some(motor),
                        _ => None,
                    })
                    .max()
                    .map_or("no motors".to_string(), |last| format!("motors 0..{last}"));
                format!("the {module} has no motor {motor} (it has {motors})")
            }
            Scope::Global { bank } => {
                format!("the {module} has no global parameters in bank {bank}")
            }
            Scope::Drive => format!("the {module} has no drive settings"),
        };
        return Some(Problem::forceable(Subject::Section(section), what, None));
    }
    let nearest = crate::suggest::nearest(
        &entry.name,
        params
            .iter()
            .filter(|p| p.scope == entry.scope)
            .map(|p| p.name.as_str()),
    );
    Some(Problem::forceable(
        Subject::Entry {
            section,
            name: entry.name.clone(),
        },
        format!("not a parameter of the {module}"),
        Some(format!(
            "not a parameter of the {module}{}",
            crate::suggest::did_you_mean(&nearest)
        )),
    ))
}

/// The problem with an entry whose number is not the module's number for its name.
fn number_problem(entry: &Entry, param: &ParamRef) -> Option<Problem> {
    let file = entry.number?;
    let what = match param.number {
        Some(number) if number == file => return None,
        Some(number) => format!("the file's number is not {number}, the module's number for it"),
        None => "the file gives it a number; the module's settings have none".to_string(),
    };
    let place = param.place();
    let detail = match param.number {
        Some(_) => format!("number = {file} in the file, but it is {place}"),
        None => format!("number = {file} in the file, but it has no number"),
    };
    Some(Problem::forceable(
        Subject::Param(param.name.clone()),
        what,
        Some(detail),
    ))
}

/// What a restore did.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Outcome {
    /// Parameters written and read back with the same value, in the order written.
    pub verified: Vec<String>,
    /// Parameters that already had the snapshot's value (not written).
    pub unchanged: usize,
    /// Parameters the module refused or that read back differently: name and what happened.
    pub failed: Vec<(String, String)>,
    /// The lines to send by hand for the manual settings whose values differ.
    pub by_hand: Vec<String>,
    /// Parameters stored to the module's permanent memory.
    pub stored: usize,
    /// Where a restore ended early (link lost, timeout, Ctrl-C).
    pub unfinished: Option<Unfinished>,
}

/// How far a restore got when the link failed.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Unfinished {
    /// What ended it.
    pub error: String,
    /// The parameter being written or read when it ended: its value on the module is unknown.
    pub in_flight: Option<String>,
    /// Parameters not written at all.
    pub not_written: Vec<String>,
}

/// A restore the link ended: what it had done, and the error.
#[derive(Debug)]
pub struct Aborted {
    /// What was done (with [`Outcome::unfinished`] set).
    pub outcome: Outcome,
    /// The error that ended it.
    pub error: SessionError,
}

/// Whether an error concerns one parameter (the restore goes on) rather than the link.
fn per_parameter(error: &SessionError) -> bool {
    matches!(
        error,
        SessionError::Device { .. } | SessionError::Refused(_)
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

/// The lines that set the plan's manual settings whose values differ from the module's.
fn by_hand(device: &mut dyn ParamDevice, plan: &Plan) -> Result<Vec<String>, SessionError> {
    let mut lines = Vec::new();
    for (param, value) in &plan.manual {
        if !holds(device, param, value)? {
            lines.push(device.write_line(param, value));
        }
    }
    Ok(lines)
}

/// Writes the plan's values that differ from the module's, reading each back. A refusal or a
/// mismatch is recorded and the rest goes on; refusals are tried once more at the end. A lost
/// link, a timeout or Ctrl-C ends the restore: [`Aborted`] then says what was written, which
/// parameter was in flight and what was not sent.
pub fn execute(device: &mut dyn ParamDevice, plan: &Plan) -> Result<Outcome, Box<Aborted>> {
    let mut run = Run {
        outcome: Outcome::default(),
        written: Vec::new(),
        attempted: vec![false; plan.writes.len()],
    };
    match run.go(device, plan) {
        Ok(()) => Ok(run.outcome),
        Err((in_flight, error)) => {
            let mut outcome = run.outcome;
            let in_flight_index = in_flight;
            // Written values count as restored when they were read back once.
            outcome.verified = run
                .written
                .iter()
                .filter(|&&i| Some(i) != in_flight_index)
                .map(|&i| plan.writes[i].0.name.clone())
                .collect();
            let failed: BTreeSet<&str> = outcome.failed.iter().map(|(n, _)| n.as_str()).collect();
            let not_written = plan
                .writes
                .iter()
                .enumerate()
                .filter(|(i, _)| !run.attempted[*i] && Some(*i) != in_flight_index)
                .map(|(_, (p, _))| p.name.clone())
                .filter(|n| !failed.contains(n.as_str()))
                .collect();
            outcome.unfinished = Some(Unfinished {
                error: error.to_string(),
                in_flight: in_flight_index.map(|i| plan.writes[i].0.name.clone()),
                not_written,
            });
            Err(Box::new(Aborted { outcome, error }))
        }
    }
}

/// The state of a restore under way.
struct Run {
    outcome: Outcome,
    /// Indices of the writes done and read back once.
    written: Vec<usize>,
    /// Whether each write was sent (or found unnecessary).
    attempted: Vec<bool>,
}

/// The index of the write in flight (if a write was) and the error that ended the restore.
type Stop = (Option<usize>, SessionError);

impl Run {
    fn go(&mut self, device: &mut dyn ParamDevice, plan: &Plan) -> Result<(), Stop> {
        self.outcome.by_hand = by_hand(device, plan).map_err(|e| (None, e))?;
        let progress = Progress::steps(plan.writes.len(), 2, "writing");
        let mut failures: Vec<(usize, String)> = Vec::new();
        let mut refused = Vec::new();
        for (i, (param, value)) in plan.writes.iter().enumerate() {
            progress.step(&param.name);
            if holds(device, param, value).map_err(|e| (None, e))? {
                self.attempted[i] = true;
                self.outcome.unchanged += 1;
                continue;
            }
            let written = write_and_verify(device, param, value).map_err(|e| (Some(i), e))?;
            self.attempted[i] = true;
            match written {
                Written::Verified => self.written.push(i),
                Written::Refused(why) => refused.push((i, why)),
                Written::Failed(why) => failures.push((i, why)),
            }
        }
        let result = self.retry_and_check(device, plan, refused, &mut failures);
        failures.sort_by_key(|(i, _)| *i);
        self.outcome.failed = failures
            .into_iter()
            .map(|(i, why)| (plan.writes[i].0.name.clone(), why))
            .collect();
        result
    }

    /// Tries the refused writes once more, then reads every written value again.
    fn retry_and_check(
        &mut self,
        device: &mut dyn ParamDevice,
        plan: &Plan,
        refused: Vec<(usize, String)>,
        failures: &mut Vec<(usize, String)>,
    ) -> Result<(), Stop> {
        let mut refused = refused.into_iter();
        while let Some((i, why)) = refused.next() {
            let (param, value) = &plan.writes[i];
            match write_and_verify(device, param, value) {
                Ok(Written::Verified) => self.written.push(i),
                Ok(Written::Refused(_)) => failures.push((i, why)),
                Ok(Written::Failed(again)) => failures.push((i, again)),
                Err(e) => {
                    // Those not tried again stay refused, as the first try left them.
                    failures.extend(refused);
                    return Err((Some(i), e));
                }
            }
        }
        self.written.sort_unstable();
        let mut verified = Vec::new();
        for &i in &self.written {
            let (param, value) = &plan.writes[i];
            match device.read(param) {
                Ok(now) if param.tolerance.same(&now.value, value) => verified.push(i),
                Ok(now) => failures.push((
                    i,
                    format!("wrote {value}, a later write changed it to {}", now.value),
                )),
                Err(e) if per_parameter(&e) => failures.push((i, e.to_string())),
                Err(e) => return Err((None, e)),
            }
        }
        self.outcome.verified = verified
            .into_iter()
            .map(|i| plan.writes[i].0.name.clone())
            .collect();
        Ok(())
    }
}

/// The lines a restore would send (`--dry-run`): reads the module and lists the writes of the
/// values that differ, then the store steps of those; and the lines to send by hand.
pub fn dry_run(
    device: &mut dyn ParamDevice,
    plan: &Plan,
    store: bool,
) -> Result<(Vec<String>, Vec<String>), SessionError> {
    let mut lines = Vec::new();
    let mut written = Vec::new();
    for (param, value) in &plan.writes {
        if !holds(device, param, value)? {
            lines.push(device.write_line(param, value));
            written.push(param.name.clone());
        }
    }
    if store {
        let params: Vec<&ParamRef> = storable(plan, &written).collect();
        lines.extend(device.store_steps(&params).into_iter().map(|s| s.line));
    }
    Ok((lines, by_hand(device, plan)?))
}

/// The parameters among `written` that the module keeps over a power cycle once stored, in the
/// restore order.
pub fn storable<'a>(plan: &'a Plan, written: &'a [String]) -> impl Iterator<Item = &'a ParamRef> {
    plan.writes
        .iter()
        .map(|(p, _)| p)
        .filter(|p| p.access.store && written.contains(&p.name))
}

/// Makes the parameters the restore wrote permanent (TMCL STAP/STGP, SMD4 STORE).
pub fn store(
    device: &mut dyn ParamDevice,
    plan: &Plan,
    outcome: &mut Outcome,
) -> Result<(), SessionError> {
    let params: Vec<&ParamRef> = storable(plan, &outcome.verified).collect();
    let steps = device.store_steps(&params);
    let progress = Progress::steps(steps.len(), 2, "storing");
    for step in &steps {
        // A step of one parameter is named by it; one for the whole configuration by its line.
        let name = match step.params.as_slice() {
            [one] if !step.whole => one.name.clone(),
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
/// `by_hand`, the lines to send by hand for the manual settings that differ.
pub fn write_skipped(plan: &Plan, by_hand: &[String], out: &mut dyn Write) -> io::Result<()> {
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
        if reason == Reason::Manual {
            for line in by_hand {
                writeln!(out, "  by hand: {line}")?;
            }
        }
    }
    Ok(())
}

/// Prints the outcome: what was written and verified, failures, what an interrupted restore did
/// not do, the stored count (to `memory`, "EEPROM").
pub fn write_outcome(outcome: &Outcome, memory: &str, out: &mut dyn Write) -> io::Result<()> {
    let verified = &outcome.verified;
    if verified.is_empty() && outcome.failed.is_empty() && outcome.unfinished.is_none() {
        writeln!(
            out,
            "nothing to write: the module already has the snapshot's value for all {} settings",
            outcome.unchanged
        )?;
    } else {
        writeln!(
            out,
            "restored {}, each read back and verified{}; {} already had the snapshot's value",
            crate::count::counted(verified.len(), "parameter"),
            list(verified),
            outcome.unchanged
        )?;
    }
    for (name, what) in &outcome.failed {
        writeln!(out, "FAILED {name}: {what}")?;
    }
    if let Some(unfinished) = &outcome.unfinished {
        writeln!(out, "the restore stopped: {}", unfinished.error)?;
        if let Some(name) = &unfinished.in_flight {
            writeln!(
                out,
                "UNKNOWN {name}: it was being written; read it to see which value it has"
            )?;
        }
        if !unfinished.not_written.is_empty() {
            writeln!(
                out,
                "NOT REACHED {} (neither compared nor written): {}",
                unfinished.not_written.len(),
                unfinished.not_written.join(", ")
            )?;
        }
    }
    if outcome.stored > 0 {
        writeln!(
            out,
            "stored {} to {memory}",
            crate::count::counted(outcome.stored, "parameter")
        )?;
    }
    Ok(())
}

/// " (a, b, c)" for a list of names, nothing for none.
fn list(names: &[String]) -> String {
    if names.is_empty() {
        String::new()
    } else {
        format!(" ({})", names.join(", "))
    }
}
