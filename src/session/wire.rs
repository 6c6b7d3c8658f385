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
//!   timeout up to a second, at least 32 byte times), bounded by one more timeout
//!   if the line never goes quiet. A clean line costs nothing: no exchange waits unless one
//!   failed. (With an echo, a peer whose late answers have all been seen is trusted at once.)
//!   A quiet line does not prove that no late answer is still coming: where replies do not name
//!   their request, the dialects put a barrier on the line before the next request that could
//!   take one (`dialect/tmcl/session/barrier.rs`, `dialect/smd4/session/barrier.rs`).
//! - A complete reply is trusted only once the bytes right after it have been seen: a reply cut
//!   short by a corrupted byte, or glued to more data, is line noise. The wait for them
//!   ([`Wire::await_more`]) follows the pace at which this reply's bytes arrived, so a link that
//!   delivers whole replies at once pays nothing: the read that took the burst took all there
//!   was (a link that [`reads_all`](crate::link::Link::reads_all)), or else a look.
//! - Whatever is discarded is counted and summarised in one notice per kind and exchange.

mod discard;
mod echo;
mod pace;
mod tally;
mod trust;

use std::fmt::Display;
use std::time::{Duration, Instant};

use crate::link::{Link, LinkError};

use super::rx::Rx;
use super::transcript::{Entry, Transcript};
use super::{SessionError, interrupt};

use discard::Discards;
use echo::{Echo, Taken};
use pace::Pace;
pub(crate) use tally::Tally;
use trust::Suspicion;
pub(crate) use trust::{Benign, Harmless, Settled, nothing_benign};

/// Who an exchange talks to, as far as replies tell: a module or drive whose replies carry its
/// address, or anyone (replies that name no sender).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Peer {
    /// Replies do not say who sent them.
    Any,
    /// Replies carry this address.
    Module(u32),
}

/// A partial line longer than this cannot be a reply or an echo of either dialect: it is dropped
/// as noise instead of being kept until its line end comes.
pub(crate) const MAX_LINE: usize = 1024;

/// How much longer than the gap asked for [`Wire::idle_for`] waits for a quiet line before it
/// says something else talks on it.
pub(crate) const QUIET_BOUND: Duration = Duration::from_secs(2);

/// A link with its receive buffer, transcript, notices and trust.
pub(crate) struct Wire {
    pub link: Box<dyn Link>,
    pub rx: Rx,
    pub transcript: Option<Transcript>,
    pub notices: Vec<String>,
    /// When the last byte was sent, for [`Wire::idle_for`].
    last_sent: Option<Instant>,
    /// When bytes last arrived, for [`Wire::idle_for`]: on a bus every module hears the
    /// others' replies too.
    last_heard: Option<Instant>,
    /// When a shared line was opened (none for a private one, the in-process simulator): the
    /// first quiet gap counts from here, since what another program or module sent just before
    /// cannot be known.
    opened: Option<Instant>,
    /// Peers whose answers may still be on the way.
    suspect: Suspicion,
    /// The peer of the exchange in progress.
    in_flight: Option<Peer>,
    discards: Discards,
    /// Discarded bytes not yet written to the transcript.
    discarded: Vec<u8>,
    pace: Pace,
    /// The last read since the last send took everything that had arrived (a link that
    /// [`reads_all`](Link::reads_all), a read shorter than its buffer).
    took_all: bool,
    /// Requests and replies counted, for `:line`.
    pub tally: Tally,
    /// The adapter's echo of what was sent, stripped (`--local-echo`).
    echo: Echo,
    /// The buffer of [`Wire::fill`] and the drain between exchanges, reused.
    scratch: Vec<u8>,
    /// When the wire was made: a deadline already past, for a read that only looks (the drain
    /// between exchanges) without reading the clock.
    made: Instant,
    /// When the last send went out, until the next read takes it as the start of its first
    /// wait slice instead of reading the clock again.
    just_sent: Option<Instant>,
}

/// How much one read of the link takes at most.
const READ_SIZE: usize = 4096;

impl Wire {
    /// How long `bytes` take on the line at its bit rate; nothing on a link without one (TCP,
    /// the in-process simulator).
    pub(crate) fn wire_time(&self, bytes: u32) -> Duration {
        self.link.byte_time().map_or(Duration::ZERO, |b| b * bytes)
    }

