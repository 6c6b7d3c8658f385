//! The module profiles of `data/profiles/` (the TMCM-142's among them): each one loads
//! through the real binary, lists every parameter it declares, drives exactly its declared axes,
//! and its data is consistent (unique numbers, ordered ranges, defaults in range, identification,
//! ASCII allow-list, I/O map). The checks return their findings, so a doctored profile shows they
//! can fail.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use toml::{Table, Value};

use crate::util::{code, repo, run, stderr, stdout, tempdir};

/// Every shipped profile: `data/profiles/*.toml`, the TMCM-142's among them.
fn profiles() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(repo().join("data/profiles"))
        .expect("data/profiles exists")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(
        files.len() >= 8,
        "at least eight module profiles: {files:?}"
    );
    files
}

fn load(path: &Path) -> Table {
    let text = std::fs::read_to_string(path).unwrap();
    text.parse::<Table>()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn rows<'a>(t: &'a Table, key: &str) -> Vec<&'a Table> {
    t.get(key)
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_table).collect())
        .unwrap_or_default()
}

fn int(t: &Table, key: &str) -> Option<i64> {
    t.get(key).and_then(Value::as_integer)
}

fn text<'a>(t: &'a Table, key: &str) -> Option<&'a str> {
    t.get(key).and_then(Value::as_str)
}

fn pair(v: Option<&Value>) -> Option<(i64, i64)> {
    let a = v?.as_array()?;
    Some((a.first()?.as_integer()?, a.get(1)?.as_integer()?))
}

fn meta(t: &Table) -> &Table {
    t.get("meta").and_then(Value::as_table).expect("[meta]")
}

/// The parameters a profile declares, as `params` prints them: (kind, number, ident).
fn declared(t: &Table) -> Vec<(String, i64, String)> {
    let mut out = Vec::new();
    for row in rows(t, "axis_parameter") {
        out.push(("axis".into(), int(row, "number").unwrap(), ident(row)));
    }
    for row in rows(t, "global_parameter") {
        let number = int(row, "number").unwrap();
        if number < 0 {
            continue; // placeholder row
        }
        let kind = format!("global/{}", int(row, "bank").unwrap_or(0));
        match int(row, "number_last") {
            Some(last) => {
                for n in number..=last {
                    out.push((kind.clone(), n, format!("{}_{n}", ident(row))));
                }
            }
            None => out.push((kind, number, ident(row))),
        }
    }
    out
}

fn ident(row: &Table) -> String {
    text(row, "ident").unwrap().to_ascii_lowercase()
}

/// One line of the `params` table.
#[derive(Debug)]
struct Listed {
    kind: String,
    number: i64,
    ident: String,
    range: Option<(i64, i64)>,
}

/// Parses `tmclsh params` output by the columns of its header line.
fn parse_params(out: &str) -> Vec<Listed> {
    let mut lines = out.lines();
    let header = lines.next().expect("a header line");
    let col = |name: &str| {
        header
            .find(name)
            .unwrap_or_else(|| panic!("{name} in {header}"))
    };
    let (name_at, acc_at, range_at, unit_at) = (col("name"), col("acc"), col("range"), col("unit"));
    lines
        .map(|line| {
            let field =
                |from: usize, to: usize| line.get(from..to.min(line.len())).unwrap_or("").trim();
            let (kind, number) = field(0, name_at).split_once(' ').expect("kind and number");
            let range = field(range_at, unit_at);
            Listed {
                kind: kind.to_string(),
                number: number.trim().parse().expect("a parameter number"),
                ident: field(name_at, acc_at).to_string(),
                range: range.split_once("..").map(|(lo, hi)| {
                    (
                        lo.parse().expect("range start"),
                        hi.parse().expect("range end"),
                    )
                }),
            }
        })
        .collect()
}

