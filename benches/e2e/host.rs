//! Rows 2 and 6, host overhead and transcript cost: N `gap()` calls in one script over a pty to
//! the unpaced simulator, side by side with the pyserial peer and with `--log`, interleaved
//! repetition by repetition so that a busy moment of the machine hits all of them alike. The
//! round trip of a bare pty (same bytes, no protocol, no simulator) is the floor underneath.

use std::fs::File;
use std::io::{Read, Write};
use std::process::Command;
use std::time::Instant;

use nix::sys::termios::{SetArg, cfmakeraw, tcgetattr, tcsetattr};

use crate::proc::{Finished, Sim, median, repo_file, run, runs, tmclsh};
use crate::report::Row;

/// How the rows are run.
pub struct Plan {
    pub n: u32,
    pub reps: usize,
    /// Whether python3 with pyserial is available.
    pub python: bool,
    pub scratch: std::path::PathBuf,
}

fn tmclsh_loop(sim: &Sim, n: u32, log: Option<&std::path::Path>) -> Finished {
    let mut command = Command::new(tmclsh());
    command
        .arg("run")
        .arg(repo_file("benches/e2e/gap_loop.rhai"))
        .args(["--port", &sim.path]);
    if let Some(log) = log {
        command.arg("--log").arg(log);
    }
    run(command.args(["--", &n.to_string()])).expect_success("tmclsh run (unpaced pty)")
}

/// Seconds per transaction, wall and CPU, over the repetitions.
#[derive(Default)]
struct Series {
    wall: Vec<f64>,
    cpu: Vec<f64>,
}

impl Series {
    fn push(&mut self, wall: f64, cpu: f64) {
        self.wall.push(wall);
        self.cpu.push(cpu);
    }

    /// Median µs per transaction, wall and CPU.
    fn us(&self) -> (f64, f64) {
        (median(&self.wall) * 1e6, median(&self.cpu) * 1e6)
    }
}

/// Runs the pyserial peer: seconds of its loop, wall and CPU.
fn peer(sim: &Sim, n: u32, read_until: bool) -> (f64, f64) {
    let mut command = Command::new("python3");
    command
        .arg(repo_file("benches/peers/pyserial_loop.py"))
        .args([&sim.path, &n.to_string()]);
    if read_until {
        command.arg("--read-until");
    }
    let done = run(&mut command).expect_success("the pyserial peer");
    (done.number(0), done.number(1))
}

