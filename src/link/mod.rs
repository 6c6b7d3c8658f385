//! Links: the byte pipes between tmclsh and a module — a serial port, a TCP socket, or the
//! built-in simulator in-process. Small on purpose: send, receive before a deadline (a deadline
//! already past takes what has arrived, which is how stale input is drained), describe, reopen
//! after the link was lost, and the line's state (`line/`: what a real serial line adds).

pub mod can;
#[cfg(unix)]
mod fd;
pub mod line;
mod serial;
mod tcp;

use std::io;
use std::time::Instant;

pub use line::{LineOptions, LineState};
pub use serial::{Resolve, SerialLink};
pub use tcp::TcpLink;

/// Why a link operation failed.
#[derive(Debug, thiserror::Error)]
pub enum LinkError {
    /// Nothing arrived before the deadline.
    #[error("timed out")]
    Timeout,
    /// The other end is gone (USB unplugged, TCP peer closed, simulator exited).
    #[error("link lost: {0}")]
    Lost(String),
    /// The link could not be opened.
    #[error("{0}")]
    Open(String),
    /// A CAN adapter reported an error of its own (slcan's BEL: a refused command or frame, a
    /// bus gone off).
    #[error("{0}")]
    Adapter(String),
}

impl LinkError {
    /// Classifies an I/O error: time-outs stay time-outs, and so does a wait cut short by a
    /// signal (Ctrl-C: the caller checks the interrupt flag and its deadline, then waits again);
    /// everything else means the link is gone.
    pub fn from_io(error: io::Error) -> LinkError {
        match error.kind() {
            io::ErrorKind::TimedOut | io::ErrorKind::WouldBlock | io::ErrorKind::Interrupted => {
                LinkError::Timeout
            }
            _ => LinkError::Lost(error.to_string()),
        }
    }

    /// A system call on a line that failed: the link is gone, whatever the error.
    pub(crate) fn from_os(error: io::Error) -> LinkError {
        LinkError::Lost(error.to_string())
    }
}

/// Every way a link fails leaves unknown what the module did.
impl crate::exit::ExitStatus for LinkError {
    fn exit(&self) -> crate::exit::Exit {
        crate::exit::Exit::Link
    }
}

/// A bidirectional byte link to one bus of modules.
pub trait Link: Send {
    /// Writes all of `bytes`.
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError>;

    /// Waits until at least one byte arrives or `deadline` passes; returns the number of bytes
    /// read into `buf` (never 0), or [`LinkError::Timeout`]. A deadline already past still
    /// returns bytes that have arrived, without waiting.
    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError>;

    /// What the link talks to, for banners and messages ("serial /dev/ttyUSB0 at 9600 baud").
    fn describe(&self) -> String;

    /// Opens the link again after it was lost. The default cannot.
    fn reopen(&mut self) -> Result<(), LinkError> {
        Err(LinkError::Open(format!(
            "{} cannot be reopened",
            self.describe()
        )))
    }

    /// Closes the link after it was found lost, so the port is not held while it is away (the
    /// next [`reopen`](Self::reopen) opens it again). The default keeps it.
    fn close(&mut self) {}

    /// A descriptor of the open link to watch while nobody talks on it (the REPL's prompt):
    /// poll(2) on it with no events asked for reports only a hang-up or an error, so the link's
    /// loss is seen without a byte read. `None` where the link has none to watch.
    #[cfg(unix)]
    fn watch(&self) -> Option<std::os::fd::OwnedFd> {
        None
    }

    /// Whether nothing but this session can be on the line (the in-process simulator): then no
    /// byte another program or module sent before it opened can sit in a module's receiver, and
    /// the first frame needs no quiet line before it. Serial ports and TCP bridges are shared.
    fn private(&self) -> bool {
        false
    }

    /// Seconds per byte on the wire, where the link knows it (serial: 10 bits per byte).
    fn byte_time(&self) -> Option<std::time::Duration> {
        None
    }

    /// Whether a [`recv`](Self::recv) that returns fewer bytes than `buf` holds took everything
    /// that had arrived (a read(2) of a port or socket does; a link that hands over one frame
    /// at a time does not): then what follows a reply that came in one burst is already known
    /// from that read, and no look of its own is made for it.
    fn reads_all(&self) -> bool {
        false
    }

    /// Whether the link carries only whole binary frames (CAN): a dialect with a text mode
    /// never enters it there.
    fn frames_only(&self) -> bool {
        false
    }

    /// The state of the line for `:line`: rate, modem lines, latency timer, byte counts, the
    /// driver's error counters — what the link has of them. The default knows nothing.
    fn line_state(&mut self) -> LineState {
        LineState::default()
    }
}

#[cfg(test)]
mod tests {
    use std::io;

    use super::LinkError;

    #[test]
    fn a_signal_during_a_wait_is_not_a_lost_link() {
        let kind = |k: io::ErrorKind| LinkError::from_io(io::Error::from(k));
        assert!(matches!(
            kind(io::ErrorKind::Interrupted),
            LinkError::Timeout
        ));
        assert!(matches!(
            kind(io::ErrorKind::WouldBlock),
            LinkError::Timeout
        ));
        assert!(matches!(kind(io::ErrorKind::TimedOut), LinkError::Timeout));
        assert!(matches!(
            kind(io::ErrorKind::ConnectionReset),
            LinkError::Lost(_)
        ));
    }
}
