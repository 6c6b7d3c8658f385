//! `tmclsh run SCRIPT [CONNECTION] [-- ARGS...]`: run a Rhai script; the exit code is the verdict.

use std::path::PathBuf;
use std::time::Duration;

use crate::dialect::{Configured, Purpose};
use crate::exit::{Exit, Failure};
use crate::script::blocks::Blocks;
use crate::script::limits::DEFAULT_MAX_MEMORY_MIB;
use crate::script::{self, Limits, junit};
use crate::session::interrupt;

use super::connection::{Audience, ModuleArgs};

/// Arguments of `run`.
#[derive(Debug, Clone, clap::Args)]
#[command(after_long_help = script_functions())]
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
    /// Memory the script may hold, in MiB (0: no limit).
    #[arg(long, value_name = "MIB", default_value_t = DEFAULT_MAX_MEMORY_MIB)]
    pub max_memory: usize,
    /// Wall-clock time after which the script is stopped, its motors too (exit code 1):
    /// 500ms, 30s, 2m, or milliseconds.
    #[arg(long, value_name = "TIME", value_parser = parse_time)]
    pub max_time: Option<Duration>,
    /// A directory the script's file functions may also reach (repeatable); by default they
    /// reach only the script's directory and the working directory.
    #[arg(long, value_name = "DIR")]
    pub allow_dir: Vec<PathBuf>,
    /// Let the script's file functions replace existing files that are not tmclsh snapshots or
    /// recordings.
    #[arg(long)]
    pub overwrite: bool,
    /// Write a JUnit XML report to FILE: one test case per `test("name", || …)` block of the
    /// script (the whole script as one case when it has none), failures with their message and
    /// script position. Written whatever the outcome; a failed block does not end the run.
    #[arg(long, value_name = "FILE", value_hint = clap::ValueHint::FilePath)]
    pub junit: Option<PathBuf>,
    /// Arguments for the script, in its array `args` (strings).
    #[arg(last = true, value_name = "ARGS")]
    pub args: Vec<String>,
}

/// Runs the script; on any failure or Ctrl-C, and when the transcript it asked for cannot be
/// written, the modules it moved are stopped (MST) and every module is put back in the mode it
/// was found in before exiting.
pub fn run(args: RunArgs, configs: &Configured) -> Result<Exit, Failure> {
    let blocks = Blocks::default();
    let result = run_reporting(&args, configs, &blocks);
    if let Some(file) = &args.junit {
        let outcome = match &result {
            Ok(Exit::Success) => Ok(()),
            Ok(exit) => Err(Failure::new(*exit, "the run failed (see its output)")),
            Err(failure) => Err(failure.clone()),
        };
        let name = args.script.display().to_string();
        let mut report = blocks.borrow().clone();
        if report.cases.is_empty() && report.outside.is_none() {
            // Refused or failed before the script ran (a compile error, no link).
            report.outside = outcome.clone().err();
        }
        let xml = junit::xml(&name, &report, &outcome);
        if let Err(e) = std::fs::write(file, xml) {
            super::diagnose(&format!("--junit {}: {e}", file.display()));
            return Ok(worst(result, Exit::Link));
        }
    }
    result
}

/// The exit code of `result`, made `exit` when the run passed.
fn worst(result: Result<Exit, Failure>, exit: Exit) -> Exit {
    match result {
        Ok(Exit::Success) => exit,
        Ok(other) => other,
        Err(failure) => {
            super::diagnose(&failure.message);
            failure.exit
        }
    }
}

/// Runs the script, leaving what its `test` blocks did in `blocks`.
fn run_reporting(args: &RunArgs, configs: &Configured, blocks: &Blocks) -> Result<Exit, Failure> {
    interrupt::install();
    script::check_file(&args.script)?;
    for dir in &args.allow_dir {
        if !dir.is_dir() {
            return Err(Failure::new(
                Exit::Refused,
                format!("--allow-dir {}: not a directory", dir.display()),
            ));
        }
    }
    let session = args.module.open(configs, Audience::Batch, Purpose::Talk)?;
    let limits = Limits {
        max_operations: args.max_operations,
        max_call_depth: args.max_call_depth,
        max_memory: (args.max_memory > 0).then(|| args.max_memory.saturating_mul(1 << 20)),
        max_time: args.max_time,
        allow_dirs: args.allow_dir.clone(),
        overwrite: args.overwrite,
        needs_transcript: true,
    };
    let (mut session, outcome) = crate::shell::run_file_with_blocks(
        &args.script,
        &args.args,
        session,
        limits,
        blocks.clone(),
    );
    for case in &blocks.borrow().cases {
        if let Some(failure) = &case.failure {
            super::diagnose(&format!("test {:?} failed: {}", case.name, failure.message));
        }
    }
    for notice in session.take_notices() {
        super::diagnose(&notice);
    }
    // A transcript lost after the script's last operation fails the run all the same.
    let lost = |session: &dyn crate::dialect::DialectSession| {
        session.transcript().and_then(|t| t.failure())
    };
    let exit = match outcome {
        Ok(()) if lost(session.as_ref()).is_none() => Exit::Success,
        Ok(()) => Exit::Link,
        Err(report) => {
            // Silence from the start may be a device of the other dialect.
            let other = (report.exit == Exit::Link)
                .then(|| session.wrong_dialect())
                .flatten();
            let report = other.unwrap_or(report);
            // A closed stdout ends the run quietly (see `crate::stdout`).
            if !crate::stdout::closed() {
                super::diagnose(&report.message);
            }
            report.exit
        }
    };
    if exit != Exit::Success {
        interrupt::take();
        for message in session.stop_motion() {
            super::diagnose(&message);
        }
    }
    for message in session.close() {
        super::diagnose(&message);
    }
    if let Some(failure) = lost(session.as_ref()) {
        eprintln!("tmclsh: {failure}: the run asked for a transcript, so it failed");
        if exit == Exit::Success {
            // Only the closing lines were lost; the script ran.
            return Ok(Exit::Link);
        }
    }
    Ok(exit)
}

/// The functions scripts can call, for `run --help` (`:help NAME` in the shell shows one).
fn script_functions() -> String {
    format!(
        "Script functions (besides Rhai's own; docs/script-functions.md):\n\n{}",
        crate::script::registry::listing(&crate::dialect::functions::tables())
    )
}

/// A time for `--max-time`: `500ms`, `30s`, `2m`, or a number of milliseconds; at least 1 ms.
fn parse_time(text: &str) -> Result<Duration, super::value::ValueError> {
    let time = crate::duration::parse(text)?;
    if time.is_zero() {
        return Err(super::value::ValueError::ZeroTime);
    }
    Ok(time)
}
