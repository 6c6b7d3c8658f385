//! The commissioning functions of Rhai scripts over a pty: snapshots and recordings, and the
//! limits on the files a script may write.

use super::{arg, expect};
use crate::sim::Sim;
use crate::util::{stderr, tempdir};

#[test]
fn a_script_saves_diffs_and_restores_a_snapshot_and_records() {
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let script = dir.join("commission.rhai");
    let snapshot = dir.join("module.toml");
    let csv = dir.join("move.csv");
    std::fs::write(
        &script,
        format!(
            r#"
let n = snapshot_save("{snapshot}");
assert(n > 100, "saved " + n);
assert_eq(snapshot_diff("{snapshot}").len(), 0);
sap("max_current", 0, 4);
let d = snapshot_diff("{snapshot}");
assert_eq(d.len(), 1);
assert_eq(d[0].name, "max_current");
assert_eq(d[0].file, 8);
assert_eq(d[0].current, 4);
assert_eq(snapshot_restore("{snapshot}"), 1);
assert_eq(gap("max_current", 0), 8);
mvp_abs(0, 3000);
let samples = record_csv("{csv}", "actual_position, target_position_reached", 20, 200);
assert(samples >= 2, "samples " + samples);
"#,
            snapshot = arg(&snapshot),
            csv = arg(&csv),
        ),
    )
    .unwrap();
    expect(&["run", arg(&script), "--port", &sim.first], 0);
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(
        text.starts_with("time_ms,actual_position,target_position_reached\n0,"),
        "{text}"
    );
}

#[test]
fn scripts_may_write_only_snapshots_and_recordings() {
    let dir = tempdir();
    let script = dir.join("bad.rhai");
    let target = dir.join("notes.txt");
    std::fs::write(&script, format!("snapshot_save(\"{}\");", arg(&target))).unwrap();
    let out = expect(&["--sim", "run", arg(&script)], 2);
    assert!(
        stderr(&out).contains("a snapshot is written to a .toml file"),
        "{}",
        stderr(&out)
    );
    assert!(!target.exists());
    std::fs::write(
        &script,
        format!(
            "record_csv(\"{}\", [\"actual_position\"], 10, 100);",
            arg(&target)
        ),
    )
    .unwrap();
    let out = expect(&["--sim", "run", arg(&script)], 2);
    assert!(stderr(&out).contains("a recording is written to a .csv file"));
    assert!(!target.exists());
}
