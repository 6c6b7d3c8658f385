//! Waiting for a lost link: the pause between tries grows from a tenth of a second to a few
//! hundred milliseconds, so an adapter plugged back is found quickly without the wait polling
//! the system in a tight loop; Ctrl-C ends it at once.

use std::time::{Duration, Instant};

use super::{SessionError, interrupt};

/// The first pause between two tries to reopen a lost link.
const FIRST: Duration = Duration::from_millis(100);

/// The longest pause: an adapter back is found within this.
const LONGEST: Duration = Duration::from_millis(400);

/// The pauses between tries to reopen a link.
#[derive(Debug, Clone)]
pub struct Backoff {
    next: Duration,
}

impl Default for Backoff {
    fn default() -> Self {
        Backoff { next: FIRST }
    }
}

impl Backoff {
    /// Waits the next pause, ending early at `until`; `Err(Interrupted)` on Ctrl-C.
    pub fn pause(&mut self, until: Option<Instant>) -> Result<(), SessionError> {
        let end = Instant::now() + self.next;
        let end = until.map_or(end, |u| end.min(u));
        self.next = (self.next * 2).min(LONGEST);
        loop {
            if interrupt::pending() {
                return Err(SessionError::Interrupted);
            }
            let now = Instant::now();
            if now >= end {
                return Ok(());
            }
            std::thread::sleep((end - now).min(interrupt::SLICE));
        }
    }

    /// The pause the next [`pause`](Self::pause) waits.
    pub fn next(&self) -> Duration {
        self.next
    }
}

/// A time for messages: `500 ms`, `2 s`, `1.5 s`.
pub fn say(time: Duration) -> String {
    if time < Duration::from_secs(1) {
        format!("{} ms", time.as_millis())
    } else {
        format!("{} s", time.as_secs_f64())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pauses_grow_to_a_few_hundred_milliseconds() {
        let mut backoff = Backoff::default();
        let mut seen = Vec::new();
        for _ in 0..5 {
            seen.push(backoff.next());
            backoff.pause(Some(Instant::now())).unwrap();
        }
        assert_eq!(seen[0], FIRST);
        assert!(seen.windows(2).all(|w| w[0] <= w[1]), "{seen:?}");
        assert_eq!(*seen.last().unwrap(), LONGEST);
    }

    #[test]
    fn times_read_as_people_write_them() {
        assert_eq!(say(Duration::from_millis(250)), "250 ms");
        assert_eq!(say(Duration::from_millis(1500)), "1.5 s");
        assert_eq!(say(Duration::from_secs(30)), "30 s");
    }
}