/// Measures rows 2 and 6 and the pty floor. Ratios are the median of the ratios within each
/// repetition, whose runs follow one another, so a slow spell of the machine cancels out.
pub fn measure(plan: &Plan) -> Vec<Row> {
    let sim = Sim::start(&[]);
    let log = plan.scratch.join("transcript.log");
    let n = f64::from(plan.n);
    let (mut ours, mut logged) = (Series::default(), Series::default());
    let (mut plain_py, mut tuned_py) = (Series::default(), Series::default());
    let (mut log_ratio, mut plain_ratio, mut tuned_ratio) = (Vec::new(), Vec::new(), Vec::new());
    let mut floor = Vec::new();
    for rep in 0..plan.reps {
        // CPU per transaction: a loop's run minus a run without transactions (start-up,
        // entering and leaving ASCII mode).
        let empty = tmclsh_loop(&sim, 0, None);
        let measure = |log: Option<&std::path::Path>, series: &mut Series| {
            if let Some(log) = log {
                let _ = std::fs::remove_file(log);
            }
            let done = tmclsh_loop(&sim, plan.n, log);
            let wall = done.number(0) / n;
            series.push(wall, done.cpu.saturating_sub(empty.cpu).as_secs_f64() / n);
            wall
        };
        // With and without --log back to back, in turns first.
        let (plain, with_log) = if rep % 2 == 0 {
            let plain = measure(None, &mut ours);
            (plain, measure(Some(&log), &mut logged))
        } else {
            let with_log = measure(Some(&log), &mut logged);
            (measure(None, &mut ours), with_log)
        };
        log_ratio.push(with_log / plain);
        if plan.python {
            let (wall, cpu) = peer(&sim, plan.n, true);
            plain_py.push(wall / n, cpu / n);
            plain_ratio.push(wall / n / plain);
            let (wall, cpu) = peer(&sim, plan.n, false);
            tuned_py.push(wall / n, cpu / n);
            tuned_ratio.push(wall / n / plain);
        }
        floor.push(pty_floor(plan.n));
    }
    let _ = std::fs::remove_file(&log);
    drop(sim);
    let floor = median(&floor) * 1e6;
    let (us, cpu) = ours.us();
    let name = format!(
        "2. Host overhead, unpaced pty (N = {}, {})",
        plan.n,
        runs(plan.reps)
    );
    let measured = format!("{us:.1} µs/tx (CPU {cpu:.1} µs)");
    let mut rows = Vec::new();
    if plan.python {
        let (plain, plain_cpu) = plain_py.us();
        let (tuned, tuned_cpu) = tuned_py.us();
        let (plain_ratio, tuned_ratio) = (median(&plain_ratio), median(&tuned_ratio));
        rows.push(Row {
            name,
            measured,
            reference: format!("pyserial read_until loop {plain:.1} µs/tx (CPU {plain_cpu:.1} µs)"),
            ratio: format!("{plain_ratio:.1}× the peer's rate"),
            target: "≤ 50 µs, ≥ 3×".into(),
            met: Some(us <= 50.0 && plain_ratio >= 3.0),
        });
        rows.push(Row {
            name: "↳ the same against a tuned pyserial loop (reads what has arrived)".into(),
            measured: format!("{us:.1} µs/tx"),
            reference: format!("tuned pyserial loop {tuned:.1} µs/tx (CPU {tuned_cpu:.1} µs)"),
            ratio: format!("{tuned_ratio:.1}× the peer's rate"),
            target: "—".into(),
            met: None,
        });
    } else {
        rows.push(Row {
            name,
            measured,
            reference: "pyserial loop: skipped (python3 with pyserial not found)".into(),
            ratio: "—".into(),
            target: "≤ 50 µs, ≥ 3×".into(),
            met: None,
        });
    }
    rows.push(Row {
        name: format!(
            "↳ pty round-trip floor: 10 bytes out, 19 back, no program ({})",
            runs(plan.reps)
        ),
        measured: format!("{floor:.1} µs/round trip"),
        reference: "—".into(),
        ratio: format!("tmclsh and the simulator add {:.1} µs", us - floor),
        target: "—".into(),
        met: None,
    });
    let (log_us, log_cpu) = logged.us();
    let extra = (median(&log_ratio) - 1.0) * 100.0;
    rows.push(Row {
        name: format!("6. Transcript cost: row 2 with --log ({})", runs(plan.reps)),
        measured: format!("{log_us:.1} µs/tx (CPU {log_cpu:.1} µs)"),
        reference: format!("without --log {us:.1} µs/tx (CPU {cpu:.1} µs)"),
        ratio: format!("{extra:+.1} %"),
        target: "≤ +20 %".into(),
        met: Some(extra <= 20.0),
    });
    rows
}

/// Seconds per round trip over a bare pseudo-terminal: the client writes the 10 bytes of a
/// request, a thread on the other side reads them and writes 19 bytes (echo and reply of
/// character-echo mode), the client reads them. The kernel's part of every transaction.
pub fn pty_floor(n: u32) -> f64 {
    let pair = nix::pty::openpty(None, None).expect("openpty");
    let mut termios = tcgetattr(&pair.slave).expect("tcgetattr");
    cfmakeraw(&mut termios);
    tcsetattr(&pair.slave, SetArg::TCSANOW, &termios).expect("tcsetattr");
    let mut master = File::from(pair.master);
    let mut slave = File::from(pair.slave);
    // The server answers until the client closes its side: closing the master first would hang
    // up the terminal before the client has read the last reply.
    let server = std::thread::spawn(move || {
        let mut buf = [0u8; 64];
        loop {
            let mut got = 0;
            while got < 10 {
                match master.read(&mut buf) {
                    Ok(0) | Err(_) => return,
                    Ok(n) => got += n,
                }
            }
            if master.write_all(&[b'x'; 19]).is_err() {
                return;
            }
        }
    });
    let mut buf = [0u8; 64];
    let mut round = |slave: &mut File| {
        slave.write_all(&[b'a'; 10]).expect("write the request");
        let mut got = 0;
        while got < 19 {
            got += slave.read(&mut buf).expect("read the reply");
        }
    };
    round(&mut slave);
    let start = Instant::now();
    for _ in 0..n {
        round(&mut slave);
    }
    let elapsed = start.elapsed().as_secs_f64();
    drop(slave);
    server.join().expect("the pty server");
    elapsed / f64::from(n)
}
