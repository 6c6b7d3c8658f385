//! The built-in simulated module behind an in-process link: the embedded default of the shell.

use std::sync::Arc;

use crate::clock::SystemClock;
use crate::link::Link;

use super::Device;
use super::inprocess::SimLink;

/// A link to `device` (a freshly powered-up simulated module), in-process, running on the wall
/// clock so motion takes real time; `name` is what the link says it talks to.
pub fn builtin_link(device: Box<dyn Device>, name: String) -> Box<dyn Link> {
    let clock = Arc::new(SystemClock::new());
    Box::new(SimLink::new(device, clock).named(name))
}
