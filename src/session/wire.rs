//! The byte side every dialect's session shares: the link, the receive buffer, the transcript and
//! the notices, and the rules that decide when the line can be trusted. Every byte goes through
//! here, so every byte reaches the transcript, and every wait is sliced so Ctrl-C is noticed
//! promptly.
//!
//! Trust, one mechanism for both dialects:
//! - An exchange runs between [`Wire::begin`] and [`Wire::finish`]. One that fails in any way
//!   (timeout, line noise, Ctrl-C, a reply that does not check out) leaves its peer *suspect*: its
//!   answer may still be on the way. So may bytes found on the line between exchanges.
//! - Before the next exchange with a suspect peer the line is resynchronised: everything that
//!   arrives is discarded until the line has been quiet for the resync window (the session
//!   timeout up to a second, at least [`RESYNC_BYTES`] byte times), bounded by one more timeout
//!   if the line never goes quiet. A clean line costs nothing: no exchange waits unless one
//!   failed. (With an echo, a peer whose late answers have all been seen is trusted at once.)
//! - A complete reply is trusted only once the bytes right after it have been seen: a reply cut
//!   short by a corrupted byte, or glued to more data, is line noise. The wait for them
//!   ([`Wire::await_more`]) follows the pace at which this reply's bytes arrived, so a link that
//!   delivers whole replies at once pays only a poll.
//! - Whatever is discarded is counted and summarised in one notice per kind and exchange.

use std::fmt::Display;
use std::time::{Duration, Instant};

use crate::link::{Link, LinkError};

use super::rx::{RX_CAP, Rx, is_line_break};
use super::transcript::{Entry, Transcript, escape_into};
use super::{SessionError, interrupt};

/// Who an exchange talks to, as far as replies tell: a module or drive whose replies carry its
/// address, or anyone (replies that name no sender).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Peer {
    /// Replies do not say who sent them.
    Any,
    /// Replies carry this address.
    Module(u32),
}

/// The resync window is at least this many byte times, whatever the timeout.
pub(crate) const RESYNC_BYTES: u32 = 32;

/// The resync window is at most this long (unless the byte times ask for more): a long
/// `--timeout` is for slow answers, not for a pause after every failure.
pub(crate) const RESYNC_MAX: Duration = Duration::from_secs(1);

/// A partial line longer than this cannot be a reply or an echo of either dialect: it is dropped
/// as noise instead of being kept until its line end comes.
pub(crate) const MAX_LINE: usize = 1024;

/// The longest wait for bytes following a reply on a link that does not know its byte time.
const MAX_SETTLE: Duration = Duration::from_millis(10);

/// Bytes arriving faster than this came in one burst: what follows a reply arrives with it.
const BURST_PACE: Duration = Duration::from_micros(10);

/// Margin on the wait for the next byte of a transmission besides a quarter of its pace: the
/// sender's and this process's wake-up lateness.
const SETTLE_SLACK: Duration = Duration::from_micros(50);

/// Discarded bytes are written to the transcript in records of about this size.
const DISCARD_RECORD: usize = 4096;

/// How much a drain between exchanges reads before it calls the line flooded.
const DRAIN_BUDGET: usize = RX_CAP;

/// Bytes that arrived between exchanges or while the line resynchronised.
const OUTSIDE: &str = "data that arrived outside any exchange (a late reply?)";

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

/// A link with its receive buffer, transcript, notices and trust.
pub(crate) struct Wire {
    pub link: Box<dyn Link>,
    pub rx: Rx,
    pub transcript: Option<Transcript>,
    pub notices: Vec<String>,
    /// When the last byte was sent, for [`Wire::idle_for`].
    last_sent: Option<Instant>,
    /// Peers whose answers may still be on the way.
    suspect: Suspicion,
    /// The peer of the exchange in progress.
    in_flight: Option<Peer>,
    discards: Discards,
    /// Discarded bytes not yet written to the transcript.
    discarded: Vec<u8>,
    pace: Pace,
}

impl Wire {
    pub fn new(link: Box<dyn Link>, transcript: Option<Transcript>) -> Self {
        precise_timers();
        Wire {
            link,
            rx: Rx::default(),
            transcript,
            notices: Vec::new(),
            last_sent: None,
            suspect: Suspicion::default(),
            in_flight: None,
            discards: Discards::default(),
            discarded: Vec::new(),
            pace: Pace::default(),
        }
    }

