//! How a script fails: the message and the exit code it means. Device functions throw this as the
//! Rhai runtime error value, so the runner can tell an assertion from a lost link.

use std::fmt;

use rhai::{Dynamic, EvalAltResult, Position};

use crate::exit::{Exit, ExitStatus};
use crate::session::SessionError;

/// A failure raised by a built-in function.
#[derive(Debug, Clone, PartialEq)]
pub struct ScriptFailure {
    /// The exit code it means.
    pub exit: Exit,
    /// What happened.
    pub message: String,
}

impl ScriptFailure {
    /// A failure with this exit code and message.
    pub fn new(exit: Exit, message: impl Into<String>) -> Self {
        ScriptFailure {
            exit,
            message: message.into(),
        }
    }

    /// As a Rhai error (the position is filled in by Rhai with the call site).
    pub fn into_rhai(self) -> Box<EvalAltResult> {
        Box::new(EvalAltResult::ErrorRuntime(
            Dynamic::from(self),
            Position::NONE,
        ))
    }
}

impl fmt::Display for ScriptFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl From<SessionError> for ScriptFailure {
    fn from(error: SessionError) -> Self {
        ScriptFailure::new(error.exit(), error.to_string())
    }
}

/// Shorthand for the result of a built-in function.
pub type Fallible<T> = Result<T, Box<EvalAltResult>>;

/// Converts a session result into a Rhai result.
pub fn device<T>(result: Result<T, SessionError>) -> Fallible<T> {
    result.map_err(|e| ScriptFailure::from(e).into_rhai())
}

/// A runtime failure (exit 1) with a message.
pub fn runtime(message: impl Into<String>) -> Box<EvalAltResult> {
    ScriptFailure::new(Exit::DeviceError, message).into_rhai()
}

/// A refused argument (exit 2): the line would not have been sent.
pub fn refused(message: impl Into<String>) -> Box<EvalAltResult> {
    ScriptFailure::new(Exit::Refused, message).into_rhai()
}
