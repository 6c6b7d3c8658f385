//! The `tmclsh` binary: parse arguments, run, exit with the documented code.

use std::process::ExitCode;

fn main() -> ExitCode {
    // A panic stops the motors of every open session and exits 101 (see `crash`).
    tmclsh::crash::guard(tmclsh::cli::main)
}
