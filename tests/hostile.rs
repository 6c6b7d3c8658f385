//! The session's guarantee under a hostile line: every value handed to a user, a `-c` line or a
//! script is the answer to that request, or the request fails with a clear message and exit code
//! 3 — in bounded time and memory, and the next request still gets its own answer.
//!
//! The misbehaving device ([`Fake`], in `fake.rs`) is the real simulator (a TMCL bus or an SMD4 drive) behind a
//! thread of the test that serves a real pseudo-terminal or a TCP socket; a rule decides, request
//! by request, what goes on the wire instead of the simulator's answer: late, cut short, glued to
//! more data, from another address, a flood, or a hang-up halfway. Everything else is the
//! simulator's own behaviour. The binary under test is the real `tmclsh`.

mod adapter_echo;
mod fake;
mod interrupt;
mod modes;
mod order;
mod smd4;
mod tmcl;

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::util::bin;

pub use fake::{Act, BOTH, Corruption, Fake, Via, await_request, on, replace_last, same};

/// How long any run may take before the test calls it a hang (a guard, not a timing claim).
pub const HANG_GUARD: Duration = Duration::from_secs(20);

/// Peak memory any run may reach: a flood must not make it grow (tmclsh needs under 10 MiB).
pub const MEMORY_BOUND_KIB: i64 = 48 * 1024;

/// What a run of tmclsh did.
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
    /// Peak resident memory of the process, KiB.
    pub peak_rss_kib: i64,
    /// What `/proc` said of the process when it first passed the memory bound (its status and
    /// the sum of its mappings), so that a rare spike can be explained from the failure alone.
    pub over_bound: Option<String>,
}

impl Run {
    /// Asserts the run ended with `code`, within the hang guard and the memory bound.
    pub fn expect(&self, code: i32, what: &str) {
        assert_eq!(
            self.code, code,
            "{what}: exit code\nstdout: {}\nstderr: {}",
            self.stdout, self.stderr
        );
        assert!(
            self.peak_rss_kib < MEMORY_BOUND_KIB,
            "{what}: peak RSS {} KiB\n{}",
            self.peak_rss_kib,
            self.over_bound.as_deref().unwrap_or("")
        );
        assert!(
            self.stderr.len() < 8 * 1024,
            "{what}: notices are summarised, not repeated: {} bytes of stderr",
            self.stderr.len()
        );
    }

    pub fn lines(&self) -> Vec<&str> {
        self.stdout.lines().collect()
    }
}

/// Runs `tmclsh ARGS` to completion, with its peak memory, failing on a hang.
pub fn tmclsh(args: &[String]) -> Run {
    let mut child = Command::new(bin())
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        // The bound is the binary's own: a panic's backtrace, symbolised from a debug build's
        // debug information, takes over 100 MB (and fails the run with 101 in any case).
        .env("RUST_BACKTRACE", "0")
        .spawn()
        .expect("tmclsh runs");
    let pid = child.id();
    let collect = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut text = Vec::new();
            let _ = pipe.read_to_end(&mut text);
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let out = collect(Box::new(child.stdout.take().unwrap()));
    let err = collect(Box::new(child.stderr.take().unwrap()));
    let started = Instant::now();
    let mut peak_rss_kib = 0;
    let mut over_bound = None;
    let status = loop {
        if let Some(status) = child.try_wait().expect("tmclsh can be waited for") {
            break status;
        }
        // The high-water mark of the process's own memory (getrusage of a child would count
        // the test process it was forked from).
        peak_rss_kib = peak_rss_kib.max(high_water_mark(pid).unwrap_or(0));
        if peak_rss_kib >= MEMORY_BOUND_KIB && over_bound.is_none() {
            let proc = |file: &str| std::fs::read_to_string(format!("/proc/{pid}/{file}"));
            over_bound = Some(format!(
                "/proc/{pid}/status:\n{}\nsmaps_rollup:\n{}",
                proc("status").unwrap_or_default(),
                proc("smaps_rollup").unwrap_or_default()
            ));
        }
        if started.elapsed() > HANG_GUARD {
            let _ = child.kill();
            let _ = child.wait();
            panic!("tmclsh {args:?} hung");
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let code = status
        .code()
        .unwrap_or_else(|| panic!("tmclsh {args:?} died: {status}"));
    Run {
        code,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
        peak_rss_kib,
        over_bound,
    }
}

/// VmHWM of a running process, KiB, once it is tmclsh: until its exec completes the child is
/// still an image of this test process (`Name:` the test thread's, the test binary's 100+ MB
/// mapped), which is where the rare 108–180 MB "peaks" of this check came from.
pub fn high_water_mark(pid: u32) -> Option<i64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let name = status.lines().find_map(|l| l.strip_prefix("Name:"))?.trim();
    if name != "tmclsh" {
        return None;
    }
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// `args` as owned strings after the connection options of `fake`. A TCP link has no bit rate
/// (tmclsh refuses `--baud` without `--port`), so `--baud N` is left out there.
pub fn with(fake: &Fake, args: &[&str]) -> Vec<String> {
    let mut all = fake.args();
    let serial = fake.args()[0] == "--port";
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        if *arg == "--baud" && !serial {
            rest.next();
            continue;
        }
        all.push(arg.to_string());
    }
    all
}

/// `tmclsh run SCRIPT` with the connection options of `fake` and `args` after the subcommand.
pub fn run_script(fake: &Fake, text: &str, args: &[&str]) -> Run {
    let path = script(text);
    let mut all = vec!["run".to_string(), path];
    all.extend(with(fake, args));
    tmclsh(&all)
}

/// Writes a Rhai script into a fresh directory; its path.
pub fn script(text: &str) -> String {
    let dir = crate::util::tempdir();
    let path = dir.join("s.rhai");
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}
