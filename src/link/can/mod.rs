//! CAN links: a bus of frames ([`CanBus`]: an slcan adapter on a serial line, SocketCAN on
//! Linux) carried as a byte [`Link`] by a dialect's [`Framer`], so every session above it is the
//! one it has on a serial line. The framer is the dialect's (TMCL: §6.1/§6.2 of the module
//! manuals); this layer only moves frames.

pub mod frame;
pub mod slcan;
mod slcan_link;
#[cfg(target_os = "linux")]
pub mod socketcan;

use std::collections::VecDeque;
use std::time::Instant;

pub use frame::CanFrame;
pub use slcan_link::SlcanLink;
#[cfg(target_os = "linux")]
pub use socketcan::SocketCanLink;

use super::{LineState, Link, LinkError};

/// A CAN bus the host takes part in: frames out, frames in before a deadline.
pub trait CanBus: Send {
    /// Queues `frame` for the bus.
    fn send_frame(&mut self, frame: &CanFrame) -> Result<(), LinkError>;

    /// The next frame from the bus, waiting until `deadline` (a deadline past takes only what
    /// has arrived).
    fn recv_frame(&mut self, deadline: Instant) -> Result<CanFrame, LinkError>;

    /// What the bus is reached through ("slcan /dev/ttyACM0 at 1000000 bit/s").
    fn describe(&self) -> String;

    /// Opens the adapter again after it was lost.
    fn reopen(&mut self) -> Result<(), LinkError> {
        Err(LinkError::Open(format!(
            "{} cannot be reopened",
            self.describe()
        )))
    }

    /// Closes the adapter after it was found lost.
    fn close(&mut self) {}

    /// A descriptor to watch for the adapter's loss (see [`Link::watch`]).
    #[cfg(unix)]
    fn watch(&self) -> Option<std::os::fd::OwnedFd> {
        None
    }

    /// What the adapter says of itself for `:line`.
    fn notes(&self) -> Vec<String> {
        Vec::new()
    }

    /// Whether [`frame_at_hand`](Self::frame_at_hand) knows every frame that has arrived (an
    /// adapter on a line whose reads take everything there is): then the link above reads all
    /// too, and what follows a reply needs no look of its own.
    fn reads_all(&self) -> bool {
        false
    }

    /// A frame that has already arrived, taken without waiting and, where the last read took
    /// everything there was, without reading again; `None` when there is none. An adapter's
    /// error found meanwhile stays for the next [`recv_frame`](Self::recv_frame), as if it came
    /// a moment later.
    fn frame_at_hand(&mut self) -> Result<Option<CanFrame>, LinkError> {
        Ok(None)
    }
}

/// A dialect's mapping between its byte frames and CAN frames.
pub trait Framer: Send {
    /// The CAN frames for bytes the session sends (bytes that complete no frame yet wait).
    fn frames(&mut self, bytes: &[u8]) -> Vec<CanFrame>;

    /// The bytes a frame from the bus stands for, or `None` for a frame not meant for the host
    /// (another node's, another master's): it is ignored and counted.
    fn bytes(&mut self, frame: &CanFrame) -> Option<Vec<u8>>;

    /// The ids the framer uses, for messages ("CAN ID 1, reply ID 2").
    fn describe(&self) -> String;
}

/// A CAN bus seen as a byte link through a framer.
pub struct CanLink {
    bus: Box<dyn CanBus>,
    framer: Box<dyn Framer>,
    pending: VecDeque<u8>,
    foreign: u64,
    frames_out: u64,
    frames_in: u64,
}

impl CanLink {
    /// Carries the framer's bytes over `bus`.
    pub fn new(bus: Box<dyn CanBus>, framer: Box<dyn Framer>) -> CanLink {
        CanLink {
            bus,
            framer,
            pending: VecDeque::new(),
            foreign: 0,
            frames_out: 0,
            frames_in: 0,
        }
    }

    /// Takes a frame from the bus: its bytes, or one more foreign frame.
    fn take(&mut self, frame: &CanFrame) {
        self.frames_in += 1;
        match self.framer.bytes(frame) {
            Some(bytes) => self.pending.extend(bytes),
            None => self.foreign += 1,
        }
    }

    /// Frames from the bus not meant for the host, ignored so far.
    pub fn foreign_frames(&self) -> u64 {
        self.foreign
    }
}

impl Link for CanLink {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        for frame in self.framer.frames(bytes) {
            self.bus.send_frame(&frame)?;
            self.frames_out += 1;
        }
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        while self.pending.is_empty() {
            let frame = self.bus.recv_frame(deadline)?;
            self.take(&frame);
        }
        // Every frame already at hand comes along, so a read shorter than `buf` took all. A
        // line lost meanwhile is found again by the next read; these bytes go up first.
        if self.bus.reads_all() {
            while let Ok(Some(frame)) = self.bus.frame_at_hand() {
                self.take(&frame);
            }
        }
        let n = buf.len().min(self.pending.len());
        for (slot, byte) in buf.iter_mut().zip(self.pending.drain(..n)) {
            *slot = byte;
        }
        Ok(n)
    }

    fn describe(&self) -> String {
        format!("{}, {}", self.bus.describe(), self.framer.describe())
    }

    fn reopen(&mut self) -> Result<(), LinkError> {
        self.pending.clear();
        self.bus.reopen()
    }

    fn close(&mut self) {
        self.bus.close()
    }

    #[cfg(unix)]
    fn watch(&self) -> Option<std::os::fd::OwnedFd> {
        self.bus.watch()
    }

    fn frames_only(&self) -> bool {
        true
    }

    fn reads_all(&self) -> bool {
        self.bus.reads_all()
    }

    fn line_state(&mut self) -> LineState {
        let mut notes = self.bus.notes();
        notes.push(format!(
            "{} frames sent, {} received, {} not for the host ignored",
            self.frames_out, self.frames_in, self.foreign
        ));
        LineState {
            notes,
            ..LineState::default()
        }
    }
}

#[cfg(test)]
mod tests;
