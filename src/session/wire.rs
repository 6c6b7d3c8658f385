//! The byte side every dialect's session shares: the link, the receive buffer, the transcript and
//! the notices. Every byte goes through here, so every byte reaches the transcript, and every wait
//! is sliced so Ctrl-C is noticed promptly.

use std::fmt::Display;
use std::time::{Duration, Instant};

use crate::link::{Link, LinkError};

use super::rx::Rx;
use super::transcript::{Entry, Transcript};
use super::{SessionError, interrupt};

/// A link with its receive buffer, transcript and notices.
pub(crate) struct Wire {
    pub link: Box<dyn Link>,
    pub rx: Rx,
    pub transcript: Option<Transcript>,
    pub notices: Vec<String>,
    /// When the last byte was sent, for [`Wire::idle_for`].
    last_sent: Option<Instant>,
}

impl Wire {
    pub fn new(link: Box<dyn Link>, transcript: Option<Transcript>) -> Self {
        Wire {
            link,
            rx: Rx::default(),
            transcript,
            notices: Vec::new(),
            last_sent: None,
        }
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

    /// Reads what arrives before `deadline` into the receive buffer. `Ok(false)` when the
    /// deadline passed with nothing new; `Err(Interrupted)` on Ctrl-C.
    pub fn fill(&mut self, deadline: Instant) -> Result<bool, SessionError> {
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
    pub fn drain(&mut self) -> Result<(), SessionError> {
        let mut buf = [0u8; 512];
        loop {
            match self.link.recv(&mut buf, Instant::now()) {
                Ok(n) => self.rx.extend(&buf[..n]),
                Err(LinkError::Timeout) => break,
                Err(e) => return Err(e.into()),
            }
        }
        let stale = self.rx.bytes();
        if stale.iter().any(|b| !matches!(b, b'\r' | b'\n' | 0)) {
            self.log_received(stale.len(), "arrived outside any exchange, discarded");
        }
        self.rx.consume(self.rx.len());
        Ok(())
    }

    /// Records the first `n` bytes of the receive buffer as received and removes them.
    pub fn log_received(&mut self, n: usize, meaning: impl Display) {
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
}
