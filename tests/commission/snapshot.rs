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
    assert!(
        !report.contains("by hand:"),
        "the link settings did not change: {report}"
    );
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
    let text = std::fs::read_to_string(repo().join("data/profiles/tmcm-142.toml")).unwrap();
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
    assert_eq!(stores, ["ASTAP 6, 0"], "stores what it writes: {lines}");
    assert!(!lines.contains("ASTGP"), "{lines}");
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
        stdout(&stored).contains("stored 1 parameter to EEPROM"),
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

/// `text` (a saved snapshot) with the value of `name` replaced by `value` (TOML).
fn with_value(text: &str, name: &str, value: &str) -> String {
    edit_line(text, name, |line| {
        let start = line.find("value = ").expect("a value") + "value = ".len();
        let end = start + line[start..].find(',').unwrap();
        format!("{}{value}{}", &line[..start], &line[end..])
    })
}

/// `text` with the line of `name` changed by `edit`.
fn edit_line(text: &str, name: &str, edit: impl Fn(&str) -> String) -> String {
    let prefix = format!("{name} = {{");
    let mut found = false;
    let lines: Vec<String> = text
        .lines()
        .map(|l| {
            if l.starts_with(&prefix) {
                found = true;
                edit(l)
            } else {
                l.to_string()
            }
        })
        .collect();
    assert!(found, "{name} is in the snapshot");
    lines.join("\n") + "\n"
}

/// The lines a `--log` transcript shows sent with `word` (`"SAP"`).
fn sent(log: &std::path::Path, word: &str) -> Vec<String> {
    std::fs::read_to_string(log)
        .unwrap_or_default()
        .lines()
        .filter(|l| l.contains(" tx ") && l.contains(word))
        .map(String::from)
        .collect()
}

#[test]
fn a_bad_file_changes_nothing_on_the_module_and_lists_every_problem() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let (before, after, bad) = (
        dir.join("before.toml"),
        dir.join("after.toml"),
        dir.join("bad.toml"),
    );
    expect(&with(&["snapshot", "save", arg(&before)], &pty(&sim)), 0);
    let text = std::fs::read_to_string(&before).unwrap();
    let text = with_value(&text, "max_current", "3"); // good, and differs
    let text = with_value(&text, "pid_i", "5"); // good, and differs
    let text = with_value(&text, "pid_p", "\"abc\"");
    let text = with_value(&text, "standby_current", "99999");
    let text = with_value(&text, "user_variable_9", "1.5");
    std::fs::write(&bad, text).unwrap();
    let log = dir.join("restore.log");
    for extra in [&[][..], &["--force"], &["--dry-run"]] {
        let mut args = with(
            &["snapshot", "restore", arg(&bad), "--log", arg(&log)],
            &pty(&sim),
        );
        args.extend(extra);
        let out = expect(&args, 2);
        let err = stderr(&out);
        assert!(
            err.contains(
                "cannot be restored onto module 1 (A), type TMCM-142; nothing was sent (3 problems):"
            ),
            "{err}"
        );
        assert!(
            err.contains("\n  pid_p: pid_p = abc is not a 32-bit integer"),
            "{err}"
        );
        assert!(err.contains("\n  standby_current: "), "{err}");
        assert!(err.contains("\n  user_variable_9: "), "{err}");
        assert!(
            !err.contains("--force restores"),
            "a bad value is never forced: {err}"
        );
        assert_eq!(stdout(&out), "", "no report: nothing happened");
    }
    assert_eq!(
        sent(&log, "SAP"),
        Vec::<String>::new(),
        "not one write was sent"
    );
    assert_eq!(sent(&log, "SGP"), Vec::<String>::new());
    // Every setting reads back as it was.
    expect(&with(&["snapshot", "save", arg(&after)], &pty(&sim)), 0);
    let same = expect(&["snapshot", "diff", arg(&before), arg(&after)], 0);
    assert!(
        stdout(&same).starts_with("no differences"),
        "{}",
        stdout(&same)
    );
}

