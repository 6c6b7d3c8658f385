//! The checks of `[[command]]` and `[[extra_command]]` rows: unique numbers and mnemonics, the
//! value range, `param_use`, and the type keywords of each command.

use std::collections::HashMap;

use super::{Problem, Step, check_range};
use crate::dialect::tmcl::profile::load::{CommandRow, KeywordRow};

/// Which rows have already used a command number or a mnemonic, for duplicates.
#[derive(Default)]
struct Seen {
    numbers: HashMap<u8, Vec<Step>>,
    mnemonics: HashMap<String, Vec<Step>>,
}

/// Every problem of one command table (`table` is its key in the file).
pub(super) fn check_commands(
    rows: &[CommandRow],
    table: &'static str,
    problems: &mut Vec<Problem>,
) {
    let mut seen = Seen::default();
    for (i, row) in rows.iter().enumerate() {
        let at = |key| vec![Step::Key(table), Step::Row(i), Step::Key(key)];
        check_number_unique(&mut seen, row, at, problems);
        check_mnemonic(&mut seen, row, at, problems);
        check_range(row.value_range, at("value_range"), "value_range", problems);
        check_param_use(row, at, problems);
        check_keywords(table, i, row, problems);
    }
}

/// A command number is defined once.
fn check_number_unique(
    seen: &mut Seen,
    row: &CommandRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    match seen.numbers.get(&row.number) {
        Some(first) => problems.push(
            Problem::at(
                at("number"),
                format!("command {} is defined twice", row.number),
            )
            .also(first.clone()),
        ),
        None => {
            seen.numbers.insert(row.number, at("number"));
        }
    }
}

/// A mnemonic is letters and digits (or empty), and defined once in any case.
fn check_mnemonic(
    seen: &mut Seen,
    row: &CommandRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    if !row.mnemonic.chars().all(|c| c.is_ascii_alphanumeric()) {
        problems.push(Problem::at(
            at("mnemonic"),
            format!(
                "mnemonic \"{}\" must be letters and digits (empty for control functions)",
                row.mnemonic.escape_debug()
            ),
        ));
    } else if !row.mnemonic.is_empty() {
        let key = row.mnemonic.to_ascii_uppercase();
        match seen.mnemonics.get(&key) {
            Some(first) => problems.push(
                Problem::at(at("mnemonic"), format!("mnemonic {key} is defined twice"))
                    .also(first.clone()),
            ),
            None => {
                seen.mnemonics.insert(key, at("mnemonic"));
            }
        }
    }
}

/// `param_use` is read, write or store.
fn check_param_use(
    row: &CommandRow,
    at: impl Fn(&'static str) -> Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    let Some(param_use) = &row.param_use else {
        return;
    };
    if !["read", "write", "store"].contains(&param_use.as_str()) {
        problems.push(Problem::at(
            at("param_use"),
            format!(
                "param_use \"{}\" is not read, write or store",
                param_use.escape_debug()
            ),
        ));
    }
}

/// The type keywords of a command: well-formed names, one keyword per type value, each name once.
fn check_keywords(table: &'static str, i: usize, row: &CommandRow, problems: &mut Vec<Problem>) {
    let mut values: HashMap<u8, Vec<Step>> = HashMap::new();
    let mut names: HashMap<String, Vec<Step>> = HashMap::new();
    for (k, keyword) in row.types.iter().enumerate() {
        let at = |key| {
            vec![
                Step::Key(table),
                Step::Row(i),
                Step::Key("types"),
                Step::Row(k),
                Step::Key(key),
            ]
        };
        if !keyword_name_is_valid(keyword) {
            problems.push(Problem::at(
                at("name"),
                format!(
                    "keyword \"{}\" of command {} must be letters, digits and _",
                    keyword.name.escape_debug(),
                    row.number
                ),
            ));
            continue;
        }
        let name = keyword.name.to_ascii_uppercase();
        if let Some(first) = values.insert(keyword.value, at("value")) {
            problems.push(
                Problem::at(
                    at("value"),
                    format!(
                        "command {}: type {} has two keywords",
                        row.number, keyword.value
                    ),
                )
                .also(first),
            );
        }
        if let Some(first) = names.insert(name.clone(), at("name")) {
            problems.push(
                Problem::at(
                    at("name"),
                    format!("command {}: keyword {name} is defined twice", row.number),
                )
                .also(first),
            );
        }
    }
}

/// A keyword is typed: letters, digits and _, not empty.
fn keyword_name_is_valid(keyword: &KeywordRow) -> bool {
    !keyword.name.is_empty()
        && keyword
            .name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_')
}
