//! Snapshots, diffs and restores against the in-memory module.

use super::super::actions::{self, RestoreOptions};
use super::super::diff::{self, Side};
use super::super::fake::FakeDevice;
use super::super::restore::{self, Reason};
use super::*;
use crate::exit::ExitStatus;

/// A diff side holding the integer `v`.
fn int(v: i64) -> Side {
    Side::Value(Reading::of(v))
}

fn captured(device: &mut FakeDevice) -> Snapshot {
    Snapshot::capture(device).unwrap()
}

#[test]
fn a_snapshot_round_trips_through_its_file_text() {
    let mut device = FakeDevice::new();
    device.set("max_current", 100);
    device.set("user_variable_7", -12345);
    device.refuse_read.push("pid_error".into());
    let snapshot = captured(&mut device);
    let text = snapshot.to_toml();
    assert!(text.contains("\n[axis.0]\n"), "{text}");
    assert!(text.contains("\n[global.2]\n"));
    assert!(
        text.contains("max_current = { number = 6, value = 100, unit = "),
        "{text}"
    );
    assert!(text.contains("firmware = \"142V9.99\""));
    assert!(text.contains("pid_error = { number = 38, error = \"module 1 (A) refused"));
    let back = Snapshot::parse(&text).unwrap();
    assert_eq!(back, snapshot);
}

#[test]
fn only_readable_parameters_are_saved_with_name_number_and_unit() {
    let mut device = FakeDevice::new();
    let snapshot = captured(&mut device);
    let readable = device.params.iter().filter(|p| p.access.read).count();
    assert_eq!(snapshot.entries.len(), readable);
    let e = snapshot
        .get(Scope::Axis { motor: 0 }, "actual_position")
        .unwrap();
    assert_eq!((e.number, e.unit.as_str()), (Some(1), "usteps"));
    assert_eq!(snapshot.module, "TMCM-142");
    assert_eq!(snapshot.address, Some(1));
}

#[test]
fn a_file_with_a_misspelt_field_or_section_is_refused_with_the_reason() {
    let bad_field =
        "[module]\nname = \"X\"\naddress = 1\n[axis.0]\na = { number = 1, valeu = 3 }\n";
    assert!(
        Snapshot::parse(bad_field)
            .unwrap_err()
            .message
            .contains("valeu")
    );
    let bad_section = "[module]\nname = \"X\"\naddress = 1\n[axes.0]\n";
    assert!(
        Snapshot::parse(bad_section)
            .unwrap_err()
            .message
            .contains("axes")
    );
    let bad_motor = "[module]\nname = \"X\"\naddress = 1\n[axis.x]\n";
    assert!(
        Snapshot::parse(bad_motor)
            .unwrap_err()
            .message
            .contains("'x' is not a number")
    );
    let no_value = "[module]\nname = \"X\"\naddress = 1\n[axis.0]\na = { number = 1 }\n";
    assert!(
        Snapshot::parse(no_value)
            .unwrap_err()
            .message
            .contains("a: no value")
    );
}

#[test]
fn the_diff_with_a_module_shows_exactly_the_changed_settings() {
    let mut device = FakeDevice::new();
    let file = captured(&mut device);
    device.set("max_current", 3);
    device.set("user_variable_55", 9);
    device.set("actual_position", 777); // live: not a setting
    let comparison = diff::with_device(&file, &mut device).unwrap();
    let changed: Vec<(&str, &Side, &Side)> = comparison
        .differences
        .iter()
        .map(|d| (d.name.as_str(), &d.left, &d.right))
        .collect();
    let before = |name| {
        file.get(device.param(name).scope, name)
            .unwrap()
            .value
            .clone()
            .unwrap()
    };
    assert_eq!(
        changed,
        [
            (
                "max_current",
                &Side::Value(Reading::of(before("max_current"))),
                &int(3)
            ),
            (
                "user_variable_55",
                &Side::Value(Reading::of(before("user_variable_55"))),
                &int(9)
            ),
        ]
    );
    let settings = device
        .params
        .iter()
        .filter(|p| p.access.read && diff::compared(p.role))
        .count();
    assert_eq!(comparison.compared, settings);
}

