//! Non-interactive use: `-c LINE` arguments, or stdin lines when stdin is not a terminal.
//!
//! For each command stdout gets exactly one line, the reply as the module sent it (without echo or
//! line ending, control characters escaped) — or only its value (`--value`), or one JSON object
//! (`--json`, [`format`]); diagnostics go to stderr, escaped too, since they quote device and
//! input text. The first failing line stops the run with its exit code (1 device error status,
//! 2 refused before sending, 3 no reply, link lost or a transcript that cannot be written,
//! 130 Ctrl-C), after stopping the motors the run set moving. With `--keep-going` a failing line
//! is reported and the run goes on (the motors too); it ends with the worst code
//! ([`Exit::worse`]). Ctrl-C and a transcript that cannot be written end it all the same.
//!
//! Piped lines end with CR, LF or CRLF ([`lines`]); a line that is too long or not UTF-8 is
//! refused like a line the validator refuses.
//! Empty lines and lines that are only a comment (`#`, `//`) are skipped; a trailing `//` comment
//! is the dialect's to drop (as the REPL's).

pub mod format;
pub mod lines;

use std::io::Write;
use std::sync::mpsc;

use crate::escape::escape_control;
use crate::exit::{Exit, ExitStatus};
use crate::session::{SessionError, interrupt};

use super::words::{Everyday, everyday, only_remark};
use super::{Flow, Shell};
pub use format::Output;
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

/// How a run treats its lines.
#[derive(Debug, Clone, Copy, Default)]
pub struct Options {
    /// What stdout gets for each line.
    pub output: Output,
    /// Go on past a failing line (`--keep-going`); the run's exit code is then the worst.
    pub keep_going: bool,
}

/// Runs every line; returns the exit code. The session is closed (modules restored) at the end.
pub fn run(
    shell: &mut Shell,
    mut lines: Lines,
    options: Options,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Exit {
    let mut number = 0;
    let mut worst = Exit::Success;
    let exit = loop {
        let line = match lines.next() {
            // Ctrl-C at the very moment the input ended still counts as Ctrl-C.
            None if interrupt::pending() => {
                break worst.worse(fail(shell, &SessionError::Interrupted, err, None));
            }
            None => break worst,
            Some(Ok(line)) => line,
            Some(Err(e)) => break worst.worse(fail(shell, &e, err, None)),
        };
        number += 1;
        let line = match line {
            Ok(line) => line,
            Err(e) => {
                let refused = SessionError::Usage(format!("line {number}: {e}; nothing sent"));
                show_failure(number, "", &refused, options.output, out);
                if options.keep_going {
                    diagnose(err, &refused.to_string());
                    worst = worst.worse(refused.exit());
                    continue;
                }
                break worst.worse(fail(shell, &refused, err, None));
            }
        };
        let text = line.trim();
        if only_remark(text) {
            continue;
        }
        let outcome = step(shell, number, text, options.output, out, err)
            .and_then(|flow| transcript_written(shell).map(|()| flow));
        match outcome {
            Ok(Flow::Continue) => {}
            Ok(Flow::Quit) => break worst,
            // Ctrl-C and a transcript that cannot be written end the run whatever was asked.
            Err(e) if goes_on(shell, &e, options) => {
                diagnose(err, &format!("line {number} ({text}): {e}"));
                interrupt::take();
                worst = worst.worse(e.exit());
            }
            Err(e) => {
                let e = match e {
                    SessionError::Timeout { .. } => match shell.session().wrong_dialect() {
                        Some(failure) => SessionError::Failed(failure),
                        None => e,
                    },
                    e => e,
                };
                break worst.worse(fail(shell, &e, err, Some((number, text))));
            }
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

/// Whether the run goes on after a failing line: with `--keep-going`, unless it was Ctrl-C or
/// the transcript the run asked for cannot be written.
fn goes_on(shell: &Shell, error: &SessionError, options: Options) -> bool {
    options.keep_going
        && !matches!(error, SessionError::Interrupted)
        && transcript_written(shell).is_ok()
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
        return Err(SessionError::TranscriptLost);
    }
    Ok(())
}

fn step(
    shell: &mut Shell,
    number: usize,
    text: &str,
    output: Output,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<Flow, SessionError> {
    if interrupt::pending() {
        show_failure(number, text, &SessionError::Interrupted, output, out);
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
        let flow = run_helper(shell, number, text, &line, output, out);
        report_notices(shell, err);
        return flow;
    }
    let result = shell.session().execute(text);
    report_notices(shell, err);
    let reply = match result {
        Ok(reply) => reply,
        Err(e) => {
            show_failure(number, text, &e, output, out);
            return Err(e);
        }
    };
    let exit = reply.clone().checked().err().map_or(0, |e| e.exit().code());
    let time = shell.timestamps.then(super::time_of_day);
    let stamp = time.as_ref().map(|t| format!("{t} ")).unwrap_or_default();
    let shown = match output {
        Output::Reply => format!("{stamp}{}", escape_control(&reply.shown)),
        Output::Value => format!("{stamp}{}", escape_control(&format::value(&reply))),
        Output::Json => {
            let mut object = format::reply_json(number, text, &reply, exit);
            if let Some(time) = time {
                object["time"] = serde_json::Value::String(time);
            }
            format::json_line(&object)
        }
    };
    if writeln!(out, "{shown}").and_then(|()| out.flush()).is_err() {
        // stdout closed (e.g. piped into `head`): the run ends here, quietly (`crate::stdout`).
        return Ok(Flow::Quit);
    }
    reply.checked()?;
    Ok(Flow::Continue)
}

/// Runs a helper line; under `--json` its output becomes one object.
fn run_helper(
    shell: &mut Shell,
    number: usize,
    text: &str,
    line: &str,
    output: Output,
    out: &mut dyn Write,
) -> Result<Flow, SessionError> {
    if output != Output::Json {
        let flow = shell.helper(line, out);
        if let Err(e) = &flow {
            show_failure(number, text, e, output, out);
        }
        return flow;
    }
    let mut captured = Vec::new();
    let flow = shell.helper(line, &mut captured);
    let object = match &flow {
        Ok(_) => format::helper_json(number, text, &String::from_utf8_lossy(&captured)),
        Err(e) => format::failure_json(number, text, &e.to_string(), e.exit().code()),
    };
    let _ = writeln!(out, "{}", format::json_line(&object));
    flow
}

/// What stdout gets for a line that failed without a reply: nothing as the module sent nothing,
/// an empty line under `--value` and an object under `--json`, so each line keeps its place.
fn show_failure(
    number: usize,
    text: &str,
    error: &SessionError,
    output: Output,
    out: &mut dyn Write,
) {
    let line = match output {
        Output::Reply => return,
        Output::Value => String::new(),
        Output::Json => format::json_line(&format::failure_json(
            number,
            text,
            &error.to_string(),
            error.exit().code(),
        )),
    };
    let _ = writeln!(out, "{line}").and_then(|()| out.flush());
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
    if matches!(error, SessionError::Lost(_)) && shell.session_ref().options().reconnect.is_none() {
        diagnose(
            err,
            "the run stops at a lost link; --reconnect WAIT (e.g. 30s) waits for it to come \
             back, sending an interrupted read again but never a motion or write",
        );
    }
    interrupt::take();
    if shell.session().may_be_moving() {
        for message in shell.session().stop_motion() {
            diagnose(err, &message);
        }
    }
    error.exit()
}
