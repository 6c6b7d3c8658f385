//! What `:line` counts of the exchanges (requests sent, replies that checked out), and the
//! driver's error counters as last seen, so that a request left without a reply can say when
//! the port counted framing errors or overruns since: a wrong rate, noise, or two drivers on an
//! RS-485 bus look like silence otherwise.

use crate::link::line::Counters;
use crate::link::{LineState, Link};

/// The exchanges so far and the counters last seen.
#[derive(Debug, Default)]
pub(crate) struct Tally {
    /// Exchanges begun.
    pub requests: u64,
    /// Exchanges that ended with a reply that checked out.
    pub replies: u64,
    /// The driver's counters when last looked at (opening, or the last failed exchange).
    seen: Option<Counters>,
    /// Whether a failed exchange has looked at them since opening.
    looked: bool,
}

impl Tally {
    /// Starts counting on a link in `state`, its counters as they are now.
    pub(crate) fn new(state: &LineState) -> Tally {
        Tally {
            seen: state.counters,
            ..Tally::default()
        }
    }

    /// After a failed exchange: the errors the port counted since the counters were last seen,
    /// as a notice, or `None` when none grew (or the port keeps no counters).
    pub(crate) fn failed(&mut self, link: &mut dyn Link) -> Option<String> {
        let now = link.line_state().counters?;
        let moved = self.seen.and_then(|before| now.moved_since(&before));
        let since = if self.looked {
            "the last request without a reply"
        } else {
            "the port was opened"
        };
        self.seen = Some(now);
        self.looked = true;
        moved.map(|moved| {
            format!(
                "the serial port counted {moved} since {since}: a rate the modules do not \
                 use, noise, or two senders on the bus at once (`:line` shows the counters)"
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use std::time::Instant;

    use super::*;
    use crate::link::LinkError;

    /// A link whose driver counts `frame` framing errors.
    struct Counting {
        frame: u64,
    }

    impl Link for Counting {
        fn send(&mut self, _: &[u8]) -> Result<(), LinkError> {
            Ok(())
        }

        fn recv(&mut self, _: &mut [u8], _: Instant) -> Result<usize, LinkError> {
            Err(LinkError::Timeout)
        }

        fn describe(&self) -> String {
            "counting".into()
        }

        fn line_state(&mut self) -> LineState {
            LineState {
                counters: Some(Counters {
                    frame: self.frame,
                    ..Counters::default()
                }),
                ..LineState::default()
            }
        }
    }

    #[test]
    fn a_failed_request_names_the_errors_counted_since_last_seen() {
        let mut link = Counting { frame: 5 };
        let mut tally = Tally::new(&link.line_state());
        assert_eq!(tally.failed(&mut link), None, "nothing new");
        link.frame = 8;
        let notice = tally.failed(&mut link).expect("moved");
        assert!(
            notice.starts_with("the serial port counted 3 framing errors"),
            "{notice}"
        );
        assert_eq!(tally.failed(&mut link), None, "said once");
    }
}
