//! Line pacing (`tmclsh sim --baud N`): bytes take the time a serial line needs, 10 bits per
//! byte (8N1) in each direction, so a user sees how long a script takes on the bench. Input
//! reaches the device byte by byte as each byte has fully arrived; output becomes visible byte by
//! byte at its wire time. The two directions are independent (full duplex, as RS-232).

use std::collections::VecDeque;
use std::time::Duration;

use super::Device;
use super::error::ConsoleError;

/// A device behind a serial line of a given baud rate.
pub struct Paced<D> {
    inner: D,
    baud: u64,
    /// Bytes on their way in, with their arrival times.
    incoming: VecDeque<(Duration, u8)>,
    /// Bytes on their way out, with the times they are complete at the host.
    outgoing: VecDeque<(Duration, u8)>,
    in_free: Duration,
    out_free: Duration,
    /// The time the inner device has been driven to.
    inner_now: Duration,
    scratch: Vec<u8>,
}

impl<D: Device> Paced<D> {
    /// Paces `inner` at `baud` bits per second (at least 1).
    pub fn new(mut inner: D, baud: u32) -> Paced<D> {
        let baud = u64::from(baud.max(1));
        inner.byte_time(Duration::from_nanos(10 * 1_000_000_000 / baud));
        Paced {
            inner,
            baud,
            incoming: VecDeque::new(),
            outgoing: VecDeque::new(),
            in_free: Duration::ZERO,
            out_free: Duration::ZERO,
            inner_now: Duration::ZERO,
            scratch: Vec::new(),
        }
    }

    /// Wire time of `bytes` bytes.
    pub fn wire_time(&self, bytes: u64) -> Duration {
        Duration::from_nanos(bytes * 10 * 1_000_000_000 / self.baud)
    }

    /// Queues what the inner device sent at `t` for the outgoing line.
    fn collect(&mut self, t: Duration) {
        self.inner.poll_output(t, &mut self.scratch);
        if self.scratch.is_empty() {
            return;
        }
        let start = self.out_free.max(t);
        for (i, &byte) in self.scratch.iter().enumerate() {
            self.outgoing
                .push_back((start + self.wire_time(i as u64 + 1), byte));
        }
        self.out_free = start + self.wire_time(self.scratch.len() as u64);
        self.scratch.clear();
    }

    /// Delivers arrived input and collects output, in time order, up to `now`.
    fn run(&mut self, now: Duration) {
        loop {
            let arrival = self.incoming.front().map(|&(t, _)| t);
            let due = self.inner.next_due(self.inner_now);
            let next = match (arrival, due) {
                (Some(a), Some(d)) => a.min(d),
                (a, d) => match a.or(d) {
                    Some(n) => n,
                    None => break,
                },
            };
            if next > now {
                break;
            }
            let t = next.max(self.inner_now);
            self.inner_now = t;
            let mut progressed = false;
            while let Some(&(at, byte)) = self.incoming.front() {
                if at > t {
                    break;
                }
                self.incoming.pop_front();
                self.inner.receive(t, &[byte]);
                progressed = true;
            }
            let queued = self.outgoing.len();
            self.collect(t);
            if !progressed && self.outgoing.len() == queued {
                break; // due but nothing came: the device will say so again later
            }
        }
        self.inner_now = self.inner_now.max(now);
        self.collect(self.inner_now);
    }
}

impl<D: Device> Device for Paced<D> {
    pass_on!(inner: hung_up);

    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        let start = self.in_free.max(now);
        for (i, &byte) in bytes.iter().enumerate() {
            self.incoming
                .push_back((start + self.wire_time(i as u64 + 1), byte));
        }
        self.in_free = start + self.wire_time(bytes.len() as u64);
        self.run(now);
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        self.run(now);
        while let Some(&(at, byte)) = self.outgoing.front() {
            if at > now {
                break;
            }
            self.outgoing.pop_front();
            out.push(byte);
        }
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        [
            self.outgoing.front().map(|&(t, _)| t),
            self.incoming.front().map(|&(t, _)| t),
            self.inner.next_due(self.inner_now.max(now)),
        ]
        .into_iter()
        .flatten()
        .min()
    }

    fn reconnect(&mut self) {
        self.incoming.clear();
        self.outgoing.clear();
        self.inner.reconnect();
    }

    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        self.run(now);
        self.inner.control(now, command)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::tmcl::protocol::{CommandFrame, Instruction};
    use crate::dialect::tmcl::sim::Bus;

    fn ms(x: f64) -> Duration {
        Duration::from_secs_f64(x / 1000.0)
    }

    #[test]
    fn a_frame_and_its_reply_take_their_wire_time() {
        // 9600 baud: 10 bits per byte = 1.0417 ms; 9 bytes in = 9.375 ms, 9 out = 18.75 ms.
        let mut line = Paced::new(Bus::builtin(), 9600);
        let frame = CommandFrame {
            address: 1,
            instruction: Instruction::new(6, 4, 0, 0),
        };
        line.receive(Duration::ZERO, &frame.encode());
        assert_eq!(line.next_due(Duration::ZERO), Some(line.wire_time(1)));
        let byte = 10.0 / 9600.0 * 1000.0;
        let mut out = Vec::new();
        line.poll_output(ms(9.0 * byte - 0.001), &mut out);
        assert!(out.is_empty(), "the request has not fully arrived");
        line.poll_output(ms(10.0 * byte - 0.001), &mut out);
        assert!(out.is_empty(), "the first reply byte is still on the wire");
        line.poll_output(ms(10.0 * byte + 0.001), &mut out);
        assert_eq!(out.len(), 1);
        line.poll_output(ms(18.0 * byte - 0.001), &mut out);
        assert_eq!(out.len(), 8);
        assert_eq!(line.next_due(ms(18.0 * byte)), Some(line.wire_time(18)));
        line.poll_output(line.wire_time(18), &mut out);
        assert_eq!(out.len(), 9);
        assert_eq!(out[2], 100, "status of the GAP reply");
    }

    #[test]
    fn back_to_back_sends_queue_on_the_line() {
        let mut line = Paced::new(Bus::builtin(), 115_200);
        let frame = CommandFrame {
            address: 1,
            instruction: Instruction::new(6, 4, 0, 0),
        }
        .encode();
        line.receive(Duration::ZERO, &frame);
        line.receive(Duration::ZERO, &frame);
        let mut out = Vec::new();
        // The second request arrives after 18 byte times; its reply ends 9 byte times later.
        line.poll_output(line.wire_time(27) - Duration::from_nanos(1), &mut out);
        assert_eq!(out.len(), 17);
        line.poll_output(line.wire_time(27), &mut out);
        assert_eq!(out.len(), 18);
    }
}
