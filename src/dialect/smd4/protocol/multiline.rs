//! Collecting a whole reply, including the multi-line ones.
//!
//! SYS:FLAGSV and COMS:NET:IPCONF answer with a first line `SFLAGS,EFLAGS,` and then text lines,
//! and the document defines **no end marker**. The only way to know such a reply is complete is
//! that the line goes quiet. The collector is pure: the session feeds it each line it reads and
//! tells it when no byte arrived for the quiet gap (default [`default_quiet_gap`], from
//! `data/smd4.toml`; make it configurable, e.g. longer on slow RS485 links):
//!
//! ```
//! use tmclsh::dialect::smd4::protocol::{Expectation, CollectorState, ReplyCollector, Smd4Spec};
//! let table = &Smd4Spec::builtin().commands;
//! let mut collector = ReplyCollector::new(Expectation::for_command(table.get("COMS:NET:IPCONF").unwrap()));
//! // The session reads a line, feeds it, and looks at what the collector needs next:
//! assert_eq!(collector.push_line("0x0000,0x0000,\r\n").unwrap(), CollectorState::AwaitQuiet);
//! // … more lines arrive; each is fed the same way …
//! assert_eq!(collector.push_line("Ethernet interface:").unwrap(), CollectorState::AwaitQuiet);
//! // … until nothing arrived for the quiet gap after the last byte:
//! let reply = collector.finish_quiet().unwrap();
//! assert_eq!(reply.lines, ["Ethernet interface:"]);
//! ```
//!
//! Single-line replies (and a multi-line command that failed with an error code) complete at once,
//! so a session only ever waits for quiet after the first line of a multi-line reply.

use std::time::Duration;

use super::Smd4Spec;
use super::reply::{Expectation, ReplyError, Smd4Reply, parse_reply};

/// The quiet gap that ends a multi-line reply, from `data/smd4.toml`.
pub fn default_quiet_gap() -> Duration {
    Smd4Spec::builtin().sim.quiet_gap
}

/// What the collector needs after a line.
#[derive(Debug, Clone, PartialEq)]
pub enum CollectorState {
    /// The reply is complete.
    Complete(Box<Smd4Reply>),
    /// More lines may follow: keep reading until the line has been quiet for the gap, then call
    /// [`ReplyCollector::finish_quiet`].
    AwaitQuiet,
}

/// Gathers the lines of one reply.
#[derive(Debug, Clone)]
pub struct ReplyCollector {
    expect: Expectation,
    head: Option<Smd4Reply>,
}

impl ReplyCollector {
    /// A collector for a reply of the given shape.
    pub fn new(expect: Expectation) -> ReplyCollector {
        ReplyCollector { expect, head: None }
    }

    /// Feeds one received line (line ending optional). The first line must be a reply; an error
    /// leaves the collector as it was, so a session may skip line noise and go on.
    pub fn push_line(&mut self, line: &str) -> Result<CollectorState, ReplyError> {
        let text = line.trim_end_matches(['\r', '\n']);
        if let Some(head) = &mut self.head {
            head.lines.push(text.to_string());
            return Ok(CollectorState::AwaitQuiet);
        }
        let reply = parse_reply(text, &self.expect)?;
        if self.expect.multi_line() && reply.is_ok() {
            self.head = Some(reply);
            Ok(CollectorState::AwaitQuiet)
        } else {
            Ok(CollectorState::Complete(Box::new(reply)))
        }
    }

    /// Whether the first line has arrived and the collector waits for the line to go quiet.
    pub fn awaiting_quiet(&self) -> bool {
        self.head.is_some()
    }

    /// The line has been quiet for the gap: the reply is complete. `None` if no first line came.
    pub fn finish_quiet(self) -> Option<Smd4Reply> {
        self.head
    }
}
