//! The checks of the family fields (`data/profiles/README.md`): identification, the ASCII
//! interface and allow-list, how the command set differs from the built-in table, the rules on
//! commands and parameters (`banks`, `range_when`, `type_ignored`) and the I/O map.

use std::collections::{BTreeSet, HashMap};

use super::{Problem, Step, check_range};
use crate::dialect::tmcl::profile::commands::{CommandTable, OperandKind};
use crate::dialect::tmcl::profile::family::{self, AsciiInterface, Condition, GENERATIONS};
use crate::dialect::tmcl::profile::load::{
    CommandRow, CommandsSection, Meta, ProfileFile, RangeWhenRow,
};
use crate::dialect::tmcl::profile::version;

mod io;

/// Every problem of the family fields.
pub(super) fn check(file: &ProfileFile, base: Option<&CommandTable>, problems: &mut Vec<Problem>) {
    check_identity(file, problems);
    check_generic(file, problems);
    check_command_set(file, base, problems);
    for (table, rows) in [
        ("command", &file.command),
        ("extra_command", &file.extra_command),
    ] {
        for (i, row) in rows.iter().enumerate() {
            check_command_rules(file, table, i, row, problems);
        }
    }
    for (table, rows) in [
        ("axis_parameter", &file.axis_parameter),
        ("global_parameter", &file.global_parameter),
    ] {
        for (i, row) in rows.iter().enumerate() {
            let at = vec![Step::Key(table), Step::Row(i)];
            check_range_when(file, &row.range_when, at, problems);
        }
    }
    check_ascii(file, base, problems);
    io::check_io(file, problems);
    check_interrupts(file, problems);
}

/// `[[interrupt]]`: a known kind, each number once (255 is EI/DI's "all"), configured by a
/// bank-3 parameter the file has.
fn check_interrupts(file: &ProfileFile, problems: &mut Vec<Problem>) {
    let mut seen = BTreeSet::new();
    for (i, row) in file.interrupt.iter().enumerate() {
        let at = |key| vec![Step::Key("interrupt"), Step::Row(i), Step::Key(key)];
        if family::InterruptKind::parse(&row.kind).is_none() {
            problems.push(Problem::at(
                at("kind"),
                format!(
                    "interrupt kind '{}' is none of timer, stop_left, stop_right, input, \
                     position_reached",
                    row.kind.escape_debug()
                ),
            ));
        }
        if row.number == family::ALL_INTERRUPTS || !seen.insert(row.number) {
            problems.push(Problem::at(
                at("number"),
                format!(
                    "interrupt {} is given twice or is 255 (all interrupts)",
                    row.number
                ),
            ));
        }
        if let Some(number) = row.config {
            let condition = Condition {
                kind: crate::dialect::tmcl::profile::ParamKind::Global { bank: 3 },
                number,
                equals: 0,
            };
            if !family::defines(file, &condition) {
                problems.push(Problem::at(
                    at("config"),
                    format!(
                        "interrupt {}: no bank-3 global parameter {number}",
                        row.number
                    ),
                ));
            }
        }
    }
}

fn meta(key: &'static str) -> Vec<Step> {
    vec![Step::Key("meta"), Step::Key(key)]
}

fn check_identity(file: &ProfileFile, problems: &mut Vec<Problem>) {
    let m = &file.meta;
    let format = m.module_number.and_then(version::format_for);
    check_module_number(m.module_number, format, problems);
    check_version_prefix(m, problems);
    check_version_format(m, format, problems);
    check_bootloader_format(m, problems);
    check_simulated_version(file, problems);
    check_aliases(m, problems);
    check_ascii_interface(m, problems);
    check_parameter_generation(m, problems);
}

/// A module number has a version format (three or four digits).
fn check_module_number(
    number: Option<u32>,
    format: Option<&'static str>,
    problems: &mut Vec<Problem>,
) {
    if let Some(number) = number {
        if format.is_none() {
            problems.push(Problem::at(
                meta("module_number"),
                format!("module_number {number}: TMCL module numbers have three or four digits"),
            ));
        }
    }
}

/// `version_prefix` is the module number's digits, which command 136 answers first.
fn check_version_prefix(m: &Meta, problems: &mut Vec<Problem>) {
    let Some(prefix) = &m.version_prefix else {
        return;
    };
    match m.module_number {
        None => problems.push(Problem::at(
            meta("version_prefix"),
            "version_prefix needs the module_number it is the digits of",
        )),
        Some(number) if *prefix != number.to_string() => problems.push(Problem::at(
            meta("version_prefix"),
            format!(
                "version_prefix \"{}\" is not the module number {number}: command 136 \
                 answers with the module number first",
                prefix.escape_debug()
            ),
        )),
        Some(_) => {}
    }
}

