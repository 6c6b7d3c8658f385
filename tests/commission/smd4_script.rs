//! The commissioning functions of Rhai scripts on a simulated SMD4, over its pty and over TCP:
//! snapshots with real values, units and user/real pairs, a restore that stores (seen through
//! SYS:LOAD), and a recording of a move.

use super::arg;
use crate::smd4::{BOTH, Drive, assert_exit};
use crate::util::tempdir;

const SCRIPT: &str = r#"
send("BAKE:T,111");
let n = snapshot_save(args[0]);
assert(n > 40, `saved ${n}`);
assert_eq(snapshot_diff(args[0]).len(), 0);

send("MOTOR:VMAX,2000");
send("MOTOR:IR,0.5");
let d = snapshot_diff(args[0]);
assert_eq(d.len(), 2);
assert_eq(d[0].name, "MOTOR:IR");
assert_eq(d[0].unit, "A rms");
assert_eq(type_of(d[0].current), "f64");
assert(d[0].current < 0.52 && d[0].current > 0.49, `IR ${d[0].current}`);
assert_eq(d[1].name, "MOTOR:VMAX");
assert_eq(d[1].file, 1000.0);
assert_eq(d[1].current, 2000.0);

assert_eq(snapshot_restore(args[0]), 2);
assert_eq(parse_number(send("MOTOR:VMAX")[0]), 1000.0);
assert_eq(snapshot_diff(args[0]).len(), 0);

// Nothing left to write: nothing to store either.
assert_eq(snapshot_restore(args[0], true), 0);
// One setting written; STORE saves the whole configuration, BAKE:T = 111 included.
send("MOTOR:VMAX,2000");
assert_eq(snapshot_restore(args[0], true), 1);
send("BAKE:T,5");
send("SYS:LOAD");
assert_eq(send("BAKE:T"), ["111"]);

send("MOTOR:RUNR,300");
// How many samples fit in 200 ms depends on the machine's load; the first is always taken.
let samples = record_csv(args[1], "MOTOR:PACT, MOTOR:VACT, SYS:FLAGS", 20, 200);
assert(samples >= 1, `samples ${samples}`);
wait_standby(10000);
"#;

#[test]
fn a_script_saves_diffs_restores_stores_and_records_an_smd4() {
    let dir = tempdir();
    let script = dir.join("commission.rhai");
    std::fs::write(&script, SCRIPT).unwrap();
    for via in BOTH {
        let drive = Drive::start(via, &[]);
        let snapshot = dir.join(format!("{via:?}.toml"));
        let csv = dir.join(format!("{via:?}.csv"));
        let out = drive.script(&script, &["--", arg(&snapshot), arg(&csv)]);
        assert_exit(&out, 0);
        let text = std::fs::read_to_string(&csv).unwrap();
        assert!(
            text.starts_with("time_ms,MOTOR:PACT,MOTOR:VACT,SYS:FLAGS\n0,"),
            "{text}"
        );
    }
}
