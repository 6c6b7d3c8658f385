//! Row 1, wire efficiency: N `GAP 1, 0` transactions against `tmclsh sim --pty --baud B`, in each
//! echo mode, against the time the bytes need on the line.
//!
//! The limit of one transaction, in byte times (10 bits per byte, 8N1, full duplex):
//! - no echo: the request, then the reply: `R + P`;
//! - line echo: the request, then the echoed line with its CR, then the reply: `R + R + P`;
//! - character echo: each character is echoed while the next one is on its way in, so the echo
//!   overlaps the request; only the echo of the final CR comes after it: `R + 1 + P`.
//!
//! `R` is the request line with its CR (`AGAP 1, 0␍`, 10 bytes), `P` the reply with its CR
//! (`BA 100 0␍`, 9 bytes), both as the library formats them. The simulator answers at once, so
//! a client that adds nothing sits at 100 %.

use std::process::Command;
use std::time::{Duration, Instant};

use nix::sys::time::TimeSpec;

use tmclsh::dialect::tmcl::profile::Profile;
use tmclsh::dialect::tmcl::protocol::{AsciiReply, Status, format_line, parse};

use crate::proc::{Sim, median, repo_file, run, tmclsh};
use crate::report::Row;

/// The prefix of this part's rows.
pub const PREFIX: &str = "1. Wire efficiency";

/// The prefix of the timer lateness row under them.
pub const LATENESS_PREFIX: &str = "↳ timer wake-up lateness";

/// The echo modes: name, GP 67 value.
const MODES: [(&str, i64); 3] = [("character echo", 0), ("line echo", 16), ("no echo", 32)];

/// One baud rate's run: transactions and repetitions (the median is reported).
pub struct Line {
    pub baud: u32,
    pub n: u32,
    pub reps: usize,
}

/// Byte times per transaction on an ideal line.
pub fn limit_bytes(gp67: i64) -> u64 {
    let profile = Profile::builtin();
    let line = parse("GAP 1, 0", &profile).expect("GAP 1, 0 parses");
    let request = format_line(&line, 1, &profile).len() as u64 + 1;
    let reply = AsciiReply {
        host: 'B',
        module: 'A',
        status: Status::Ok,
        value: 0,
    }
    .format()
    .len() as u64
        + 1;
    match gp67 {
        0 => request + 1 + reply,
        16 => request + request + reply,
        _ => request + reply,
    }
}

/// Measures every echo mode at each line speed.
pub fn measure(lines: &[Line]) -> Vec<Row> {
    let script = repo_file("benches/e2e/gap_loop.rhai");
    let mut rows = Vec::new();
    for line in lines {
        let sim = Sim::start(&["--baud", &line.baud.to_string()]);
        for (mode, gp67) in MODES {
            let per_tx: Vec<f64> = (0..line.reps)
                .map(|_| {
                    let done = run(Command::new(tmclsh())
                        .arg("run")
                        .arg(&script)
                        .args(["--port", &sim.path, "--baud", &line.baud.to_string()])
                        .args(["--", &line.n.to_string(), &gp67.to_string()]))
                    .expect_success("tmclsh run (wire efficiency)");
                    done.number(0) / f64::from(line.n)
                })
                .collect();
            let measured = median(&per_tx);
            let bytes = limit_bytes(gp67);
            let limit = bytes as f64 * 10.0 / f64::from(line.baud);
            let efficiency = limit / measured * 100.0;
            rows.push(Row {
                name: format!(
                    "{PREFIX}, {} baud, {mode} (N = {}, {})",
                    line.baud,
                    line.n,
                    crate::proc::runs(line.reps)
                ),
                measured: format!("{:.3} ms/tx", measured * 1e3),
                reference: format!("limit {:.3} ms/tx ({bytes} byte times)", limit * 1e3),
                ratio: format!("{efficiency:.1} % of the limit"),
                target: "≥ 97 %".into(),
                met: Some(efficiency >= 97.0),
            });
        }
    }
    let late = timer_lateness(2000) * 1e6;
    rows.push(Row {
        name: format!("{LATENESS_PREFIX}: ppoll for one byte time at 115200 baud, slack 1 ns"),
        measured: format!("{late:.1} µs (median of 2000)"),
        reference: "—".into(),
        ratio: "—".into(),
        target: "—".into(),
        met: None,
    });
    rows
}

/// How late a timed wake-up comes on this machine: the simulator waits like this for every
/// byte it delivers, so the last byte of each reply reaches the client that much after its wire
/// time. Median seconds over `samples` waits of one byte time at 115200 baud, in a thread with
/// the simulator's timer slack.
fn timer_lateness(samples: usize) -> f64 {
    std::thread::spawn(move || {
        let _ = nix::sys::prctl::set_timerslack(1);
        let wait = Duration::from_nanos(1_000_000_000 * 10 / 115_200);
        let late: Vec<f64> = (0..samples)
            .map(|_| {
                let start = Instant::now();
                let _ = nix::poll::ppoll(&mut [], Some(TimeSpec::from(wait)), None);
                start.elapsed().saturating_sub(wait).as_secs_f64()
            })
            .collect();
        median(&late)
    })
    .join()
    .expect("the timer thread")
}

/// The heading of this part's section.
pub const HEADING: &str = "## Wire efficiency";

/// The section that says when row 1 was measured, under what load, and how the simulator paces.
pub fn section(date: &str, load_before: &str, load_after: &str) -> String {
    format!(
        "{HEADING}\n\n{} The simulator delivers each byte at its wire time and never before, \
         waking for it with a timed ppoll (timer slack 1 ns), which comes late by about the \
         timer lateness row. Only these rows: `cargo bench --bench e2e -- --wire`.\n",
        crate::report::measured_under("Row 1", date, load_before, load_after)
    )
}