/// `version_format` is the format of the module number's length (either, without a number).
fn check_version_format(m: &Meta, format: Option<&'static str>, problems: &mut Vec<Problem>) {
    let Some(written) = &m.version_format else {
        return;
    };
    let expected: &[&str] = match format {
        Some(f) => &[f][..],
        None => &["NNNVa.bc", "NNNNVabc"],
    };
    if !expected.contains(&written.as_str()) {
        problems.push(Problem::at(
            meta("version_format"),
            format!(
                "version_format \"{}\" must be {} (136 answers eight characters)",
                written.escape_debug(),
                expected.join(" or ")
            ),
        ));
    }
}

/// `bootloader_format` is the `version_format` with B for V.
fn check_bootloader_format(m: &Meta, problems: &mut Vec<Problem>) {
    let Some(loader) = &m.bootloader_format else {
        return;
    };
    let expected = m.version_format.as_ref().map(|f| f.replacen('V', "B", 1));
    match expected {
        Some(expected) if *loader != expected => problems.push(Problem::at(
            meta("bootloader_format"),
            format!(
                "bootloader_format \"{}\" must be the version_format with B for V: \
                 \"{expected}\"",
                loader.escape_debug()
            ),
        )),
        None => problems.push(Problem::at(
            meta("bootloader_format"),
            "bootloader_format needs the version_format it varies",
        )),
        Some(_) => {}
    }
}

/// The simulator's `version_string` has the module's format and prefix.
fn check_simulated_version(file: &ProfileFile, problems: &mut Vec<Problem>) {
    let m = &file.meta;
    let simulated = file
        .simulation
        .as_ref()
        .and_then(|s| s.version_string.as_ref());
    let (Some(text), Some(format)) = (simulated, &m.version_format) else {
        return;
    };
    let prefix = m.version_prefix.as_deref().unwrap_or("");
    if !version::fits(text, format) || !text.starts_with(prefix) {
        problems.push(Problem::at(
            vec![Step::Key("simulation"), Step::Key("version_string")],
            format!(
                "version_string \"{}\" does not have the module's format {format}{}",
                text.escape_debug(),
                if prefix.is_empty() {
                    String::new()
                } else {
                    format!(" starting with {prefix}")
                }
            ),
        ));
    }
}

/// Aliases are product names without spaces, other than the module's own, each given once.
fn check_aliases(m: &Meta, problems: &mut Vec<Problem>) {
    let mut aliases: HashMap<String, usize> = HashMap::new();
    for (k, alias) in m.aliases.iter().enumerate() {
        let at = vec![Step::Key("meta"), Step::Key("aliases"), Step::Row(k)];
        if alias.trim().is_empty() || alias.chars().any(|c| c.is_control() || c.is_whitespace()) {
            problems.push(Problem::at(
                at,
                format!(
                    "alias \"{}\" must be a product name without spaces",
                    alias.escape_debug()
                ),
            ));
        } else if alias.eq_ignore_ascii_case(&m.module) {
            problems.push(Problem::at(
                at,
                format!("alias {alias} is the module's own name"),
            ));
        } else if aliases.insert(alias.to_ascii_lowercase(), k).is_some() {
            problems.push(Problem::at(at, format!("alias {alias} is given twice")));
        }
    }
}

/// `ascii_interface` is one of the words [`AsciiInterface`] knows.
fn check_ascii_interface(m: &Meta, problems: &mut Vec<Problem>) {
    let Some(word) = &m.ascii_interface else {
        return;
    };
    if AsciiInterface::parse(word).is_none() {
        problems.push(Problem::at(
            meta("ascii_interface"),
            format!(
                "ascii_interface \"{}\" must be yes, no or unconfirmed",
                word.escape_debug()
            ),
        ));
    }
}

/// `parameter_generation` is one of [`GENERATIONS`].
fn check_parameter_generation(m: &Meta, problems: &mut Vec<Problem>) {
    let Some(generation) = &m.parameter_generation else {
        return;
    };
    if !GENERATIONS.contains(&generation.as_str()) {
        problems.push(Problem::at(
            meta("parameter_generation"),
            format!(
                "parameter_generation \"{}\" must be one of {} (data/profiles/README.md)",
                generation.escape_debug(),
                GENERATIONS.join(", ")
            ),
        ));
    }
}

