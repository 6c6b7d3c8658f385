//! Ctrl-C as a flag: the handler only records the interrupt; whoever is waiting (a reply, a script
//! `sleep`, a watch) notices it within one wait slice and stops the motors it is responsible for.

use std::sync::Once;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

static INTERRUPTED: AtomicBool = AtomicBool::new(false);
static INSTALL: Once = Once::new();

/// The longest a wait runs before checking for Ctrl-C (the signal may wake another thread).
pub const SLICE: Duration = Duration::from_millis(20);

/// Routes SIGINT/SIGTERM to the flag (once per process).
pub fn install() {
    INSTALL.call_once(|| {
        // If another handler is already installed (embedding), Ctrl-C keeps its default meaning.
        let _ = ctrlc::set_handler(|| INTERRUPTED.store(true, Ordering::SeqCst));
    });
}

/// Whether Ctrl-C was pressed and not yet handled.
pub fn pending() -> bool {
    INTERRUPTED.load(Ordering::SeqCst)
}

/// Marks the interrupt handled; returns whether there was one.
pub fn take() -> bool {
    INTERRUPTED.swap(false, Ordering::SeqCst)
}

/// Raises the flag as Ctrl-C would (tests, and faces that see Ctrl-C as a key).
pub fn raise() {
    INTERRUPTED.store(true, Ordering::SeqCst);
}
