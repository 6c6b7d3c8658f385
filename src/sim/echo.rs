//! An adapter that echoes (`tmclsh sim --adapter-echo`): a 2-wire RS-485 converter without echo
//! suppression hears its own transmitter, so every byte the host sends comes back to the host,
//! before the module's answer to it. The host must strip those bytes itself (`--local-echo`).
//!
//! Wrap it outside line pacing and faults: on a 2-wire bus nothing else can be on the line
//! while the host sends, so the whole request comes back before anything the module sends (a
//! module's own character echo included), and faults judge the module's replies, not the
//! adapter. The echo comes back at once rather than at the line's pace.

use std::time::Duration;

use super::Device;

/// A device behind an adapter that hands back every byte it is sent.
pub struct AdapterEcho<D> {
    inner: D,
    /// What goes back to the host next, in order: earlier output of the device, then echoes.
    out: Vec<u8>,
}

impl<D: Device> AdapterEcho<D> {
    /// `inner` behind an echoing adapter.
    pub fn new(inner: D) -> AdapterEcho<D> {
        AdapterEcho {
            inner,
            out: Vec::new(),
        }
    }
}

impl<D: Device> Device for AdapterEcho<D> {
    pass_on!(inner: hung_up, byte_time, control);

    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        // What the device sent before these bytes goes back before their echo.
        self.inner.poll_output(now, &mut self.out);
        self.out.extend_from_slice(bytes);
        self.inner.receive(now, bytes);
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        out.append(&mut self.out);
        self.inner.poll_output(now, out);
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        if self.out.is_empty() {
            self.inner.next_due(now)
        } else {
            Some(now)
        }
    }

    fn reconnect(&mut self) {
        self.out.clear();
        self.inner.reconnect();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::tmcl::protocol::{CommandFrame, Instruction};
    use crate::dialect::tmcl::sim::Bus;

    #[test]
    fn the_request_comes_back_before_the_reply() {
        let mut device = AdapterEcho::new(Bus::builtin());
        let frame = CommandFrame {
            address: 1,
            instruction: Instruction::new(6, 4, 0, 0),
        }
        .encode();
        device.receive(Duration::ZERO, &frame);
        assert_eq!(device.next_due(Duration::ZERO), Some(Duration::ZERO));
        let mut out = Vec::new();
        device.poll_output(Duration::from_millis(10), &mut out);
        assert_eq!(out.len(), 18, "{out:?}");
        assert_eq!(out[..9], frame, "the echo first");
        assert_eq!(out[9], 2, "then the reply, from the host address");
    }
}
