//! Row 9, an FTDI adapter's latency timer: N `GAP 1, 0` transactions (no echo) at 115200 baud
//! through `tmclsh sim --latency MS`, which holds each reply as the adapter does, against the
//! same line without a timer. 16 ms is what an untouched adapter costs (where tmclsh cannot set
//! the low-latency flag, it says so and gives the fix); 1 ms is the timer it sets.

use std::process::Command;

use crate::proc::{Sim, median, repo_file, run, runs, tmclsh};
use crate::report::Row;

/// The rate of the rows: where the timer, not the wire, sets the pace.
const BAUD: &str = "115200";

/// The timers measured, in milliseconds.
const TIMERS: [u64; 2] = [16, 1];

/// Seconds per transaction through a simulator started with `args`, median of `reps` runs.
fn per_tx(args: &[&str], n: u32, reps: usize) -> f64 {
    let script = repo_file("benches/e2e/gap_loop.rhai");
    let sim = Sim::start(args);
    let each: Vec<f64> = (0..reps)
        .map(|_| {
            let done = run(Command::new(tmclsh())
                .arg("run")
                .arg(&script)
                .args(["--port", &sim.path, "--baud", BAUD])
                .args(["--", &n.to_string(), "32"]))
            .expect_success("tmclsh run (latency timer)");
            done.number(0) / f64::from(n)
        })
        .collect();
    median(&each)
}

/// The rows: one per timer.
pub fn measure(n: u32, reps: usize) -> Vec<Row> {
    let without = per_tx(&["--baud", BAUD], n, reps);
    TIMERS
        .iter()
        .map(|ms| {
            let with = per_tx(&["--baud", BAUD, "--latency", &ms.to_string()], n, reps);
            Row {
                name: format!(
                    "9. Latency timer {ms} ms (sim --latency), {BAUD} baud, no echo (N = {n}, {})",
                    runs(reps)
                ),
                measured: format!("{:.3} ms/tx", with * 1e3),
                reference: format!("no timer {:.3} ms/tx", without * 1e3),
                ratio: format!("{:.1}× as long", with / without),
                target: "—".into(),
                met: None,
            }
        })
        .collect()
}

/// `markdown` with the latency rows replaced, or added at the end of the results table.
pub fn splice(markdown: &str, rows: &[String]) -> String {
    super::report::splice_rows(markdown, "9. Latency timer", rows)
}

/// The heading of this part's section.
pub const HEADING: &str = "## Latency timers";

/// The section that says when row 9 was measured and under what load.
pub fn section(date: &str, load_before: &str, load_after: &str) -> String {
    format!(
        "{HEADING}\n\n{} Only these rows: `cargo bench --bench e2e -- --latency`.\n",
        crate::report::measured_under("Row 9", date, load_before, load_after)
    )
}
