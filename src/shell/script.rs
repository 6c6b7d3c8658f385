//! Scripts over the shell's session, whatever its dialect: the engine from [`crate::script`], the
//! dialect's device functions from the session itself.

use std::path::Path;

use std::rc::Rc;

use crate::dialect::{DialectSession, elsewhere};
use crate::exit::Failure;
use crate::script::blocks::Blocks;
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
    run_file_with_blocks(path, args, session, limits, Blocks::default())
}

/// [`run_file`], leaving what the script's `test` blocks did in `blocks`.
pub fn run_file_with_blocks(
    path: &Path,
    args: &[String],
    session: Box<dyn DialectSession>,
    limits: Limits,
    blocks: Blocks,
) -> (Box<dyn DialectSession>, Result<(), Failure>) {
    match Script::from_file(path, args, limits) {
        Ok(script) => run(script.report_blocks_to(blocks), session),
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
    run(Script::from_source(name, source, args, limits), session)
}

/// Runs `script` over `session`; a call of another dialect's function says which.
fn run(
    script: Script,
    session: Box<dyn DialectSession>,
) -> (Box<dyn DialectSession>, Result<(), Failure>) {
    let this = session.dialect();
    let script = script.explain_unknown(Rc::new(move |function| {
        elsewhere::script_dialect(this, function).map(elsewhere::script_message)
    }));
    session.run_script(&script)
}
