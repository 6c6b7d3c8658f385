//! Barriers (the reasoning is in the TMCL session's `barrier.rs`): an SMD4 reply names at most
//! its drive, so after a failed request its reply may still come and pass for the next one's
//! answer, however long the line was quiet. Before the next request to that drive the session
//! sends a mnemonic no drive knows, which the drive refuses with −103 (Invalid Mnemonic) — a
//! refusal no validated request gets — and discards every reply before that refusal. The drive
//! runs commands strictly in arrival order (the protocol says so), so once the refusal is in, no
//! earlier reply can come. Nothing is run, so nothing changes.

use std::collections::{BTreeMap, BTreeSet};

use crate::dialect::smd4::protocol::{ErrorCode, Expectation, Request, Smd4Reply, parse_reply};
use crate::session::{SessionError, barrier_failed};

use super::{DriveName, Smd4Session};

/// The barrier's mnemonic: no drive has it.
pub(super) const BARRIER: &str = "TMCLSH:BARRIER";

/// What the session knows of late replies: the drives (by address) whose failed request may
/// still be answered, and barriers given up whose refusal may still come.
#[derive(Debug, Default)]
pub(super) struct Doubt {
    drives: BTreeSet<Option<u32>>,
    lost_barriers: BTreeMap<Option<u32>, u32>,
}

impl Doubt {
    /// A barrier's refusal came from `address`: whether it is the late one of a barrier given up
    /// earlier (then counted off).
    pub(super) fn barrier_arrived(&mut self, address: Option<u32>) -> bool {
        match self.lost_barriers.get_mut(&address) {
            Some(n) if *n > 0 => {
                *n -= 1;
                true
            }
            _ => false,
        }
    }
}

/// Whether `reply` is the refusal a barrier gets.
pub(super) fn barrier_like(reply: &Smd4Reply) -> bool {
    reply
        .error
        .as_ref()
        .is_some_and(|e| e.code == ErrorCode::InvalidMnemonic)
}

/// Whether a reply line is a barrier's refusal.
pub(super) fn barrier_line(line: &[u8]) -> bool {
    let text = String::from_utf8_lossy(line);
    parse_reply(&text, &Expectation::default()).is_ok_and(|r| barrier_like(&r))
}

impl Smd4Session {
    /// Whether a reply from the drive at `address` may be a late one: its own request failed, or
    /// any did when replies carry no prefix.
    fn in_doubt(&self, address: Option<u32>) -> bool {
        let doubt = &self.doubt.drives;
        doubt.contains(&address) || (self.unprefixed_replies && !doubt.is_empty())
    }

    /// A request to `address` failed: its reply may still come.
    pub(super) fn request_failed(&mut self, address: Option<u32>) {
        self.doubt.drives.insert(address);
    }

    /// A request to `address` was answered: in order, no refusal of a barrier given up before
    /// it can come any more.
    pub(super) fn request_answered(&mut self, address: Option<u32>) {
        self.doubt.lost_barriers.remove(&address);
    }

    /// A refusal like a barrier's came from `address` outside a barrier: whether it is the late
    /// one of a barrier given up earlier (then counted off).
    pub(super) fn lost_barrier_arrived(&mut self, address: Option<u32>) -> bool {
        self.doubt.barrier_arrived(address)
    }

    /// Puts a barrier on the line before a request to `address` when a reply given up earlier
    /// may still come. Stops that must go out at once do not wait for one.
    pub(super) fn barrier(&mut self, address: Option<u32>) -> Result<(), SessionError> {
        if self.core.urgent || !self.in_doubt(address) {
            return Ok(());
        }
        let mut barrier = Request::new(BARRIER);
        barrier.address = address;
        let shown = barrier.format(self.smd4.prefix);
        self.core.wire.note(&format!(
            "barrier: {shown} to {}, whose refusal no request given up earlier can send; \
             everything before it is discarded",
            DriveName(address)
        ));
        match self.round_trip(&barrier, false) {
            Ok(Some(reply)) if barrier_like(&reply) => {
                if self.unprefixed_replies {
                    self.doubt.drives.clear();
                } else {
                    self.doubt.drives.remove(&address);
                }
                Ok(())
            }
            Ok(_) => {
                *self.doubt.lost_barriers.entry(address).or_default() += 1;
                Err(SessionError::Link(format!(
                    "{} did not refuse the barrier '{shown}' as a drive refuses an unknown \
                     mnemonic (-103); the request was not sent, and the next one puts another \
                     barrier first",
                    DriveName(address)
                )))
            }
            Err(error) => {
                *self.doubt.lost_barriers.entry(address).or_default() += 1;
                Err(barrier_failed(&shown, error))
            }
        }
    }
}