fn check_generic(file: &ProfileFile, problems: &mut Vec<Problem>) {
    if !file.meta.generic {
        return;
    }
    for (table, empty) in [
        ("axis_parameter", file.axis_parameter.is_empty()),
        ("global_parameter", file.global_parameter.is_empty()),
    ] {
        if !empty {
            problems.push(Problem::at(
                vec![Step::Key(table), Step::Row(0)],
                "a generic profile knows parameters by number only: it has no parameter rows",
            ));
        }
    }
}

/// `[commands]` and `[[extra_command]]` against the table they change.
fn check_command_set(file: &ProfileFile, base: Option<&CommandTable>, problems: &mut Vec<Problem>) {
    let own = !file.command.is_empty();
    if let Some(section) = &file.commands {
        check_commands_section(section, own, base, problems);
    }
    if own && !file.extra_command.is_empty() {
        problems.push(Problem::at(
            vec![Step::Key("extra_command"), Step::Row(0)],
            "[[extra_command]] adds to the built-in command table, but this file has its own \
             [[command]] rows: make it a [[command]] row",
        ));
    }
    let Some(base) = base.filter(|_| !own) else {
        return;
    };
    check_extra_commands_are_new(file, base, problems);
    check_command_ranges(file, base, problems);
}

/// A `[[command_range]]` row names a command the module has, by its number and mnemonic, with
/// a range from low to high.
fn check_command_ranges(file: &ProfileFile, base: &CommandTable, problems: &mut Vec<Problem>) {
    let absent: &[u8] = file.commands.as_ref().map_or(&[], |c| &c.absent);
    for (i, row) in file.command_range.iter().enumerate() {
        let at = |key| vec![Step::Key("command_range"), Step::Row(i), Step::Key(key)];
        match base.by_number(row.number) {
            Some(spec) if !absent.contains(&row.number) => {
                if !spec.mnemonic.eq_ignore_ascii_case(&row.mnemonic) {
                    problems.push(Problem::at(
                        at("mnemonic"),
                        format!(
                            "command {} is {}, not {}",
                            row.number,
                            spec.display_name(),
                            row.mnemonic.escape_debug()
                        ),
                    ));
                }
            }
            _ => problems.push(Problem::at(
                at("number"),
                format!("command {} is not in this module's table", row.number),
            )),
        }
        let [lo, hi] = row.value_range;
        if lo > hi {
            problems.push(Problem::at(
                at("value_range"),
                format!("value_range [{lo}, {hi}] runs backwards"),
            ));
        }
    }
}

/// `[commands]` changes the built-in table (not a file's own rows): its `base` and the
/// commands it marks `absent`, each once and each in that table.
fn check_commands_section(
    section: &CommandsSection,
    own: bool,
    base: Option<&CommandTable>,
    problems: &mut Vec<Problem>,
) {
    let at = |key| vec![Step::Key("commands"), Step::Key(key)];
    if own {
        problems.push(Problem::at(
            vec![Step::Key("commands")],
            "[commands] changes the built-in command table, but this file has its own \
             [[command]] rows: leave the command out instead",
        ));
    }
    if let Some(word) = &section.base {
        if word != "builtin" {
            problems.push(Problem::at(
                at("base"),
                format!(
                    "base \"{}\" must be \"builtin\" (the only table a profile starts from)",
                    word.escape_debug()
                ),
            ));
        }
    }
    let mut seen = BTreeSet::new();
    for (k, &number) in section.absent.iter().enumerate() {
        let at = vec![Step::Key("commands"), Step::Key("absent"), Step::Row(k)];
        if !seen.insert(number) {
            problems.push(Problem::at(
                at,
                format!("absent command {number} is given twice"),
            ));
        } else if let Some(base) = base {
            if base.by_number(number).is_none() {
                problems.push(Problem::at(
                    at,
                    format!("absent command {number} is not in the built-in command table"),
                ));
            }
        }
    }
}

