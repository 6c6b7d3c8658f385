//! Trinamic TMCL: everything tmclsh knows about TMCL modules — the pure protocol, the module
//! profiles, the session (ASCII mode, binary direct mode), the simulated module bus, the assembler
//! and stand-alone programs, and the faces the shell, the REPL and scripts use.

pub mod asm;
pub mod commission;
pub mod helpers;
pub mod hint;
pub mod profile;
pub mod program;
pub mod protocol;
pub mod render;
pub mod replay;
pub mod scan;
pub mod script;
pub mod session;
pub mod sim;
