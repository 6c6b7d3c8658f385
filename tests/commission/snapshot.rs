//! Snapshots against the simulator: saved, the module changed, the diff shows exactly the change,
//! the restore brings it back and verifies; a module with a read-only parameter; EEPROM storing.

use super::{arg, expect};
use crate::sim::Sim;
use crate::util::{repo, stderr, stdout, tempdir};

/// The connection flags for a simulator started with `Sim::start`.
fn pty(sim: &Sim) -> Vec<&str> {
    vec!["--port", &sim.first]
}

fn with<'a>(base: &[&'a str], connection: &[&'a str]) -> Vec<&'a str> {
    base.iter().chain(connection).copied().collect()
}

/// The rows of a diff table: (name, left, right).
fn rows(text: &str) -> Vec<(String, String, String)> {
    text.lines()
        .skip(1)
        .map(|l| {
            let cells: Vec<&str> = l.split_whitespace().collect();
            // name, where (two words), left, right, unit...
            (cells[0].into(), cells[3].into(), cells[4].into())
        })
        .collect()
}

fn exercise(connection: &[&str]) {
    let dir = tempdir();
    let file = dir.join("module.toml");
    let saved = expect(&with(&["snapshot", "save", arg(&file)], connection), 0);
    assert!(stdout(&saved).starts_with("saved "), "{}", stdout(&saved));
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(text.contains("firmware = \"142V1.06\""), "{text}");
    assert!(
        text.contains("max_current = { number = 6, value = 8,"),
        "{text}"
    );

    let same = expect(&with(&["snapshot", "diff", arg(&file)], connection), 0);
    assert!(stdout(&same).starts_with("no differences in "));

    expect(
        &with(
            &[
                "-c",
                "SAP max_current, 0, 3",
                "-c",
                "SGP user_variable_5, 2, -42",
                "-c",
                "MVP ABS, 0, 100",
            ],
            connection,
        ),
        0,
    );
    let differ = expect(&with(&["snapshot", "diff", arg(&file)], connection), 1);
    assert_eq!(
        rows(&stdout(&differ)),
        [
            ("max_current".into(), "8".into(), "3".into()),
            ("user_variable_5".into(), "0".into(), "-42".into())
        ],
        "exactly the change; the move's positions are live values"
    );
    assert!(
        stdout(&differ)
            .lines()
            .nth(1)
            .unwrap()
            .ends_with("1/15 of full scale (0 = 0 %, 15 = 100 %)")
    );
    assert!(stderr(&differ).contains("2 of "), "{}", stderr(&differ));

    let restored = expect(&with(&["snapshot", "restore", arg(&file)], connection), 0);
    let report = stdout(&restored);
    assert!(
        report.contains("restored 2 parameters, each read back and verified"),
        "{report}"
    );
    assert!(report.contains("(live values, not settings): target_position, actual_position"));
    assert!(report.contains("by hand: ASGP 66, 0, 1"), "{report}");
    expect(&with(&["snapshot", "diff", arg(&file)], connection), 0);
}

#[test]
fn save_change_diff_restore_over_a_pty() {
    let sim = Sim::start(&["--pty"]);
    exercise(&pty(&sim));
}

#[test]
fn save_change_diff_restore_over_tcp() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    exercise(&["--tcp", &sim.first]);
}

#[test]
fn two_files_are_compared_without_a_module() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let (a, b) = (dir.join("a.toml"), dir.join("b.toml"));
    expect(&with(&["snapshot", "save", arg(&a)], &pty(&sim)), 0);
    expect(&with(&["-c", "SAP standby_current, 0, 5"], &pty(&sim)), 0);
    expect(&with(&["snapshot", "save", arg(&b)], &pty(&sim)), 0);
    drop(sim);
    let out = expect(&["snapshot", "diff", arg(&a), arg(&b)], 1);
    assert_eq!(
        rows(&stdout(&out)),
        [("standby_current".into(), "2".into(), "5".into())]
    );
    assert!(
        !stderr(&out).contains("built-in"),
        "no module, not even the simulated one: {}",
        stderr(&out)
    );
}

/// The built-in profile with `max_current` made read-only.
fn read_only_profile(dir: &std::path::Path) -> std::path::PathBuf {
    let text = std::fs::read_to_string(repo().join("data/tmcm142.toml")).unwrap();
    let at = text.find("ident = \"max_current\"").unwrap();
    let access = at + text[at..].find("access = \"RWE\"").unwrap();
    let changed = format!("{}access = \"R\"{}", &text[..access], &text[access + 14..]);
    let path = dir.join("read-only.toml");
    std::fs::write(&path, changed).unwrap();
    path
}

