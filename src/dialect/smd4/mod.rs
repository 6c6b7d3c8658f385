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
    console_help: CONSOLE_HELP,
    legacy_note: Some(replay::OPENED),
    scan_addresses: "1-247",
    // 247 fits a byte; a test of the descriptor compares the two.
    max_address: protocol::MAX_ADDRESS as u8,
    scan_example: "1-247 50ms",
    param_example: "MOTOR:PACT,MOTOR:VACT",
};

/// The commands of its simulator's console (`tmclsh sim --help`).
const CONSOLE_HELP: &str = " SMD4 drive (--protocol smd4):
  limit pos|neg 0|1                  set the level of a limit input (active after LIMIT:POL+/-)
  exten 0|1                          set the external enable input
  joystick 0|1                       plug a joystick in or out
  fault BIT|NAME                     latch an EFLAGS bit (e.g. 2 or TempOver); the motor stops
  flash-failure on|off               make STORE fail with -5 (worn-out flash) or work again
  power-cycle                        restart from the stored configuration
  motor                              show position, velocity, standby, target velocity reached
  flags                              show SFLAGS, EFLAGS and whether addressing mode is on
  setting MNEMONIC                   show a working setting (e.g. COMS:SERIAL:SLAVEADDR)";