    pub(crate) fn new(mut link: Box<dyn Link>, transcript: Option<Transcript>) -> Self {
        precise_timers();
        let state = link.line_state();
        let tally = Tally::new(&state);
        let opened = (!link.private()).then(Instant::now);
        let mut wire = Wire {
            tally,
            link,
            rx: Rx::default(),
            transcript,
            notices: Vec::new(),
            last_sent: None,
            last_heard: None,
            opened,
            suspect: Suspicion::default(),
            in_flight: None,
            discards: Discards::default(),
            discarded: Vec::new(),
            pace: Pace::default(),
            took_all: false,
            echo: Echo::default(),
            scratch: Vec::new(),
            made: Instant::now(),
            just_sent: None,
        };
        // What the line said of itself on opening (a latency timer left high, modem lines a
        // port lacks) belongs in the transcript too: a log shared later explains itself.
        for note in &state.notes {
            wire.note(note);
        }
        wire
    }

    /// Sets whether the adapter echoes what is sent: yes, no, or to be found out at open.
    pub(crate) fn set_local_echo(&mut self, mode: super::LocalEcho) {
        self.echo = Echo::new(mode);
    }

    /// Starts an exchange with `peer`: takes what arrived since the last one (anything but line
    /// ends and `benign` data makes the line suspect), and unless `urgent` (a stop that must go
    /// out now) resynchronises first when the peer is suspect.
    pub(crate) fn begin(
        &mut self,
        peer: Peer,
        urgent: bool,
        timeout: Duration,
        benign: Benign,
    ) -> Result<(), SessionError> {
        self.in_flight = None;
        self.just_sent = None;
        self.drain(benign)?;
        if !urgent && self.suspect.covers(peer) {
            self.resync(timeout)?;
        }
        self.pace = Pace::default();
        self.in_flight = Some(peer);
        self.tally.requests += 1;
        Ok(())
    }

    /// Ends the exchange started by [`Wire::begin`]: a failed one leaves its peer suspect; what
    /// was discarded becomes one notice per kind.
    pub(crate) fn finish(&mut self, ok: bool) {
        self.just_sent = None;
        match (self.in_flight.take(), ok) {
            (Some(peer), false) => {
                self.suspect.add(peer);
                if let Some(notice) = self.tally.failed(self.link.as_mut()) {
                    self.notices.push(notice);
                }
            }
            (Some(_), true) => self.tally.replies += 1,
            (None, _) => {}
        }
        self.flush_discarded();
        let summary = self.discards.summary();
        self.notices.extend(summary);
        self.discards = Discards::default();
    }

    /// Writes bytes to the link and the transcript; returns when they went out, from which an
    /// exchange counts its time-out. The meaning is formatted only when a transcript is being
    /// written (pass `format_args!`), so it costs nothing otherwise.
    pub(crate) fn send(
        &mut self,
        bytes: &[u8],
        meaning: impl Display,
    ) -> Result<Instant, SessionError> {
        self.log(Entry::Sent, bytes, meaning);
        self.took_all = false;
        self.link.send(bytes).map_err(SessionError::from)?;
        let sent = Instant::now();
        self.last_sent = Some(sent);
        self.just_sent = Some(sent);
        self.sent_for_echo(bytes);
        Ok(sent)
    }

    /// Keeps the line idle until nothing was sent or heard on it for `gap` (a module in binary
    /// mode hears the replies of the others on its bus as well as our lines), counting from the
    /// opening of a shared line when nothing passed yet. Binary receivers on a bus find the start
    /// of a frame only after such a pause (a UART time-out), so this is needed before the first
    /// binary frame to a module that may have seen other traffic; it is a rule of the line, not a
    /// guessed reply delay. It reads while it waits — what arrives (a reply another program left
    /// unread, another module's chatter) stays in the receive buffer for the caller to drain and
    /// starts the gap again — and gives up when the line never falls quiet within
    /// [`QUIET_BOUND`]. Ctrl-C interrupts it.
    pub(crate) fn idle_for(&mut self, gap: Duration) -> Result<(), SessionError> {
        let started = Instant::now();
        let bound = started + gap + QUIET_BOUND;
        loop {
            let Some(last) = self.last_sent.max(self.last_heard).max(self.opened) else {
                return Ok(());
            };
            let until = last + gap;
            let now = Instant::now();
            // A stall of this thread is not silence: what arrived meanwhile is read first.
            if now >= until && !self.fill(now)? {
                return Ok(());
            }
            if now >= until {
                continue;
            }
            if Instant::now() >= bound {
                let message = format!(
                    "the line did not fall quiet for {} ms within {} ms: something else talks on \
                     it (another program on the port, a module sending on its own)",
                    gap.as_millis(),
                    (gap + QUIET_BOUND).as_millis()
                );
                self.note(&message);
                return Err(SessionError::Link(message));
            }
            self.fill(until.min(bound))?;
        }
    }

