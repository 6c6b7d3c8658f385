//! Waiting inside scripts: sliced so Ctrl-C interrupts promptly, with a spinner on a terminal.

use std::time::{Duration, Instant};

use crate::exit::{Exit, Failure};
use crate::progress::Progress;
use crate::session::interrupt;

use super::failure::{Fallible, thrown};

/// How often a wait re-checks its condition.
pub const POLL: Duration = Duration::from_millis(10);

/// Sleeps for `duration`, waking every slice to notice Ctrl-C.
pub fn sleep(duration: Duration) -> Fallible<()> {
    let end = Instant::now() + duration;
    loop {
        if interrupt::pending() {
            return Err(thrown(Failure::new(Exit::Interrupted, "interrupted")));
        }
        let now = Instant::now();
        if now >= end {
            return Ok(());
        }
        std::thread::sleep((end - now).min(interrupt::SLICE));
    }
}

/// Calls `check` until it returns true or `timeout` passes; `what` names the awaited condition in
/// the spinner and in the timeout error.
pub fn until(
    what: &str,
    timeout: Duration,
    mut check: impl FnMut() -> Fallible<bool>,
) -> Fallible<()> {
    let start = Instant::now();
    // A spinner for waits long enough to wonder about.
    let spinner = if timeout >= Duration::from_millis(500) {
        Progress::waiting(what)
    } else {
        Progress::hidden()
    };
    let result = loop {
        match check() {
            Ok(true) => break Ok(()),
            Ok(false) => {}
            Err(e) => break Err(e),
        }
        if start.elapsed() >= timeout {
            break Err(thrown(Failure::new(
                Exit::DeviceError,
                format!(
                    "timed out after {} ms waiting for {what}",
                    timeout.as_millis()
                ),
            )));
        }
        if let Err(e) = sleep(POLL) {
            break Err(e);
        }
    };
    drop(spinner);
    result
}
