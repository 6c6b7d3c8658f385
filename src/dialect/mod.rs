//! The protocols tmclsh speaks. Each dialect is one folder ([`tmcl`], [`smd4`]) holding
//! everything about it — pure protocol code, tables, session, simulator, script functions, shell
//! helpers, completion, commissioning adapter, scan and replay — and one line in the list
//! ([`all`]), which a program embedding the library extends with [`register`].
//!
//! The layers above (shell, REPL, CLI) know a dialect only through its [`Dialect`] descriptor, the
//! [`DialectConfig`] the command line configures from it, and the [`DialectSession`] it opens
//! with its [`Faces`]. A dialect's own code that needs its concrete session type gets it back by
//! downcasting inside its folder, never outside it.

mod config;
pub mod elsewhere;
pub mod faces;
pub mod functions;
pub mod grammar;
pub mod guard;
pub mod helper;
mod list;
pub mod replay;
pub mod session;
pub mod smd4;
pub mod tmcl;

use std::fmt;
use std::path::Path;

#[cfg(feature = "cli")]
use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};

pub use config::{Configured, DialectConfig, Opening, Purpose};
pub use faces::Faces;
pub use grammar::Grammar;
pub use helper::{ArgKind, Helper, Section};
pub use list::{RegisterError, all, by_name, default_dialect, register};
pub use session::{DialectSession, Reply};

/// The mark of a value the module's documentation does not confirm (a parameter row taken from a
/// sibling module, a command the document leaves open), the same in every dialect's tables and
/// help; `:help params` explains it.
pub const UNCERTAIN: &str = "*";

/// The dialects built in, the default first: `--protocol` offers them in this order, and
/// [`all`] lists those registered after them.
static BUILT_IN: &[&Dialect] = &[&tmcl::DIALECT, &smd4::DIALECT];

/// A dialect: what the layers above need to know about it without knowing it. One static value
/// per dialect, listed in [`all`].
pub struct Dialect {
    /// The name `--protocol` takes and transcript headers record (`tmcl`).
    pub name: &'static str,
    /// One line for the help of `--protocol`.
    pub summary: &'static str,
    /// What its modules are called in messages (`TMCL modules`, `SMD4 drives`).
    pub devices: &'static str,
    /// Whether a typed line reads as one of its commands by its own grammar and built-in
    /// tables, right arguments or not: how a line typed in the wrong session is told
    /// ([`elsewhere`]).
    pub recognises: fn(&str) -> bool,
    /// The device functions its scripts have, besides those every script has: how a script
    /// run in the wrong session is told.
    pub script_functions: &'static [crate::script::registry::ScriptFn],
    /// Its helper commands besides those every dialect has (`:bin`, `:flags` …).
    pub helpers: &'static [Helper],
    /// Reads the dialect's tables (TMCL: the `--profile` file) into a [`DialectConfig`].
    pub configure: Configure,
    /// Options of the shared group only this dialect uses (TMCL: `--module`, `--profile`); with
    /// its session flags, refused when another dialect is chosen ([`Dialect::owned_options`]).
    pub own_options: &'static [&'static str],
    /// Adds its session flags (`tmclsh --protocol NAME --FLAG`) to a command.
    #[cfg(feature = "cli")]
    pub session_flags: fn(clap::Command) -> clap::Command,
    /// Adds its simulator flags of one group to `tmclsh sim`.
    #[cfg(feature = "cli")]
    pub sim_flags: fn(SimFlags, clap::Command) -> clap::Command,
    /// The first of its simulator flags given on a command line, which the other dialects'
    /// simulators refuse.
    #[cfg(feature = "cli")]
    pub sim_flag_given: fn(&CommandLine) -> Option<&'static str>,
    /// The commands of its simulator's console, for `tmclsh sim --help` and the console's `help`.
    pub console: &'static crate::sim::console::Section,
    /// The note that opens its sessions in a transcript written before transcripts had headers;
    /// a file with none of these notes is read as the default dialect's.
    pub legacy_note: Option<&'static str>,
    /// What `:scan` and `tmclsh scan` try by default (`1-26`).
    pub scan_addresses: &'static str,
    /// The highest bus address a scan may name.
    pub max_address: u8,
    /// The example in the usage of `:scan`.
    pub scan_example: &'static str,
    /// Two of its readable parameters, for the examples in the usage of `:watch` and `:record`.
    pub param_example: &'static str,
}

