//! AML SMD4: everything tmclsh knows about SMD4 drives — the pure protocol and its command table,
//! the session, the simulated drive, and the faces the shell, the REPL and scripts use.

pub mod commission;
pub mod config;
mod exit;
pub mod flags;
mod grammar;
mod help;
pub mod helpers;
pub mod params;
pub mod protocol;
pub mod render;
pub mod replay;
pub mod scan;
pub mod script;
pub mod session;
pub mod sim;

pub use grammar::Smd4Grammar;

use crate::dialect::Dialect;

/// SMD4 in the list of dialects.
pub static DIALECT: Dialect = Dialect {
    name: "smd4",
    summary: "AML SMD4 text protocol",
    devices: "SMD4 drives",
    helpers: helpers::HELPERS,
    configure: config::configure,
    own_options: &[],
    refusal: "is for SMD4 drives (--protocol smd4)",
    session_flags: <flags::SessionFlags as clap::Args>::augment_args,
    sim_flags: sim::flags::add,
    sim_flag_given: sim::flags::given,
    simulated: "SMD4",
    legacy_note: Some(replay::OPENED),
    scan_addresses: "1-247",
    scan_example: "1-247 50ms",
};
