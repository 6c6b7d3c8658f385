//! Waiting inside scripts: sliced so Ctrl-C interrupts promptly, with a spinner on a terminal
//! (with the `cli` feature, which brings the terminal faces).

#[cfg(feature = "cli")]
use std::io::IsTerminal;
use std::time::{Duration, Instant};

#[cfg(feature = "cli")]
use indicatif::{ProgressBar, ProgressStyle};

use crate::exit::Exit;
use crate::session::interrupt;

use super::failure::{Fallible, ScriptFailure};

/// How often a wait re-checks its condition.
pub const POLL: Duration = Duration::from_millis(10);

/// Sleeps for `duration`, waking every slice to notice Ctrl-C.
pub fn sleep(duration: Duration) -> Fallible<()> {
    let end = Instant::now() + duration;
    loop {
        if interrupt::pending() {
            return Err(ScriptFailure::new(Exit::Interrupted, "interrupted").into_rhai());
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
    #[cfg(feature = "cli")]
    let spinner = spinner(what, timeout);
    let result = loop {
        match check() {
            Ok(true) => break Ok(()),
            Ok(false) => {}
            Err(e) => break Err(e),
        }
        if start.elapsed() >= timeout {
            break Err(ScriptFailure::new(
                Exit::DeviceError,
                format!(
                    "timed out after {} ms waiting for {what}",
                    timeout.as_millis()
                ),
            )
            .into_rhai());
        }
        if let Err(e) = sleep(POLL) {
            break Err(e);
        }
    };
    #[cfg(feature = "cli")]
    if let Some(spinner) = spinner {
        spinner.finish_and_clear();
    }
    result
}

#[cfg(feature = "cli")]
fn spinner(what: &str, timeout: Duration) -> Option<ProgressBar> {
    if !std::io::stderr().is_terminal() || timeout < Duration::from_millis(500) {
        return None;
    }
    let bar = ProgressBar::new_spinner();
    bar.set_style(ProgressStyle::with_template("{spinner} {msg} {elapsed}").ok()?);
    bar.set_message(format!("waiting for {what}"));
    bar.enable_steady_tick(Duration::from_millis(120));
    Some(bar)
}