/// An extra command takes neither the number nor the mnemonic of a command the built-in table
/// keeps (one marked absent may come back).
fn check_extra_commands_are_new(
    file: &ProfileFile,
    base: &CommandTable,
    problems: &mut Vec<Problem>,
) {
    let absent: &[u8] = file.commands.as_ref().map_or(&[], |c| &c.absent);
    for (i, row) in file.extra_command.iter().enumerate() {
        let at = |key| vec![Step::Key("extra_command"), Step::Row(i), Step::Key(key)];
        if let Some(spec) = base.by_number(row.number) {
            if !absent.contains(&row.number) {
                problems.push(Problem::at(
                    at("number"),
                    format!(
                        "command {} ({}) is in the built-in table already",
                        row.number,
                        spec.display_name()
                    ),
                ));
                continue;
            }
        }
        if let Some(spec) = base.by_mnemonic(&row.mnemonic) {
            if !absent.contains(&spec.number) {
                problems.push(Problem::at(
                    at("mnemonic"),
                    format!(
                        "mnemonic {} is command {} of the built-in table already",
                        spec.mnemonic, spec.number
                    ),
                ));
            }
        }
    }
}

/// `operands`, `banks`, `range_when` and `type_ignored` of one command row.
fn check_command_rules(
    file: &ProfileFile,
    table: &'static str,
    i: usize,
    row: &CommandRow,
    problems: &mut Vec<Problem>,
) {
    let at = |key| vec![Step::Key(table), Step::Row(i), Step::Key(key)];
    let kinds: Vec<Option<OperandKind>> = row
        .operands
        .iter()
        .map(|o| OperandKind::parse(o.strip_suffix('?').unwrap_or(o)))
        .collect();
    for (k, kind) in kinds.iter().enumerate() {
        if kind.is_none() {
            problems.push(Problem::at(
                vec![Step::Key(table), Step::Row(i)],
                format!(
                    "command {}: unknown operand kind '{}'",
                    row.number,
                    row.operands[k].escape_debug()
                ),
            ));
        }
    }
    let has = |kind: OperandKind| kinds.contains(&Some(kind));
    if let Some(banks) = &row.banks {
        if !has(OperandKind::Bank) {
            problems.push(Problem::at(
                at("banks"),
                format!(
                    "command {}: banks apply to a command with a bank operand",
                    row.number
                ),
            ));
        } else if banks.is_empty() {
            problems.push(Problem::at(
                at("banks"),
                format!("command {}: banks must name at least one bank", row.number),
            ));
        } else if banks.iter().collect::<BTreeSet<_>>().len() != banks.len() {
            problems.push(Problem::at(
                at("banks"),
                format!("command {}: a bank is given twice", row.number),
            ));
        }
    }
    if !row.range_when.is_empty() && !has(OperandKind::Value) {
        problems.push(Problem::at(
            at("range_when"),
            format!(
                "command {}: range_when applies to a command with a value operand",
                row.number
            ),
        ));
    }
    let place = vec![Step::Key(table), Step::Row(i)];
    check_range_when(file, &row.range_when, place, problems);
    if row.type_ignored && !row.types.is_empty() {
        problems.push(Problem::at(
            at("type_ignored"),
            format!(
                "command {}: type_ignored contradicts the keywords its type byte selects",
                row.number
            ),
        ));
    }
}

/// The `range_when` entries of a row at `row_place`.
fn check_range_when(
    file: &ProfileFile,
    entries: &[RangeWhenRow],
    row_place: Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    for (k, entry) in entries.iter().enumerate() {
        let at = |key| {
            let mut place = row_place.clone();
            place.extend([Step::Key("range_when"), Step::Row(k), Step::Key(key)]);
            place
        };
        check_range(Some(entry.range), at("range"), "range_when range", problems);
        let condition = match (entry.axis_parameter, entry.global_parameter) {
            (Some(number), None) => Condition {
                kind: crate::dialect::tmcl::profile::ParamKind::Axis,
                number,
                equals: entry.equals,
            },
            (None, Some(number)) => Condition {
                kind: crate::dialect::tmcl::profile::ParamKind::Global { bank: entry.bank },
                number,
                equals: entry.equals,
            },
            _ => {
                problems.push(Problem::at(
                    at("equals"),
                    "range_when names one parameter: axis_parameter or global_parameter (with bank)",
                ));
                continue;
            }
        };
        let key = if entry.axis_parameter.is_some() {
            "axis_parameter"
        } else {
            "global_parameter"
        };
        if !family::defines(file, &condition) {
            problems.push(Problem::at(
                at(key),
                format!(
                    "range_when depends on {}, which this profile does not define",
                    condition.describe().split(" = ").next().unwrap_or_default()
                ),
            ));
        }
    }
}

