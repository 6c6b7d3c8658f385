//! Runaway scripts are bounded: building a large array is linear (the ratio lives in the
//! benchmark), `--max-time` ends a loop and a script whose motor turns (stopping it), and memory
//! is capped. Deadlines here are hang guards, not timing assertions.

use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::sim::Sim;
use crate::util::{bin, code, stderr, stdout, tempdir};

/// Runs `tmclsh run` on `source` with `extra`, killing it (and failing) past `guard`.
fn run_within(source: &str, extra: &[&str], guard: Duration) -> Output {
    let script = tempdir().join("limit.rhai");
    std::fs::write(&script, source).unwrap();
    let mut child = Command::new(bin())
        .args(linked(extra))
        .arg("run")
        .arg(&script)
        .args(extra)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > guard {
            let _ = child.kill();
            panic!("still running after {guard:?}: {source}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

#[test]
fn two_hundred_thousand_pushes_finish() {
    // Quadratic, this took minutes; linear, a few seconds even unoptimised.
    let source = "let a = [];\nfor i in 0..200000 { a.push(i); }\nprint(a.len());\n";
    let out = run_within(source, &[], Duration::from_secs(90));
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "200000\n");
}

#[test]
fn max_time_ends_a_runaway_loop() {
    let out = run_within(
        "let n = 0;\nloop { n += 1; }\n",
        &["--max-time", "300ms", "--max-operations", "0"],
        Duration::from_secs(30),
    );
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("runaway script: it ran longer than its --max-time of 300ms"),
        "{}",
        stderr(&out)
    );
    let out = run_within("print(1);", &["--max-time", "0"], Duration::from_secs(30));
    assert_eq!(code(&out), 2, "{}", stderr(&out));
}

#[test]
fn max_time_stops_a_script_whose_motor_turns_and_the_motor() {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let source = "ror(0, 100000);\nprint(\"spinning\");\nsleep(600000);\n";
    let out = run_within(
        source,
        &["--port", &sim.first, "--max-time", "1s"],
        Duration::from_secs(30),
    );
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    assert_eq!(stdout(&out), "spinning\n");
    let err = stderr(&out);
    assert!(
        err.contains("ran longer than its --max-time of 1s"),
        "{err}"
    );
    assert!(
        err.contains("stopped motor 0 of module 1 (A) with MST"),
        "{err}"
    );
    sim.console("advance 10s");
    assert!(
        sim.console("motor").contains("velocity 0"),
        "the motor ends stopped"
    );
}

#[test]
fn a_script_that_grows_without_bound_hits_the_memory_cap() {
    for source in [
        "let s = \"ab\";\nloop { s += s; }\n",
        "let a = [1];\nloop { a += a; }\n",
        "let s = \"\";\ns.pad(100000000000, \"x\");\n",
        "let a = [];\na.pad(100000000, [1, 2, 3]);\n",
        "let b = blob(100000000000);\n",
    ] {
        let out = run_within(source, &["--max-memory", "64"], Duration::from_secs(60));
        assert_eq!(code(&out), 1, "{source}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("runaway script: it holds more memory than allowed"),
            "{source}: {}",
            stderr(&out)
        );
    }
    let out = run_within(
        "let s = \"\"; s.pad(1000, \"ab\"); assert_eq(s.len(), 1000);\nlet a = []; a.pad(3, 7); assert_eq(a, [7, 7, 7]);\nassert_eq(blob(4, 1).len(), 4);\n",
        &[],
        Duration::from_secs(30),
    );
    assert_eq!(code(&out), 0, "pad and blob still work: {}", stderr(&out));
}

/// `--sim` unless `extra` names a link: a script run without a terminal must be told what it
/// talks to.
fn linked(extra: &[&str]) -> Vec<&'static str> {
    if extra.iter().any(|a| *a == "--port" || *a == "--tcp") {
        Vec::new()
    } else {
        vec!["--sim"]
    }
}
