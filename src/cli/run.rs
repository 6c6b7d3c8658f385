//! `tmclsh run SCRIPT [CONNECTION] [-- ARGS...]`: run a Rhai script; the exit code is the verdict.

use std::path::PathBuf;
use std::sync::Arc;

use crate::exit::Exit;
use crate::profile::Profile;
use crate::script::{self, Limits};
use crate::session::interrupt;

use super::Failure;
use super::connection::ModuleArgs;

/// Arguments of `run`.
#[derive(Debug, Clone, clap::Args)]
pub struct RunArgs {
    /// The Rhai script to run.
    #[arg(value_name = "SCRIPT")]
    pub script: PathBuf,
    /// Which module, and how to talk to it.
    #[command(flatten)]
    pub module: ModuleArgs,
    /// Operations after which a runaway script is stopped (0: no limit).
    #[arg(long, value_name = "N", default_value_t = Limits::default().max_operations)]
    pub max_operations: u64,
    /// Deepest nesting of function calls.
    #[arg(long, value_name = "N", default_value_t = Limits::default().max_call_depth)]
    pub max_call_depth: usize,
    /// Arguments for the script, in its array `args` (strings).
    #[arg(last = true, value_name = "ARGS")]
    pub args: Vec<String>,
}

/// Runs the script; on any failure or Ctrl-C the modules it moved are stopped (MST) and every
/// module is put back in the mode it was found in before exiting.
pub fn run(args: RunArgs, profile: &Arc<Profile>) -> Result<Exit, Failure> {
    interrupt::install();
    script::check_file(&args.script).map_err(|r| Failure::new(r.exit, r.message))?;
    let session = args.module.open(profile)?;
    let limits = Limits {
        max_operations: args.max_operations,
        max_call_depth: args.max_call_depth,
    };
    let (mut session, outcome) = script::run_file(&args.script, &args.args, session, limits);
    for notice in session.take_notices() {
        eprintln!("tmclsh: {notice}");
    }
    let exit = match outcome {
        Ok(()) => Exit::Success,
        Err(report) => {
            eprintln!("tmclsh: {}", report.message);
            interrupt::take();
            for message in session.stop_motion() {
                eprintln!("tmclsh: {message}");
            }
            report.exit
        }
    };
    for message in session.close() {
        eprintln!("tmclsh: {message}");
    }
    if let Some(failure) = session.transcript().and_then(|t| t.failure()) {
        eprintln!("tmclsh: {failure}: the run asked for a transcript, so it failed");
        if exit == Exit::Success {
            return Ok(Exit::Link);
        }
    }
    Ok(exit)
}
