//! An FTDI adapter's latency timer (`tmclsh sim --latency MS`): the chip holds the bytes it
//! received from the line until its timer runs out or a USB packet is full, so a host that
//! leaves the timer at its default (16 ms) waits up to 16 ms for every reply. The simulator holds
//! what it sends the same way, so the cost can be seen, measured and explained without the
//! hardware.

use std::time::Duration;

use super::Device;

/// Bytes an FTDI chip sends in one USB packet before it stops waiting: 64 less its 2 status
/// bytes (FTDI AN232B-04, "Data throughput, latency and handshaking").
pub const PACKET: usize = 62;

/// A device behind a latency timer of a given length.
pub struct Latency<D> {
    inner: D,
    timer: Duration,
    /// Bytes held, and when the first of them arrived (the timer runs from there).
    held: Vec<u8>,
    since: Option<Duration>,
}

impl<D: Device> Latency<D> {
    /// Holds `inner`'s output for `timer` (or until [`PACKET`] bytes wait).
    pub fn new(inner: D, timer: Duration) -> Latency<D> {
        Latency {
            inner,
            timer,
            held: Vec::new(),
            since: None,
        }
    }

    /// Collects the inner device's output up to `now`.
    fn collect(&mut self, now: Duration) {
        let before = self.held.len();
        self.inner.poll_output(now, &mut self.held);
        if before == 0 && !self.held.is_empty() {
            self.since = Some(now);
        }
    }

    fn due(&self) -> Option<Duration> {
        self.since.map(|since| since + self.timer)
    }
}

impl<D: Device> Device for Latency<D> {
    pass_on!(inner: hung_up, byte_time, control);

    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        self.collect(now);
        self.inner.receive(now, bytes);
        self.collect(now);
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        self.collect(now);
        // Full packets leave at once; the rest when the timer runs out.
        while self.held.len() >= PACKET {
            out.extend(self.held.drain(..PACKET));
        }
        if self.held.is_empty() {
            self.since = None;
        } else if self.due().is_some_and(|due| due <= now) {
            out.append(&mut self.held);
            self.since = None;
        } else if self.since.is_none() {
            self.since = Some(now);
        }
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        [self.due(), self.inner.next_due(now)]
            .into_iter()
            .flatten()
            .min()
    }

    fn reconnect(&mut self) {
        self.held.clear();
        self.since = None;
        self.inner.reconnect();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::tmcl::protocol::{CommandFrame, Instruction};
    use crate::dialect::tmcl::sim::Bus;

    fn gap(address: u8) -> Vec<u8> {
        CommandFrame {
            address,
            instruction: Instruction::new(6, 4, 0, 0),
        }
        .encode()
        .to_vec()
    }

    #[test]
    fn a_reply_waits_for_the_timer() {
        let timer = Duration::from_millis(16);
        let mut line = Latency::new(Bus::builtin(), timer);
        line.receive(Duration::ZERO, &gap(1));
        let mut out = Vec::new();
        line.poll_output(Duration::ZERO, &mut out);
        assert!(out.is_empty(), "held by the timer");
        assert_eq!(line.next_due(Duration::ZERO), Some(timer));
        line.poll_output(timer - Duration::from_micros(1), &mut out);
        assert!(out.is_empty());
        line.poll_output(timer, &mut out);
        assert_eq!(out.len(), 9, "the whole reply when the timer runs out");
        assert_eq!(line.next_due(timer), None);
    }

    #[test]
    fn a_full_packet_leaves_at_once() {
        let mut line = Latency::new(Bus::builtin(), Duration::from_millis(16));
        // Seven replies: 63 bytes, one packet of 62 at once, one byte held.
        let requests: Vec<u8> = (0..7).flat_map(|_| gap(1)).collect();
        line.receive(Duration::ZERO, &requests);
        let mut out = Vec::new();
        line.poll_output(Duration::ZERO, &mut out);
        assert_eq!(out.len(), PACKET);
        line.poll_output(Duration::from_millis(16), &mut out);
        assert_eq!(out.len(), 63);
    }
}
