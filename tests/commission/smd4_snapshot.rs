//! Snapshots of a simulated SMD4 (`tmclsh sim --protocol smd4`) over its pty and over TCP: saved,
//! the drive changed, the diff shows exactly the change (couplings included) with units and exits
//! 1, the restore brings it back and verifies; STORE makes it survive SYS:LOAD and a power cycle;
//! refusals are reported per setting; a moving drive is not restored. Expected values come from
//! `data/smd4.toml` through the library (defaults, labels, current levels).

use std::path::Path;
use std::process::Output;

use tmclsh::commission::{ParamValue, Scope, Snapshot, Tolerance};
use tmclsh::dialect::smd4::protocol::{Smd4Command, Smd4Spec};

use super::arg;
use crate::smd4::{Drive, Via, assert_exit, client, lines};
use crate::util::tempdir;

fn command(mnemonic: &str) -> &'static Smd4Command {
    Smd4Spec::builtin().commands.get(mnemonic).unwrap()
}

fn default(mnemonic: &str) -> String {
    command(mnemonic).default.clone().unwrap()
}

/// Whether `printed` (a value as a table shows it) is on the same current level as `amps`.
fn same_level(mnemonic: &str, printed: &str, amps: f64) -> bool {
    let arg = command(mnemonic).arg.as_ref().unwrap();
    let step = Tolerance::Step(arg.max.unwrap() / f64::from(arg.levels.unwrap()));
    let value: f64 = printed
        .parse()
        .unwrap_or_else(|_| panic!("{printed} is a number"));
    step.same(&value.into(), &amps.into())
}

/// `tmclsh snapshot ACTION FILE … CONNECTION EXTRA`.
fn snapshot(drive: &Drive, action: &[&str], extra: &[&str]) -> Output {
    let mut args: Vec<String> = std::iter::once("snapshot")
        .chain(action.iter().copied())
        .map(String::from)
        .collect();
    args.extend(drive.connection());
    args.extend(extra.iter().map(|a| a.to_string()));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    client(&[], &args, "")
}

/// Lines sent through the shell (`-c` each), which must all succeed.
fn send(drive: &Drive, extra: &[&str], lines_: &[&str]) -> Vec<String> {
    let mut args: Vec<&str> = extra.to_vec();
    for line in lines_ {
        args.extend(["-c", line]);
    }
    let out = drive.run(&args);
    assert_exit(&out, 0);
    lines(&out)
}

