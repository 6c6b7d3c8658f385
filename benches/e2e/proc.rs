//! Running the measured programs as child processes: their output, wall time, CPU time and peak
//! resident memory, the last two from wait4(2) so that each process is measured on its own.

use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use std::time::{Duration, Instant};

/// The release `tmclsh` that cargo built for this benchmark.
pub fn tmclsh() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_tmclsh"))
}

/// A file of the repository.
pub fn repo_file(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// What one finished process did.
pub struct Finished {
    pub stdout: String,
    pub stderr: String,
    pub success: bool,
    /// User plus system time.
    pub cpu: Duration,
    /// Peak resident set size, bytes.
    pub max_rss: u64,
}

impl Finished {
    /// The first number printed on stdout, where the measured loops print their seconds.
    pub fn number(&self, index: usize) -> f64 {
        self.stdout
            .split_whitespace()
            .nth(index)
            .and_then(|w| w.parse().ok())
            .unwrap_or_else(|| {
                panic!(
                    "expected a number on stdout, got {:?} (stderr {:?})",
                    self.stdout, self.stderr
                )
            })
    }

    /// Panics with the output unless the process succeeded.
    pub fn expect_success(self, what: &str) -> Finished {
        assert!(
            self.success,
            "{what} failed: stdout {:?} stderr {:?}",
            self.stdout, self.stderr
        );
        self
    }
}

/// Runs `command` to the end with empty stdin, capturing its output.
#[allow(clippy::zombie_processes, reason = "wait4 reaps the child")]
pub fn run(command: &mut Command) -> Finished {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut child = command
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start {command:?}: {e}"));
    let stdout = drain(child.stdout.take());
    let stderr = drain(child.stderr.take());
    let (success, usage) = wait4(&child);
    Finished {
        stdout: stdout.join().expect("stdout reader"),
        stderr: stderr.join().expect("stderr reader"),
        success,
        cpu: cpu_time(&usage),
        max_rss: u64::try_from(usage.ru_maxrss).unwrap_or(0) * 1024,
    }
}

/// Runs `command` with no I/O at all and returns its wall time: for start-up, where even a
/// reader thread would be part of what is measured.
#[allow(clippy::zombie_processes, reason = "wait4 reaps the child")]
pub fn run_silent(command: &mut Command) -> (bool, Duration) {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    let start = Instant::now();
    let child = command
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start {command:?}: {e}"));
    let (success, _) = wait4(&child);
    (success, start.elapsed())
}

fn drain<R: Read + Send + 'static>(pipe: Option<R>) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut text = String::new();
        if let Some(mut pipe) = pipe {
            let _ = pipe.read_to_string(&mut text);
        }
        text
    })
}

/// Reaps `child` (it must not be waited for again) and returns its success and resource usage.
fn wait4(child: &Child) -> (bool, libc::rusage) {
    let pid = libc::pid_t::try_from(child.id()).expect("pid fits");
    let mut status = 0;
    // SAFETY: rusage is plain data, all-zero is a valid value.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    loop {
        // SAFETY: valid pointers to a status and a rusage of this stack frame.
        let reaped = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
        if reaped == pid {
            break;
        }
        let error = std::io::Error::last_os_error();
        assert_eq!(
            error.kind(),
            std::io::ErrorKind::Interrupted,
            "wait4: {error}"
        );
    }
    let success = libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0;
    (success, usage)
}

fn cpu_time(usage: &libc::rusage) -> Duration {
    let time = |t: libc::timeval| {
        Duration::from_secs(t.tv_sec as u64) + Duration::from_micros(t.tv_usec as u64)
    };
    time(usage.ru_utime) + time(usage.ru_stime)
}

/// A running `tmclsh sim --pty`, ended when dropped.
pub struct Sim {
    child: Child,
    /// The pseudo-terminal to connect to.
    pub path: String,
    // Held open: the console ends on end of input, and the simulator's stdout stays writable.
    _stdin: ChildStdin,
    _stdout: BufReader<ChildStdout>,
}

impl Sim {
    /// Starts `tmclsh sim --pty ARGS` and reads the path it serves on.
    pub fn start(args: &[&str]) -> Sim {
        let mut child = Command::new(tmclsh())
            .args(["sim", "--pty"])
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("tmclsh sim starts");
        let stdin = child.stdin.take().expect("stdin");
        let mut stdout = BufReader::new(child.stdout.take().expect("stdout"));
        let mut path = String::new();
        stdout
            .read_line(&mut path)
            .expect("tmclsh sim prints its pty");
        let path = path.trim().to_string();
        assert!(path.starts_with('/'), "tmclsh sim printed {path:?}");
        Sim {
            child,
            path,
            _stdin: stdin,
            _stdout: stdout,
        }
    }
}

impl Drop for Sim {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The median of `values` (which must not be empty).
pub fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mid = sorted.len() / 2;
    if sorted.len() % 2 == 1 {
        sorted[mid]
    } else {
        (sorted[mid - 1] + sorted[mid]) / 2.0
    }
}

/// "1 run" or "median of 5 runs", for the row names.
pub fn runs(reps: usize) -> String {
    match reps {
        1 => "1 run".into(),
        n => format!("median of {n} runs"),
    }
}
