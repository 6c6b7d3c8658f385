//! A session that heard nothing from the start asks whether a TMCL module is on the line before
//! it blames the port, the baud rate or the addressing: `--protocol tmcl` forgotten (or
//! `--protocol smd4` left in a configuration) looks like silence otherwise.

use std::time::{Duration, Instant};

use crate::dialect::smd4::protocol::sniff::{TMCL_ASCII_PROBE, TMCL_FRAME_PROBE, tmcl_reply};
use crate::escape::escape_control;
use crate::exit::{Exit, Failure};
use crate::session::transcript::Entry;

use super::Smd4Session;

/// How long a module may take to answer a probe, at most (the session's timeout if shorter),
/// besides the bytes' time on the wire.
const PROBE_WAIT: Duration = Duration::from_millis(200);

/// A TMCL module drops a partial binary frame after this much quiet (its UART time-out): the
/// drive's text sent before must be forgotten before the probe frame.
const FRAME_GAP: Duration = Duration::from_millis(10);

impl Smd4Session {
    /// When nothing has come from the line yet: the failure naming a TMCL module if one answers
    /// a probe in either of its modes, else `None` (and the caller's own error stands).
    pub(super) fn sniff_other_dialect(&mut self) -> Option<Failure> {
        // A drive addressed with `--address` ignores what is not for it: silence is its answer.
        if self.core.wire.heard_anything() || self.smd4.address.is_some() {
            return None;
        }
        self.core.wire.idle_for(FRAME_GAP).ok()?;
        let probes: [(&[u8], &str); 2] = [
            (
                &TMCL_FRAME_PROBE,
                "a TMCL binary frame (136 to module 1), to tell what is on the line",
            ),
            (
                TMCL_ASCII_PROBE,
                "a TMCL ASCII request (GGP 67 to module 1), to tell what is on the line",
            ),
        ];
        for (probe, meaning) in probes {
            if let Some(heard) = self.probe(probe, meaning) {
                let message = format!(
                    "this looks like a Trinamic TMCL module, not an SMD4 drive: nothing answered \
                     in SMD4, and a TMCL request got {}; give --protocol tmcl",
                    escape_control(&heard)
                );
                self.core.wire.note(&message);
                return Some(Failure::new(Exit::Refused, message));
            }
        }
        // What a drive holds of the probes is ended, so its next packet starts clean.
        let _ = self
            .core
            .wire
            .send(b"\r\n", "end of line, ends what the probes left");
        None
    }

    /// Sends `probe` and reads what comes until a TMCL reply is recognised or the wait is over.
    fn probe(&mut self, probe: &[u8], meaning: &str) -> Option<String> {
        self.core.wire.send(probe, meaning).ok()?;
        let wire = self.core.wire.wire_time(64);
        let deadline = Instant::now() + PROBE_WAIT.min(self.core.options.timeout) + wire;
        let mut heard = None;
        while heard.is_none() && Instant::now() < deadline && self.core.wire.rx.len() < 256 {
            if !matches!(self.core.wire.fill(deadline), Ok(true)) {
                break;
            }
            heard = tmcl_reply(self.core.wire.rx.bytes());
        }
        let bytes = self.core.wire.rx.clear();
        if !bytes.is_empty() {
            let what = if heard.is_some() {
                "a TMCL module's reply"
            } else {
                "not a TMCL reply, discarded"
            };
            self.core.wire.log(Entry::Received, &bytes, what);
        }
        heard
    }
}
