//! Trinamic TMCL: everything tmclsh knows about TMCL modules — the pure protocol, the module
//! profiles, the session (ASCII mode, binary direct mode), the simulated module bus, the assembler
//! and stand-alone programs, and the faces the shell, the REPL and scripts use.

pub mod asm;
#[cfg(feature = "cli")]
pub mod cli;
pub mod commission;
pub mod complete;
pub mod config;
pub mod flags;
mod grammar;
mod help;
pub mod helpers;
pub mod hint;
mod output;
pub mod params;
pub mod ports;
pub mod profile;
pub mod program;
pub mod protocol;
pub mod render;
pub mod replay;
pub mod scan;
pub mod script;
pub mod session;
pub mod sim;

pub use grammar::{ModuleLines, TmclGrammar};

use crate::dialect::{Dialect, DialectSession};

use session::TmclSession;

/// TMCL in the list of dialects.
pub static DIALECT: Dialect = Dialect {
    name: "tmcl",
    summary: "Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`",
    devices: "TMCL modules",
    recognises: protocol::line::recognises,
    script_functions: script::FUNCTIONS,
    helpers: helpers::HELPERS,
    configure: config::configure,
    own_options: &["module", "profile"],
    #[cfg(feature = "cli")]
    session_flags: <flags::SessionFlags as clap::Args>::augment_args,
    #[cfg(feature = "cli")]
    sim_flags: sim::flags::add,
    #[cfg(feature = "cli")]
    sim_flag_given: sim::flags::given,
    console: &sim::CONSOLE,
    legacy_note: None,
    scan_addresses: "1-26",
    max_address: 255,
    scan_example: "1-26 200ms",
    param_example: "actual_position,actual_speed",
};

/// Whether `dialect` is TMCL (for the subcommands only TMCL has: `download`).
pub fn is(dialect: &Dialect) -> bool {
    *dialect == DIALECT
}

/// The TMCL session behind a session of any dialect, if it is one.
pub fn session(session: &mut dyn DialectSession) -> Option<&mut TmclSession> {
    session.as_any_mut().downcast_mut()
}
