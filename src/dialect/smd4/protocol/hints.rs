//! Completion of the hierarchical mnemonics (`MOTOR:`, `SYS:`, `COMS:NET:` …) and of argument
//! values, and the hint text (usage, unit, range, default) shown while typing. All from the table.

use crate::dialect::grammar::Candidate;

use super::commands::{ReplyShape, Smd4Command, Smd4CommandTable};

/// The line with its placeholder: `MOTOR:VMAX[,<FLOAT Hz>]`, `MOTOR:RUNV,<+|->`, `SYS:CLR`.
pub fn usage(spec: &Smd4Command) -> String {
    match &spec.arg {
        None => spec.mnemonic.clone(),
        Some(_) if spec.readable => format!("{}[,{}]", spec.mnemonic, placeholder(spec)),
        Some(_) => format!("{},{}", spec.mnemonic, placeholder(spec)),
    }
}

fn placeholder(spec: &Smd4Command) -> String {
    let Some(arg) = &spec.arg else {
        return String::new();
    };
    if !arg.choices.is_empty() && arg.choices.len() <= 6 {
        let values: Vec<&str> = arg.choices.iter().map(|c| c.value.as_str()).collect();
        return format!("<{}>", values.join("|"));
    }
    match spec.unit.as_str() {
        "" => format!("<{}>", arg.ty.name()),
        unit => format!("<{} {unit}>", arg.ty.name()),
    }
}

/// What the argument accepts: `1..15000 Hz, default 1000` or `0 Thermocouple | 1 RTD, default 0`.
pub fn arg_summary(spec: &Smd4Command) -> String {
    let Some(arg) = &spec.arg else {
        return "no argument".into();
    };
    let mut parts = Vec::new();
    if !arg.choices.is_empty() {
        let options: Vec<String> = arg
            .choices
            .iter()
            .map(|c| match c.label.as_str() {
                "" => c.value.clone(),
                label => format!("{} {label}", c.value),
            })
            .collect();
        parts.push(options.join(" | "));
    } else {
        let range = arg.range_text();
        let text = match (range.is_empty(), spec.unit.is_empty()) {
            (true, true) => arg.ty.name().to_string(),
            (true, false) => format!("{} {}", arg.ty.name(), spec.unit),
            (false, true) => range,
            (false, false) => format!("{range} {}", spec.unit),
        };
        parts.push(text);
    }
    if let Some(levels) = arg.levels {
        parts.push(format!("in {levels} steps"));
    }
    if let Some(default) = &spec.default {
        parts.push(format!("default {default}"));
    }
    parts.join(", ")
}

/// The commands whose mnemonic contains `filter` (any case), in the document's order: what
/// `tmclsh --protocol smd4 params` and the shell's `:params` list.
pub fn matching<'a>(
    table: &'a Smd4CommandTable,
    filter: &str,
) -> impl Iterator<Item = &'a Smd4Command> + 'a {
    let needle = filter.to_ascii_uppercase();
    table.iter().filter(move |s| s.mnemonic.contains(&needle))
}

/// One row of the command table: mnemonic, access (R, W, R/W) and what the argument accepts.
pub fn table_row(spec: &Smd4Command) -> String {
    let access = match (spec.readable, spec.writable) {
        (true, true) => "R/W",
        (true, false) => "R",
        (false, true) => "W",
        (false, false) => "",
    };
    let mark = if spec.uncertain {
        crate::dialect::UNCERTAIN
    } else {
        " "
    };
    format!(
        "{:<22}{mark} {:<4} {}",
        spec.mnemonic,
        access,
        arg_summary(spec)
    )
}

/// One line of help: usage, accepted values, access, the reply and the description.
pub fn hint(spec: &Smd4Command) -> String {
    let access = match (spec.readable, spec.writable, spec.arg.is_some()) {
        (true, true, true) => "read/write",
        (true, _, _) => "read-only",
        (false, true, true) => "write-only",
        _ => "runs an action",
    };
    let mut text = format!("{}  {access}", usage(spec));
    if spec.arg.is_some() {
        text.push_str(&format!(", {}", arg_summary(spec)));
    }
    if spec.arg.is_none() && !spec.unit.is_empty() {
        text.push_str(&format!(", in {}", spec.unit));
    }
    match spec.reply {
        ReplyShape::UserReal => text.push_str("; replies user,real value"),
        ReplyShape::MultiLine => text.push_str("; replies several lines"),
        _ => {}
    }
    if spec.requires_standby {
        text.push_str("; setting needs the motor in standby");
    }
    format!("{text} — {}", spec.description)
}

/// Candidates for the word that starts at byte `start` of the line.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct WordCompletion {
    /// Byte offset where the replaced word starts.
    pub start: usize,
    /// Candidates, sorted.
    pub candidates: Vec<Candidate>,
}

/// Completes `line` (the text before the cursor): the mnemonic one level at a time (`M` →
/// `MOTOR:`, `COMS:` → `COMS:NET:`, `COMS:SERIAL:`), or the value of the first argument.
pub fn complete(table: &Smd4CommandTable, line: &str) -> WordCompletion {
    let start = prefix_len(line);
    let body = &line[start..];
    match body.split_once(',') {
        None => WordCompletion {
            start,
            candidates: complete_mnemonic(table, body),
        },
        Some((mnemonic, arg)) if !arg.contains(',') => {
            let lead = arg.len() - arg.trim_start().len();
            WordCompletion {
                start: start + mnemonic.len() + 1 + lead,
                candidates: table
                    .get(mnemonic)
                    .map(|spec| complete_arg(spec, arg.trim_start()))
                    .unwrap_or_default(),
            }
        }
        Some(_) => WordCompletion {
            start: line.len(),
            candidates: Vec::new(),
        },
    }
}

