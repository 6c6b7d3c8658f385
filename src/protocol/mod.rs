//! Protocol dialects spoken by the modules tmclsh talks to.

pub mod tmcl;
