//! How a script fails: built-in functions throw a [`Failure`] (message and exit code) as the Rhai
//! runtime error value, so the runner can tell an assertion from a lost link.

use rhai::{Dynamic, EvalAltResult, Position};

use crate::exit::{Exit, Failure};
use crate::session::SessionError;

/// Shorthand for the result of a built-in function.
pub type Fallible<T> = Result<T, Box<EvalAltResult>>;

/// `failure` as a Rhai error (the position is filled in by Rhai with the call site).
pub fn thrown(failure: Failure) -> Box<EvalAltResult> {
    Box::new(EvalAltResult::ErrorRuntime(
        Dynamic::from(failure),
        Position::NONE,
    ))
}

/// Converts a session result into a Rhai result.
pub fn device<T>(result: Result<T, SessionError>) -> Fallible<T> {
    result.map_err(|e| thrown(e.into()))
}

/// A runtime failure (exit 1) with a message.
pub fn runtime(message: impl Into<String>) -> Box<EvalAltResult> {
    thrown(Failure::new(Exit::DeviceError, message))
}

/// A refused argument (exit 2): the line would not have been sent.
pub fn refused(message: impl Into<String>) -> Box<EvalAltResult> {
    thrown(Failure::refused(message))
}
