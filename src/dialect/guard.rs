//! Sessions dropped while the thread panics stop what they set moving and restore module modes,
//! wherever they were when the panic struck (the REPL, a script's engine, a download), and tell
//! [`crate::crash`] what they did. A normal drop does nothing: every face closes its session
//! itself and reports on it. Each dialect's session calls [`on_panic`] from its `Drop`.

use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::session::interrupt;

use super::DialectSession;

/// During a panic: stops what `session` set moving, then ends it with `close` (which returns what
/// it restored), and records both for the crash report. Does nothing otherwise.
pub fn on_panic<S: DialectSession>(session: &mut S, close: impl FnOnce(&mut S) -> Vec<String>) {
    if !std::thread::panicking() {
        return;
    }
    let described = session.describe();
    let (stopped, restored) = while_unwinding(|| {
        let stopped = session.stop_motion();
        (stopped, close(session))
    });
    crate::crash::record_stop(described, stopped, restored);
}

/// Runs `stop` during a panic: a pending Ctrl-C must not cancel the stop, and a second panic
/// inside it must not abort the process before the message is out.
fn while_unwinding(
    stop: impl FnOnce() -> (Vec<String>, Vec<String>),
) -> (Vec<String>, Vec<String>) {
    interrupt::take();
    catch_unwind(AssertUnwindSafe(stop)).unwrap_or_else(|_| {
        let failed = "stopping failed with a second internal error".to_string();
        (vec![failed], Vec::new())
    })
}
