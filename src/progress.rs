//! Progress of long operations — every parameter read for a snapshot or written back, a bus
//! scan, a download, a script's wait — reported to whatever display the front end installed.
//!
//! The operations only say how far they are ([`Progress`]); how that looks is the display's
//! business, installed once by the command line ([`install`]; its terminal bars live in
//! `cli/progress.rs`). Without one, as in tests and in programs that use the library, progress
//! costs nothing and shows nothing.

use std::sync::OnceLock;

/// Where progress is shown.
pub trait Display: Send + Sync {
    /// A bar of `len` steps labelled `label` ("reading"), or `None` to show nothing.
    fn bar(&self, len: u64, label: &str) -> Option<Box<dyn Meter>>;

    /// A spinner while waiting for `what` ("motor 0 to reach its target position"), or `None`.
    fn spinner(&self, what: &str) -> Option<Box<dyn Meter>>;
}

/// One shown bar or spinner.
pub trait Meter {
    /// One step done; `next` is what comes next.
    fn step(&self, next: &str);

    /// `done` of `total` steps done (the total may grow as the work learns more).
    fn set(&self, done: u64, total: u64);

    /// The work ended: the bar goes away.
    fn finish(&self);
}

static DISPLAY: OnceLock<Box<dyn Display>> = OnceLock::new();

fn installed() -> Option<&'static dyn Display> {
    DISPLAY.get().map(|d| &**d)
}

/// Installs the display every later [`Progress`] uses; a second call changes nothing.
pub fn install(display: Box<dyn Display>) {
    let _ = DISPLAY.set(display);
}

/// The progress of one operation; shows nothing when no display is installed, or when the
/// display declines. Removed from the screen when dropped.
pub struct Progress(Option<Box<dyn Meter>>);

impl Progress {
    /// A bar of `len` steps labelled `label`, when there are at least `min` steps: a bar that
    /// would only flash by is not worth drawing.
    pub fn steps(len: usize, min: usize, label: &str) -> Progress {
        Progress::steps_on(installed(), len, min, label)
    }

    /// A spinner while waiting for `what`.
    pub fn waiting(what: &str) -> Progress {
        Progress(installed().and_then(|d| d.spinner(what)))
    }

    fn steps_on(display: Option<&dyn Display>, len: usize, min: usize, label: &str) -> Progress {
        if len < min.max(1) {
            return Progress::hidden();
        }
        Progress(display.and_then(|d| d.bar(len as u64, label)))
    }

    /// Nothing shown.
    pub fn hidden() -> Progress {
        Progress(None)
    }

    /// One step done; `next` is what comes next.
    pub fn step(&self, next: &str) {
        if let Some(meter) = &self.0 {
            meter.step(next);
        }
    }

    /// `done` of `total` steps done.
    pub fn set(&self, done: usize, total: usize) {
        if let Some(meter) = &self.0 {
            meter.set(done as u64, total as u64);
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(meter) = &self.0 {
            meter.finish();
        }
    }
}

#[cfg(test)]
mod tests {
    use std::sync::{Arc, Mutex};

    use super::*;

    /// A display that writes down what it is told.
    #[derive(Default)]
    struct Recorder(Arc<Mutex<Vec<String>>>);

    struct Line(Arc<Mutex<Vec<String>>>);

    impl Display for Recorder {
        fn bar(&self, len: u64, label: &str) -> Option<Box<dyn Meter>> {
            self.0.lock().unwrap().push(format!("bar {label} {len}"));
            Some(Box::new(Line(self.0.clone())))
        }
        fn spinner(&self, what: &str) -> Option<Box<dyn Meter>> {
            self.0.lock().unwrap().push(format!("spinner {what}"));
            Some(Box::new(Line(self.0.clone())))
        }
    }

    impl Meter for Line {
        fn step(&self, next: &str) {
            self.0.lock().unwrap().push(format!("step {next}"));
        }
        fn set(&self, done: u64, total: u64) {
            self.0.lock().unwrap().push(format!("set {done}/{total}"));
        }
        fn finish(&self) {
            self.0.lock().unwrap().push("finish".into());
        }
    }

    #[test]
    fn a_bar_hears_every_step_and_goes_away_when_dropped() {
        let display = Recorder::default();
        let progress = Progress::steps_on(Some(&display), 3, 2, "reading");
        progress.step("axis 4");
        progress.set(2, 3);
        drop(progress);
        assert_eq!(
            *display.0.lock().unwrap(),
            ["bar reading 3", "step axis 4", "set 2/3", "finish"]
        );
    }

    #[test]
    fn too_few_steps_or_no_display_show_nothing() {
        let display = Recorder::default();
        let short = Progress::steps_on(Some(&display), 63, 64, "download");
        short.step("x");
        drop(short);
        assert!(display.0.lock().unwrap().is_empty());
        let none = Progress::steps_on(None, 100, 2, "reading");
        none.set(1, 100);
        drop(none);
    }
}
