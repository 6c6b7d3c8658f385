//! AML SMD4: everything tmclsh knows about SMD4 drives — the pure protocol and its command table,
//! the session, the simulated drive, and the faces the shell, the REPL and scripts use.

pub mod commission;
pub mod config;
mod exit;
pub mod flags;
mod grammar;
mod help;
pub mod helpers;
mod output;
pub mod params;
pub mod protocol;
pub mod render;
pub mod replay;
pub mod scan;
pub mod script;
pub mod session;
pub mod sim;
pub mod values;

pub use grammar::Smd4Grammar;

use crate::dialect::Dialect;

/// SMD4 in the list of dialects.
pub static DIALECT: Dialect = Dialect {
    name: "smd4",
    summary: "AML SMD4 text protocol",
    devices: "SMD4 drives",
    recognises: protocol::request::recognises,
    script_functions: script::FUNCTIONS,
    helpers: helpers::HELPERS,
    configure: config::configure,
    own_options: &[],
    #[cfg(feature = "cli")]
    session_flags: <flags::SessionFlags as clap::Args>::augment_args,
    #[cfg(feature = "cli")]
    sim_flags: sim::flags::add,
    #[cfg(feature = "cli")]
    sim_flag_given: sim::flags::given,
    console: &sim::CONSOLE,
    legacy_note: Some(replay::OPENED),
    scan_addresses: "1-247",
    // 247 fits a byte; a test of the descriptor compares the two.
    max_address: protocol::MAX_ADDRESS as u8,
    scan_example: "1-247 50ms",
    param_example: "MOTOR:PACT,MOTOR:VACT",
};
