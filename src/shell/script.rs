//! Scripts over the shell's session, whatever its dialect: the engine from [`crate::script`], the
//! dialect's device functions from the session itself.

use std::path::Path;

use crate::dialect::DialectSession;
use crate::exit::Failure;
use crate::script::{Limits, Script};

/// Runs the script at `path` with `args` over `session`; returns the session and the outcome.
/// Its file functions reach the script's directory, the working directory and
/// `limits.allow_dirs`.
pub fn run_file(
    path: &Path,
    args: &[String],
    session: Box<dyn DialectSession>,
    limits: Limits,
) -> (Box<dyn DialectSession>, Result<(), Failure>) {
    match Script::from_file(path, args, limits) {
        Ok(script) => session.run_script(&script),
        Err(failure) => (session, Err(failure)),
    }
}

/// Runs script text; `name` labels messages. Its file functions reach the working directory and
/// `limits.allow_dirs`.
pub fn run_source(
    name: &str,
    source: &str,
    args: &[String],
    session: Box<dyn DialectSession>,
    limits: Limits,
) -> (Box<dyn DialectSession>, Result<(), Failure>) {
    session.run_script(&Script::from_source(name, source, args, limits))
}
