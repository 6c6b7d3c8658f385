//! The subcommands only TMCL has: `asm`, `disasm`, `download`, `upload` and `profiles`. They are
//! part of the command line (a dialect's `cli/` folder is in the `cli` layer), and use its
//! connection options and diagnostics; `cli/mod.rs` only dispatches to them.

pub mod asm;
pub mod disasm;
pub mod download;
pub mod profiles;
pub mod upload;

use crate::dialect::Configured;

use super::profile::Profile;

/// The TMCL profile, for the subcommands that read module tables (`asm`, `disasm`, `download`).
pub fn profile(configs: &Configured) -> &Profile {
    let tmcl = configs.of(&super::DIALECT);
    super::config::profile(tmcl).expect("TMCL is configured with its profile")
}