#[test]
fn the_diff_report_names_units_and_places_and_exits_one() {
    let dir = std::env::temp_dir().join(format!("tmclsh-diff-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("s.toml");
    let mut device = FakeDevice::new();
    actions::save(&mut device, &path, &mut Vec::new()).unwrap();
    let same = actions::diff(&mut device, &path, &mut Vec::new());
    assert!(same.is_ok());
    device.set("max_positioning_speed", 1234);
    let mut out = Vec::new();
    let error = actions::diff(&mut device, &path, &mut out).unwrap_err();
    assert_eq!(
        crate::exit::ExitStatus::exit(&error),
        crate::exit::Exit::DeviceError
    );
    assert!(error.to_string().starts_with("1 of "), "{error}");
    let text = String::from_utf8(out).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "{text}");
    assert!(lines[0].starts_with("parameter") && lines[0].contains("module 1"));
    let row: Vec<&str> = lines[1].split_whitespace().collect();
    assert_eq!(row[0], "max_positioning_speed");
    assert_eq!(&row[1..3], ["axis", "4"]);
    assert_eq!(row[4], "1234");
    assert_eq!(row[5], "usteps/t");
}

#[test]
fn two_files_are_compared_by_name_including_entries_only_one_has() {
    let mut device = FakeDevice::new();
    let left = captured(&mut device);
    let mut right = left.clone();
    let i = right
        .entries
        .iter()
        .position(|e| e.name == "max_current")
        .unwrap();
    right.entries[i].value = Ok(1.into());
    right.entries.retain(|e| e.name != "standby_current");
    right.entries.push(Entry {
        scope: Scope::Global { bank: 9 },
        name: "mystery".into(),
        number: Some(1),
        value: Ok(5.into()),
        real: None,
        label: None,
        unit: String::new(),
        access: "RW".into(),
    });
    let comparison = diff::between(&left, &right, &device.params);
    let names: Vec<(&str, &Side)> = comparison
        .differences
        .iter()
        .map(|d| (d.name.as_str(), &d.right))
        .collect();
    assert_eq!(
        names,
        [
            ("max_current", &int(1)),
            ("standby_current", &Side::Missing),
            ("mystery", &int(5)),
        ]
    );
}

#[test]
fn restore_writes_unit_mode_and_limits_first_then_table_order() {
    let mut device = FakeDevice::new();
    let snapshot = captured(&mut device);
    let plan = restore::plan(&snapshot, &device.params, &device);
    let order: Vec<&str> = plan.writes.iter().map(|(p, _)| p.name.as_str()).collect();
    assert_eq!(
        &order[..5],
        [
            "unit_conversion_mode",
            "max_positioning_speed",
            "max_acceleration",
            "max_current",
            "standby_current"
        ]
    );
    let numbers: Vec<u32> = plan.writes[4..]
        .iter()
        .filter(|(p, _)| matches!(p.scope, Scope::Axis { .. }))
        .filter_map(|(p, _)| p.number)
        .collect();
    assert!(numbers.windows(2).all(|w| w[0] < w[1]), "{numbers:?}");
    assert!(order.iter().all(|n| device.param(n).access.write));
}

#[test]
fn restore_skips_read_only_live_and_link_settings_and_lists_them() {
    let mut device = FakeDevice::new();
    let snapshot = captured(&mut device);
    let plan = restore::plan(&snapshot, &device.params, &device);
    let reason = |name: &str| {
        plan.skipped
            .iter()
            .find(|s| s.name == name)
            .map(|s| s.reason)
    };
    assert_eq!(reason("target_position_reached"), Some(Reason::ReadOnly));
    assert_eq!(reason("actual_position"), Some(Reason::Live));
    assert_eq!(reason("serial_address"), Some(Reason::Manual));
    assert_eq!(reason("max_current"), None);
    let mut out = Vec::new();
    let by_hand = vec![device.write_line(&device.param("serial_address"), &ParamValue::Int(1))];
    restore::write_skipped(&plan, &by_hand, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("(read-only): "), "{text}");
    assert!(text.contains("target_position_reached"));
    assert!(text.contains("by hand: SET serial_address 1"), "{text}");
    assert!(!plan.writes.iter().any(|(p, _)| p.name == "serial_address"));
}

#[test]
fn a_restore_brings_changed_settings_back_and_verifies_each() {
    let mut device = FakeDevice::new();
    device.set("max_current", 10);
    let snapshot = captured(&mut device);
    device.set("max_current", 2);
    device.set("pid_p", 77);
    device.set("actual_position", 500);
    let plan = restore::plan(&snapshot, &device.params, &device);
    assert_eq!(plan.problems, []);
    let outcome = restore::execute(&mut device, &plan).unwrap();
    assert_eq!(device.get("max_current"), 10);
    assert_eq!(
        ParamValue::Int(device.get("pid_p")),
        snapshot
            .get(Scope::Axis { motor: 0 }, "pid_p")
            .unwrap()
            .value
            .clone()
            .unwrap()
    );
    assert_eq!(
        device.get("actual_position"),
        500,
        "live values are not written"
    );
    assert_eq!(
        outcome.verified,
        ["max_current", "pid_p"],
        "the two changed settings"
    );
    assert_eq!(outcome.unchanged, plan.writes.len() - 2);
    assert_eq!(device.log, ["write max_current 10", "write pid_p 0"]);
    assert!(outcome.failed.is_empty());
}

#[test]
fn a_refused_write_and_a_value_that_does_not_stick_are_reported_and_the_rest_goes_on() {
    let mut device = FakeDevice::new();
    let snapshot = captured(&mut device);
    device.refuse_write.push("max_current".into());
    device.stuck.push("pid_i".into());
    device.set("max_current", 1);
    device.set("pid_i", 5);
    device.set("pid_d", 6);
    let plan = restore::plan(&snapshot, &device.params, &device);
    assert_eq!(plan.problems, []);
    let outcome = restore::execute(&mut device, &plan).unwrap();
    let failed: Vec<&str> = outcome.failed.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(failed, ["max_current", "pid_i"]);
    let pid_i = &outcome.failed[1].1;
    assert!(
        pid_i.starts_with("wrote ") && pid_i.ends_with("reads back 5"),
        "{pid_i}"
    );
    assert_eq!(
        device.get("pid_d"),
        0,
        "writes after a failure still happen"
    );
    assert_eq!(outcome.verified, ["pid_d"]);
}

#[test]
fn store_happens_only_when_confirmed_and_only_for_the_written_eeprom_parameters() {
    let dir = std::env::temp_dir().join(format!("tmclsh-store-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("s.toml");
    let mut device = FakeDevice::new();
    actions::save(&mut device, &path, &mut Vec::new()).unwrap();
    let options = RestoreOptions {
        store: true,
        ..RestoreOptions::default()
    };
    let mut never = |_: &str| -> Result<bool, SessionError> { panic!("nothing to store") };
    let mut out = Vec::new();
    actions::restore(&mut device, &path, options, &mut never, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("not stored to EEPROM: the restore wrote nothing"),
        "{text}"
    );
    assert!(
        text.contains("nothing to write: the module already has"),
        "{text}"
    );

    device.set("standby_current", 9);
    device.set("stop_deceleration", 9);
    device.set("max_current", 9);
    let mut asked = Vec::new();
    let mut no = |q: &str| {
        asked.push(q.to_string());
        Ok(false)
    };
    actions::restore(&mut device, &path, options, &mut no, &mut Vec::new()).unwrap();
    assert!(!device.log.iter().any(|l| l.starts_with("store")));
    assert_eq!(
        asked,
        ["store 2 parameters (max_current, standby_current) to the EEPROM of module 1 (A)?"],
        "the question names what would be stored: the written EEPROM parameters"
    );

    device.log.clear();
    device.set("standby_current", 7);
    device.set("max_current", 7);
    let mut yes = |_: &str| Ok(true);
    let outcome = actions::restore(&mut device, &path, options, &mut yes, &mut Vec::new()).unwrap();
    let stored: Vec<&str> = device
        .log
        .iter()
        .filter_map(|l| l.strip_prefix("store "))
        .collect();
    assert_eq!(stored, ["max_current", "standby_current"]);
    assert_eq!(outcome.stored, 2);
    let last_write = device
        .log
        .iter()
        .rposition(|l| l.starts_with("write"))
        .unwrap();
    let first_store = device
        .log
        .iter()
        .position(|l| l.starts_with("store"))
        .unwrap();
    assert!(last_write < first_store, "stores come after every write");
}

#[test]
fn a_dry_run_prints_the_lines_and_sends_nothing() {
    let dir = std::env::temp_dir().join(format!("tmclsh-dry-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("s.toml");
    let mut device = FakeDevice::new();
    actions::save(&mut device, &path, &mut Vec::new()).unwrap();
    device.set("pid_p", 3);
    device.set("max_current", 4);
    let options = RestoreOptions {
        store: true,
        dry_run: true,
        ..RestoreOptions::default()
    };
    let mut out = Vec::new();
    let mut never = |_: &str| -> Result<bool, SessionError> { panic!("no prompt") };
    actions::restore(&mut device, &path, options, &mut never, &mut out).unwrap();
    assert!(device.log.is_empty());
    assert_eq!(device.get("pid_p"), 3);
    let text = String::from_utf8(out).unwrap();
    let lines: Vec<&str> = text.lines().take(4).collect();
    assert_eq!(
        lines,
        [
            "SET max_current 8",
            "SET pid_p 0",
            "STORE max_current",
            "STORE pid_p"
        ]
    );
}

/// The snapshot of a fresh fake module with `edit` applied to its entries.
fn edited(device: &mut FakeDevice, edit: impl FnOnce(&mut Snapshot)) -> Snapshot {
    let mut snapshot = captured(device);
    edit(&mut snapshot);
    snapshot
}

fn entry<'a>(snapshot: &'a mut Snapshot, name: &str) -> &'a mut Entry {
    snapshot
        .entries
        .iter_mut()
        .find(|e| e.name == name)
        .unwrap()
}

fn restore_file(
    device: &mut FakeDevice,
    snapshot: &Snapshot,
    options: RestoreOptions,
) -> (Result<restore::Outcome, SessionError>, String) {
    let mut out = Vec::new();
    let mut yes = |_: &str| Ok(true);
    let result = actions::restore_snapshot(device, snapshot, "s.toml", options, &mut yes, &mut out);
    (result, String::from_utf8(out).unwrap())
}

#[test]
fn a_bad_value_anywhere_refuses_the_whole_file_before_anything_is_sent() {
    let mut device = FakeDevice::new();
    let snapshot = edited(&mut device, |s| {
        entry(s, "max_current").value = Ok(ParamValue::Int(3));
        entry(s, "pid_p").value = Ok(ParamValue::Text("abc".into()));
        entry(s, "standby_current").value = Ok(ParamValue::Int(99999));
        entry(s, "user_variable_9").value = Ok(ParamValue::Float(1.5));
    });
    device.set("max_current", 5);
    for force in [false, true] {
        let options = RestoreOptions {
            force,
            ..RestoreOptions::default()
        };
        let (result, _) = restore_file(&mut device, &snapshot, options);
        let error = result.unwrap_err();
        assert_eq!(error.exit(), crate::exit::Exit::Refused);
        let message = error.to_string();
        assert!(
            message.contains("nothing was sent (3 problems)"),
            "{message}"
        );
        for name in ["pid_p", "standby_current", "user_variable_9"] {
            assert!(
                message.contains(&format!("\n  {name}: ")),
                "{name}: {message}"
            );
        }
        assert!(
            !message.contains("--force restores"),
            "bad values are never forced"
        );
    }
    assert!(device.log.is_empty(), "{:?}", device.log);
    assert_eq!(
        device.get("max_current"),
        5,
        "the good value was not written either"
    );
}

#[test]
fn another_module_wrong_numbers_unknown_motors_and_names_are_refused_unless_forced() {
    let mut device = FakeDevice::new();
    let mut snapshot = edited(&mut device, |s| {
        s.module = "TMCM-1140".into();
        entry(s, "pid_i").number = Some(99);
        let mut extra = s.entries[0].clone();
        extra.scope = Scope::Axis { motor: 3 };
        s.entries.push(extra);
        let mut extra = s.entries[0].clone();
        extra.name = "max_curent".into();
        s.entries.push(extra);
    });
    entry(&mut snapshot, "pid_i").value = Ok(ParamValue::Int(21));
    let (result, _) = restore_file(&mut device, &snapshot, RestoreOptions::default());
    let message = result.unwrap_err().to_string();
    assert!(message.contains("(4 problems)"), "{message}");
    assert!(message.contains("a snapshot of a TMCM-1140, and module 1 (A) is a TMCM-142"));
    assert!(
        message.contains("pid_i: number = 99 in the file, but it is axis 3"),
        "{message}"
    );
    assert!(message.contains("[axis.3]: the TMCM-142 has no motor 3 (it has motors 0..0)"));
    assert!(
        message.contains("max_curent: not a parameter of the TMCM-142; did you mean max_current?"),
        "{message}"
    );
    assert!(message.contains("--force restores by name"));
    assert!(device.log.is_empty());

    let force = RestoreOptions {
        force: true,
        ..RestoreOptions::default()
    };
    let (result, report) = restore_file(&mut device, &snapshot, force);
    let outcome = result.unwrap();
    assert_eq!(outcome.verified, ["pid_i"], "written by name");
    assert_eq!(device.get("pid_i"), 21);
    assert_eq!(
        report.lines().filter(|l| l.starts_with("forced: ")).count(),
        4,
        "{report}"
    );
    assert!(
        report.contains("(not parameters of this module)"),
        "{report}"
    );
}

#[test]
fn a_file_of_the_other_dialect_or_with_nothing_restorable_is_refused_even_forced() {
    let mut device = FakeDevice::new();
    let drive = edited(&mut device, |s| {
        s.module = "SMD4".into();
        for e in &mut s.entries {
            e.scope = Scope::Drive;
            e.number = None;
        }
    });
    let live_only = edited(&mut device, |s| {
        s.entries.retain(|e| e.name == "actual_position");
    });
    for snapshot in [&drive, &live_only] {
        for force in [false, true] {
            let options = RestoreOptions {
                force,
                ..RestoreOptions::default()
            };
            let (result, _) = restore_file(&mut device, snapshot, options);
            let message = result.unwrap_err().to_string();
            assert!(
                message.contains("nothing in it is a setting of the TMCM-142"),
                "{message}"
            );
        }
    }
    let (result, _) = restore_file(&mut device, &drive, RestoreOptions::default());
    assert!(
        result
            .unwrap_err()
            .to_string()
            .contains("it holds SMD4 drive settings, and module 1 (A) is a TMCL module")
    );
    assert!(device.log.is_empty());
}

#[test]
fn problems_told_to_a_script_quote_nothing_from_the_file() {
    let mut device = FakeDevice::new();
    let snapshot = edited(&mut device, |s| {
        s.module = "secret-module".into();
        entry(s, "pid_p").value = Ok(ParamValue::Text("secret-value".into()));
        entry(s, "pid_i").number = Some(77);
        let mut extra = s.entries[0].clone();
        extra.name = "secret_name".into();
        s.entries.push(extra);
    });
    let redact = RestoreOptions {
        redact: true,
        ..RestoreOptions::default()
    };
    let (result, _) = restore_file(&mut device, &snapshot, redact);
    let message = result.unwrap_err().to_string();
    assert!(message.contains("(4 problems)"), "{message}");
    assert!(
        !message.contains("secret") && !message.contains("77"),
        "{message}"
    );
    assert!(
        message.contains("pid_p: the module would refuse this value"),
        "{message}"
    );

    let text = "[module]\nname = \"x\"\n[axis.0]\npassword = \"secret-line\"\n";
    let error = Snapshot::parse(text).unwrap_err();
    assert!(
        error.message.contains("secret-line"),
        "the CLI may show it: {}",
        error.message
    );
    assert_eq!(
        error.redacted(),
        "the first problem is at line 4, column 12"
    );
}

#[test]
fn a_link_failure_midway_reports_what_was_written_in_flight_and_not_sent() {
    let mut device = FakeDevice::new();
    let snapshot = captured(&mut device);
    device.set("max_current", 1);
    device.set("pid_i", 5);
    device.set("pid_d", 6);
    device.time_out_at = Some("pid_i".into());
    let (result, report) = restore_file(&mut device, &snapshot, RestoreOptions::default());
    let error = result.unwrap_err();
    assert_eq!(error.exit(), crate::exit::Exit::Link, "{error}");
    assert!(
        report.contains("restored 1 parameter, each read back and verified (max_current)"),
        "{report}"
    );
    assert!(
        report.contains("the restore stopped: no reply from module 1 (A)"),
        "{report}"
    );
    assert!(
        report.contains("UNKNOWN pid_i: it was being written"),
        "{report}"
    );
    let not_reached = report
        .lines()
        .find(|l| l.starts_with("NOT REACHED "))
        .unwrap();
    assert!(not_reached.contains(": pid_d, "), "{report}");
    assert!(!not_reached.contains("max_current") && !not_reached.contains("pid_i,"));
    assert_eq!(device.log, ["write max_current 8"]);
    assert_eq!(device.get("pid_d"), 6);
}

#[test]
fn the_by_hand_list_shows_only_the_manual_settings_that_differ() {
    let mut device = FakeDevice::new();
    let snapshot = edited(&mut device, |s| {
        entry(s, "max_current").value = Ok(ParamValue::Int(3));
    });
    let (result, report) = restore_file(&mut device, &snapshot, RestoreOptions::default());
    result.unwrap();
    assert!(
        report.contains("set them by hand): eeprom_magic"),
        "{report}"
    );
    assert!(
        !report.contains("by hand:"),
        "serial_address is the same: {report}"
    );
    let snapshot = edited(&mut device, |s| {
        entry(s, "serial_address").value = Ok(ParamValue::Int(2));
    });
    let (result, report) = restore_file(&mut device, &snapshot, RestoreOptions::default());
    result.unwrap();
    assert!(
        report.contains("  by hand: SET serial_address 2"),
        "{report}"
    );
    assert!(!device.log.iter().any(|l| l.contains("serial_address")));
}
