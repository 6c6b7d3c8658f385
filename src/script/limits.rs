//! The bounds a script runs within: operations, call depth, memory, wall-clock time, and the
//! files it may reach. Each ends a runaway script with a clear error (exit code 1, like any
//! runtime error), after which the runner stops the motors the script moved.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::thread::JoinHandle;
use std::time::Duration;

use crate::session::interrupt;

/// Limits a script runs under.
#[derive(Debug, Clone)]
pub struct Limits {
    /// Operations before a runaway script is stopped (0 = no limit).
    pub max_operations: u64,
    /// Deepest function call nesting.
    pub max_call_depth: usize,
    /// Bytes the script may hold beyond what tmclsh held when it started (`None`: no limit).
    /// Enforced where the program counts its allocations: the binary does; a program embedding
    /// the library registers a counter with [`count_allocations_with`](super::count_allocations_with).
    pub max_memory: Option<usize>,
    /// Wall-clock time the script may run (`None`: no limit).
    pub max_time: Option<Duration>,
    /// Directories the file functions may reach besides the script's and the working directory.
    pub allow_dirs: Vec<PathBuf>,
    /// Whether file functions may replace existing files tmclsh did not write.
    pub overwrite: bool,
    /// Whether the run ends when the transcript it asked for cannot be written (`tmclsh run`,
    /// as `-c`; the REPL's `:source` goes on without one, as the REPL does).
    pub needs_transcript: bool,
}

/// The default memory budget in MiB.
pub const DEFAULT_MAX_MEMORY_MIB: usize = 256;

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_operations: 100_000_000,
            max_call_depth: 64,
            max_memory: Some(DEFAULT_MAX_MEMORY_MIB << 20),
            max_time: None,
            allow_dirs: Vec::new(),
            overwrite: false,
            needs_transcript: false,
        }
    }
}

/// Ends a script at its deadline: a thread that, when the time is up, marks the run expired and
/// raises the interrupt flag, so the engine (between operations) and every wait (sleeps, replies)
/// stop within one wait slice, as on Ctrl-C.
pub struct Watchdog {
    expired: Arc<AtomicBool>,
    cancel: Option<mpsc::Sender<()>>,
    thread: Option<JoinHandle<()>>,
}

impl Watchdog {
    /// Starts watching for `limit` (none: never expires).
    pub fn start(limit: Option<Duration>) -> Watchdog {
        let expired = Arc::new(AtomicBool::new(false));
        let Some(limit) = limit else {
            return Watchdog {
                expired,
                cancel: None,
                thread: None,
            };
        };
        let (cancel, cancelled) = mpsc::channel::<()>();
        let flag = expired.clone();
        let thread = std::thread::spawn(move || {
            if let Err(mpsc::RecvTimeoutError::Timeout) = cancelled.recv_timeout(limit) {
                flag.store(true, Ordering::SeqCst);
                interrupt::raise();
            }
        });
        Watchdog {
            expired,
            cancel: Some(cancel),
            thread: Some(thread),
        }
    }

    /// The flag the engine checks between operations.
    pub fn flag(&self) -> Arc<AtomicBool> {
        self.expired.clone()
    }

    /// Stops watching; returns whether the time ran out. The interrupt it raised is taken back
    /// when the script finished anyway.
    pub fn stop(mut self, finished: bool) -> bool {
        drop(self.cancel.take());
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
        let expired = self.expired.load(Ordering::SeqCst);
        if expired && finished {
            interrupt::take();
        }
        expired
    }
}

/// What a script that ran out of time is told.
pub fn out_of_time(limit: Option<Duration>) -> String {
    let limit = limit.map_or(String::new(), |l| {
        format!(" of {}", humantime::format_duration(l))
    });
    format!("runaway script: it ran longer than its --max-time{limit}")
}
