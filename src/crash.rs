//! The last line of defence: a bug in tmclsh must not leave a motor turning.
//!
//! The binary runs under [`guard`]. When anything panics, the stack unwinds; every open session is
//! dropped on the way and, seeing the thread panicking, stops what it set moving (MST on every
//! axis, STOP for programs it started, MOTOR:STOP on SMD4 drives) and returns modules to the mode
//! they were found in, as far as the link still allows (`session::guard`), then records what it
//! did here. [`guard`] then prints one message — what went wrong and what was stopped — and exits
//! with 101. The panic hook only keeps the message, so nothing is printed twice.

use std::backtrace::{Backtrace, BacktraceStatus};
use std::io::Write;
use std::panic::{self, PanicHookInfo, UnwindSafe};
use std::process::ExitCode;
use std::sync::{Mutex, MutexGuard, PoisonError};

use crate::exit::Exit;

// Sessions stop their motors while the stack unwinds; an aborting panic would skip that.
#[cfg(panic = "abort")]
compile_error!(
    "tmclsh must be built with panic = \"unwind\": its crash guard runs while unwinding"
);

/// The exit code of a crash (the one Rust uses for a panic, documented in docs/exit-codes.md).
pub const EXIT_CODE: u8 = 101;

/// The environment variable that injects a crash at a named point: present in every build, so the
/// crash guard's tests hold for `cargo test --release` too (a user who sets it gets the crash asked
/// for, with the motors stopped as for any other).
pub const INJECT_VAR: &str = "TMCLSH_TEST_CRASH";

/// What a panic said, and where.
struct Panic {
    message: String,
    location: String,
    /// Captured (with `RUST_BACKTRACE`) but not symbolised: only the report resolves it, once,
    /// for the first panic. Resolving reads the binary's debug information, which in a debug
    /// build takes over 100 MB; doing it in the hook cost that for every panic, also for the ones
    /// caught while stopping, whose backtraces are never shown.
    backtrace: Option<Backtrace>,
}

/// What one session did while the stack unwound.
struct Stopped {
    session: String,
    stopped: Vec<String>,
    restored: Vec<String>,
}

static PANICS: Mutex<Vec<Panic>> = Mutex::new(Vec::new());
static STOPPED: Mutex<Vec<Stopped>> = Mutex::new(Vec::new());

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Runs `main` (the whole program); a panic becomes a message on stderr and exit code 101, after
/// the sessions that were open have stopped their motors.
pub fn guard(main: impl FnOnce() -> Exit + UnwindSafe) -> ExitCode {
    panic::set_hook(Box::new(keep));
    match panic::catch_unwind(main) {
        Ok(exit) => exit.into(),
        Err(_) => {
            // Not eprintln!, which panics when stderr is gone.
            let _ = writeln!(std::io::stderr(), "{}", report());
            ExitCode::from(EXIT_CODE)
        }
    }
}

/// The panic hook: keeps the message for [`report`]. Panics on other threads (which hold no
/// session) are told at once, as the program may go on. Nothing here may panic: a panic inside
/// the hook aborts the process before any session could stop its motors.
fn keep(info: &PanicHookInfo<'_>) {
    let payload = info.payload();
    let message = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "panic".to_string());
    let location = info.location().map(ToString::to_string).unwrap_or_default();
    let thread = std::thread::current();
    match thread.name() {
        Some("main") => {}
        name => {
            let name = name.unwrap_or("unnamed");
            let _ = writeln!(
                std::io::stderr(),
                "tmclsh: internal error in thread {name}: {message} (at {location})"
            );
            return;
        }
    }
    let backtrace = Backtrace::capture();
    let backtrace = (backtrace.status() == BacktraceStatus::Captured).then_some(backtrace);
    lock(&PANICS).push(Panic {
        message,
        location,
        backtrace,
    });
}

/// Called by a session dropped during a panic: what it stopped, and what it did to restore module
/// modes (or why it could not).
pub fn record_stop(session: String, stopped: Vec<String>, restored: Vec<String>) {
    lock(&STOPPED).push(Stopped {
        session,
        stopped,
        restored,
    });
}

/// The message after a crash: `tmclsh: internal error: …; motors stopped: …`.
fn report() -> String {
    let panics = std::mem::take(&mut *lock(&PANICS));
    let stopped = std::mem::take(&mut *lock(&STOPPED));
    let (first, later) = match panics.split_first() {
        Some((first, later)) => (format!("{} (at {})", first.message, first.location), later),
        None => ("panic".to_string(), &[][..]),
    };
    let mut text = format!("tmclsh: internal error: {first}; ");
    if stopped.is_empty() {
        text.push_str("motors stopped: none (no module was connected)");
    }
    for (i, session) in stopped.iter().enumerate() {
        if i > 0 {
            text.push_str("; ");
        }
        text.push_str(&format!("on {}: motors stopped: ", session.session));
        if session.stopped.is_empty() {
            text.push_str("none (this session set none moving)");
        } else {
            let stopped: Vec<&str> = session
                .stopped
                .iter()
                .map(|s| s.strip_prefix("stopped ").unwrap_or(s))
                .collect();
            text.push_str(&stopped.join(", "));
        }
        for restored in &session.restored {
            text.push_str(&format!("; {restored}"));
        }
    }
    for panic in later {
        text.push_str(&format!(
            "\ntmclsh: while stopping: {} (at {})",
            panic.message, panic.location
        ));
    }
    text.push_str(
        "\ntmclsh: this is a bug in tmclsh; please report it with the command and files that caused it",
    );
    if let Some(backtrace) = panics.first().and_then(|p| p.backtrace.as_ref()) {
        text.push_str(&format!("\n{backtrace}"));
    }
    text
}

/// A crash injected for the tests of the crash guard: panics when [`INJECT_VAR`] is `name` or
/// `name:detail`. Read at every point (a REPL line, a downloaded word, an assembled file: never a
/// hot path).
#[doc(hidden)]
#[track_caller]
pub fn point(name: &str, detail: &str) {
    if let Some(wanted) = std::env::var_os(INJECT_VAR) {
        let wanted = wanted.to_string_lossy();
        let hit = match wanted.split_once(':') {
            Some((n, d)) => n == name && d == detail,
            None => wanted == name,
        };
        if hit {
            panic!("crash injected at {wanted} ({INJECT_VAR})");
        }
    }
}
