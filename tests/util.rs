//! Shared harness: running the real binary and reading its results.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// How long an expect-style test waits for a piece of terminal output before failing, in ms: a
/// hang guard, not a timing assertion, so generous enough for a loaded 2-core machine.
pub const EXPECT_MS: u64 = 30_000;

/// The `tmclsh` binary cargo built for these tests.
pub fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_tmclsh"))
}

/// The repository root.
pub fn repo() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `tmclsh ARGS` to completion with empty stdin.
pub fn run(args: &[&str]) -> Output {
    Command::new(bin())
        .args(args)
        .stdin(Stdio::null())
        .env("NO_COLOR", "1")
        .output()
        .expect("tmclsh runs")
}

/// Runs `tmclsh ARGS` with `input` on stdin (a pipe, so stdin is not a terminal).
pub fn run_with_stdin(args: &[&str], input: &str) -> Output {
    run_with_stdin_in(Path::new("."), args, input)
}

/// [`run_with_stdin`] in the working directory `dir`.
pub fn run_with_stdin_in(dir: &Path, args: &[&str], input: &str) -> Output {
    use std::io::Write;
    let mut child = Command::new(bin())
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        .spawn()
        .expect("tmclsh runs");
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(input.as_bytes()).unwrap();
    drop(stdin);
    child.wait_with_output().expect("tmclsh finishes")
}

/// stdout as text.
pub fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// stderr as text.
pub fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// The exit code (panics on death by signal).
pub fn code(output: &Output) -> i32 {
    output.status.code().expect("tmclsh exited normally")
}

/// A fresh, empty directory in the system temp dir (the soak harness's, which the benchmark
/// shares).
pub fn tempdir() -> std::path::PathBuf {
    crate::soak::harness::fresh_dir("tmclsh-test")
}

/// `tmclsh ARGS` in a pseudo-terminal, with extra environment variables.
pub fn terminal(args: &[&str], env: &[(&str, &str)]) -> rexpect::session::PtySession {
    let data = tempdir();
    let mut command = Command::new(bin());
    command
        .args(args)
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("RUST_BACKTRACE", "0")
        .env("XDG_DATA_HOME", &data)
        .env("HOME", &data);
    for (name, value) in env {
        command.env(name, value);
    }
    rexpect::session::spawn_command(command, Some(EXPECT_MS)).expect("tmclsh starts in a pty")
}
