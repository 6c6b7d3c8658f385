//! Simulated modules. The simulator is the embedded default of the shell and the ground every
//! test stands on, so it is a first-class part of the product.
//!
//! Each simulated bus is a pure state machine ([`Device`]): bytes in, bytes out, time as an input.
//! Thin adapters serve a device on a pseudo-terminal, on loopback TCP, or in-process behind a
//! [`crate::link::Link`]; decorators add line pacing and fault injection to any device.

mod builtin;
pub mod clock;
pub mod smd4;

pub use builtin::builtin_link;

use std::time::Duration;

/// A simulated bus endpoint as a pure state machine. `now` is the simulation time since the device
/// was created; it never goes backwards between calls.
pub trait Device: Send {
    /// Bytes from the host arrive at `now`.
    fn receive(&mut self, now: Duration, bytes: &[u8]);

    /// Appends to `out` the bytes the device has sent by `now`.
    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>);

    /// When the device will next have output (or an internal event) due, if it knows.
    /// Adapters wait until then rather than polling.
    fn next_due(&self, now: Duration) -> Option<Duration>;

    /// Whether the device has hung up (fault injection); adapters then close the connection.
    fn hung_up(&self) -> bool {
        false
    }
}