/// A parsed command line, which a dialect reads its own session and simulator flags from:
/// clap's matches.
#[cfg(feature = "cli")]
pub type CommandLine = clap::ArgMatches;

/// Without the `cli` feature there is no command line (no value of this type exists): sessions
/// open with their dialect's defaults, or are built from the dialect's own options type.
#[cfg(not(feature = "cli"))]
#[derive(Debug)]
pub enum CommandLine {}

/// How a dialect reads its tables: from the `--profile` file, if one is given; the error is a
/// refusal (exit 2).
pub type Configure = fn(profile: Option<&Path>) -> Result<Box<dyn DialectConfig>, String>;

impl Dialect {
    /// Its name for messages with the indefinite article (`a TMCL`, `an SMD4`).
    pub fn indefinite(&self) -> String {
        crate::article::with_article(&self.name.to_uppercase())
    }

    /// Why one of its options is refused when `chosen` is the protocol: the default dialect's
    /// name the protocol chosen, the others' the `--protocol` that takes them.
    pub fn refusal(&self, chosen: &Dialect) -> String {
        if self == default_dialect() {
            format!(
                "is for {}, and the protocol is {}",
                self.devices, chosen.name
            )
        } else {
            format!("is for {} (--protocol {})", self.devices, self.name)
        }
    }
}

#[cfg(feature = "cli")]
impl Dialect {
    /// The ids of every option only this dialect uses: those of the shared group it lists, and
    /// its session flags.
    pub fn owned_options(&self) -> Vec<String> {
        let flags = (self.session_flags)(clap::Command::new("flags"));
        self.own_options
            .iter()
            .map(|id| id.to_string())
            .chain(flags.get_arguments().map(|a| a.get_id().to_string()))
            .collect()
    }
}

impl fmt::Debug for Dialect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_tuple("Dialect").field(&self.name).finish()
    }
}

impl PartialEq for Dialect {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self, other)
    }
}

impl Eq for Dialect {}

/// Where a dialect's simulator flags are listed in `tmclsh sim --help`: with the bus layout
/// (after `--listen`), with the module's setup (after `--manual-clock`), or among the quirk
/// switches (after the faults).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SimFlags {
    /// Bus layout (TMCL: `--modules`).
    Bus,
    /// The simulated module's setup (TMCL: switches, the choices the manual leaves open).
    Module,
    /// Switches for each reading of an ambiguous document (SMD4 quirks).
    Quirks,
}

/// The value parser of `--protocol`: the names in the list, each with its summary.
#[cfg(feature = "cli")]
pub fn protocol_parser() -> impl TypedValueParser<Value = &'static Dialect> {
    let values = all()
        .iter()
        .map(|d| PossibleValue::new(d.name).help(d.summary));
    PossibleValuesParser::new(values).map(|name| by_name(&name).expect("a listed name"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_each_dialect_as_its_descriptor_derives_it() {
        assert_eq!(tmcl::DIALECT.indefinite(), "a TMCL");
        assert_eq!(smd4::DIALECT.indefinite(), "an SMD4");
        assert_eq!(
            tmcl::DIALECT.refusal(&smd4::DIALECT),
            "is for TMCL modules, and the protocol is smd4"
        );
        assert_eq!(
            smd4::DIALECT.refusal(&tmcl::DIALECT),
            "is for SMD4 drives (--protocol smd4)"
        );
    }
}
