//! The built-in simulated module behind an in-process link: the embedded default of the shell.

use std::sync::Arc;

use crate::link::Link;
use crate::profile::Profile;
use crate::protocol::Dialect;

/// A link to a freshly powered-up simulated module (address 1) of `profile`, or a simulated SMD4,
/// in-process.
pub fn builtin_link(profile: &Arc<Profile>, dialect: Dialect) -> Box<dyn Link> {
    let _ = (profile, dialect);
    unimplemented!("the in-process simulator arrives with the simulator work")
}
