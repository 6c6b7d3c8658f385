//! Sessions dropped while the thread panics stop what they set moving and restore module modes,
//! wherever they were when the panic struck (the REPL, a script's engine, a download), and tell
//! [`crate::crash`] what they did. A normal drop does nothing: every face closes its session
//! itself and reports on it.

use crate::dialect::session::DialectSession;
use std::panic::{AssertUnwindSafe, catch_unwind};

use super::interrupt;
use crate::dialect::smd4::session::Smd4Session;
use crate::dialect::tmcl::session::TmclSession;

impl Drop for TmclSession {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            return;
        }
        let session = self.describe();
        let (stopped, restored) = while_unwinding(|| {
            let stopped = self.stop_motion();
            let mut restored = self.close();
            if restored.is_empty() {
                restored.push(if self.options().stay_ascii {
                    "modules left in ASCII mode (--stay-ascii)".to_string()
                } else {
                    "modules returned to the mode they were found in".to_string()
                });
            }
            (stopped, restored)
        });
        crate::crash::record_stop(session, stopped, restored);
    }
}

impl Drop for Smd4Session {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            return;
        }
        let session = self.describe();
        let (stopped, restored) = while_unwinding(|| (self.stop_motion(), self.close()));
        crate::crash::record_stop(session, stopped, restored);
    }
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
