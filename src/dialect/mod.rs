//! Protocol dialects spoken by the modules tmclsh talks to.

pub mod session;
pub mod smd4;
pub mod tmcl;

/// Which protocol a module speaks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Dialect {
    /// Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`.
    #[default]
    Tmcl,
    /// AML SMD4 text protocol.
    Smd4,
}
