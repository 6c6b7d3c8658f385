//! The session flags of the TMCL dialect (`tmclsh --echo line`, `--no-enter`, `--stay-ascii`,
//! `--binary`): how a session meets the modules and how it leaves them. Declared here, added to
//! every command that opens a session through the descriptor, read back by their ids.

use crate::dialect::CommandLine;

use super::session::Echo;

/// Settings of the TMCL dialect. They stay under the shared options' heading, where they were
/// before the dialects declared their own.
#[cfg(feature = "cli")]
#[derive(Debug, Clone, clap::Args)]
#[group(id = "tmcl_flags")]
pub struct SessionFlags {
    /// Set the target module's echo on opening: char, line (every reply attributed to its
    /// request) or none (global parameter 67 in RAM; it stays after tmclsh ends).
    #[arg(long, value_enum, value_name = "MODE")]
    pub echo: Option<EchoMode>,
    /// Do not send the enter-ASCII-mode frame (the module is already in ASCII mode).
    #[arg(long)]
    pub no_enter: bool,
    /// Leave the modules in ASCII mode on exit instead of restoring the mode they were found in.
    #[arg(long)]
    pub stay_ascii: bool,
    /// Talk to the modules in binary direct mode (typed lines go out as binary frames), whether
    /// or not they have the ASCII interface.
    #[arg(long)]
    pub binary: bool,
}

/// The echo modes of a TMCL module, as `--echo` and `:echo` name them; the session reads the
/// word given ([`echo`]).
#[cfg(feature = "cli")]
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum EchoMode {
    /// Every character echoed as it arrives.
    Char,
    /// The whole line echoed after its end.
    Line,
    /// No echo, only the reply.
    None,
}

/// Whether the switch `id` (`--binary`, `--no-enter`, `--stay-ascii`) is on, by the command
/// line or a configuration file.
#[cfg(feature = "cli")]
pub fn switch(flags: Option<&CommandLine>, id: &str) -> bool {
    flags
        .and_then(|m| m.try_get_one::<bool>(id).ok().flatten().copied())
        .unwrap_or(false)
}

/// Without a command line every switch is off: the session enters ASCII mode where the module
/// has it, and puts the modules back at the end.
#[cfg(not(feature = "cli"))]
pub fn switch(flags: Option<&CommandLine>, _id: &str) -> bool {
    flags.is_some_and(|never| match *never {})
}

/// The echo `--echo` (or a configuration file) asks the target module to use, by its word.
#[cfg(feature = "cli")]
pub fn echo(flags: Option<&CommandLine>) -> Option<Echo> {
    let mut words = flags?.try_get_raw("echo").ok().flatten()?;
    words.next().and_then(|w| Echo::parse(&w.to_string_lossy()))
}

/// Without a command line, the module's own echo setting is kept.
#[cfg(not(feature = "cli"))]
pub fn echo(flags: Option<&CommandLine>) -> Option<Echo> {
    flags.map(|never| match *never {})
}
