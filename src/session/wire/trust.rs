//! When the line is trusted: resynchronising after a failure, the check of what follows a reply,
//! and what may arrive between exchanges (the rules are in `wire.rs`).

use std::time::{Duration, Instant};

use crate::link::LinkError;

use super::super::SessionError;
use super::super::rx::{RX_CAP, is_line_break};
use super::echo::Taken;
use super::{MAX_LINE, Peer, Wire};

/// The resync window is at least this many byte times, whatever the timeout.
const RESYNC_BYTES: u32 = 32;

/// The resync window is at most this long (unless the byte times ask for more): a long
/// `--timeout` is for slow answers, not for a pause after every failure.
pub(super) const RESYNC_MAX: Duration = Duration::from_secs(1);

/// The longest wait for bytes following a reply on a link that does not know its byte time.
const MAX_SETTLE: Duration = Duration::from_millis(10);

/// Bytes arriving faster than this came in one burst: what follows a reply arrives with it.
const BURST_PACE: Duration = Duration::from_micros(10);

/// Margin on the wait for the next byte of a transmission besides a quarter of its pace: the
/// sender's and this process's wake-up lateness.
const SETTLE_SLACK: Duration = Duration::from_micros(50);

/// How much a drain between exchanges reads before it calls the line flooded.
const DRAIN_BUDGET: usize = RX_CAP;

/// Bytes that arrived between exchanges or while the line resynchronised.
const OUTSIDE: &str = "late or unsolicited data that arrived outside any exchange";

/// Recognises harmless data that arrived between exchanges (TMCL position events, late answers
/// a dialect can attribute); `None` when it cannot vouch for all of it.
pub(crate) type Benign<'a> = &'a mut dyn FnMut(&[u8]) -> Option<Harmless>;

/// What harmless data between exchanges amounts to.
#[derive(Debug, Default)]
pub(crate) struct Harmless {
    /// What the user should hear (events).
    pub notices: Vec<String>,
    /// Peers whose late answers have now all been seen: trusted again.
    pub answered: Vec<Peer>,
}

/// Nothing is harmless.
pub(crate) fn nothing_benign(_: &[u8]) -> Option<Harmless> {
    None
}

impl Wire {
    /// Waits, no later than `deadline`, for more bytes of the transmission that just delivered a
    /// complete reply: as long as the next byte would take at the pace this exchange's bytes came
    /// in. A burst is not waited for: when the read that took it took all there was, that read
    /// already answered (a look now would only race the sender by microseconds); otherwise one
    /// look. True when bytes arrived.
    pub(crate) fn await_more(&mut self, deadline: Instant) -> Result<bool, SessionError> {
        let wait = self.settle_time();
        if wait.is_zero() && self.took_all {
            return Ok(false);
        }
        self.fill((Instant::now() + wait).min(deadline))
    }

    /// Checks what follows a complete reply that ends `from` bytes into the receive buffer,
    /// waiting as [`Wire::await_more`] does for the rest of the transmission (beyond `deadline`
    /// by at most that wait, so a reply in its last moment is checked too). `from` is just past
    /// the byte that ended the reply's line. The rest of that line end (the LF of a CR LF), NULs
    /// and lines `benign` accepts may follow; anything else — the rest of a value a corrupted
    /// byte cut short, even a line end more (`-5227` CR CR was `-52270` CR), a second reply, a
    /// fragment — is noise. Consumes nothing.
    pub(crate) fn settle(
        &mut self,
        from: usize,
        deadline: Instant,
        benign: &mut dyn FnMut(&[u8]) -> bool,
    ) -> Result<Settled, SessionError> {
        // Read from the clock only when there is something to wait for (see below).
        let settle = self.settle_time();
        let mut hard_end = None;
        let mut pos = from;
        // The byte that ended the last line: after a CR one LF may complete it, nothing more.
        let mut ended_by = from
            .checked_sub(1)
            .and_then(|i| self.rx.bytes().get(i).copied())
            .unwrap_or(b'\n');
        loop {
            loop {
                let bytes = self.rx.bytes();
                while pos < bytes.len() && is_line_break(bytes[pos]) {
                    match (ended_by, bytes[pos]) {
                        (_, 0) => {}
                        (b'\r', b'\n') => ended_by = b'\n',
                        _ => return Ok(Settled::Noise),
                    }
                    pos += 1;
                }
                if pos == bytes.len() {
                    break;
                }
                match self.rx.line_end(pos) {
                    Some(end) if end - pos <= MAX_LINE && benign(&self.rx.bytes()[pos..end]) => {
                        ended_by = self.rx.bytes()[end];
                        pos = end + 1;
                    }
                    Some(_) => return Ok(Settled::Noise),
                    None if self.rx.len() - pos > MAX_LINE => return Ok(Settled::Noise),
                    None => break,
                }
            }
            let done = if pos < self.rx.len() {
                Settled::Noise
            } else {
                Settled::Clean(pos)
            };
            // A burst the last read took whole has nothing after it: `await_more` says so
            // without a clock, and so would an end already passed.
            if self.settle_time().is_zero() && self.took_all {
                return Ok(done);
            }
            let now = Instant::now();
            let hard_end = *hard_end.get_or_insert(deadline.max(now + settle));
            if now >= hard_end || !self.await_more(hard_end)? {
                return Ok(done);
            }
        }
    }

    /// How long after a reply's last byte the next one of the same transmission would arrive.
    pub(crate) fn settle_time(&self) -> Duration {
        let pace = self.pace.per_byte();
        if pace < BURST_PACE {
            return Duration::ZERO;
        }
        let cap = self
            .link
            .byte_time()
            .map_or(MAX_SETTLE, |b| (b * 2).min(MAX_SETTLE));
        // The next byte is due one byte time after the last.
        pace.min(cap) * 5 / 4 + SETTLE_SLACK
    }