/// The ASCII interface and its allow-list against the command table.
fn check_ascii(file: &ProfileFile, base: Option<&CommandTable>, problems: &mut Vec<Problem>) {
    let interface = file
        .meta
        .ascii_interface
        .as_deref()
        .and_then(AsciiInterface::parse);
    let Some(list) = file
        .ascii
        .as_ref()
        .and_then(|a| a.allowed_commands.as_ref())
    else {
        return;
    };
    let list_at = vec![Step::Key("ascii"), Step::Key("allowed_commands")];
    if interface == Some(AsciiInterface::No) {
        problems.push(Problem::at(
            list_at,
            "a module without the ASCII interface (ascii_interface = \"no\") has no ASCII \
             allow-list",
        ));
        return;
    }
    let known = known_mnemonics(file, base);
    let seen = check_allowed_commands(list, &known, problems);
    // A file with its own rows states the list twice: both must say the same.
    if !file.command.is_empty() {
        check_list_matches_flags(file, &seen, list_at, problems);
    }
}

/// The mnemonics of the module's table (upper case), each with whether the module has it: a
/// command marked absent in `[commands]` is known but lacking.
fn known_mnemonics(file: &ProfileFile, base: Option<&CommandTable>) -> Vec<(String, bool)> {
    let absent: &[u8] = file.commands.as_ref().map_or(&[], |c| &c.absent);
    let mut known: Vec<(String, bool)> = Vec::new();
    if file.command.is_empty() {
        // Extra commands first: one may bring back an absent command under its number.
        known.extend(
            file.extra_command
                .iter()
                .map(|c| (c.mnemonic.to_ascii_uppercase(), true)),
        );
        if let Some(base) = base {
            known.extend(
                base.iter()
                    .map(|c| (c.mnemonic.clone(), !absent.contains(&c.number))),
            );
        }
    } else {
        known.extend(
            file.command
                .iter()
                .map(|c| (c.mnemonic.to_ascii_uppercase(), true)),
        );
    }
    known
}

/// Each word of `allowed_commands` is listed once and names a command the module has; returns
/// the words listed, in upper case.
fn check_allowed_commands(
    list: &[String],
    known: &[(String, bool)],
    problems: &mut Vec<Problem>,
) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    for (k, word) in list.iter().enumerate() {
        let at = vec![
            Step::Key("ascii"),
            Step::Key("allowed_commands"),
            Step::Row(k),
        ];
        let upper = word.to_ascii_uppercase();
        if !seen.insert(upper.clone()) {
            problems.push(Problem::at(
                at,
                format!("ASCII command {word} is listed twice"),
            ));
            continue;
        }
        if known.is_empty() {
            continue; // no table to check against (a file read without the built-in one)
        }
        match known.iter().find(|(m, _)| !m.is_empty() && *m == upper) {
            None => problems.push(Problem::at(
                at,
                format!("ASCII command {word} is not a command of this profile"),
            )),
            Some((_, false)) => problems.push(Problem::at(
                at,
                format!("ASCII command {word} is marked absent in [commands]"),
            )),
            Some(_) => {}
        }
    }
    seen
}

/// The `listed` commands are those of the file's `[[command]]` rows flagged `ascii_allowed`.
fn check_list_matches_flags(
    file: &ProfileFile,
    listed: &BTreeSet<String>,
    list_at: Vec<Step>,
    problems: &mut Vec<Problem>,
) {
    let flagged: BTreeSet<String> = file
        .command
        .iter()
        .filter(|c| c.ascii_allowed)
        .map(|c| c.mnemonic.to_ascii_uppercase())
        .collect();
    let missing: Vec<&String> = flagged.difference(listed).collect();
    let unflagged: Vec<&String> = listed.difference(&flagged).collect();
    if missing.is_empty() && unflagged.is_empty() {
        return;
    }
    let mut parts = Vec::new();
    if !missing.is_empty() {
        parts.push(format!(
            "ascii_allowed rows not listed: {}",
            joined(&missing)
        ));
    }
    if !unflagged.is_empty() {
        parts.push(format!(
            "listed without ascii_allowed: {}",
            joined(&unflagged)
        ));
    }
    problems.push(Problem::at(
        list_at,
        format!(
            "allowed_commands disagrees with the ascii_allowed flags of the [[command]] \
             rows ({})",
            parts.join("; ")
        ),
    ));
}

/// "A, B, C".
fn joined(words: &[&String]) -> String {
    words
        .iter()
        .map(|s| s.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests;
