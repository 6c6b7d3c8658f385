//! A profile file checked at the door: every row is checked before the profile is used, and each
//! problem names the line of the file it is on. A wrong table would otherwise show up much later —
//! as a value the validator lets through, a name that cannot be typed, a simulator that never
//! answers — far from its cause.
//!
//! The checks work on the parsed rows and name a place (a path of keys and row numbers); only
//! when something is wrong is the file parsed a second time, keeping spans, to turn places into
//! line numbers.

use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::commands::CommandTable;
use super::load::ProfileFile;

mod command_rows;
mod decoding;
mod family;
mod param_rows;

/// One step of a place in the file: a key of a table, or a row of an array.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Step {
    /// A key.
    Key(&'static str),
    /// The n-th element of an array (from 0).
    Row(usize),
}

/// Something wrong, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Problem {
    place: Vec<Step>,
    message: String,
    /// Where the other half of a conflict (a duplicate) is.
    first: Option<Vec<Step>>,
}

impl Problem {
    pub(crate) fn at(place: Vec<Step>, message: impl Into<String>) -> Self {
        Problem {
            place,
            message: message.into(),
            first: None,
        }
    }

    pub(crate) fn also(mut self, first: Vec<Step>) -> Self {
        self.first = Some(first);
        self
    }
}

/// The largest parameter, command or keyword number.
const MAX_NUMBER: i64 = 255;
/// A number of -1 marks a placeholder row (a bank whose contents are unknown).
const PLACEHOLDER: i64 = -1;

/// Every problem of the file's rows, in file order of the checks. `base` is the command table a
/// file without `[[command]]` rows starts from.
pub(crate) fn check(file: &ProfileFile, base: Option<&CommandTable>) -> Vec<Problem> {
    let mut problems = Vec::new();
    check_meta(file, &mut problems);
    param_rows::check_params(&file.axis_parameter, "axis_parameter", &mut problems);
    param_rows::check_params(&file.global_parameter, "global_parameter", &mut problems);
    command_rows::check_commands(&file.command, "command", &mut problems);
    command_rows::check_commands(&file.extra_command, "extra_command", &mut problems);
    check_simulation(file, &mut problems);
    family::check(file, base, &mut problems);
    problems
}

fn check_meta(file: &ProfileFile, problems: &mut Vec<Problem>) {
    let at = |key| vec![Step::Key("meta"), Step::Key(key)];
    if file.meta.module.trim().is_empty() {
        problems.push(Problem::at(at("module"), "module must name the module"));
    } else if file.meta.module.chars().any(char::is_control) {
        problems.push(Problem::at(
            at("module"),
            "module must not contain control characters",
        ));
    }
    if file.meta.axes == 0 {
        problems.push(Problem::at(
            at("axes"),
            "axes must be at least 1 (motors are numbered 0..axes-1)",
        ));
    }
    if file.meta.tmcl_program_memory_commands == 0 {
        problems.push(Problem::at(
            at("tmcl_program_memory_commands"),
            "tmcl_program_memory_commands must be at least 1",
        ));
    }
}

pub(crate) fn check_range(
    range: Option<[i64; 2]>,
    place: Vec<Step>,
    key: &str,
    problems: &mut Vec<Problem>,
) {
    let Some([lo, hi]) = range else { return };
    if lo > hi {
        problems.push(Problem::at(
            place,
            format!("{key} [{lo}, {hi}] is reversed: the low end comes first"),
        ));
    } else if i32::try_from(lo).is_err() || i32::try_from(hi).is_err() {
        problems.push(Problem::at(
            place,
            format!("{key} [{lo}, {hi}] reaches beyond 32-bit values"),
        ));
    }
}

fn check_simulation(file: &ProfileFile, problems: &mut Vec<Problem>) {
    let Some(sim) = &file.simulation else { return };
    let at = |key| vec![Step::Key("simulation"), Step::Key(key)];
    let positive = [
        ("velocity_pps_per_unit", sim.velocity_pps_per_unit),
        ("acceleration_pps2_per_unit", sim.acceleration_pps2_per_unit),
        ("encoder_usteps_per_count", sim.encoder_usteps_per_count),
    ];
    for (key, value) in positive {
        if value.is_some_and(|v| !(v.is_finite() && v > 0.0)) {
            problems.push(Problem::at(
                at(key),
                format!("{key} must be a positive number"),
            ));
        }
    }
    let at_least_one = [
        ("tick_ms", sim.tick_ms.map(u64::from)),
        ("frame_timeout_ms", sim.frame_timeout_ms.map(u64::from)),
        ("ascii_line_max", sim.ascii_line_max.map(|v| v as u64)),
    ];
    for (key, value) in at_least_one {
        if value == Some(0) {
            problems.push(Problem::at(at(key), format!("{key} must be at least 1")));
        }
    }
    let roles = sim.axis_roles.as_ref().map(|r| r.all()).unwrap_or_default();
    for (role, number) in roles.iter().filter_map(|(r, n)| Some((r, (*n)?))) {
        let n = i64::from(number);
        let defined = file
            .axis_parameter
            .iter()
            .any(|row| (row.number..=row.number_last.unwrap_or(row.number)).contains(&n));
        if !defined {
            problems.push(Problem::at(
                at("axis_roles"),
                format!("axis_roles.{role} = {number} names no [[axis_parameter]] row"),
            ));
        }
    }
}

/// The problems as `line N: …` lines, sorted by line. Lines come from a spanned parse of `text`.
pub(crate) fn render(text: &str, problems: &[Problem]) -> Vec<String> {
    let root = DeTable::parse(text).ok();
    let line = |place: &[Step]| root.as_ref().map(|root| line_of(text, root, place));
    let mut lines: Vec<(usize, String)> = problems
        .iter()
        .map(|p| {
            let at = line(&p.place).unwrap_or(0);
            let first = p
                .first
                .as_deref()
                .and_then(line)
                .map(|n| format!(" (first on line {n})"))
                .unwrap_or_default();
            (at, format!("line {at}: {}{first}", p.message))
        })
        .collect();
    lines.sort_by_key(|(at, _)| *at);
    lines.dedup();
    lines.into_iter().map(|(_, text)| text).collect()
}

/// A TOML parse or schema error as `line N: message`.
pub(crate) fn render_toml_error(text: &str, error: &toml::de::Error) -> String {
    let message = error.message().trim_end();
    match error.span() {
        Some(span) => format!("line {}: {message}", line_at(text, span.start)),
        None => message.to_string(),
    }
}

/// The line of `place`, or of the nearest enclosing table or row that exists (a missing key is
/// reported on its row's header).
fn line_of(text: &str, root: &Spanned<DeTable<'_>>, place: &[Step]) -> usize {
    let mut span = root.span();
    let mut value: Option<&DeValue<'_>> = None;
    let mut table: Option<&DeTable<'_>> = Some(root.get_ref());
    for step in place {
        let next = match (step, table, value) {
            (Step::Key(key), Some(t), _) => t.get(*key),
            (Step::Row(i), _, Some(DeValue::Array(items))) => items.get(*i),
            _ => None,
        };
        let Some(next) = next else { break };
        span = next.span();
        value = Some(next.get_ref());
        table = match next.get_ref() {
            DeValue::Table(t) => Some(t),
            _ => None,
        };
    }
    line_at(text, span.start)
}

fn line_at(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

#[cfg(test)]
mod tests;