/// Data-level findings for one profile (empty when it is consistent).
fn check_data(t: &Table, builtin: &Table) -> Vec<String> {
    let mut problems = Vec::new();
    let m = meta(t);
    let module = text(m, "module").unwrap_or("");

    // Unique numbers and identifiers per bank; ordered ranges; defaults inside ranges.
    let mut numbers = BTreeSet::new();
    let mut idents = BTreeSet::new();
    for (kind, number, ident) in declared(t) {
        if !numbers.insert((kind.clone(), number)) {
            problems.push(format!("{kind} {number} declared twice"));
        }
        let family = if kind == "axis" { "axis" } else { "global" };
        if !idents.insert((family, ident.clone())) {
            problems.push(format!("{family} identifier {ident} declared twice"));
        }
    }
    let params = rows(t, "axis_parameter")
        .into_iter()
        .chain(rows(t, "global_parameter"));
    for row in params {
        let name = ident(row);
        let range = pair(row.get("range"));
        if let Some((lo, hi)) = range {
            if lo > hi {
                problems.push(format!("{name}: range {lo}..{hi} is not ordered"));
            }
        }
        if let (Some(default), Some((lo, hi))) = (int(row, "default"), range) {
            if !(lo..=hi).contains(&default) {
                problems.push(format!("{name}: default {default} outside {lo}..{hi}"));
            }
        }
        for when in row
            .get("range_when")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            match pair(when.get("range")) {
                Some((lo, hi)) if lo <= hi => {}
                other => problems.push(format!("{name}: range_when range {other:?}")),
            }
        }
        if row.get("uncertain").and_then(Value::as_bool) == Some(true)
            && text(row, "uncertain_reason").is_none_or(str::is_empty)
        {
            problems.push(format!("{name}: uncertain without a reason"));
        }
        if text(row, "source").is_none_or(str::is_empty) {
            problems.push(format!("{name}: no source"));
        }
    }

    // Commands the module has beside the built-in table, and its own ranges: each with a source.
    for (table, key) in [("extra_command", "mnemonic"), ("command_range", "mnemonic")] {
        for row in rows(t, table) {
            let name = format!("{table} {}", text(row, key).unwrap_or("?"));
            if text(row, "source").is_none_or(str::is_empty) {
                problems.push(format!("{name}: no source"));
            }
            if row.get("uncertain").and_then(Value::as_bool) == Some(true)
                && text(row, "uncertain_reason").is_none_or(str::is_empty)
            {
                problems.push(format!("{name}: uncertain without a reason"));
            }
        }
    }

    // Commands left out as unconfirmed: said why and where, and really left out.
    let section = t.get("commands").and_then(Value::as_table);
    let unconfirmed = section
        .and_then(|c| c.get("unconfirmed"))
        .and_then(Value::as_array);
    if let (Some(section), Some(numbers)) = (section, unconfirmed) {
        for key in ["unconfirmed_reason", "unconfirmed_source"] {
            if text(section, key).is_none_or(str::is_empty) {
                problems.push(format!("[commands] unconfirmed without {key}"));
            }
        }
        for number in numbers.iter().filter_map(Value::as_integer) {
            if rows(t, "extra_command")
                .iter()
                .any(|c| int(c, "number") == Some(number))
            {
                problems.push(format!("unconfirmed command {number} is in the table"));
            }
        }
    }

    // Identification: the 136 prefix is the module number, the version string has its format.
    let number = int(m, "module_number").unwrap_or(-1);
    if !module.ends_with(&format!("-{number}")) {
        problems.push(format!(
            "module_number {number} is not the number of {module}"
        ));
    }
    if text(m, "version_prefix") != Some(number.to_string().as_str()) {
        problems.push(format!(
            "version_prefix {:?} is not {number}",
            text(m, "version_prefix")
        ));
    }
    let format = text(m, "version_format").unwrap_or("");
    let expected = if number < 1000 {
        "NNNVa.bc"
    } else {
        "NNNNVabc"
    };
    if format != expected {
        problems.push(format!("version_format {format:?}, expected {expected}"));
    }
    if text(m, "bootloader_format") != Some(format.replace('V', "B").as_str()) {
        problems.push("bootloader_format is not version_format with B for V".into());
    }
    let simulation = t.get("simulation").and_then(Value::as_table);
    let version = simulation
        .and_then(|s| text(s, "version_string"))
        .unwrap_or("");
    if !fits(version, format) || !version.starts_with(&number.to_string()) {
        problems.push(format!(
            "simulated version {version:?} does not fit {format} for {number}"
        ));
    }

    // 136 type 1: the module number in the upper 16 bits (TMCM-1310 p63), the version below; the
    // TMCM-142's own manual (p92) leaves the upper bytes unused.
    let binary = simulation
        .and_then(|s| int(s, "version_binary"))
        .unwrap_or(0);
    let type_number = if number == 142 { 0 } else { number };
    if binary >> 16 != type_number {
        problems.push(format!(
            "136 type 1 value {binary} does not carry the type number {type_number}"
        ));
    }

    // ASCII: an allow-list exactly when the module has (or may have) the interface, naming known
    // commands only; binary-only modules lack 139.
    let ascii = text(m, "ascii_interface").unwrap_or("");
    if !["yes", "no", "unconfirmed"].contains(&ascii) {
        problems.push(format!("ascii_interface {ascii:?}"));
    }
    let mut known: BTreeMap<String, i64> = rows(builtin, "command")
        .iter()
        .map(|c| {
            (
                text(c, "mnemonic").unwrap().to_string(),
                int(c, "number").unwrap(),
            )
        })
        .collect();
    for c in rows(t, "extra_command") {
        known.insert(
            text(c, "mnemonic").unwrap().to_string(),
            int(c, "number").unwrap(),
        );
    }
    let absent: BTreeSet<i64> = t
        .get("commands")
        .and_then(|c| c.get("absent"))
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_integer).collect())
        .unwrap_or_default();
    for n in &absent {
        if !known.values().any(|v| v == n) {
            problems.push(format!("absent command {n} is not in the built-in table"));
        }
    }
    let allowed: Option<Vec<&str>> = t
        .get("ascii")
        .and_then(|a| a.get("allowed_commands"))
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_str).collect());
    match (ascii, &allowed) {
        ("no", Some(_)) => problems.push("binary-only module with an ASCII allow-list".into()),
        ("no", None) if !absent.contains(&139) => {
            problems.push("binary-only module does not list 139 as absent".into())
        }
        ("yes" | "unconfirmed", None) => problems.push("no [ascii] allowed_commands".into()),
        _ => {}
    }
    for word in allowed.iter().flatten() {
        match known.get(*word) {
            None => problems.push(format!("ASCII command {word} is not a known command")),
            Some(n) if absent.contains(n) => {
                problems.push(format!("ASCII command {word} is marked absent"))
            }
            _ => {}
        }
    }
    // Where the profile has its own command rows, their flags must say the same as the list.
    let flagged: BTreeSet<&str> = rows(t, "command")
        .iter()
        .filter(|c| c.get("ascii_allowed").and_then(Value::as_bool) == Some(true))
        .map(|c| text(c, "mnemonic").unwrap())
        .collect();
    if !flagged.is_empty() && allowed.iter().flatten().copied().collect::<BTreeSet<_>>() != flagged
    {
        problems.push("[ascii] allowed_commands disagrees with the ascii_allowed flags".into());
    }

    // I/O: the simulator's port lists are the I/O map's banks; analog ranges fit the ADC.
    let adc_max = simulation.and_then(|s| int(s, "adc_max")).unwrap_or(1023);
    for (bank, key) in [(0, "digital_inputs"), (1, "analog_inputs"), (2, "outputs")] {
        let mapped: BTreeSet<i64> = rows(t, "io_port")
            .iter()
            .filter(|p| int(p, "bank") == Some(bank))
            .filter_map(|p| int(p, "port"))
            .collect();
        let simulated: BTreeSet<i64> = simulation
            .and_then(|s| s.get(key))
            .and_then(Value::as_array)
            .map(|a| a.iter().filter_map(Value::as_integer).collect())
            .unwrap_or_default();
        if mapped != simulated {
            problems.push(format!(
                "[simulation] {key} {simulated:?} != bank {bank} ports {mapped:?}"
            ));
        }
    }
    for port in rows(t, "io_port") {
        if int(port, "bank") == Some(1) {
            if let Some((_, hi)) = pair(port.get("range")) {
                if hi > adc_max {
                    problems.push(format!(
                        "analog port range up to {hi} above adc_max {adc_max}"
                    ));
                }
            }
        }
    }
    problems
}

