//! Progress on the terminal: the one set-up of indicatif's bars and spinners, on stderr and only
//! when stderr is a terminal, so pipes, logs and tests see no control sequences. Installed as the
//! display of [`crate::progress`] when the command line starts.

use std::io::IsTerminal;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};

use crate::progress::{Display, Meter};

/// Bars and spinners on a terminal's stderr.
pub(super) struct TerminalProgress;

impl Display for TerminalProgress {
    fn bar(&self, len: u64, label: &str) -> Option<Box<dyn Meter>> {
        if !std::io::stderr().is_terminal() {
            return None;
        }
        let style = ProgressStyle::with_template(
            "{prefix} [{bar:30}] {pos}/{len} {msg} (about {eta} left)",
        )
        .ok()?;
        let bar = ProgressBar::new(len);
        bar.set_style(style.progress_chars("=> "));
        bar.set_prefix(label.to_string());
        Some(Box::new(Shown(bar)))
    }

    fn spinner(&self, what: &str) -> Option<Box<dyn Meter>> {
        if !std::io::stderr().is_terminal() {
            return None;
        }
        let style = ProgressStyle::with_template("{spinner} {msg} {elapsed}").ok()?;
        let spinner = ProgressBar::new_spinner();
        spinner.set_style(style);
        spinner.set_message(format!("waiting for {what}"));
        spinner.enable_steady_tick(Duration::from_millis(120));
        Some(Box::new(Shown(spinner)))
    }
}

/// A bar or spinner on the screen.
struct Shown(ProgressBar);

impl Meter for Shown {
    fn step(&self, next: &str) {
        self.0.set_message(next.to_string());
        self.0.inc(1);
    }

    fn set(&self, done: u64, total: u64) {
        self.0.set_length(total);
        self.0.set_position(done);
    }

    fn finish(&self) {
        self.0.finish_and_clear();
    }
}
