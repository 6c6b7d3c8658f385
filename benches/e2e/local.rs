//! Rows 3, 4 and 5, on the built-in simulator (no OS I/O between tmclsh and the module):
//! transactions per second, start-up against importing pyserial, and peak memory with `--log`.

use std::process::Command;
use std::time::Duration;

use crate::proc::{median, repo_file, run, run_silent, tmclsh};
use crate::report::Row;

fn gap_loop(n: u32, log: Option<&std::path::Path>) -> crate::proc::Finished {
    let mut command = Command::new(tmclsh());
    command
        .arg("run")
        .arg(repo_file("benches/e2e/gap_loop.rhai"))
        .arg("--sim");
    if let Some(log) = log {
        command.arg("--log").arg(log);
    }
    run(command.args(["--", &n.to_string()])).expect_success("tmclsh run (built-in simulator)")
}

/// Row 3: the script loop against the in-process simulator.
pub fn in_process(n: u32, reps: usize) -> Row {
    let seconds: Vec<f64> = (0..reps).map(|_| gap_loop(n, None).number(0)).collect();
    let per_second = f64::from(n) / median(&seconds);
    Row {
        name: format!(
            "3. In-process: gap() in a script loop (N = {n}, {})",
            crate::proc::runs(reps)
        ),
        measured: format!(
            "{} tx/s ({:.2} µs/tx)",
            thousands(per_second),
            1e6 / per_second
        ),
        reference: "—".into(),
        ratio: "—".into(),
        target: "≥ 1,000,000 tx/s".into(),
        met: Some(per_second >= 1_000_000.0),
    }
}

/// Row 4: `tmclsh -c "GAP 1, 0"`, whole process, against `python3 -c "import serial"`.
pub fn start_up(runs: usize, python: bool) -> Row {
    let check = run(Command::new(tmclsh()).args(["-c", "GAP 1, 0"]))
        .expect_success("tmclsh -c \"GAP 1, 0\"");
    assert!(
        check.stdout.contains("BA 100"),
        "tmclsh -c printed {:?}",
        check.stdout
    );
    let mut ours = Vec::new();
    let mut theirs = Vec::new();
    for _ in 0..runs {
        ours.push(ms(timed(Command::new(tmclsh()).args(["-c", "GAP 1, 0"]))));
        if python {
            theirs.push(ms(timed(
                Command::new("python3").args(["-c", "import serial"]),
            )));
        }
    }
    let ours = median(&ours);
    let name = format!(
        "4. Start-up: tmclsh -c \"GAP 1, 0\", whole process ({})",
        crate::proc::runs(runs)
    );
    let (reference, ratio) = if python {
        let theirs = median(&theirs);
        (
            format!("python3 -c \"import serial\" {theirs:.2} ms"),
            format!("{:.1}× quicker", theirs / ours),
        )
    } else {
        (
            "python3 -c \"import serial\": skipped (not available)".into(),
            "—".into(),
        )
    };
    Row {
        name,
        measured: format!("{ours:.2} ms"),
        reference,
        ratio,
        target: "≤ 10 ms".into(),
        met: Some(ours <= 10.0),
    }
}

/// The row under row 4: the size of the binary whose start-up it measured.
pub fn size() -> Row {
    let bytes = std::fs::metadata(tmclsh())
        .expect("the tmclsh binary is there")
        .len();
    Row {
        name: "↳ size of that binary on disk (the release profile)".into(),
        measured: format!("{:.1} MB", bytes as f64 / 1e6),
        reference: "—".into(),
        ratio: "—".into(),
        target: "—".into(),
        met: None,
    }
}

fn timed(command: &mut Command) -> Duration {
    let (success, wall) = run_silent(command);
    assert!(success, "{command:?} failed");
    wall
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// Row 5: peak RSS of the loop with `--log`, at N and at N/10, to show it does not grow.
pub fn memory(n: u32, scratch: &std::path::Path) -> Row {
    let log = scratch.join("memory.log");
    let measure = |n: u32| {
        let _ = std::fs::remove_file(&log);
        let done = gap_loop(n, Some(&log));
        let lines = std::fs::read_to_string(&log)
            .map(|t| t.lines().count())
            .unwrap_or(0);
        assert!(lines >= 2 * n as usize, "the transcript has {lines} lines");
        done.max_rss as f64 / (1024.0 * 1024.0)
    };
    let small = measure(n / 10);
    let large = measure(n);
    let _ = std::fs::remove_file(&log);
    let growth = large - small;
    Row {
        name: format!(
            "5. Peak RSS with --log, {} transactions (built-in simulator)",
            thousands(f64::from(n))
        ),
        measured: format!("{large:.1} MiB"),
        reference: format!(
            "{} transactions: {small:.1} MiB",
            thousands(f64::from(n / 10))
        ),
        ratio: format!("{growth:+.2} MiB for 10× the transactions"),
        target: "≤ 20 MB, flat".into(),
        met: Some(large * 1.048_576 <= 20.0 && growth <= 0.05 * small),
    }
}

/// `1234567.8` as `1,234,568`.
pub fn thousands(value: f64) -> String {
    let digits = format!("{:.0}", value);
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}
