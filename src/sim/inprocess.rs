//! The simulator in-process, behind the [`Link`] trait: sending hands bytes to the device at the
//! clock's time, receiving waits on the clock until the device has output or the deadline
//! passes. There are no threads: with a [`crate::clock::ManualClock`] waiting is instant and
//! deterministic; with the system clock it is a real wait for real output.

use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use crate::link::{Link, LinkError};

use super::Device;
use super::error::ConsoleError;
use crate::clock::Clock;

/// A device shared between a link and whoever inspects it (tests, the console).
pub type SharedDevice = Arc<Mutex<dyn Device>>;

/// A link to a simulated device in this process.
pub struct SimLink {
    device: SharedDevice,
    clock: Arc<dyn Clock>,
    /// Output taken from the device but not yet returned (the caller's buffer was full).
    pending: Vec<u8>,
    name: String,
}

/// The shortest wait when the device said output was due but produced none (no busy loop).
const NUDGE: Duration = Duration::from_micros(1);

impl SimLink {
    /// A link owning `device`.
    pub fn new(device: Box<dyn Device>, clock: Arc<dyn Clock>) -> SimLink {
        SimLink::shared(Arc::new(Mutex::new(device)), clock)
    }

    /// A link to a device others hold too (keep an `Arc<Mutex<Bus>>` to reach the bus typed).
    pub fn shared(device: SharedDevice, clock: Arc<dyn Clock>) -> SimLink {
        SimLink {
            device,
            clock,
            pending: Vec::new(),
            name: "simulated module (in-process)".into(),
        }
    }

    /// Sets what [`Link::describe`] says.
    pub fn named(mut self, name: impl Into<String>) -> SimLink {
        self.name = name.into();
        self
    }

    /// Runs `f` on the device at the current time (set inputs, inspect motion).
    pub fn with_device<R>(&self, f: impl FnOnce(&mut dyn Device, Duration) -> R) -> R {
        let now = self.clock.now();
        let mut device = self.lock();
        f(&mut *device, now)
    }

    /// Runs a control command on the device (see the `tmclsh sim` console).
    pub fn control(&self, command: &str) -> Result<String, ConsoleError> {
        self.with_device(|device, now| device.control(now, command))
            .unwrap_or_else(|| Err(ConsoleError::Unknown(command.to_string())))
    }

    fn lock(&self) -> MutexGuard<'_, dyn Device + 'static> {
        // A panic elsewhere must not make the simulator unusable for the rest of a test run.
        self.device.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn take(&mut self, buf: &mut [u8]) -> usize {
        let n = buf.len().min(self.pending.len());
        buf[..n].copy_from_slice(&self.pending[..n]);
        self.pending.drain(..n);
        n
    }
}

impl Link for SimLink {
    fn private(&self) -> bool {
        true
    }

    /// A read takes all the output due by now.
    fn reads_all(&self) -> bool {
        true
    }

    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        let now = self.clock.now();
        let mut device = self.lock();
        if device.hung_up() {
            return Err(LinkError::Lost("the simulator hung up".into()));
        }
        device.receive(now, bytes);
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        if buf.is_empty() {
            return Ok(0);
        }
        // The deadline is wall time; the wait happens on the simulation clock. It is placed on
        // that clock only when nothing is due yet: a read whose output is there asks the clock
        // once, and so does a look on the wall clock (see `Clock::deadline`).
        let mut until = None;
        loop {
            // Output due now is taken even behind what a full buffer left, so that a read
            // shorter than `buf` took all there was (`reads_all`).
            let now = self.clock.now();
            let hung = {
                let mut device = self.device.lock().unwrap_or_else(|e| e.into_inner());
                device.poll_output(now, &mut self.pending);
                device.hung_up()
            };
            if !self.pending.is_empty() {
                return Ok(self.take(buf));
            }
            if hung {
                return Err(LinkError::Lost("the simulator hung up".into()));
            }
            let until = *until.get_or_insert_with(|| self.clock.deadline(now, deadline));
            if now >= until {
                return Err(LinkError::Timeout);
            }
            // When output is due is asked only before a real wait: a look, and a read whose
            // reply is there, take none.
            let due = self.lock().next_due(now);
            let target = due.map_or(until, |d| d.min(until));
            self.clock.wait(target.saturating_sub(now).max(NUDGE));
        }
    }

    fn describe(&self) -> String {
        self.name.clone()
    }

    fn reopen(&mut self) -> Result<(), LinkError> {
        self.pending.clear();
        self.lock().reconnect();
        Ok(())
    }
}

#[cfg(test)]
mod tests;
