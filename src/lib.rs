//! tmclsh — a terminal and scripting shell for the ASCII command interfaces of stepper-motor
//! modules: Trinamic modules speaking TMCL (TMCM-142 first) and AML SMD4 drives.
//!
//! The library holds everything; the `tmclsh` binary only parses arguments and maps errors to exit
//! codes. Each protocol is one [`dialect`] folder (its pure protocol code, tables as data, session,
//! simulator and faces), and every face — the REPL, one-shot `-c` lines, piped stdin and Rhai
//! scripts — goes through the same session to a link: a serial port, a TCP socket or the built-in
//! simulated module.
//!
//! The `cli` feature (on by default) adds the command line ([`cli`]) and the interactive shell
//! (`repl`) with their dependencies; without it the library is the dialects, sessions, scripts,
//! simulators and commissioning tools alone, for embedding.
#![deny(missing_docs)]
#![warn(unreachable_pub)]

pub mod article;
#[cfg(feature = "cli")]
pub mod cli;
pub mod clock;
pub mod commission;
pub mod count;
pub mod crash;
pub mod dialect;
pub mod duration;
pub mod escape;
pub mod exit;
pub mod file;
#[doc(hidden)]
pub mod fuzz_entry;
pub mod link;
pub mod progress;
#[cfg(feature = "cli")]
pub mod repl;
pub mod script;
pub mod session;
pub mod shell;
pub mod sim;
pub mod stdout;
pub mod suggest;
pub mod wrap;