/// Whether `version` has the 136 format `format` (N digit, V letter, a/b/c digits, "." literal).
fn fits(version: &str, format: &str) -> bool {
    version.len() == format.len()
        && version.chars().zip(format.chars()).all(|(c, f)| match f {
            'N' | 'a' | 'b' | 'c' => c.is_ascii_digit(),
            other => c == other,
        })
}

#[test]
fn every_profile_loads_and_lists_exactly_its_parameters() {
    for path in profiles() {
        let t = load(&path);
        let out = run(&["--profile", path.to_str().unwrap(), "params"]);
        assert_eq!(code(&out), 0, "{}: {}", path.display(), stderr(&out));
        let listed = parse_params(&stdout(&out));
        let shown: BTreeSet<(String, i64, String)> = listed
            .iter()
            .map(|l| (l.kind.clone(), l.number, l.ident.clone()))
            .collect();
        let wanted: BTreeSet<(String, i64, String)> = declared(&t).into_iter().collect();
        assert_eq!(shown, wanted, "{}", path.display());
        assert_eq!(
            listed.len(),
            wanted.len(),
            "{}: a row listed twice",
            path.display()
        );
        for l in &listed {
            if let Some((lo, hi)) = l.range {
                assert!(lo <= hi, "{}: {} range {lo}..{hi}", path.display(), l.ident);
            }
        }
    }
}

