//! The subcommands only TMCL has: `asm`, `disasm`, `download`, `upload` and `profiles`. They are
//! part of the command line (a dialect's `cli/` folder is in the `cli` layer), and use its
//! connection options and diagnostics; `cli/mod.rs` only dispatches to them.

pub mod asm;
pub mod disasm;
pub mod download;
pub mod profiles;
pub mod upload;

use std::path::Path;

use crate::cli::connection::ModuleArgs;
use crate::dialect::Configured;
use crate::exit::{Exit, Failure};
use crate::session::interrupt;

use super::profile::Profile;

/// The TMCL profile, for the subcommands that read module tables (`asm`, `disasm`, `download`).
pub fn profile(configs: &Configured) -> &Profile {
    let tmcl = configs.of(&super::DIALECT);
    super::config::profile(tmcl).expect("TMCL is configured with its profile")
}

/// What `download` and `upload` do before anything else: take Ctrl-C, and refuse a module of
/// another protocol.
fn start_module_command(module: &ModuleArgs) -> Result<(), Failure> {
    interrupt::install();
    if super::is(module.protocol()) {
        Ok(())
    } else {
        Err(Failure::new(
            Exit::Refused,
            "this subcommand works with TMCL modules only",
        ))
    }
}

/// The file `asm` or `disasm` reads, with the name its messages give it.
fn read_input(path: &Path) -> Result<(String, Vec<u8>), Failure> {
    let bytes = crate::file::read(path, crate::file::READ_LIMIT)
        .map_err(|e| Failure::new(Exit::Refused, format!("cannot read {e}")))?;
    Ok((path.display().to_string(), bytes))
}
