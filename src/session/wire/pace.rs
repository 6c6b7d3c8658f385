//! The pace at which an exchange's bytes arrive, for the wait after a reply.

use std::time::{Duration, Instant};

/// When this exchange's bytes arrived: the first read, and the last with how many came after the
/// first.
#[derive(Debug, Default)]
pub(super) struct Pace {
    first: Option<Instant>,
    last: Option<Instant>,
    bytes_after_first: u32,
}

impl Pace {
    /// Notes `bytes` read at `now`.
    pub(super) fn record(&mut self, bytes: usize, now: Instant) {
        if self.first.is_none() {
            self.first = Some(now);
        } else {
            self.last = Some(now);
            let bytes = u32::try_from(bytes).unwrap_or(u32::MAX);
            self.bytes_after_first = self.bytes_after_first.saturating_add(bytes);
        }
    }

    /// The mean time per byte since the exchange's first read: zero when everything came in one
    /// read. A mean over the exchange is not thrown by one late wake-up.
    pub(super) fn per_byte(&self) -> Duration {
        match (self.first, self.last) {
            (Some(first), Some(last)) if self.bytes_after_first > 0 => {
                (last - first) / self.bytes_after_first
            }
            _ => Duration::ZERO,
        }
    }
}