    /// Starts an exchange with `peer`: takes what arrived since the last one (anything but line
    /// ends and `benign` data makes the line suspect), and unless `urgent` (a stop that must go
    /// out now) resynchronises first when the peer is suspect.
    pub fn begin(
        &mut self,
        peer: Peer,
        urgent: bool,
        timeout: Duration,
        benign: Benign,
    ) -> Result<(), SessionError> {
        self.in_flight = None;
        self.drain(benign)?;
        if !urgent && self.suspect.covers(peer) {
            self.resync(timeout)?;
        }
        self.pace = Pace::default();
        self.in_flight = Some(peer);
        Ok(())
    }

    /// Ends the exchange started by [`Wire::begin`]: a failed one leaves its peer suspect; what
    /// was discarded becomes one notice per kind.
    pub fn finish(&mut self, ok: bool) {
        if let (Some(peer), false) = (self.in_flight.take(), ok) {
            self.suspect.add(peer);
        }
        self.flush_discarded();
        let summary = self.discards.summary();
        self.notices.extend(summary);
        self.discards = Discards::default();
    }

    /// Writes bytes to the link and the transcript. The meaning is formatted only when a
    /// transcript is being written (pass `format_args!`), so it costs nothing otherwise.
    pub fn send(&mut self, bytes: &[u8], meaning: impl Display) -> Result<(), SessionError> {
        self.log(Entry::Sent, bytes, meaning);
        self.link.send(bytes).map_err(SessionError::from)?;
        self.last_sent = Some(Instant::now());
        Ok(())
    }

    /// Keeps the line idle until `gap` has passed since the last byte sent. Binary receivers on
    /// a bus find the start of a frame only after such a pause (a UART time-out), so this is
    /// needed before the first binary frame to a module that has seen other traffic; it is a
    /// rule of the line, not a guessed reply delay. Ctrl-C interrupts it.
    pub fn idle_for(&mut self, gap: Duration) -> Result<(), SessionError> {
        let Some(last) = self.last_sent else {
            return Ok(());
        };
        let until = last + gap;
        loop {
            if interrupt::pending() {
                return Err(SessionError::Interrupted);
            }
            let now = Instant::now();
            if now >= until {
                return Ok(());
            }
            std::thread::sleep((until - now).min(interrupt::SLICE));
        }
    }

    /// Reads what arrives before `until` into the receive buffer: `Ok(false)` when `until`
    /// passed with nothing new (an `until` already past still takes what has arrived);
    /// `Err(Interrupted)` on Ctrl-C. Callers bound their loops with their own deadline, so a
    /// line that never stops talking cannot keep them.
    pub fn fill(&mut self, until: Instant) -> Result<bool, SessionError> {
        let mut buf = [0u8; 4096];
        loop {
            if interrupt::pending() {
                return Err(SessionError::Interrupted);
            }
            let slice_end = until.min(Instant::now() + interrupt::SLICE);
            match self.link.recv(&mut buf, slice_end) {
                Ok(n) => {
                    self.pace.record(n);
                    if self.rx.extend(&buf[..n]).is_err() {
                        let held = self.rx.clear();
                        self.log(Entry::Received, &held, "receive buffer full, discarded");
                        self.log(Entry::Received, &buf[..n], "receive buffer full, discarded");
                        self.note("line noise: 64 KiB arrived without a usable line");
                        return Err(SessionError::Link(
                            "line noise: 64 KiB arrived without a usable line; check the port, the \
                             baud rate and what else talks on the line"
                                .into(),
                        ));
                    }
                    return Ok(true);
                }
                Err(LinkError::Timeout) if Instant::now() >= until => return Ok(false),
                Err(LinkError::Timeout) => continue,
                Err(e) => {
                    let message = e.to_string();
                    self.note(&message);
                    return Err(e.into());
                }
            }
        }
    }

    /// Waits, no later than `deadline`, for more bytes of the transmission that just delivered a
    /// complete reply: as long as the next byte would take at the pace this exchange's bytes came
    /// in, or just a poll when they came in one burst. True when bytes arrived.
    pub fn await_more(&mut self, deadline: Instant) -> Result<bool, SessionError> {
        let wait = self.settle_time();
        self.fill((Instant::now() + wait).min(deadline))
    }

