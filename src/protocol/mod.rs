//! Protocol dialects spoken by the modules tmclsh talks to.

pub mod smd4;
pub mod tmcl;