#[test]
fn a_restore_onto_a_module_with_a_read_only_parameter_skips_and_lists_it() {
    let dir = tempdir();
    let file = dir.join("module.toml");
    {
        let sim = Sim::start(&["--pty"]);
        expect(
            &with(
                &["-c", "SAP max_current, 0, 11", "-c", "SAP pid_p, 0, 7"],
                &pty(&sim),
            ),
            0,
        );
        expect(&with(&["snapshot", "save", arg(&file)], &pty(&sim)), 0);
    }
    let profile = read_only_profile(&dir);
    let sim = Sim::start(&["--pty", "--profile", arg(&profile)]);
    let restore = with(
        &[
            "--profile",
            arg(&profile),
            "snapshot",
            "restore",
            arg(&file),
        ],
        &pty(&sim),
    );
    let out = expect(&restore, 0);
    let report = stdout(&out);
    let read_only = report
        .lines()
        .find(|l| l.starts_with("skipped ") && l.contains("(read-only)"))
        .unwrap_or_else(|| panic!("{report}"));
    assert!(read_only.contains("max_current"), "{read_only}");
    let check = expect(
        &with(
            &[
                "--profile",
                arg(&profile),
                "-c",
                "GAP max_current, 0",
                "-c",
                "GAP pid_p, 0",
            ],
            &pty(&sim),
        ),
        0,
    );
    assert_eq!(
        stdout(&check),
        "BA 100 8\nBA 100 7\n",
        "max_current untouched, pid_p restored"
    );
}

#[test]
fn store_writes_the_eeprom_after_confirmation_and_a_dry_run_changes_nothing() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let file = dir.join("module.toml");
    expect(&with(&["-c", "SAP max_current, 0, 12"], &pty(&sim)), 0);
    expect(&with(&["snapshot", "save", arg(&file)], &pty(&sim)), 0);
    expect(&with(&["-c", "SAP max_current, 0, 1"], &pty(&sim)), 0);

    let dry = expect(
        &with(
            &["snapshot", "restore", arg(&file), "--dry-run", "--store"],
            &pty(&sim),
        ),
        0,
    );
    let lines = stdout(&dry);
    let writes: Vec<&str> = lines.lines().filter(|l| l.starts_with("ASAP")).collect();
    assert_eq!(writes, ["ASAP 6, 0, 12"], "only what differs: {lines}");
    let stores: Vec<&str> = lines.lines().filter(|l| l.starts_with("ASTAP")).collect();
    assert_eq!(
        stores[0], "ASTAP 255, 0",
        "stores in restore order: {lines}"
    );
    assert!(stores.contains(&"ASTAP 6, 0") && lines.contains("\nASTGP 55, 2\n"));
    let unchanged = expect(&with(&["-c", "GAP max_current, 0"], &pty(&sim)), 0);
    assert_eq!(stdout(&unchanged), "BA 100 1\n");

    let refused = expect(
        &with(&["snapshot", "restore", arg(&file), "--store"], &pty(&sim)),
        2,
    );
    assert!(
        stderr(&refused).contains("add --yes"),
        "{}",
        stderr(&refused)
    );

    let stored = expect(
        &with(
            &["snapshot", "restore", arg(&file), "--store", "--yes"],
            &pty(&sim),
        ),
        0,
    );
    assert!(
        stdout(&stored).contains("parameters to EEPROM"),
        "{}",
        stdout(&stored)
    );
    let from_eeprom = expect(
        &with(
            &[
                "-c",
                "SAP max_current, 0, 2",
                "-c",
                "RSAP max_current, 0",
                "-c",
                "GAP max_current, 0",
            ],
            &pty(&sim),
        ),
        0,
    );
    assert!(
        stdout(&from_eeprom).ends_with("BA 100 12\n"),
        "{}",
        stdout(&from_eeprom)
    );
}

#[test]
fn a_damaged_snapshot_file_is_refused_before_anything_is_sent() {
    let dir = tempdir();
    let file = dir.join("bad.toml");
    std::fs::write(&file, "[module]\nname = \"TMCM-142\"\naddress = 1\n[axis.0]\nmax_current = { number = 6, valeu = 3 }\n").unwrap();
    let out = expect(&["snapshot", "restore", arg(&file)], 2);
    assert!(
        stderr(&out).contains("is not a tmclsh snapshot"),
        "{}",
        stderr(&out)
    );
    assert!(stderr(&out).contains("valeu"));
}

#[test]
fn the_shell_helper_saves_diffs_and_restores() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let file = dir.join("shell.toml");
    let save = format!(":snapshot save {}", arg(&file));
    let diff = format!(":snapshot diff {}", arg(&file));
    let restore = format!(":snapshot restore {}", arg(&file));
    let store = format!(":snapshot restore {} --store", arg(&file));
    let out = expect(
        &with(
            &["-c", &save, "-c", "SAP pid_i, 0, 33", "-c", &diff],
            &pty(&sim),
        ),
        1,
    );
    let text = stdout(&out);
    assert!(text.starts_with("saved "), "{text}");
    let table = &text[text.find("\nparameter").expect("a diff table") + 1..];
    assert_eq!(rows(table), [("pid_i".into(), "0".into(), "33".into())]);
    expect(&with(&["-c", &restore, "-c", &diff], &pty(&sim)), 0);
    let refused = expect(&with(&["-c", &store], &pty(&sim)), 2);
    assert!(
        stderr(&refused).contains("add --yes"),
        "{}",
        stderr(&refused)
    );
}
