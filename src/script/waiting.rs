//! Waiting inside scripts: sliced so Ctrl-C interrupts promptly, with a spinner on a terminal
//! (with the `cli` feature, which brings the terminal faces).

use std::time::{Duration, Instant};

use crate::exit::{Exit, Failure};
use crate::progress::Progress;
use crate::session::interrupt;

use super::failure::{Fallible, thrown};

/// How often a wait re-checks its condition.
pub(crate) const POLL: Duration = Duration::from_millis(10);

/// Sleeps for `duration`, waking every slice to notice Ctrl-C.
pub(crate) fn sleep(duration: Duration) -> Fallible<()> {
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
pub(crate) fn until(
    what: &str,
    timeout: Duration,
    mut check: impl FnMut() -> Fallible<bool>,
) -> Fallible<()> {
    until_showing(what, timeout, || check().map(|done| (done, String::new())))
}

/// [`until`] for a condition that also gives the value it saw, which a timeout reports (the
/// last one).
pub(crate) fn until_showing(
    what: &str,
    timeout: Duration,
    mut check: impl FnMut() -> Fallible<(bool, String)>,
) -> Fallible<()> {
    let mut last: String;
    let start = Instant::now();
    // A spinner for waits long enough to wonder about.
    let spinner = if timeout >= Duration::from_millis(500) {
        Progress::waiting(what)
    } else {
        Progress::hidden()
    };
    let result = loop {
        match check() {
            Ok((true, _)) => break Ok(()),
            Ok((false, value)) => last = value,
            Err(e) => break Err(e),
        }
        if start.elapsed() >= timeout {
            let seen = if last.is_empty() {
                String::new()
            } else {
                format!(" (last value: {last})")
            };
            break Err(thrown(Failure::new(
                Exit::DeviceError,
                format!(
                    "timed out after {} ms waiting for {what}{seen}",
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
