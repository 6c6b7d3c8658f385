//! A session that heard nothing from the start asks whether an SMD4 drive is on the line before
//! it blames the port or the firmware: "does not answer in ASCII mode" is the wrong diagnosis
//! when `--protocol smd4` was forgotten.

use std::time::Instant;

use crate::dialect::tmcl::protocol::sniff::{SMD4_PROBE, smd4_reply};
use crate::escape::escape_control;
use crate::exit::{Exit, Failure};
use crate::session::SessionError;
use crate::session::transcript::Entry;

use super::TmclSession;

/// The most a sniff reads: a drive's packet error and its firmware line.
const ENOUGH: usize = 256;

impl TmclSession {
    /// When no module has answered anything yet: the failure naming an SMD4 drive if one
    /// answers [`SMD4_PROBE`], else `None` (and the caller's own error stands).
    pub(super) fn sniff_other_dialect(&mut self) -> Option<SessionError> {
        if self.core.wire.heard_anything() {
            return None;
        }
        let stray = self.core.wire.rx.clear();
        if !stray.is_empty() {
            self.core
                .wire
                .log(Entry::Received, &stray, "unexpected data, discarded");
        }
        self.core
            .wire
            .send(SMD4_PROBE, "an SMD4 query, to tell what is on the line")
            .ok()?;
        let deadline = Instant::now() + self.optional_wait(SMD4_PROBE.len() as u32 + 64);
        let mut heard = None;
        while Instant::now() < deadline && self.core.wire.rx.len() < ENOUGH {
            match self.core.wire.fill(deadline) {
                Ok(true) => {}
                _ => break,
            }
            heard = smd4_reply(self.core.wire.rx.bytes());
            if heard.is_some() {
                break;
            }
        }
        let bytes = self.core.wire.rx.clear();
        if !bytes.is_empty() {
            let what = if heard.is_some() {
                "an SMD4 drive's reply"
            } else {
                "not an SMD4 reply, discarded"
            };
            self.core.wire.log(Entry::Received, &bytes, what);
        }
        let reply = heard?;
        let message = format!(
            "this looks like an AML SMD4 drive, not a TMCL module: nothing answered in TMCL, \
             and an SMD4 query got the SMD4 reply `{}`; give --protocol smd4",
            escape_control(&reply)
        );
        self.core.wire.note(&message);
        Some(SessionError::Failed(Failure::new(Exit::Refused, message)))
    }
}