    /// Reads what arrives before `until` into the receive buffer: `Ok(false)` when `until`
    /// passed with nothing new (an `until` already past still takes what has arrived);
    /// `Err(Interrupted)` on Ctrl-C. Callers bound their loops with their own deadline, so a
    /// line that never stops talking cannot keep them.
    pub(crate) fn fill(&mut self, until: Instant) -> Result<bool, SessionError> {
        let mut buf = self.take_scratch();
        let result = self.fill_from(until, &mut buf);
        self.scratch = buf;
        result
    }

    /// The buffer reads go through, kept between them: a transaction clears no 4 KiB of stack.
    fn take_scratch(&mut self) -> Vec<u8> {
        let mut buf = std::mem::take(&mut self.scratch);
        buf.resize(READ_SIZE, 0);
        buf
    }

    fn fill_from(&mut self, until: Instant, buf: &mut [u8]) -> Result<bool, SessionError> {
        loop {
            if interrupt::pending() {
                return Err(SessionError::Interrupted);
            }
            // A slice from the send just made is a little shorter than one from now, never
            // longer; later slices start from the clock.
            let start = self.just_sent.take().unwrap_or_else(Instant::now);
            let slice_end = until.min(start + interrupt::SLICE);
            match self.link.recv(buf, slice_end) {
                Ok(n) => {
                    let heard = Instant::now();
                    self.pace.record(n, heard);
                    self.took_all = n < buf.len() && self.link.reads_all();
                    self.last_heard = Some(heard);
                    let before = self.rx.len();
                    let taken = self.take_in(&buf[..n])?;
                    if matches!(taken, Taken::Kept) && self.rx.len() == before {
                        continue; // only the adapter's echo: nothing new yet
                    }
                    if let Taken::Overflow = taken {
                        let held = self.rx.clear();
                        self.log(Entry::Received, &held, "receive buffer full, discarded");
                        self.log(Entry::Received, &buf[..n], "receive buffer full, discarded");
                        self.note("line noise: 64 KiB arrived without a usable line");
                        return Err(SessionError::noise(
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

    /// When bytes last arrived (the last read that took any).
    pub(crate) fn heard_at(&self) -> Option<Instant> {
        self.last_heard
    }

    /// Whether anything at all has come from the line since it was opened: a session that
    /// heard nothing may be talking the wrong protocol.
    pub(crate) fn heard_anything(&self) -> bool {
        self.last_heard.is_some()
    }

    /// Records the first `n` bytes of the receive buffer as received and removes them.
    pub(crate) fn log_received(&mut self, n: usize, meaning: impl Display) {
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
    pub(crate) fn note(&mut self, text: &str) {
        self.log(Entry::Note, b"", text);
    }

    /// Records bytes or a note; a transcript that cannot be written is closed with a notice.
    pub(crate) fn log(&mut self, entry: Entry, bytes: &[u8], meaning: impl Display) {
        self.flush_discarded();
        if let Some(t) = &mut self.transcript {
            if let Err(e) = t.record(entry, bytes, meaning) {
                self.close_transcript(&e);
            }
        }
    }

    /// Says that the transcript failed. It stays attached, so the faces can see its
    /// [`Transcript::failure`] and end a run that asked for it; it records nothing more.
    fn close_transcript(&mut self, error: &std::io::Error) {
        if let Some(t) = &self.transcript {
            self.notices.push(format!(
                "cannot write the transcript {}: {error}; nothing more is recorded",
                t.path().display()
            ));
        }
    }

    /// Forgets what was received (a link opened anew). Suspicion stays: a device behind a
    /// reopened port may still answer what it was asked before.
    pub(crate) fn reset(&mut self) {
        if self.opened.is_some() {
            self.opened = Some(Instant::now());
        }
        self.rx.clear();
        self.took_all = false;
        self.reset_echo();
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

#[cfg(test)]
mod tests;
