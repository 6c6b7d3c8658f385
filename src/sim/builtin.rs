//! The built-in simulated module behind an in-process link: the embedded default of the shell.

use std::sync::Arc;

use crate::dialect::Dialect;
use crate::dialect::tmcl::profile::Profile;
use crate::link::Link;

use super::inprocess::SimLink;
use crate::clock::SystemClock;
use crate::dialect::smd4::sim::{Smd4Options, Smd4Sim};
use crate::dialect::tmcl::sim::{Bus, BusOptions};

/// A link to a freshly powered-up simulated module (address 1) of `profile`, or a simulated SMD4,
/// in-process, running on the wall clock so motion takes real time.
pub fn builtin_link(profile: &Arc<Profile>, dialect: Dialect) -> Box<dyn Link> {
    let clock = Arc::new(SystemClock::new());
    let link = match dialect {
        Dialect::Tmcl => SimLink::new(
            Box::new(Bus::new(profile.clone(), BusOptions::default())),
            clock,
        )
        .named(format!("simulated {} (built-in)", profile.module)),
        Dialect::Smd4 => SimLink::new(Box::new(Smd4Sim::new(Smd4Options::default())), clock)
            .named("simulated SMD4 (built-in)"),
    };
    Box::new(link)
}
