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
    indefinite: "an SMD4",
    recognises: protocol::request::recognises,
    script_functions: script::FUNCTIONS,
    helpers: helpers::HELPERS,
    configure: config::configure,
    own_options: &[],
    refusal: "is for SMD4 drives (--protocol smd4)",
    #[cfg(feature = "cli")]
    session_flags: <flags::SessionFlags as clap::Args>::augment_args,
    #[cfg(feature = "cli")]
    sim_flags: sim::flags::add,
    #[cfg(feature = "cli")]
    sim_flag_given: sim::flags::given,
    simulated: "SMD4",
    console: &sim::CONSOLE,
    legacy_note: Some(replay::OPENED),
    typed_here,
    scan_addresses: "1-247",
    // 247 fits a byte; a test of the descriptor compares the two.
    max_address: protocol::MAX_ADDRESS as u8,
    scan_example: "1-247 50ms",
    param_example: "MOTOR:PACT,MOTOR:VACT",
};

/// SMD4 mnemonics have colons (`MOTOR:VMAX`, `@3,SYS:FW`): how the history of earlier versions,
/// shared with TMCL, is split.
fn typed_here(line: &str) -> bool {
    line.contains(':')
}
