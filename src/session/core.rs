//! What every dialect's session holds alike: the wire (link, receive buffer, transcript, notices),
//! the session options, and what the session set going — so that whatever a face asks of a
//! session regardless of dialect (describe, notices, transcript, timeouts, reconnecting, whether
//! something may still move) is written once, over this core.

use std::collections::BTreeSet;

use crate::link::Link;

use super::SessionOptions;
use super::transcript::Transcript;
use super::wire::Wire;

/// Bus addresses of modules or drives; `None` stands for requests sent without an address (an
/// SMD4 drive talked to without an `@N` prefix).
pub type Addresses = BTreeSet<Option<u32>>;

/// The state every dialect's session shares.
pub struct SessionCore {
    /// The link with its receive buffer, transcript, notices and trust.
    pub(crate) wire: Wire,
    /// The session's settings.
    pub options: SessionOptions,
    /// Where this session started motors: stopped when a run is aborted.
    pub moved: Addresses,
    /// Where this session started a stored program: stopped when a run is aborted.
    pub running: Addresses,
    /// Requests go out without waiting for a suspect line to go quiet (stops, mode restores).
    pub urgent: bool,
    /// The session is bringing a lost link back: a loss now fails at once rather than waiting
    /// inside the wait.
    pub relinking: bool,
}

impl SessionCore {
    /// A core over `link`, writing `transcript` if given.
    pub fn new(
        link: Box<dyn Link>,
        options: SessionOptions,
        transcript: Option<Transcript>,
    ) -> Self {
        let mut wire = Wire::new(link, transcript);
        wire.set_local_echo(options.local_echo);
        if let Some(wait) = options.reconnect {
            wire.note(&format!(
                "a lost link is waited for up to {} (--reconnect); only an interrupted read is \
                 sent again",
                super::relink::say(wait)
            ));
        }
        SessionCore {
            wire,
            options,
            moved: Addresses::new(),
            running: Addresses::new(),
            urgent: false,
            relinking: false,
        }
    }

    /// What the link talks to.
    pub fn describe(&self) -> String {
        self.wire.link.describe()
    }

    /// Writes a remark into the transcript.
    pub fn note(&mut self, text: &str) {
        self.wire.note(text);
    }
}
