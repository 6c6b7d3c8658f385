//! Ctrl-C as a flag: the handler only records the interrupt; whoever is waiting (a reply, a script
//! `sleep`, a watch) notices it within one wait slice and stops the motors it is responsible for.
//!
//! SIGTERM and SIGHUP raise the same flag, so every wait ends as it does for Ctrl-C, and are
//! remembered apart for good ([`terminated`]): the run ends with `128 + signal` once the motors
//! are stopped. The line editor blocks in `read()` and restarts it after a signal, so while it
//! waits at the prompt ([`Prompting`]) the signal is passed on to it as the SIGINT it returns on.

use std::sync::Once;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::time::Duration;

static INTERRUPTED: AtomicBool = AtomicBool::new(false);
static TERMINATED: AtomicI32 = AtomicI32::new(0);
/// Set when an interrupt is taken after SIGTERM or SIGHUP: the run is stopping its motors and
/// ending, and the flag raised again (ctrlc's thread runs late, the prompt is sent SIGINT) must
/// not cancel the stops.
static ENDING: AtomicBool = AtomicBool::new(false);
static PROMPTING: AtomicBool = AtomicBool::new(false);
static INSTALL: Once = Once::new();

/// The longest a wait runs before checking for Ctrl-C (the signal may wake another thread).
pub const SLICE: Duration = Duration::from_millis(20);

/// A signal that ends the run: SIGTERM or SIGHUP.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Termination {
    /// SIGTERM (`kill`, a service manager): exit 143.
    Term,
    /// SIGHUP (the terminal went away): exit 129.
    Hup,
}

impl Termination {
    /// The signal's number.
    pub fn number(self) -> i32 {
        match self {
            Termination::Term => 15,
            Termination::Hup => 1,
        }
    }

    /// The signal's name, for messages.
    pub fn name(self) -> &'static str {
        match self {
            Termination::Term => "SIGTERM",
            Termination::Hup => "SIGHUP",
        }
    }

    fn from_number(number: i32) -> Option<Self> {
        match number {
            15 => Some(Termination::Term),
            1 => Some(Termination::Hup),
            _ => None,
        }
    }
}

/// Routes SIGINT/SIGTERM/SIGHUP to the flag, and SIGTERM/SIGHUP to [`terminated`] (once per
/// process; call it from the thread that will wait at a prompt).
pub fn install() {
    INSTALL.call_once(|| {
        // If another handler is already installed (embedding), Ctrl-C keeps its default meaning.
        if ctrlc::set_handler(|| INTERRUPTED.store(true, Ordering::SeqCst)).is_ok() {
            #[cfg(unix)]
            watch_terminations();
        }
    });
}

/// A thread that records SIGTERM and SIGHUP (ctrlc's handler, still called, raises the flag) and,
/// while the prompt waits, passes them on to the waiting thread as SIGINT until it has left the
/// prompt: a signal that lands just before the editor's own handler is in place is sent again.
#[cfg(unix)]
fn watch_terminations() {
    use nix::sys::pthread::{pthread_kill, pthread_self};
    use nix::sys::signal::Signal;
    use signal_hook::consts::{SIGHUP, SIGTERM};

    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGTERM, SIGHUP]) else {
        return; // ctrlc's handler still raises the flag
    };
    let waiter = pthread_self();
    let spawned = std::thread::Builder::new()
        .name("terminations".into())
        .spawn(move || {
            let Some(number) = signals.forever().next() else {
                return;
            };
            // ctrlc's handler, chained, raises the interrupt flag.
            let _ = TERMINATED.compare_exchange(0, number, Ordering::SeqCst, Ordering::SeqCst);
            // Runs until the process exits; a further TERM or HUP changes nothing.
            loop {
                if PROMPTING.load(Ordering::SeqCst) {
                    let _ = pthread_kill(waiter, Signal::SIGINT);
                }
                std::thread::sleep(SLICE * 5);
            }
        });
    drop(spawned);
}

/// Whether Ctrl-C was pressed and not yet handled (never once the run is ending after SIGTERM or
/// SIGHUP, so nothing cancels its stops).
pub fn pending() -> bool {
    INTERRUPTED.load(Ordering::SeqCst) && !ENDING.load(Ordering::SeqCst)
}

/// Marks the interrupt handled; returns whether there was one.
pub fn take() -> bool {
    let taken = INTERRUPTED.swap(false, Ordering::SeqCst);
    if TERMINATED.load(Ordering::SeqCst) != 0 {
        ENDING.store(true, Ordering::SeqCst);
    }
    taken
}

/// Raises the flag as Ctrl-C would (tests, and faces that see Ctrl-C as a key).
pub fn raise() {
    INTERRUPTED.store(true, Ordering::SeqCst);
}

/// The SIGTERM or SIGHUP received, if any: unlike Ctrl-C it is never taken back, and the run
/// ends after stopping what it set moving.
pub fn terminated() -> Option<Termination> {
    Termination::from_number(TERMINATED.load(Ordering::SeqCst))
}

/// Whether the line editor waits at the prompt now.
pub fn prompting() -> bool {
    PROMPTING.load(Ordering::SeqCst)
}

/// Marks the time the line editor waits at the prompt (dropped when it returns), so a SIGTERM or
/// SIGHUP reaches it.
pub struct Prompting(());

impl Prompting {
    /// The prompt is about to wait.
    pub fn start() -> Self {
        PROMPTING.store(true, Ordering::SeqCst);
        Prompting(())
    }
}

impl Drop for Prompting {
    fn drop(&mut self) {
        PROMPTING.store(false, Ordering::SeqCst);
    }
}