    /// Checks what follows a complete reply that ends `from` bytes into the receive buffer,
    /// waiting as [`Wire::await_more`] does for the rest of the transmission (beyond `deadline`
    /// by at most that wait, so a reply in its last moment is checked too). Line ends and lines
    /// `benign` accepts may follow; anything else — the rest of a value a corrupted byte cut
    /// short, a second reply, a fragment — is noise. Consumes nothing.
    pub fn settle(
        &mut self,
        from: usize,
        deadline: Instant,
        benign: &mut dyn FnMut(&[u8]) -> bool,
    ) -> Result<Settled, SessionError> {
        let hard_end = deadline.max(Instant::now() + self.settle_time());
        let mut pos = from;
        loop {
            loop {
                let bytes = self.rx.bytes();
                while pos < bytes.len() && is_line_break(bytes[pos]) {
                    pos += 1;
                }
                if pos == bytes.len() {
                    break;
                }
                match self.rx.line_end(pos) {
                    Some(end) if end - pos <= MAX_LINE && benign(&self.rx.bytes()[pos..end]) => {
                        pos = end + 1;
                    }
                    Some(_) => return Ok(Settled::Noise),
                    None if self.rx.len() - pos > MAX_LINE => return Ok(Settled::Noise),
                    None => break,
                }
            }
            let partial = pos < self.rx.len();
            if Instant::now() >= hard_end {
                return Ok(if partial {
                    Settled::Noise
                } else {
                    Settled::Clean(pos)
                });
            }
            if !self.await_more(hard_end)? {
                return Ok(if partial {
                    Settled::Noise
                } else {
                    Settled::Clean(pos)
                });
            }
        }
    }