#[test]
fn each_refusal_class_is_listed_and_force_restores_by_name() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let (good, odd) = (dir.join("good.toml"), dir.join("odd.toml"));
    expect(&with(&["snapshot", "save", arg(&good)], &pty(&sim)), 0);
    let text = std::fs::read_to_string(&good).unwrap();
    let text = text.replace("name = \"TMCM-142\"", "name = \"TMCM-1140\"");
    let text = with_value(&text, "pid_i", "21");
    let text = edit_line(&text, "pid_i", |l| {
        l.replace("number = 31,", "number = 99,")
    });
    let text = text.replace(
        "[axis.0]\n",
        "[axis.0]\nmax_curent = { number = 6, value = 2 }\n",
    );
    let text = format!("{text}\n[axis.3]\nmax_current = {{ number = 6, value = 2 }}\n");
    std::fs::write(&odd, text).unwrap();
    let log = dir.join("odd.log");
    let restore = with(
        &["snapshot", "restore", arg(&odd), "--log", arg(&log)],
        &pty(&sim),
    );
    let out = expect(&restore, 2);
    let err = stderr(&out);
    for problem in [
        "(4 problems):",
        "\n  it is a snapshot of a TMCM-1140, and module 1 (A) is a TMCM-142",
        "\n  pid_i: number = 99 in the file, but it is axis 31",
        "\n  [axis.0] max_curent: not a parameter of the TMCM-142; did you mean max_current?",
        "\n  [axis.3]: the TMCM-142 has no motor 3 (it has motors 0..0)",
        "\n--force restores by name anyway",
    ] {
        assert!(err.contains(problem), "{problem}: {err}");
    }
    assert_eq!(sent(&log, "SAP"), Vec::<String>::new());

    let mut forced = restore.clone();
    forced.push("--force");
    let out = expect(&forced, 0);
    let report = stdout(&out);
    assert_eq!(
        report.lines().filter(|l| l.starts_with("forced: ")).count(),
        4,
        "{report}"
    );
    assert!(
        report.contains("restored 1 parameter, each read back and verified (pid_i)"),
        "{report}"
    );
    let check = expect(&with(&["-c", "GAP pid_i, 0"], &pty(&sim)), 0);
    assert_eq!(
        stdout(&check),
        "BA 100 21\n",
        "written by name, to axis parameter 31"
    );
}

#[test]
fn a_snapshot_of_the_other_dialect_or_with_nothing_restorable_is_refused_even_forced() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let drive = dir.join("drive.toml");
    std::fs::write(
        &drive,
        "[module]\nname = \"SMD4\"\n[drive]\n\"MOTOR:IR\" = { value = 1.0, unit = \"A rms\", access = \"RWE\" }\n",
    )
    .unwrap();
    let live = dir.join("live.toml");
    std::fs::write(
        &live,
        "[module]\nname = \"TMCM-142\"\n[axis.0]\nactual_position = { number = 1, value = 5 }\n",
    )
    .unwrap();
    for (file, problem) in [
        (
            &drive,
            "it holds SMD4 drive settings, and module 1 (A) is a TMCL module",
        ),
        (&live, "nothing in it is a setting of the TMCM-142"),
    ] {
        for force in [None, Some("--force")] {
            let mut args = with(&["snapshot", "restore", arg(file)], &pty(&sim));
            args.extend(force);
            let out = expect(&args, 2);
            let err = stderr(&out);
            assert!(err.contains(problem) || force.is_some(), "{err}");
            assert!(
                err.contains("nothing in it is a setting of the TMCM-142"),
                "{err}"
            );
            assert!(!stdout(&out).contains("restored"), "never 'restored 0'");
        }
    }
}

#[test]
fn a_restore_with_nothing_to_write_says_so() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let file = dir.join("same.toml");
    expect(&with(&["snapshot", "save", arg(&file)], &pty(&sim)), 0);
    let out = expect(
        &with(
            &["snapshot", "restore", arg(&file), "--store", "--yes"],
            &pty(&sim),
        ),
        0,
    );
    let report = stdout(&out);
    assert!(
        report.contains(
            "nothing to write: the module already has the snapshot's value for all 87 settings"
        ),
        "{report}"
    );
    assert!(
        report.contains("not stored to EEPROM: the restore wrote nothing"),
        "{report}"
    );
    assert!(!report.contains("restored 0"), "{report}");
    assert!(
        !report.contains("by hand:"),
        "the link settings are the same: {report}"
    );
}

/// The built-in profile with max_current limited to 0..10: a simulator serving it refuses what
/// a client with the built-in profile lets through.
fn narrow_profile(dir: &std::path::Path) -> std::path::PathBuf {
    let text = std::fs::read_to_string(repo().join("data/profiles/tmcm-142.toml")).unwrap();
    let at = text.find("ident = \"max_current\"").unwrap();
    let range = at + text[at..].find("range = [0, 15]").unwrap();
    let changed = format!("{}range = [0, 10]{}", &text[..range], &text[range + 15..]);
    let path = dir.join("narrow.toml");
    std::fs::write(&path, changed).unwrap();
    path
}