/// The hint for what has been typed so far: the command's help once the mnemonic is complete,
/// the accepted values after the comma.
pub fn hint_for_line(table: &Smd4CommandTable, line: &str) -> Option<String> {
    let body = &line[prefix_len(line)..];
    match body.split_once(',') {
        None => table.get(body).map(hint),
        Some((mnemonic, _)) => table.get(mnemonic).map(arg_summary),
    }
}

/// Length of an `@N` or `@N,` prefix at the start of the line.
fn prefix_len(line: &str) -> usize {
    let Some(rest) = line.strip_prefix('@') else {
        return 0;
    };
    let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
    let comma = usize::from(digits > 0 && rest[digits..].starts_with(','));
    1 + digits + comma
}

fn complete_mnemonic(table: &Smd4CommandTable, typed: &str) -> Vec<Candidate> {
    let typed_upper = typed.to_ascii_uppercase();
    let mut words: Vec<String> = table
        .mnemonics()
        .filter(|m| m.starts_with(&typed_upper))
        .map(|m| match m[typed_upper.len()..].find(':') {
            Some(colon) => m[..typed_upper.len() + colon + 1].to_string(),
            None => m.to_string(),
        })
        .collect();
    words.sort();
    words.dedup();
    words
        .into_iter()
        .map(|w| Candidate {
            display: w.clone(),
            replacement: w,
        })
        .collect()
}

fn complete_arg(spec: &Smd4Command, typed: &str) -> Vec<Candidate> {
    let Some(arg) = &spec.arg else {
        return Vec::new();
    };
    arg.choices
        .iter()
        .filter(|c| c.value.starts_with(typed))
        .map(|c| Candidate {
            replacement: c.value.clone(),
            display: match c.label.as_str() {
                "" => c.value.clone(),
                label => format!("{} ({label})", c.value),
            },
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::protocol::Smd4Spec;

    fn words(completion: &WordCompletion) -> Vec<&str> {
        completion
            .candidates
            .iter()
            .map(|c| c.replacement.as_str())
            .collect()
    }

    #[test]
    fn completes_one_level_at_a_time() {
        let table = &Smd4Spec::builtin().commands;
        let top = complete(table, "");
        for group in ["BAKE:", "BOOST:", "COMS:", "LIMIT:", "MOTOR:", "SYS:"] {
            assert!(words(&top).contains(&group), "{group} in {:?}", words(&top));
        }
        assert!(
            words(&top)
                .iter()
                .all(|w| w.ends_with(':') || !w.contains(':'))
        );
        assert_eq!(words(&complete(table, "co")), ["COMS:"]);
        assert_eq!(
            words(&complete(table, "COMS:")),
            ["COMS:NET:", "COMS:SERIAL:"]
        );
        assert_eq!(
            words(&complete(table, "limit:en")),
            ["LIMIT:EN", "LIMIT:EN+", "LIMIT:EN-"]
        );
        assert!(words(&complete(table, "MOTOR:")).contains(&"MOTOR:RUNV"));
        assert!(complete(table, "XYZ").candidates.is_empty());
        let addressed = complete(table, "@3SYS:FL");
        assert_eq!(addressed.start, 2);
        assert_eq!(words(&addressed), ["SYS:FLAGS", "SYS:FLAGSV"]);
        assert_eq!(complete(table, "@12,MO").start, 4);
    }

    #[test]
    fn completes_argument_values() {
        let table = &Smd4Spec::builtin().commands;
        let runv = complete(table, "MOTOR:RUNV,");
        assert_eq!(runv.start, 11);
        assert_eq!(words(&runv), ["+", "-"]);
        assert_eq!(words(&complete(table, "MOTOR:RES, 1")), ["16", "128"]);
        let mode = complete(table, "sys:mode,");
        assert_eq!(mode.candidates[1].display, "1 (Remote)");
        assert!(complete(table, "MOTOR:VMAX,").candidates.is_empty());
        assert!(complete(table, "MOTOR:RES,8,").candidates.is_empty());
    }

    #[test]
    fn hints_show_unit_range_and_default() {
        let table = &Smd4Spec::builtin().commands;
        let vmax = hint(table.get("MOTOR:VMAX").unwrap());
        assert!(vmax.starts_with("MOTOR:VMAX[,<FLOAT Hz>]  read/write, 1..15000 Hz, default 1000; replies user,real value"), "{vmax}");
        let ir = arg_summary(table.get("MOTOR:IR").unwrap());
        assert_eq!(ir, "0..1.044 A rms, in 31 steps, default 1.044");
        let res = hint(table.get("MOTOR:RES").unwrap());
        assert!(
            res.contains("<8|16|32|64|128|256>") && res.contains("standby"),
            "{res}"
        );
        assert_eq!(usage(table.get("MOTOR:RUNV").unwrap()), "MOTOR:RUNV,<+|->");
        assert_eq!(usage(table.get("SYS:CLR").unwrap()), "SYS:CLR");
        assert!(hint(table.get("MOTOR:T").unwrap()).contains("read-only, in degC"));
        assert_eq!(
            hint_for_line(table, "@1LIMIT:STOPMODE,").as_deref(),
            Some("0 Hard stop | 1 Soft stop, default 0")
        );
        assert!(hint_for_line(table, "MOTOR:VM").is_none());
    }
}
