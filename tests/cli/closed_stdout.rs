//! A closed stdout (`| head -1`, `| true`) ends a run at its next write, quietly, with 141 as for
//! a tool SIGPIPE ended (docs/exit-codes.md) — over real pipes.

use std::fs::File;
use std::io::{BufRead, BufReader};
use std::os::fd::{FromRawFd, OwnedFd};
use std::process::{Command, Output, Stdio};

use crate::util::{bin, code, stderr, tempdir};

/// A pipe: (read end, write end), closed on exec, so that only the child it is given to holds it
/// (a read end inherited by a child would keep the pipe open for ever).
fn pipe() -> (OwnedFd, OwnedFd) {
    let mut fds = [0; 2];
    // SAFETY: `fds` has room for the two descriptors pipe2(2) returns; each is owned once below.
    assert_eq!(
        unsafe { libc::pipe2(fds.as_mut_ptr(), libc::O_CLOEXEC) },
        0,
        "pipe2(2)"
    );
    // SAFETY: both descriptors were just opened and belong to nothing else.
    unsafe { (OwnedFd::from_raw_fd(fds[0]), OwnedFd::from_raw_fd(fds[1])) }
}

/// `tmclsh ARGS` with stdout a pipe whose reader is already gone (`| true` that won the race):
/// every write finds it closed.
fn into_closed_pipe(args: &[&str]) -> Output {
    let (reader, writer) = pipe();
    drop(reader);
    Command::new(bin())
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::from(writer))
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        .output()
        .expect("tmclsh runs")
}

/// Quiet: no word of the pipe, no crash report.
fn assert_quiet(out: &Output) {
    let text = stderr(out);
    for word in ["pipe", "Broken", "panick", "stdout", "internal error"] {
        assert!(!text.contains(word), "stderr mentions {word:?}: {text}");
    }
}

#[test]
fn an_output_only_command_ends_quietly_with_141() {
    for args in [
        &["params"][..],
        &["man"],
        &["profiles"],
        &["completions", "bash"],
    ] {
        let out = into_closed_pipe(args);
        assert_eq!(code(&out), 141, "{args:?}: {}", stderr(&out));
        assert_quiet(&out);
    }
}

#[test]
fn c_lines_end_at_the_first_write_and_send_nothing_after_it() {
    let dir = tempdir();
    let log = dir.join("log.txt");
    let out = into_closed_pipe(&[
        "--sim",
        "--log",
        log.to_str().unwrap(),
        "-c",
        "GAP 1, 0",
        "-c",
        "ROR 0, 500",
    ]);
    assert_eq!(code(&out), 141, "{}", stderr(&out));
    assert_quiet(&out);
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(transcript.contains("GAP 1, 0"), "{transcript}");
    assert!(
        !transcript.contains("ROR"),
        "sent after stdout closed: {transcript}"
    );
}

#[test]
fn a_script_printing_forever_ends_when_its_reader_goes_away() {
    let dir = tempdir();
    let script = dir.join("forever.rhai");
    std::fs::write(
        &script,
        "let n = 0;\nloop { n += 1; print(`line ${n}`); }\n",
    )
    .unwrap();
    let (reader, writer) = pipe();
    let child = Command::new(bin())
        .args(["run", script.to_str().unwrap(), "--sim"])
        .stdin(Stdio::null())
        .stdout(Stdio::from(writer))
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        .spawn()
        .expect("tmclsh runs");
    // `| head -1`: one line read, then the reader is gone.
    let mut first = String::new();
    BufReader::new(File::from(reader))
        .read_line(&mut first)
        .unwrap();
    assert_eq!(first, "line 1\n");
    let out = child.wait_with_output().expect("tmclsh ends");
    assert_eq!(code(&out), 141, "{}", stderr(&out));
    assert_quiet(&out);
}
