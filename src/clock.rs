//! Simulation time: the wall clock for users, a manual clock for deterministic tests.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// A source of simulation time, counted from the clock's creation.
pub trait Clock: Send + Sync {
    /// Time since the clock started.
    fn now(&self) -> Duration;

    /// Lets `duration` pass: the wall clock sleeps, a manual clock jumps ahead.
    fn wait(&self, duration: Duration);

    /// How long, in real time, until the clock shows `target`; `None` when real time does not
    /// move this clock (a manual clock), so a server waits only for input or a wake-up.
    fn real_time_until(&self, target: Duration) -> Option<Duration> {
        Some(target.saturating_sub(self.now()))
    }

    /// When the wall-clock `deadline` falls on this clock, seen at `now` (the clock's time just
    /// read): as much later than `now` as the deadline is later than the wall clock.
    fn deadline(&self, now: Duration, deadline: Instant) -> Duration {
        now + deadline.saturating_duration_since(Instant::now())
    }
}

/// Real time.
#[derive(Debug, Clone)]
pub struct SystemClock {
    start: Instant,
}

impl SystemClock {
    /// A clock starting now.
    pub fn new() -> Self {
        SystemClock {
            start: Instant::now(),
        }
    }
}

impl Default for SystemClock {
    fn default() -> Self {
        Self::new()
    }
}

impl Clock for SystemClock {
    fn now(&self) -> Duration {
        self.start.elapsed()
    }

    fn wait(&self, duration: Duration) {
        std::thread::sleep(duration);
    }

    /// The wall clock is this clock: the deadline is read off it, without reading the time.
    fn deadline(&self, _now: Duration, deadline: Instant) -> Duration {
        deadline.saturating_duration_since(self.start)
    }
}

/// Time that only moves when told to: tests advance it explicitly, or by waiting on it.
#[derive(Debug, Clone, Default)]
pub struct ManualClock {
    micros: Arc<AtomicU64>,
}

impl ManualClock {
    /// A clock at zero.
    pub fn new() -> Self {
        Self::default()
    }

    /// Moves time forward.
    pub fn advance(&self, duration: Duration) {
        self.micros
            .fetch_add(duration.as_micros() as u64, Ordering::SeqCst);
    }
}

impl Clock for ManualClock {
    fn now(&self) -> Duration {
        Duration::from_micros(self.micros.load(Ordering::SeqCst))
    }

    fn wait(&self, duration: Duration) {
        self.advance(duration);
    }

    fn real_time_until(&self, _target: Duration) -> Option<Duration> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn manual_clock_moves_only_when_told() {
        let clock = ManualClock::new();
        assert_eq!(clock.now(), Duration::ZERO);
        clock.advance(Duration::from_millis(5));
        clock.wait(Duration::from_millis(7));
        assert_eq!(clock.now(), Duration::from_millis(12));
        let shared = clock.clone();
        shared.advance(Duration::from_micros(1));
        assert_eq!(clock.now(), Duration::from_micros(12_001));
    }

    #[test]
    fn system_clock_moves_forward() {
        let clock = SystemClock::new();
        let a = clock.now();
        assert!(clock.now() >= a);
    }

    #[test]
    fn a_wall_deadline_falls_as_far_ahead_on_either_clock() {
        let ahead = Duration::from_secs(3600);
        let system = SystemClock::new();
        let now = system.now();
        let on_system = system.deadline(now, Instant::now() + ahead);
        assert!(on_system >= now + ahead && on_system <= system.now() + ahead);
        let manual = ManualClock::new();
        manual.advance(Duration::from_secs(5));
        let on_manual = manual.deadline(manual.now(), Instant::now() + ahead);
        assert!(on_manual <= Duration::from_secs(5) + ahead);
        assert!(on_manual > Duration::from_secs(5) + ahead - Duration::from_secs(60));
        let past = Instant::now();
        assert_eq!(manual.deadline(manual.now(), past), Duration::from_secs(5));
    }
}
