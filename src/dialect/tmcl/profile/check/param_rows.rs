//! The checks of `[[axis_parameter]]` and `[[global_parameter]]` rows: numbers, identifiers,
//! access, range and default of each row, then duplicates across the table.

use std::collections::HashMap;

use super::{MAX_NUMBER, PLACEHOLDER, Problem, Step, check_range, decoding};
use crate::dialect::tmcl::profile::load::ParamRow;

/// Which rows have already used a number or an identifier, for duplicates.
#[derive(Default)]
struct Seen {
    numbers: HashMap<(u8, i64), Vec<Step>>,
    idents: HashMap<String, Vec<Step>>,
}

/// Every problem of one parameter table (`table` is its key in the file).
pub(super) fn check_params(rows: &[ParamRow], table: &'static str, problems: &mut Vec<Problem>) {
    let mut seen = Seen::default();
    let what = match table {
        "axis_parameter" => "axis parameter",
        _ => "global parameter",
    };
    for (i, row) in rows.iter().enumerate() {
        let at = |key| vec![Step::Key(table), Step::Row(i), Step::Key(key)];
        let before = problems.len();
        if row.number == PLACEHOLDER {
            continue; // placeholder rows define no parameter
        }
        check_numbers(row, at, problems);
        check_words(row, at, problems);
        check_range(row.range, at("range"), "range", problems);
        check_default(row, at, problems);
        decoding::check(table, i, row, problems);
        if problems.len() > before {
            continue; // duplicates of a broken row would only repeat its problem
        }
        check_numbers_unique(&mut seen, table, what, row, at, problems);
        check_idents_unique(&mut seen, what, row, at, problems);
    }
}

/// `number` and `number_last` lie in 0..255, in that order.
fn check_numbers(
    row: &ParamRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    if !(0..=MAX_NUMBER).contains(&row.number) {
        problems.push(Problem::at(
            at("number"),
            format!(
                "number {} is outside 0..{MAX_NUMBER} (-1 marks a placeholder row)",
                row.number
            ),
        ));
    }
    if let Some(number_last) = row.number_last {
        if number_last > MAX_NUMBER || number_last < row.number {
            problems.push(Problem::at(
                at("number_last"),
                format!(
                    "number_last {number_last} must lie between number ({}) and {MAX_NUMBER}",
                    row.number
                ),
            ));
        }
    }
}

/// An identifier users can type, a name (but for a spanning row) and known access letters.
fn check_words(
    row: &ParamRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    if let Some(problem) = ident_problem(&row.ident) {
        problems.push(Problem::at(at("ident"), problem));
    }
    if row.name.trim().is_empty() && row.number_last.is_none() {
        problems.push(Problem::at(at("name"), "name must not be empty"));
    }
    if let Some(bad) = row.access.chars().find(|c| !"RWErwe".contains(*c)) {
        problems.push(Problem::at(
            at("access"),
            format!(
                "access \"{}\" has the unknown letter {bad:?}; use R (read), W (write), \
                 E (stored in EEPROM)",
                row.access.escape_debug()
            ),
        ));
    }
}

/// The default lies within the range, or without a range within 32 bits.
fn check_default(
    row: &ParamRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    let Some(default) = row.default else { return };
    match row.range {
        Some([lo, hi]) if lo <= hi && !(lo..=hi).contains(&default) => {
            problems.push(Problem::at(
                at("default"),
                format!("default {default} lies outside the range {lo}..{hi}"),
            ));
        }
        None if i32::try_from(default).is_err() => problems.push(Problem::at(
            at("default"),
            format!("default {default} is not a 32-bit value"),
        )),
        _ => {}
    }
}

/// Each number of the row (each of a spanning row) is defined once per bank.
fn check_numbers_unique(
    seen: &mut Seen,
    table: &str,
    what: &str,
    row: &ParamRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    let last = row.number_last.unwrap_or(row.number);
    for number in row.number..=last {
        let key = (row.bank, number);
        match seen.numbers.get(&key) {
            Some(first) => problems.push(
                Problem::at(
                    at("number"),
                    format!(
                        "{what} {} is defined twice",
                        numbered(table, row.bank, number)
                    ),
                )
                .also(first.clone()),
            ),
            None => {
                seen.numbers.insert(key, at("number"));
            }
        }
    }
}

/// Each identifier the row makes is defined once in the table.
fn check_idents_unique(
    seen: &mut Seen,
    what: &str,
    row: &ParamRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    for ident in idents(row) {
        match seen.idents.get(&ident) {
            Some(first) => problems.push(
                Problem::at(
                    at("ident"),
                    format!("{what} identifier '{ident}' is defined twice"),
                )
                .also(first.clone()),
            ),
            None => {
                seen.idents.insert(ident, at("ident"));
            }
        }
    }
}

fn numbered(table: &str, bank: u8, number: i64) -> String {
    if table == "axis_parameter" {
        number.to_string()
    } else {
        format!("{number} of bank {bank}")
    }
}

/// The identifiers a row defines (one per number for a `number_last` row), as looked up.
fn idents(row: &ParamRow) -> Vec<String> {
    let ident = row.ident.to_ascii_lowercase();
    match row.number_last {
        None => vec![ident],
        Some(last) => (row.number..=last.min(MAX_NUMBER))
            .map(|n| format!("{ident}_{n}"))
            .collect(),
    }
}

/// What is wrong with an identifier users are to type, if anything.
fn ident_problem(ident: &str) -> Option<String> {
    let mut chars = ident.chars();
    let Some(first) = chars.next() else {
        return Some("ident must not be empty".into());
    };
    let well_formed = (first.is_ascii_alphabetic() || first == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    (!well_formed).then(|| {
        format!(
            "ident \"{}\" must be letters, digits and _ (no spaces), starting with a letter or _",
            ident.escape_debug()
        )
    })
}
