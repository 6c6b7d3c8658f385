//! The `tmclsh` binary: parse arguments, run, exit with the documented code.

use std::alloc::System;
use std::process::ExitCode;

use cap::Cap;

/// The process's allocator, counting what is allocated, so `--max-memory` bounds a script at one
/// atomic add per allocation (see `tmclsh::script::memory`). No limit is set on it: a failed
/// allocation would abort; the script engine enforces the budget instead.
#[global_allocator]
static ALLOCATOR: Cap<System> = Cap::new(System, usize::MAX);

fn main() -> ExitCode {
    tmclsh::script::count_allocations_with(|| ALLOCATOR.allocated());
    // A panic stops the motors of every open session and exits 101 (see `crash`).
    tmclsh::crash::guard(tmclsh::cli::main)
}
