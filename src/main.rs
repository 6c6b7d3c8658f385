//! The `tmclsh` binary: parse arguments, run, exit with the documented code.

use std::process::ExitCode;

fn main() -> ExitCode {
    tmclsh::cli::main().into()
}
