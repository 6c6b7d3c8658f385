//! A progress bar on stderr while many parameters are read or written — only when stderr is a
//! terminal, so pipes, logs and tests see no control sequences, and only with the `cli` feature
//! (the terminal faces): an embedding library draws nothing.

#[cfg(feature = "cli")]
use std::io::IsTerminal;

#[cfg(feature = "cli")]
use indicatif::{ProgressBar, ProgressStyle};

/// Without the `cli` feature there is never a bar.
#[cfg(not(feature = "cli"))]
enum ProgressBar {}

#[cfg(not(feature = "cli"))]
impl ProgressBar {
    fn set_message(&self, _: String) {}
    fn inc(&self, _: u64) {}
    fn finish_and_clear(&self) {}
}

/// A progress bar, or nothing when stderr is not a terminal.
pub struct Progress(Option<ProgressBar>);

impl Progress {
    /// A bar of `len` steps labelled `what` ("reading"), shown only on a terminal.
    #[cfg(feature = "cli")]
    pub fn new(len: usize, what: &str) -> Progress {
        if len < 2 || !std::io::stderr().is_terminal() {
            return Progress::hidden();
        }
        let bar = ProgressBar::new(len as u64);
        if let Ok(style) = ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} {msg}") {
            bar.set_style(style.progress_chars("=> "));
        }
        bar.set_prefix(what.to_string());
        Progress(Some(bar))
    }

    /// No bar: without the `cli` feature, there are none.
    #[cfg(not(feature = "cli"))]
    pub fn new(_len: usize, _what: &str) -> Progress {
        Progress::hidden()
    }

    /// No bar.
    pub fn hidden() -> Progress {
        Progress(None)
    }

    /// One step done; `name` is what comes next.
    pub fn step(&self, name: &str) {
        if let Some(bar) = &self.0 {
            bar.set_message(name.to_string());
            bar.inc(1);
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(bar) = &self.0 {
            bar.finish_and_clear();
        }
    }
}
