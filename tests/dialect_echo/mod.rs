//! A dialect built outside the crate, as a program embedding the library would build one: a
//! loopback that sends back the text of each `ECHO text` line. It proves that a new dialect is
//! one folder plus one entry in the list ([`tmclsh::dialect::register`]); its tests drive it
//! through the library's own shell and script entry points.

mod config;
mod faces;
mod protocol;
mod script;
mod session;
mod sim;
mod tests;

use tmclsh::dialect::Dialect;
use tmclsh::sim::console::Section;

/// What messages and the banner call the simulated device.
const MODULE: &str = "echo loopback";

/// The echo dialect in the list of dialects.
pub static DIALECT: Dialect = Dialect {
    name: "echo",
    summary: "a loopback that sends each line back (a test dialect)",
    devices: "echo loopbacks",
    recognises: protocol::recognises,
    script_functions: script::FUNCTIONS,
    helpers: &[],
    configure: config::configure,
    own_options: &[],
    session_flags: |cmd| cmd,
    sim_flags: |_, cmd| cmd,
    sim_flag_given: |_| None,
    console: &CONSOLE,
    legacy_note: None,
    scan_addresses: "1",
    max_address: 1,
    scan_example: "1 50ms",
    param_example: "none",
};

/// Its simulator's console has only the commands every simulator has.
static CONSOLE: Section = Section {
    heading: "echo loopback (--protocol echo)",
    commands: &[],
};