#[test]
fn a_write_the_module_refuses_midway_is_reported_with_what_was_written() {
    let dir = tempdir();
    let profile = narrow_profile(&dir);
    let sim = Sim::start(&["--pty", "--profile", arg(&profile)]);
    let file = dir.join("module.toml");
    expect(&with(&["snapshot", "save", arg(&file)], &pty(&sim)), 0);
    let text = std::fs::read_to_string(&file).unwrap();
    let text = with_value(&text, "max_current", "12");
    let text = with_value(&text, "pid_p", "5");
    let text = with_value(&text, "user_variable_5", "7");
    std::fs::write(&file, text).unwrap();
    let out = expect(
        &with(
            &["snapshot", "restore", arg(&file), "--store", "--yes"],
            &pty(&sim),
        ),
        1,
    );
    let report = stdout(&out);
    assert!(
        report.contains(
            "restored 2 parameters, each read back and verified (pid_p, user_variable_5)"
        ),
        "{report}"
    );
    assert!(
        report.contains("FAILED max_current: module 1 (A) refused 'ASAP 6, 0, 12'"),
        "{report}"
    );
    assert!(
        report.contains("not stored to EEPROM: some parameters failed"),
        "{report}"
    );
    assert!(
        stderr(&out).contains("1 parameter not restored: max_current"),
        "{}",
        stderr(&out)
    );
    let check = expect(
        &with(
            &["-c", "GAP max_current, 0", "-c", "GAP pid_p, 0"],
            &pty(&sim),
        ),
        0,
    );
    assert_eq!(stdout(&check), "BA 100 8\nBA 100 5\n");
}

#[test]
fn a_link_that_fails_midway_leaves_a_report_of_what_was_written_and_what_was_not() {
    let dir = tempdir();
    let file = dir.join("module.toml");
    let edited = dir.join("edited.toml");
    let first_log = dir.join("first.log");
    {
        let sim = Sim::start(&["--pty"]);
        expect(&with(&["snapshot", "save", arg(&file)], &pty(&sim)), 0);
        let text = std::fs::read_to_string(&file).unwrap();
        let text = with_value(&text, "max_current", "3");
        let text = with_value(&text, "pid_p", "5");
        let text = with_value(&text, "pid_d", "6");
        std::fs::write(&edited, text).unwrap();
        // The same restore on a module that answers: where pid_p's write comes.
        let args = with(
            &[
                "snapshot",
                "restore",
                arg(&edited),
                "--log",
                arg(&first_log),
            ],
            &pty(&sim),
        );
        expect(&args, 0);
    }
    let replies: Vec<String> = std::fs::read_to_string(&first_log)
        .unwrap()
        .lines()
        .filter(|l| l.contains(" rx "))
        .map(String::from)
        .collect();
    let before_write = 1 + replies
        .iter()
        .position(|l| l.contains("rx \"AGAP 30, 0\\r"))
        .expect("pid_p is read before it is written");
    // A module that stops answering right after that read: pid_p's write gets no reply.
    let silent_after = before_write.to_string();
    let sim = Sim::start(&["--pty", "--silent-after", &silent_after]);
    let args = with(
        &["snapshot", "restore", arg(&edited), "--timeout", "200"],
        &pty(&sim),
    );
    let out = expect(&args, 3);
    let report = stdout(&out);
    assert!(
        report.contains("restored 1 parameter, each read back and verified (max_current)"),
        "{report}"
    );
    assert!(
        report.contains("the restore stopped: no reply from module 1 (A) within 200 ms"),
        "{report}"
    );
    assert!(
        report.contains("UNKNOWN pid_p: it was being written"),
        "{report}"
    );
    let not_reached = report
        .lines()
        .find(|l| l.starts_with("NOT REACHED "))
        .unwrap_or_else(|| panic!("{report}"));
    assert!(
        not_reached.contains(" pid_d,") && !not_reached.contains("pid_p"),
        "{not_reached}"
    );
    assert!(stderr(&out).contains("no reply from module 1 (A) within 200 ms"));
}

#[test]
fn the_store_confirmation_on_a_terminal_names_what_the_restore_wrote() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let file = dir.join("module.toml");
    expect(&with(&["-c", "SAP max_current, 0, 12"], &pty(&sim)), 0);
    expect(&with(&["snapshot", "save", arg(&file)], &pty(&sim)), 0);
    expect(
        &with(
            &[
                "-c",
                "SAP max_current, 0, 2",
                "-c",
                "SGP user_variable_5, 2, 9",
            ],
            &pty(&sim),
        ),
        0,
    );
    let mut command = std::process::Command::new(crate::util::bin());
    command
        .args([
            "snapshot",
            "restore",
            arg(&file),
            "--store",
            "--port",
            &sim.first,
        ])
        .env("NO_COLOR", "1");
    let mut p = rexpect::session::spawn_command(command, Some(crate::util::EXPECT_MS)).unwrap();
    p.exp_string(
        "store 2 parameters (max_current, user_variable_5) to the EEPROM of module 1 (A)? [y/N]",
    )
    .unwrap();
    p.send_line("n").unwrap();
    p.exp_string("restored 2 parameters").unwrap();
    p.exp_eof().unwrap();
    let check = expect(
        &with(
            &["-c", "RSAP max_current, 0", "-c", "GAP max_current, 0"],
            &pty(&sim),
        ),
        0,
    );
    assert_eq!(
        stdout(&check),
        "BA 100 0\nBA 100 8\n",
        "restored to 12 in RAM, the EEPROM still has the default 8"
    );
}
