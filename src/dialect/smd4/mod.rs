//! AML SMD4: everything tmclsh knows about SMD4 drives — the pure protocol and its command table,
//! the session, the simulated drive, and the faces the shell, the REPL and scripts use.

pub mod commission;
pub mod helpers;
pub mod protocol;
pub mod render;
pub mod replay;
pub mod scan;
pub mod script;
pub mod session;
pub mod sim;
