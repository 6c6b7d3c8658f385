//! Simulated modules. The simulator is the embedded default of the shell and the ground every
//! test stands on, so it is a first-class part of the product.
//!
//! Each simulated bus is a pure state machine ([`Device`]): bytes in, bytes out, time as an input.
//! Thin adapters serve a device on a pseudo-terminal, on loopback TCP, or in-process behind a
//! [`crate::link::Link`]; decorators add line pacing, an adapter that echoes, an adapter's latency
//! timer and fault injection to any device.

/// The [`Device`] methods a decorator passes on unchanged to the device it wraps (in `$inner`),
/// written once rather than in every decorator.
macro_rules! pass_on {
    ($inner:ident: $($method:ident),+) => {
        $(pass_on!(@ $inner $method);)+
    };
    (@ $inner:ident hung_up) => {
        fn hung_up(&self) -> bool {
            self.$inner.hung_up()
        }
    };
    (@ $inner:ident byte_time) => {
        fn byte_time(&mut self, time: std::time::Duration) {
            self.$inner.byte_time(time)
        }
    };
    (@ $inner:ident control) => {
        fn control(
            &mut self,
            now: std::time::Duration,
            command: &str,
        ) -> Option<Result<String, $crate::sim::error::ConsoleError>> {
            self.$inner.control(now, command)
        }
    };
}

mod builtin;
pub mod console;
pub mod echo;
pub mod error;
pub mod fault;
pub mod inprocess;
pub mod latency;
pub mod pacing;
pub mod ramp;
#[cfg(unix)]
pub mod serve;
pub mod slcan;
pub mod store;

pub use builtin::builtin_link;

/// Where a simulator logs its traffic (`tmclsh sim --verbose`): one decoded line at a time.
pub type LogSink = Box<dyn FnMut(&str) + Send>;

use std::time::Duration;

use error::ConsoleError;

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

    /// A new connection replaces one that hung up: a device that hung up may talk again.
    fn reconnect(&mut self) {}

    /// The line in front is paced (`--baud`): each byte arrives this long after the one before
    /// it, which a receiver that times out on quiet must not count as quiet.
    fn byte_time(&mut self, time: Duration) {
        let _ = time;
    }

    /// Runs a control command (from the `tmclsh sim` console or a test): set an input, move a
    /// switch, trigger a fault. `None` when the device does not know the command, so that
    /// decorators can pass it on to the device they wrap.
    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        let _ = (now, command);
        None
    }
}

impl<D: Device + ?Sized> Device for Box<D> {
    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        (**self).receive(now, bytes)
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        (**self).poll_output(now, out)
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        (**self).next_due(now)
    }

    fn hung_up(&self) -> bool {
        (**self).hung_up()
    }

    fn reconnect(&mut self) {
        (**self).reconnect()
    }

    fn byte_time(&mut self, time: Duration) {
        (**self).byte_time(time)
    }

    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        (**self).control(now, command)
    }
}