#[test]
fn every_profile_drives_exactly_its_declared_axes() {
    for path in profiles() {
        let t = load(&path);
        let axes = int(meta(&t), "axes").unwrap_or(1);
        let file = path.to_str().unwrap();
        let last = format!("GAP 1, {}", axes - 1);
        let out = run(&["--sim", "--profile", file, "-c", &last]);
        assert_eq!(code(&out), 0, "{file} {last}: {}", stderr(&out));
        let beyond = format!("GAP 1, {axes}");
        let out = run(&["--sim", "--profile", file, "-c", &beyond]);
        assert_eq!(code(&out), 2, "{file} {beyond} must be refused");
        let count = if axes == 1 {
            "has one motor".to_string()
        } else {
            format!("has {axes} motors")
        };
        let said = stderr(&out);
        assert!(
            said.contains(&format!("motor {axes} does not exist")) && said.contains(&count),
            "{file}: {said}"
        );
    }
}

#[test]
fn every_profile_is_consistent() {
    let builtin = load(&repo().join("data/profiles/tmcm-142.toml"));
    for path in profiles() {
        let problems = check_data(&load(&path), &builtin);
        assert!(
            problems.is_empty(),
            "{}:\n  {}",
            path.display(),
            problems.join("\n  ")
        );
    }
}

#[test]
fn the_family_profiles_declare_the_issue_s_modules() {
    let mut found = BTreeMap::new();
    for path in profiles() {
        let t = load(&path);
        let m = meta(&t);
        let aliases: Vec<String> = m
            .get("aliases")
            .and_then(Value::as_array)
            .map(|a| {
                a.iter()
                    .filter_map(|v| v.as_str().map(String::from))
                    .collect()
            })
            .unwrap_or_default();
        found.insert(
            text(m, "module").unwrap().to_string(),
            (
                int(m, "axes").unwrap_or(1),
                text(m, "ascii_interface").unwrap().to_string(),
                aliases,
            ),
        );
    }
    let expect = |module: &str, axes: i64, ascii: &str| {
        let (a, s, _) = found
            .get(module)
            .unwrap_or_else(|| panic!("{module} has a profile"));
        assert_eq!((*a, s.as_str()), (axes, ascii), "{module}");
    };
    expect("TMCM-142", 1, "yes");
    expect("TMCM-1140", 1, "yes");
    expect("TMCM-1141", 1, "yes");
    expect("TMCM-1021", 1, "yes");
    expect("TMCM-1160", 1, "yes");
    expect("TMCM-6110", 6, "yes");
    expect("TMCM-3110", 3, "unconfirmed");
    expect("TMCM-1260", 1, "no");
    expect("TMCM-6214", 6, "no");
    assert!(found["TMCM-1141"].2.contains(&"PD-1141".to_string()));
    assert!(found["TMCM-1160"].2.contains(&"PD-1160".to_string()));
}

#[test]
fn the_checks_catch_a_doctored_profile() {
    let builtin = load(&repo().join("data/profiles/tmcm-142.toml"));
    let path = repo().join("data/profiles/tmcm-6110.toml");
    let good = std::fs::read_to_string(&path).unwrap();
    let doctored = good
        .replacen("default = 1000\n", "default = 99999\n", 1) // AP4 is 0..2047
        .replacen("version_prefix = \"6110\"", "version_prefix = \"6111\"", 1)
        .replacen("outputs = [0, 1, 2, 3, 4, 5, 6, 7]", "outputs = [0, 1]", 1)
        .replacen("\"UF7\"]", "\"UF7\", \"SAC\"]", 1)
        .replacen("axes = 6", "axes = 2", 1);
    assert_ne!(doctored, good);
    let problems = check_data(&doctored.parse::<Table>().unwrap(), &builtin).join("\n");
    for finding in [
        "default 99999 outside 0..2047",
        "version_prefix",
        "[simulation] outputs",
        "ASCII command SAC is marked absent",
    ] {
        assert!(
            problems.contains(finding),
            "{finding} not found in:\n{problems}"
        );
    }
    // The binary refuses motor 2 of the doctored two-axis module, which the real one has.
    let dir = tempdir();
    let file = dir.join("doctored.toml");
    std::fs::write(&file, &doctored).unwrap();
    let out = run(&[
        "--sim",
        "--profile",
        file.to_str().unwrap(),
        "-c",
        "GAP 1, 2",
    ]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    let out = run(&[
        "--sim",
        "--profile",
        path.to_str().unwrap(),
        "-c",
        "GAP 1, 2",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}