    /// How long the line must be quiet before a suspect peer is trusted again: as long as the
    /// timeout (a reply that missed it gets as long again to turn up) up to [`RESYNC_MAX`], and
    /// at least [`RESYNC_BYTES`] byte times (a slow line still delivering).
    pub(crate) fn resync_window(&self, timeout: Duration) -> Duration {
        let bytes = self.wire_time(RESYNC_BYTES);
        timeout.min(RESYNC_MAX).max(bytes)
    }

    /// Trusts `peer` again without waiting: its late answers have all been seen.
    pub(crate) fn trust(&mut self, peer: Peer) {
        self.suspect.peers.retain(|&p| p != peer);
    }

    /// Discards everything until the line has been quiet for the resync window; fails, sending
    /// nothing, if it does not go quiet within one more timeout.
    pub(super) fn resync(&mut self, timeout: Duration) -> Result<(), SessionError> {
        let window = self.resync_window(timeout);
        let give_up = Instant::now() + window + timeout;
        self.note(&format!(
            "resynchronising: waiting until the line has been quiet for {} ms",
            window.as_millis()
        ));
        let mut quiet_since = Instant::now();
        loop {
            let quiet_until = quiet_since + window;
            let now = Instant::now();
            // A stall of this thread is not silence: what arrived meanwhile is taken first.
            if now >= quiet_until && self.fill(now)? {
                quiet_since = Instant::now();
                let n = self.rx.len();
                self.discard(n, OUTSIDE);
                continue;
            }
            if now >= quiet_until {
                self.flush_discarded();
                self.suspect = Suspicion::default();
                return Ok(());
            }
            if now >= give_up {
                self.flush_discarded();
                self.note("the line did not go quiet");
                return Err(SessionError::noise(format!(
                    "line noise: the line did not go quiet for {} ms within {} ms after a failed \
                     request, so nothing was sent; check what else talks on the line",
                    window.as_millis(),
                    (window + timeout).as_millis()
                )));
            }
            if self.fill(quiet_until.min(give_up))? {
                quiet_since = Instant::now();
                let n = self.rx.len();
                self.discard(n, OUTSIDE);
            }
        }
    }

    /// Takes what arrived outside any exchange (late replies, line noise, events), logging it;
    /// anything but line ends and benign data makes the line suspect.
    pub(crate) fn drain(&mut self, benign: Benign) -> Result<(), SessionError> {
        let mut buf = self.take_scratch();
        let result = self.drain_into(benign, &mut buf);
        self.scratch = buf;
        result
    }

    fn drain_into(&mut self, benign: Benign, buf: &mut [u8]) -> Result<(), SessionError> {
        let mut read = 0;
        while read < DRAIN_BUDGET {
            // A deadline long past: a look at what has arrived, with no clock read for it.
            match self.link.recv(buf, self.made) {
                Ok(n) => {
                    read += n;
                    self.last_heard = Some(Instant::now());
                    match self.take_in(&buf[..n]) {
                        Ok(Taken::Kept) => {}
                        Ok(Taken::Overflow) => {
                            read = DRAIN_BUDGET;
                            self.discard_unexpected(Some(&buf[..n]));
                        }
                        // A wrong echo between exchanges: said, and the line is suspect.
                        Err(e) => {
                            self.notices.push(e.to_string());
                            self.suspect.add(Peer::Any);
                        }
                    }
                }
                Err(LinkError::Timeout) => break,
                Err(e) => return Err(e.into()),
            }
        }
        if read >= DRAIN_BUDGET {
            self.discard_unexpected(None);
            return Ok(());
        }
        let stale = self.rx.bytes();
        if stale.iter().all(|&b| is_line_break(b)) {
            let n = stale.len();
            self.discard_quietly(n, "line ends between exchanges");
        } else if let Some(harmless) = benign(stale) {
            let n = stale.len();
            self.notices.extend(harmless.notices);
            for peer in harmless.answered {
                self.trust(peer);
            }
            self.log_received(n, "events and late answers between exchanges, discarded");
        } else {
            self.discard_unexpected(None);
        }
        Ok(())
    }

    /// Discards the receive buffer (and `more`) as data outside any exchange; the line is suspect.
    fn discard_unexpected(&mut self, more: Option<&[u8]>) {
        let n = self.rx.len();
        self.discard(n, OUTSIDE);
        if let Some(more) = more {
            self.discards.count(OUTSIDE, more);
            self.keep_discarded(more);
        }
        self.suspect.add(Peer::Any);
    }
}

/// What followed a complete reply.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Settled {
    /// Only line ends and harmless lines: the first `n` buffered bytes belong to the reply.
    Clean(usize),
    /// Anything else: the reply may be cut short or not the only one, and is not trusted.
    Noise,
}

/// Peers whose answers may still be on the way.
#[derive(Debug, Default)]
pub(super) struct Suspicion {
    pub(super) peers: Vec<Peer>,
}

impl Suspicion {
    pub(super) fn add(&mut self, peer: Peer) {
        if !self.peers.contains(&peer) {
            self.peers.push(peer);
        }
    }

    /// Whether an exchange with `peer` could take a stale answer: the peer itself is suspect, or
    /// something whose replies name no sender, or `peer` cannot tell its replies from others'.
    pub(super) fn covers(&self, peer: Peer) -> bool {
        match peer {
            Peer::Any => !self.peers.is_empty(),
            module => self.peers.iter().any(|&p| p == module || p == Peer::Any),
        }
    }
}
