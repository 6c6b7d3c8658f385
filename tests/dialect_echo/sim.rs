//! The simulated loopback, a pure state machine: each line received is answered at once, with
//! the text of an echo request or with `?`.

use std::time::Duration;

use tmclsh::sim::Device;

use super::protocol::{UNKNOWN, parse};

/// The loopback: the line being received, and the answers not yet taken.
#[derive(Debug, Default)]
pub struct EchoDevice {
    line: Vec<u8>,
    output: Vec<u8>,
}

impl Device for EchoDevice {
    fn receive(&mut self, _: Duration, bytes: &[u8]) {
        for &byte in bytes {
            if byte != b'\r' && byte != b'\n' {
                self.line.push(byte);
                continue;
            }
            let line = String::from_utf8_lossy(&std::mem::take(&mut self.line)).into_owned();
            if !line.is_empty() {
                let answer = parse(&line).unwrap_or(UNKNOWN);
                self.output
                    .extend_from_slice(format!("{answer}\r\n").as_bytes());
            }
        }
    }

    fn poll_output(&mut self, _: Duration, out: &mut Vec<u8>) {
        out.append(&mut self.output);
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        (!self.output.is_empty()).then_some(now)
    }
}