    /// How long after a reply's last byte the next one of the same transmission would arrive.
    pub fn settle_time(&self) -> Duration {
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
    pub fn resync_window(&self, timeout: Duration) -> Duration {
        let bytes = self
            .link
            .byte_time()
            .map_or(Duration::ZERO, |b| b * RESYNC_BYTES);
        timeout.min(RESYNC_MAX).max(bytes)
    }

    /// Trusts `peer` again without waiting: its late answers have all been seen.
    pub fn trust(&mut self, peer: Peer) {
        self.suspect.peers.retain(|&p| p != peer);
    }

    /// Discards everything until the line has been quiet for the resync window; fails, sending
    /// nothing, if it does not go quiet within one more timeout.
    fn resync(&mut self, timeout: Duration) -> Result<(), SessionError> {
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
            if now >= quiet_until {
                self.flush_discarded();
                self.suspect = Suspicion::default();
                return Ok(());
            }
            if now >= give_up {
                self.flush_discarded();
                self.note("the line did not go quiet");
                return Err(SessionError::Link(format!(
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
    pub fn drain(&mut self, benign: Benign) -> Result<(), SessionError> {
        let mut buf = [0u8; 4096];
        let mut read = 0;
        while read < DRAIN_BUDGET {
            match self.link.recv(&mut buf, Instant::now()) {
                Ok(n) => {
                    read += n;
                    if self.rx.extend(&buf[..n]).is_err() {
                        read = DRAIN_BUDGET;
                        self.discard_unexpected(Some(&buf[..n]));
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

    /// Consumes the first `n` buffered bytes as discarded data of `kind`, counted for the
    /// exchange's summary (the first occurrence is shown).
    pub fn discard(&mut self, n: usize, kind: &str) {
        let n = n.min(self.rx.len());
        let bytes = &self.rx.bytes()[..n];
        self.discards.count(kind, bytes);
        self.keep_discarded_from_rx(n);
    }

    /// Consumes the first `n` buffered bytes as the rest of data already counted as discarded
    /// (an overlong line whose end arrives later).
    pub fn discard_more(&mut self, n: usize) {
        let n = n.min(self.rx.len());
        self.keep_discarded_from_rx(n);
    }

    /// Consumes the first `n` buffered bytes into the transcript only: expected leftovers such
    /// as line ends, or the late answer of a request already given up.
    pub fn discard_quietly(&mut self, n: usize, meaning: impl Display) {
        let n = n.min(self.rx.len());
        if n == 0 {
            return;
        }
        self.flush_discarded();
        self.log_received(n, format_args!("{meaning}, discarded"));
    }

    fn keep_discarded_from_rx(&mut self, n: usize) {
        if self.transcript.is_some() {
            self.discarded.extend_from_slice(&self.rx.bytes()[..n]);
            if self.discarded.len() >= DISCARD_RECORD {
                self.flush_discarded();
            }
        }
        self.rx.consume(n);
    }

    fn keep_discarded(&mut self, bytes: &[u8]) {
        if self.transcript.is_some() {
            self.discarded.extend_from_slice(bytes);
            if self.discarded.len() >= DISCARD_RECORD {
                self.flush_discarded();
            }
        }
    }

    /// Writes the discarded bytes gathered so far as one record.
    fn flush_discarded(&mut self) {
        if self.discarded.is_empty() {
            return;
        }
        let bytes = std::mem::take(&mut self.discarded);
        if let Some(t) = &mut self.transcript {
            if let Err(e) = t.record(Entry::Received, &bytes, "not a reply, discarded") {
                self.close_transcript(&e);
            }
        }
        self.discarded = bytes;
        self.discarded.clear();
    }

    /// Records the first `n` bytes of the receive buffer as received and removes them.
    pub fn log_received(&mut self, n: usize, meaning: impl Display) {
        self.flush_discarded();
        if let Some(t) = &mut self.transcript {
            let n = n.min(self.rx.len());
            if let Err(e) = t.record(Entry::Received, &self.rx.bytes()[..n], meaning) {
                self.close_transcript(&e);
            }
        }
        self.rx.consume(n);
    }

    /// A remark in the transcript.
    pub fn note(&mut self, text: &str) {
        self.log(Entry::Note, b"", text);
    }

    /// Records bytes or a note; a transcript that cannot be written is closed with a notice.
    pub fn log(&mut self, entry: Entry, bytes: &[u8], meaning: impl Display) {
        self.flush_discarded();
        if let Some(t) = &mut self.transcript {
            if let Err(e) = t.record(entry, bytes, meaning) {
                self.close_transcript(&e);
            }
        }
    }

    /// Stops writing a transcript that failed, with a notice.
    fn close_transcript(&mut self, error: &std::io::Error) {
        if let Some(t) = self.transcript.take() {
            self.notices.push(format!(
                "stopped writing the transcript {}: {error}",
                t.path().display()
            ));
        }
    }

    /// Forgets what was received (a link opened anew). Suspicion stays: a device behind a
    /// reopened port may still answer what it was asked before.
    pub fn reset(&mut self) {
        self.rx.clear();
        self.discarded.clear();
    }
}

/// Asks the kernel to wake this thread at its timers' exact times: the wait for the byte after a
/// reply is about a byte time long (87 µs at 115200 baud), and the default timer slack of a Linux
/// thread (50 µs) would add half as much again to every exchange.
fn precise_timers() {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    let _ = nix::sys::prctl::set_timerslack(1);
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
struct Suspicion {
    peers: Vec<Peer>,
}

impl Suspicion {
    fn add(&mut self, peer: Peer) {
        if !self.peers.contains(&peer) {
            self.peers.push(peer);
        }
    }

    /// Whether an exchange with `peer` could take a stale answer: the peer itself is suspect, or
    /// something whose replies name no sender, or `peer` cannot tell its replies from others'.
    fn covers(&self, peer: Peer) -> bool {
        match peer {
            Peer::Any => !self.peers.is_empty(),
            module => self.peers.iter().any(|&p| p == module || p == Peer::Any),
        }
    }
}

/// When this exchange's bytes arrived: the first read, and the last with how many came after the
/// first.
#[derive(Debug, Default)]
struct Pace {
    first: Option<Instant>,
    last: Option<Instant>,
    bytes_after_first: u32,
}

impl Pace {
    fn record(&mut self, bytes: usize) {
        let now = Instant::now();
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
    fn per_byte(&self) -> Duration {
        match (self.first, self.last) {
            (Some(first), Some(last)) if self.bytes_after_first > 0 => {
                (last - first) / self.bytes_after_first
            }
            _ => Duration::ZERO,
        }
    }
}

/// What one exchange discarded, by kind.
#[derive(Debug, Default)]
struct Discards {
    kinds: Vec<Discarded>,
}

#[derive(Debug)]
struct Discarded {
    kind: String,
    times: u64,
    bytes: u64,
    first: String,
}

/// How much of a discarded line a notice shows.
const SHOWN: usize = 80;

impl Discards {
    fn count(&mut self, kind: &str, bytes: &[u8]) {
        if let Some(d) = self.kinds.iter_mut().find(|d| d.kind == kind) {
            // Counted, never shown again: one notice per kind, however long a flood goes on.
            d.times += 1;
            d.bytes += bytes.len() as u64;
            return;
        }
        let mut first = String::new();
        escape_into(&bytes[..bytes.len().min(SHOWN)], &mut first);
        if bytes.len() > SHOWN {
            first.push('…');
        }
        self.kinds.push(Discarded {
            kind: kind.to_string(),
            times: 1,
            bytes: bytes.len() as u64,
            first,
        });
    }

    fn summary(&self) -> Vec<String> {
        self.kinds
            .iter()
            .map(|d| match d.times {
                1 => format!("ignored {}: {}", d.kind, d.first),
                n => format!(
                    "ignored {} {n} times ({} bytes), the first: {}",
                    d.kind, d.bytes, d.first
                ),
            })
            .collect()
    }
}

#[cfg(test)]
mod tests;
