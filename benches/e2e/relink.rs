//! Row 9, the reconnect time: an idle REPL on a port behind a stable symlink, the adapter
//! unplugged and plugged back (`tmclsh sim --link`, console `unplug`), timed from the moment the
//! new pseudo-terminal is there (the simulator's `pty PATH` line) to the REPL's `reconnected`.
//! The REPL runs on a pseudo-terminal of its own, read by a thread that stamps what arrives.

use std::fs::File;
use std::io::{BufRead, BufReader, Read, Write};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

use crate::proc::{median, runs, tmclsh};
use crate::report::Row;

/// The start of the row's name, by which `--reconnect` finds it in BENCHMARKS.md.
pub const ROW_PREFIX: &str = "10. Reconnect";

/// How long any one step may take.
const PATIENCE: Duration = Duration::from_secs(30);

/// Lines or bytes as they arrived, stamped.
struct Stamped {
    rx: Receiver<(Instant, String)>,
    seen: String,
}

impl Stamped {
    fn new(rx: Receiver<(Instant, String)>) -> Stamped {
        Stamped {
            rx,
            seen: String::new(),
        }
    }

    /// Waits for `text`; the time the chunk completing it arrived. What came before it and the
    /// text itself are consumed.
    fn until(&mut self, text: &str) -> Instant {
        let deadline = Instant::now() + PATIENCE;
        let mut at = Instant::now();
        loop {
            if let Some(i) = self.seen.find(text) {
                self.seen.drain(..i + text.len());
                return at;
            }
            let left = deadline.saturating_duration_since(Instant::now());
            let (when, chunk) = self
                .rx
                .recv_timeout(left)
                .unwrap_or_else(|_| panic!("no {text:?}; seen {:?}", self.seen));
            at = when;
            self.seen.push_str(&chunk);
        }
    }
}

/// Measures `reps` unplug–replug cycles under one REPL.
pub fn measure(reps: usize, scratch: &Path) -> Row {
    let link = scratch.join("relink-by-id");
    let mut sim = Command::new(tmclsh())
        .args(["sim", "--pty", "--link"])
        .arg(&link)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("tmclsh sim starts");
    let mut console = sim.stdin.take().expect("stdin");
    let (tx, rx) = channel();
    let stdout = sim.stdout.take().expect("stdout");
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines() {
            let Ok(line) = line else { break };
            if tx.send((Instant::now(), line + "\n")).is_err() {
                break;
            }
        }
    });
    let mut sim_out = Stamped::new(rx);
    sim_out.until("\n");
    let (mut repl, mut repl_out) = repl(&link, scratch);
    repl_out.until("A> ");
    let mut times = Vec::new();
    for rep in 0..reps {
        // Outages of different lengths: the replug falls at different points of the pauses
        // between tries.
        let outage = 0.25 + 0.15 * rep as f64;
        writeln!(console, "unplug {outage:.2}").expect("console");
        console.flush().expect("console");
        sim_out.until("ok unplugged");
        // The answer says "the pty comes back": the new path is the line that starts with it.
        repl_out.until("link lost");
        let back = sim_out.until("\npty /");
        let done = repl_out.until("reconnected");
        times.push(done.saturating_duration_since(back).as_secs_f64() * 1000.0);
        repl_out.until("A> ");
    }
    let _ = repl.kill();
    let _ = repl.wait();
    let _ = sim.kill();
    let _ = sim.wait();
    let (min, max) = times
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), t| (lo.min(*t), hi.max(*t)));
    Row {
        name: format!(
            "{ROW_PREFIX}: idle REPL, adapter unplugged and back on a new pty behind --link, \
             back to `reconnected` ({})",
            runs(reps)
        ),
        measured: format!("{:.0} ms", median(&times)),
        reference: format!("min {min:.0} ms, max {max:.0} ms"),
        ratio: "tries at pauses growing to 400 ms; outages 0.25 s and longer".into(),
        target: "—".into(),
        met: None,
    }
}

/// The REPL on `link` in a pseudo-terminal of its own; its output stamped as it arrives.
fn repl(link: &Path, home: &Path) -> (Child, Stamped) {
    let pty = nix::pty::openpty(None, None).expect("a pseudo-terminal");
    let slave = File::from(pty.slave);
    let io = |f: &File| Stdio::from(f.try_clone().expect("the terminal"));
    let child = Command::new(tmclsh())
        .arg("--port")
        .arg(link)
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("HOME", home)
        .env("XDG_DATA_HOME", home)
        .env("XDG_CONFIG_HOME", home)
        .stdin(io(&slave))
        .stdout(io(&slave))
        .stderr(io(&slave))
        .spawn()
        .expect("tmclsh starts");
    drop(slave);
    let mut master = File::from(pty.master);
    let (tx, rx) = channel();
    std::thread::spawn(move || {
        let mut buf = [0u8; 4096];
        while let Ok(n) = master.read(&mut buf) {
            if n == 0 {
                break;
            }
            let text = String::from_utf8_lossy(&buf[..n]).into_owned();
            if tx.send((Instant::now(), text)).is_err() {
                break;
            }
        }
    });
    (child, Stamped::new(rx))
}

/// `markdown` with the reconnect row replaced, or added at the end of the results table.
pub fn splice(markdown: &str, row_line: &str) -> String {
    super::report::splice_rows(markdown, ROW_PREFIX, &[row_line.to_string()])
}
