//! Sending and receiving bytes: every byte goes through here, so every byte reaches the
//! transcript, and every wait is sliced so Ctrl-C is noticed promptly.

use std::time::Instant;

use super::super::transcript::Entry;
use super::super::{SessionError, interrupt};
use super::TmclSession;
use crate::link::LinkError;

impl TmclSession {
    /// Writes bytes to the link and the transcript.
    pub(super) fn send(&mut self, bytes: &[u8], meaning: &str) -> Result<(), SessionError> {
        self.log(Entry::Sent, bytes, meaning);
        self.link.send(bytes).map_err(SessionError::from)
    }

    /// Reads what arrives before `deadline` into the receive buffer. `Ok(false)` when the
    /// deadline passed with nothing new; `Err(Interrupted)` on Ctrl-C.
    pub(super) fn fill(&mut self, deadline: Instant) -> Result<bool, SessionError> {
        let mut buf = [0u8; 512];
        loop {
            if interrupt::pending() {
                return Err(SessionError::Interrupted);
            }
            let slice_end = deadline.min(Instant::now() + interrupt::SLICE);
            match self.link.recv(&mut buf, slice_end) {
                Ok(n) => {
                    self.rx.extend(&buf[..n]);
                    return Ok(true);
                }
                Err(LinkError::Timeout) if Instant::now() >= deadline => return Ok(false),
                Err(LinkError::Timeout) => continue,
                Err(e) => {
                    let message = e.to_string();
                    self.note(&message);
                    return Err(e.into());
                }
            }
        }
    }

    /// Drops bytes that arrived outside any exchange (late replies, line noise), logging them.
    pub(super) fn drain(&mut self) -> Result<(), SessionError> {
        let mut buf = [0u8; 512];
        loop {
            match self.link.recv(&mut buf, Instant::now()) {
                Ok(n) => self.rx.extend(&buf[..n]),
                Err(LinkError::Timeout) => break,
                Err(e) => return Err(e.into()),
            }
        }
        let stale = self.rx.clear();
        let meaningful = stale.iter().any(|b| !matches!(b, b'\r' | b'\n' | 0));
        if meaningful {
            self.log(
                Entry::Received,
                &stale,
                "arrived outside any exchange, discarded",
            );
        }
        Ok(())
    }
}
