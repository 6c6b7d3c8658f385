//! Non-interactive use: `-c LINE` arguments, or stdin lines when stdin is not a terminal.
//!
//! For each command stdout gets exactly one line, the reply as the module sent it (without echo or
//! line ending, control characters escaped); diagnostics go to stderr, escaped too, since they
//! quote device and input text. The first failing line stops the run with its exit code
//! (1 device error status, 2 refused before sending, 3 no reply, link lost or a transcript that
//! cannot be written, 130 Ctrl-C), after stopping the motors the run set moving.
//!
//! Piped lines end with CR, LF or CRLF ([`lines`]); a line that is too long or not UTF-8 is
//! refused like a line the validator refuses.

pub mod lines;

use std::io::Write;
use std::sync::mpsc;

use crate::escape::escape_control;
use crate::exit::{Exit, ExitStatus};
use crate::session::{SessionError, interrupt};

use super::words::{Everyday, everyday};
use super::{Flow, Shell};
use lines::{LineError, LineReader, MAX_LINE};

/// Lines read ahead of the one running: enough to keep the reader busy, few enough that a large
/// file on stdin is not read into memory ahead of a slow module.
const READ_AHEAD: usize = 16;

/// One line of input, or why it cannot be used.
type Line = Result<String, LineError>;

/// Where lines come from.
pub enum Lines {
    /// Given up front (`-c`).
    Given(std::vec::IntoIter<String>),
    /// Read as they arrive (stdin); a reader thread keeps Ctrl-C responsive while waiting.
    Stream(mpsc::Receiver<std::io::Result<Line>>),
}

impl Lines {
    /// Lines of stdin, read on a thread as they arrive.
    pub fn stdin() -> Lines {
        let (tx, rx) = mpsc::sync_channel(READ_AHEAD);
        std::thread::spawn(move || {
            for line in LineReader::new(std::io::stdin().lock()) {
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        Lines::Stream(rx)
    }

    fn next(&mut self) -> Option<Result<Line, SessionError>> {
        match self {
            Lines::Given(lines) => lines.next().map(|line| match line.len() {
                length if length > MAX_LINE => Ok(Err(LineError::TooLong)),
                _ => Ok(Ok(line)),
            }),
            Lines::Stream(rx) => loop {
                if interrupt::pending() {
                    return Some(Err(SessionError::Interrupted));
                }
                match rx.recv_timeout(interrupt::SLICE) {
                    Ok(Ok(line)) => return Some(Ok(line)),
                    Ok(Err(e)) => {
                        return Some(Err(SessionError::Usage(format!("reading stdin: {e}"))));
                    }
                    Err(mpsc::RecvTimeoutError::Timeout) => continue,
                    Err(mpsc::RecvTimeoutError::Disconnected) => return None,
                }
            },
        }
    }
}

/// Runs every line; returns the exit code. The session is closed (modules restored) at the end.
pub fn run(shell: &mut Shell, mut lines: Lines, out: &mut dyn Write, err: &mut dyn Write) -> Exit {
    let mut number = 0;
    let exit = loop {
        let line = match lines.next() {
            // Ctrl-C at the very moment the input ended still counts as Ctrl-C.
            None if interrupt::pending() => {
                break fail(shell, &SessionError::Interrupted, err, None);
            }
            None => break Exit::Success,
            Some(Ok(line)) => line,
            Some(Err(e)) => break fail(shell, &e, err, None),
        };
        number += 1;
        let line = match line {
            Ok(line) => line,
            Err(e) => {
                let refused = SessionError::Usage(format!("line {number}: {e}; nothing sent"));
                break fail(shell, &refused, err, None);
            }
        };
        let text = line.trim();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        match step(shell, text, out, err).and_then(|flow| transcript_written(shell).map(|()| flow))
        {
            Ok(Flow::Continue) => {}
            Ok(Flow::Quit) => break Exit::Success,
            Err(e) => break fail(shell, &e, err, Some((number, text))),
        }
    };
    for message in shell.session().close() {
        diagnose(err, &message);
    }
    if let (Exit::Success, Err(e)) = (exit, transcript_written(shell)) {
        // Only the closing lines were lost; the commands ran.
        report_notices(shell, err);
        diagnose(err, &e.to_string());
        return e.exit();
    }
    exit
}

/// One line of diagnostics on stderr.
fn diagnose(err: &mut dyn Write, message: &str) {
    let _ = writeln!(err, "tmclsh: {}", escape_control(message));
}

/// A run that asked for a transcript ends when it cannot be written (the notice before says why).
fn transcript_written(shell: &Shell) -> Result<(), SessionError> {
    let failed = shell
        .session_ref()
        .transcript()
        .is_some_and(|t| t.failure().is_some());
    if failed {
        return Err(SessionError::Link(
            "the run stops: it asked for a transcript that cannot be written".into(),
        ));
    }
    Ok(())
}

fn step(
    shell: &mut Shell,
    text: &str,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<Flow, SessionError> {
    if interrupt::pending() {
        return Err(SessionError::Interrupted);
    }
    let helper = match everyday(text) {
        Some(Everyday::Helper(line)) => Some(line),
        Some(Everyday::Clear) => {
            diagnose(
                err,
                "clear: there is no screen to clear outside the interactive shell",
            );
            return Ok(Flow::Continue);
        }
        None => text.starts_with(':').then(|| text.to_string()),
    };
    if let Some(line) = helper {
        let flow = shell.helper(&line, out);
        report_notices(shell, err);
        return flow;
    }
    let result = shell.session().execute(text);
    report_notices(shell, err);
    let reply = result?;
    let shown = reply.shown();
    let shown = escape_control(&shown);
    if writeln!(out, "{shown}").and_then(|()| out.flush()).is_err() {
        // stdout closed (e.g. piped into `head`): not an error, just stop.
        return Ok(Flow::Quit);
    }
    reply.checked()?;
    Ok(Flow::Continue)
}

fn report_notices(shell: &mut Shell, err: &mut dyn Write) {
    for notice in shell.session().take_notices() {
        diagnose(err, &notice);
    }
}

/// Reports a failure, stops what the run set moving, and gives the exit code.
fn fail(
    shell: &mut Shell,
    error: &SessionError,
    err: &mut dyn Write,
    at: Option<(usize, &str)>,
) -> Exit {
    match at {
        Some((number, text)) => diagnose(err, &format!("line {number} ({text}): {error}")),
        None => diagnose(err, &error.to_string()),
    }
    interrupt::take();
    if shell.session().may_be_moving() {
        for message in shell.session().stop_motion() {
            diagnose(err, &message);
        }
    }
    error.exit()
}
