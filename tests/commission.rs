//! The commissioning toolkit against the simulator: snapshots, bus scans, recordings, live watch
//! and transcripts that replay — the real binary over a pty or loopback TCP, and the library
//! in-process on a manual clock where exact timing matters.

mod record;
mod repl;
mod replay;
mod scan;
mod script;
mod signals;
mod smd4_record;
mod smd4_replay;
mod smd4_scan;
mod smd4_script;
mod smd4_snapshot;
mod snapshot;

use std::path::Path;
use std::process::Output;

use crate::util::{code, run, stderr, stdout};

/// Runs `tmclsh ARGS` and expects exit code `expected`, showing the output when it differs.
pub fn expect(args: &[&str], expected: i32) -> Output {
    let out = run(args);
    assert_eq!(
        code(&out),
        expected,
        "tmclsh {}\nstdout:\n{}\nstderr:\n{}",
        args.join(" "),
        stdout(&out),
        stderr(&out)
    );
    out
}

/// A path as a `&str` argument.
pub fn arg(path: &Path) -> &str {
    path.to_str().expect("temporary paths are UTF-8")
}
