//! The simulated TMCL modules: binary and ASCII TMCL on a bus of modules, each of its own profile
//! (a TMCM-142, a six-axis TMCM-6110, a binary-only TMCM-1260), motion that takes time on every
//! motor, parameters and EEPROM from the profile, I/O, program memory.
//!
//! Everything here is a pure state machine: bytes and time in, bytes out. [`Bus`] is the
//! [`crate::sim::Device`] the adapters serve; the modules on it ([`module`]) decode frames and
//! lines and hand commands to their [`machine`], whose motor ([`motion`], [`ramp`]) is computed
//! analytically from time, so results are exact and independent of how often anyone looks.

mod ascii;
mod bus;
pub mod can;
mod control;
mod control_cmd;
mod events;
mod exec;
#[cfg(feature = "cli")]
pub mod flags;
mod interrupts;
mod io;
mod live;
mod machine;
mod module;
mod motion;
mod options;
mod outcome;
mod params;
mod program;
mod ramp;
mod runner;
mod state;
mod vm;

pub use bus::{Bus, BusOptions};
pub(crate) use control_cmd::CONSOLE;
pub use motion::MotorState;
pub use motion::{Switch, Switches};
pub use options::{Backspace, LineEnd, Quirks};
pub use state::{BusImage, Eeprom, ModuleImage};

#[cfg(test)]
mod tests;