/// The rows of a diff table without a "where" column: name, file, drive, unit (cells are
/// separated by two spaces or more; labels and units have single spaces).
fn rows(text: &str) -> Vec<Vec<String>> {
    let mut table = text.lines().skip_while(|l| !l.starts_with("parameter"));
    let header = table.next().expect("a diff table");
    assert!(!header.contains("where"), "{header}");
    table
        .take_while(|l| !l.is_empty() && !l.starts_with("no differences"))
        .map(|l| {
            l.split("  ")
                .map(str::trim)
                .filter(|c| !c.is_empty())
                .map(String::from)
                .collect()
        })
        .collect()
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn exercise(via: Via, extra: &[&str]) {
    let drive = Drive::start(via, &[]);
    let dir = tempdir();
    let file = dir.join("drive.toml");
    let file = arg(&file);
    send(&drive, extra, &["MOTOR:IR,0.3", "MOTOR:IA,0.6"]);
    let saved = snapshot(&drive, &["save", file], extra);
    assert_exit(&saved, 0);
    assert!(stdout(&saved).starts_with("saved "), "{}", stdout(&saved));
    let text = std::fs::read_to_string(file).unwrap();
    let firmware = command("SYS:FW").sim_value.clone().unwrap();
    assert!(
        text.contains(&format!("firmware = \"{firmware}\"")),
        "{text}"
    );
    assert!(text.contains("\n[drive]\n"), "{text}");
    assert!(text.contains("\"MOTOR:IR\" = { value = 0.30"), "{text}");
    assert!(
        text.contains("unit = \"A rms\", access = \"RWE\" }"),
        "{text}"
    );
    assert!(text.contains("\"SYS:MODE\" = { value = 1, label = \"Remote\""));
    assert!(text.contains("\"MOTOR:VMAX\" = { value = 1000.0, real = 1000.0, unit = \"Hz\""));

    let same = snapshot(&drive, &["diff", file], extra);
    assert_exit(&same, 0);
    assert!(stdout(&same).starts_with("no differences in "));

    // IR above IA raises IA; VSTART above VSTOP raises VSTOP; the position is a live value.
    send(
        &drive,
        extra,
        &[
            "MOTOR:IR,0.9",
            "MOTOR:VSTART,300",
            "LIMIT:EN,1",
            "COMS:SERIAL:BAUD,9600",
            "MOTOR:PACT,55",
        ],
    );
    let differ = snapshot(&drive, &["diff", file], extra);
    assert_exit(&differ, 1);
    let table = rows(&stdout(&differ));
    let names: Vec<&str> = table.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(
        names,
        [
            "MOTOR:IR",
            "MOTOR:IA",
            "LIMIT:EN",
            "MOTOR:VSTART",
            "MOTOR:VSTOP",
            "COMS:SERIAL:BAUD"
        ],
        "exactly the change: {}",
        stdout(&differ)
    );
    assert!(same_level("MOTOR:IR", &table[0][1], 0.3) && same_level("MOTOR:IR", &table[0][2], 0.9));
    assert!(same_level("MOTOR:IA", &table[1][1], 0.6) && same_level("MOTOR:IA", &table[1][2], 0.9));
    assert_eq!(table[0][3], command("MOTOR:IR").unit);
    let en = command("LIMIT:EN");
    assert_eq!(
        table[2][1..],
        [
            format!("0 ({})", en.label_of("0").unwrap()),
            format!("1 ({})", en.label_of("1").unwrap())
        ]
    );
    assert_eq!(
        table[3][1..],
        [default("MOTOR:VSTART"), "300".into(), "Hz".into()]
    );
    assert_eq!(
        table[4][1..],
        [default("MOTOR:VSTOP"), "300".into(), "Hz".into()]
    );
    assert_eq!(
        table[5][1..],
        [default("COMS:SERIAL:BAUD"), "9600".into(), "baud".into()]
    );
    assert!(stderr(&differ).contains("6 of "), "{}", stderr(&differ));

    let restored = snapshot(&drive, &["restore", file], extra);
    assert_exit(&restored, 0);
    let report = stdout(&restored);
    assert!(
        report.contains("restored 5 parameters, each read back and verified"),
        "{report}"
    );
    assert!(
        report.contains("(live values, not settings): MOTOR:PACT"),
        "{report}"
    );
    let prefix = if extra.is_empty() { "" } else { "@1" };
    let by_hand = format!(
        "by hand: {prefix}COMS:SERIAL:BAUD,{}",
        default("COMS:SERIAL:BAUD")
    );
    assert!(report.contains(&by_hand), "{report}");

    // Only the link setting left for manual handling still differs.
    let left = snapshot(&drive, &["diff", file], extra);
    assert_exit(&left, 1);
    let names: Vec<String> = rows(&stdout(&left))
        .into_iter()
        .map(|r| r[0].clone())
        .collect();
    assert_eq!(names, ["COMS:SERIAL:BAUD"]);
    send(
        &drive,
        extra,
        &[&format!("COMS:SERIAL:BAUD,{}", default("COMS:SERIAL:BAUD"))],
    );
    assert_exit(&snapshot(&drive, &["diff", file], extra), 0);
    let position = send(&drive, extra, &["MOTOR:PACT"]);
    assert!(
        position[0].ends_with(",55.00"),
        "live values are not written: {position:?}"
    );
}

#[test]
fn save_change_diff_restore_over_a_pty() {
    exercise(Via::Pty, &[]);
}

#[test]
fn save_change_diff_restore_over_tcp_with_an_address_prefix() {
    exercise(Via::Tcp, &["--address", "1"]);
}

/// The value of `mnemonic` in the snapshot `file`.
fn saved(file: &Path, mnemonic: &str) -> ParamValue {
    let snapshot = Snapshot::load(file).unwrap();
    snapshot
        .get(Scope::Drive, mnemonic)
        .unwrap()
        .value
        .clone()
        .unwrap()
}

#[test]
fn store_survives_sys_load_and_a_power_cycle_and_a_dry_run_changes_nothing() {
    let dir = tempdir();
    let state = dir.join("smd4-state.toml");
    let mut drive = Drive::start(Via::Pty, &["--state", arg(&state)]);
    let file = dir.join("drive.toml");
    send(&drive, &[], &["MOTOR:IH,0.3", "BAKE:T,120"]);
    assert_exit(&snapshot(&drive, &["save", arg(&file)], &[]), 0);
    send(&drive, &[], &["MOTOR:IH,0.6", "BAKE:T,80"]);

    let dry = snapshot(
        &drive,
        &["restore", arg(&file), "--dry-run", "--store"],
        &[],
    );
    assert_exit(&dry, 0);
    let sent: Vec<String> = lines(&dry)
        .into_iter()
        .take_while(|l| !l.starts_with("skipped"))
        .collect();
    assert_eq!(
        sent,
        [
            format!("MOTOR:IH,{}", saved(&file, "MOTOR:IH")),
            "BAKE:T,120".to_string(),
            "STORE".to_string()
        ]
    );
    assert_eq!(send(&drive, &[], &["BAKE:T"]), ["0x0888,0x0000,80"]);
    assert!(!state.exists(), "nothing stored by a dry run");

    let refused = snapshot(&drive, &["restore", arg(&file), "--store"], &[]);
    assert_exit(&refused, 2);
    assert!(
        stderr(&refused).contains("add --yes"),
        "{}",
        stderr(&refused)
    );

    let stored = snapshot(&drive, &["restore", arg(&file), "--store", "--yes"], &[]);
    assert_exit(&stored, 0);
    assert!(
        stdout(&stored).contains("parameters to non-volatile memory"),
        "{}",
        stdout(&stored)
    );
    let state_text = std::fs::read_to_string(&state).unwrap();
    assert!(state_text.contains("\"BAKE:T\" = 120"), "{state_text}");

    let loaded = send(
        &drive,
        &[],
        &[
            "MOTOR:IH,0.9",
            "BAKE:T,90",
            "SYS:LOAD",
            "BAKE:T",
            "MOTOR:IH",
        ],
    );
    assert_eq!(loaded[3], "0x0888,0x0000,120");
    let ih = loaded[4].rsplit(',').next().unwrap();
    assert!(same_level("MOTOR:IH", ih, 0.3), "{loaded:?}");

    send(&drive, &[], &["BAKE:T,91"]);
    drive.console("power-cycle");
    assert_eq!(send(&drive, &[], &["BAKE:T"]), ["0x0888,0x0000,120"]);
    assert_exit(&snapshot(&drive, &["diff", arg(&file)], &[]), 0);

    // A STORE the drive refuses (worn flash) fails the restore, by name.
    drive.console("flash-failure on");
    send(&drive, &[], &["BAKE:T,70"]);
    let worn = snapshot(&drive, &["restore", arg(&file), "--store", "--yes"], &[]);
    assert_exit(&worn, 1);
    let report = stdout(&worn);
    assert!(report.contains("restored 1 parameter"), "{report}");
    assert!(
        report.contains("FAILED STORE: the drive refused 'STORE': error -5"),
        "{report}"
    );
}

#[test]
fn a_file_the_table_refuses_is_refused_whole_and_settings_the_drive_refuses_are_reported_each() {
    let drive = Drive::start(Via::Tcp, &[]);
    let dir = tempdir();
    let file = dir.join("edited.toml");
    assert_exit(&snapshot(&drive, &["save", arg(&file)], &[]), 0);
    let text = std::fs::read_to_string(&file).unwrap();
    let edited = text
        .replace(
            "\"MOTOR:RES\" = { value = 256,",
            "\"MOTOR:RES\" = { value = 100,",
        )
        .replace("\"BAKE:T\" = { value = 150,", "\"BAKE:T\" = { value = 250,");
    assert_ne!(edited, text);
    std::fs::write(&file, edited).unwrap();
    send(&drive, &[], &["LIMIT:EN,1"]);

    // Checked against data/smd4.toml before sending: the whole file is refused, nothing sent.
    let out = snapshot(&drive, &["restore", arg(&file)], &[]);
    assert_exit(&out, 2);
    let err = stderr(&out);
    assert!(err.contains("nothing was sent (2 problems)"), "{err}");
    assert!(
        err.contains("\n  MOTOR:RES: 100 is not accepted by MOTOR:RES"),
        "{err}"
    );
    assert!(err.contains("\n  BAKE:T: "), "{err}");
    assert!(!stdout(&out).contains("restored"), "{}", stdout(&out));
    assert!(
        send(&drive, &[], &["LIMIT:EN"])[0].ends_with(",1"),
        "LIMIT:EN, a good value of the file, was not written either"
    );

    // Sent anyway: the drive refuses them itself (-2), each reported, nothing stored.
    send(&drive, &[], &["LIMIT:EN,1"]);
    let out = snapshot(
        &drive,
        &["restore", arg(&file), "--store", "--yes"],
        &["--no-validate"],
    );
    assert_exit(&out, 1);
    let report = stdout(&out);
    assert!(
        report.contains("FAILED MOTOR:RES: the drive refused 'MOTOR:RES,100': error -2"),
        "{report}"
    );
    assert!(report.contains("FAILED BAKE:T: the drive refused 'BAKE:T,250': error -2"));
    assert!(report.contains("not stored to non-volatile memory: some parameters failed"));
    let now = send(&drive, &[], &["MOTOR:RES", "LIMIT:EN"]);
    assert!(
        now[0].ends_with(&format!(",{}", default("MOTOR:RES"))),
        "{now:?}"
    );
    assert!(now[1].ends_with(",0"), "{now:?}");
}

#[test]
fn a_moving_drive_is_not_restored_until_it_stands_still() {
    let mut drive = Drive::start(Via::Pty, &["--manual-clock"]);
    let dir = tempdir();
    let file = dir.join("drive.toml");
    assert_exit(&snapshot(&drive, &["save", arg(&file)], &[]), 0);
    send(&drive, &[], &["LIMIT:EN,1", "MOTOR:RUNV,+"]);
    let out = snapshot(&drive, &["restore", arg(&file)], &[]);
    assert_exit(&out, 1);
    assert!(
        stderr(&out).contains("is moving (no standby flag)"),
        "{}",
        stderr(&out)
    );
    assert!(!drive.motor().standby, "still running");
    let en = send(&drive, &[], &["LIMIT:EN"]);
    assert!(en[0].ends_with(",1"), "nothing written: {en:?}");

    send(&drive, &[], &["MOTOR:STOP"]);
    drive.console("advance 5s");
    assert!(drive.motor().standby);
    let out = snapshot(&drive, &["restore", arg(&file)], &[]);
    assert_exit(&out, 0);
    assert!(
        stdout(&out).contains("restored 1 parameter"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn two_files_compare_currents_by_level_and_reals_to_the_reported_digits() {
    let drive = Drive::start(Via::Pty, &[]);
    let dir = tempdir();
    let (a, b) = (dir.join("a.toml"), dir.join("b.toml"));
    send(&drive, &[], &["MOTOR:IR,1.0"]);
    assert_exit(&snapshot(&drive, &["save", arg(&a)], &[]), 0);
    drop(drive);
    let text = std::fs::read_to_string(&a).unwrap();
    let ir = format!("\"MOTOR:IR\" = {{ value = {},", saved(&a, "MOTOR:IR"));
    assert!(text.contains(&ir), "{text}");
    // 1.0 A rounds to the level the drive reported; 1000.04 Hz is 1.0000E+03 in 5 digits.
    let close = text.replace(&ir, "\"MOTOR:IR\" = { value = 1.0,").replace(
        "\"MOTOR:VMAX\" = { value = 1000.0,",
        "\"MOTOR:VMAX\" = { value = 1000.04,",
    );
    std::fs::write(&b, &close).unwrap();
    let compare = |expected: i32| {
        let out = client(
            &[],
            &["snapshot", "diff", arg(&a), arg(&b), "--protocol", "smd4"],
            "",
        );
        assert_exit(&out, expected);
        out
    };
    compare(0);
    std::fs::write(
        &b,
        close.replace(
            "\"MOTOR:VMAX\" = { value = 1000.04,",
            "\"MOTOR:VMAX\" = { value = 1000.2,",
        ),
    )
    .unwrap();
    let out = compare(1);
    let table = rows(&stdout(&out));
    assert_eq!(table.len(), 1, "{}", stdout(&out));
    assert_eq!(table[0], ["MOTOR:VMAX", "1000", "1000.2", "Hz"]);
}

#[test]
fn the_shell_helper_saves_diffs_and_restores_an_smd4() {
    let drive = Drive::start(Via::Pty, &[]);
    let dir = tempdir();
    let file = dir.join("shell.toml");
    let save = format!(":snapshot save {}", arg(&file));
    let diff = format!(":snapshot diff {}", arg(&file));
    let restore = format!(":snapshot restore {}", arg(&file));
    let out = drive.run(&["-c", &save, "-c", "MOTOR:THIGH,500", "-c", &diff]);
    assert_exit(&out, 1);
    let text = stdout(&out);
    assert!(text.starts_with("saved "), "{text}");
    assert_eq!(
        rows(&text),
        [["MOTOR:THIGH", &default("MOTOR:THIGH"), "500", "Hz"]]
    );
    let out = drive.run(&["-c", &restore, "-c", &diff]);
    assert_exit(&out, 0);
    assert!(stdout(&out).contains("restored 1 parameter"));
}

#[test]
fn a_tmcl_snapshot_or_one_of_another_drive_is_refused_by_an_smd4() {
    let drive = Drive::start(Via::Pty, &[]);
    let dir = tempdir();
    let (tmcl, other) = (dir.join("tmcl.toml"), dir.join("other.toml"));
    // A TMCM-142 snapshot, from the built-in simulator.
    let out = crate::util::run(&["--sim", "snapshot", "save", arg(&tmcl)]);
    assert_exit(&out, 0);
    for force in [&[][..], &["--force"]] {
        let out = snapshot(&drive, &["restore", arg(&tmcl)], force);
        assert_exit(&out, 2);
        let err = stderr(&out);
        assert!(
            err.contains("nothing in it is a setting of the SMD4"),
            "{err}"
        );
        if force.is_empty() {
            assert!(
                err.contains(
                    "it holds TMCL axis and global parameters, and the drive is an SMD4 drive"
                ),
                "{err}"
            );
            assert!(err.contains("it is a snapshot of a TMCM-142"), "{err}");
        }
    }
    assert_exit(&snapshot(&drive, &["save", arg(&other)], &[]), 0);
    let text = std::fs::read_to_string(&other).unwrap();
    let text = text
        .replace("name = \"SMD4\"", "name = \"SMD2\"")
        .replace("\"LIMIT:EN\" = { value = 0,", "\"LIMIT:EN\" = { value = 1,");
    std::fs::write(&other, text).unwrap();
    let out = snapshot(&drive, &["restore", arg(&other)], &[]);
    assert_exit(&out, 2);
    assert!(
        stderr(&out).contains("it is a snapshot of an SMD2, and the drive is an SMD4"),
        "{}",
        stderr(&out)
    );
    assert!(
        send(&drive, &[], &["LIMIT:EN"])[0].ends_with(",0"),
        "nothing sent"
    );
    let out = snapshot(&drive, &["restore", arg(&other)], &["--force"]);
    assert_exit(&out, 0);
    assert!(
        send(&drive, &[], &["LIMIT:EN"])[0].ends_with(",1"),
        "forced"
    );
}
