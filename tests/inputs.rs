//! Inputs and files checked at the door, through the real binary: module profiles refused with
//! the line of each problem (and a custom profile served by the built-in simulator), piped lines
//! with any line ending, bad bytes, control characters and endless lines, and transcripts that
//! say what they are of and end a run that cannot write them; and the wording of the messages
//! bad lines get.

mod files;
mod messages;
mod piped;
mod profile;
mod transcript;

use std::io::Write;
use std::process::{Command, Stdio};

use crate::util::bin;

/// What a run of the binary gave.
pub struct Piped {
    /// The exit code.
    pub code: i32,
    /// stdout.
    pub stdout: String,
    /// stderr, as bytes (control characters are what some tests look for).
    pub stderr: Vec<u8>,
}

impl Piped {
    /// stderr as text, without the line saying that the built-in simulator answers (that notice
    /// is the subject of `tests/options/rules.rs`; here every run is on the simulator).
    pub fn stderr(&self) -> String {
        let text = String::from_utf8_lossy(&self.stderr);
        let notice = "tmclsh: using the built-in simulated ";
        match text.split_once('\n') {
            Some((first, rest)) if first.starts_with(notice) => rest.to_string(),
            _ => text.into_owned(),
        }
    }
}

/// Runs `tmclsh ARGS` with `input` written to its stdin (a pipe) from a thread. The input may be
/// more than the binary reads: a write it refuses (a closed pipe) ends the writing.
pub fn run_piped(args: &[&str], input: Vec<u8>) -> Piped {
    let mut child = Command::new(bin())
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        .spawn()
        .expect("tmclsh runs");
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || {
        for chunk in input.chunks(64 * 1024) {
            if stdin.write_all(chunk).is_err() {
                break;
            }
        }
    });
    let output = child.wait_with_output().expect("tmclsh finishes");
    writer.join().unwrap();
    Piped {
        code: output.status.code().expect("tmclsh exited normally"),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: output.stderr,
    }
}
