//! `exit()` in a script: Rhai's own ends the run as if the script had passed, whatever value it is
//! given, so a script that gave up with `exit(1)` passed and left its motors turning. Here
//! `exit()` and `exit(0)` end the script as its last line would, and any other value fails it with
//! exit code 1 — the value shown, the motors stopped like on any failure. The value is never the
//! exit code itself: 2, 3 and 130 mean input refused, a link failure and Ctrl-C to whoever reads
//! the code.

use rhai::{Dynamic, Engine, EvalAltResult, INT, Position};

use crate::escape::escape_control;
use crate::exit::{Exit, Failure};

/// How `exit` ended a script: carried as the token of Rhai's termination, which no `catch` stops
/// and no function call wraps.
#[derive(Debug, Clone)]
enum Ended {
    /// `exit()` or `exit(0)`.
    Passed,
    /// Any other value, as the script wrote it.
    Failed(String),
}

/// Registers `exit()` and `exit(value)` over Rhai's own.
pub(crate) fn register(engine: &mut Engine) {
    volatile!(engine, "exit", || -> Result<(), Box<EvalAltResult>> {
        Err(end(Ended::Passed))
    });
    volatile!(
        engine,
        "exit",
        |value: Dynamic| -> Result<(), Box<EvalAltResult>> {
            let passed = value.is_unit() || value.as_int().is_ok_and(|n: INT| n == 0);
            Err(end(if passed {
                Ended::Passed
            } else {
                Ended::Failed(show(&value))
            }))
        }
    );
}

fn end(ended: Ended) -> Box<EvalAltResult> {
    Box::new(EvalAltResult::ErrorTerminated(
        Dynamic::from(ended),
        Position::NONE,
    ))
}

/// The value as the script wrote it: a string quoted, anything else as Rhai shows it.
fn show(value: &Dynamic) -> String {
    let text = if value.is_string() {
        format!("{:?}", value.to_string())
    } else {
        value.to_string()
    };
    escape_control(&text).into_owned()
}

/// What an `exit` call that ended the script means: `None` when `error` is no `exit` call,
/// `Some(Ok)` for a script that passed, `Some(Err)` with the failure (its message without the
/// position, which the caller puts in front).
pub(crate) fn outcome(error: &EvalAltResult) -> Option<Result<(), Failure>> {
    let token = match error {
        EvalAltResult::ErrorTerminated(token, _) => token,
        // Called from a closure a built-in function ran (`map`, `filter`): wrapped by it.
        EvalAltResult::ErrorInFunctionCall(_, _, inner, _) => return outcome(inner),
        _ => return None,
    };
    match token.clone().try_cast::<Ended>()? {
        Ended::Passed => Some(Ok(())),
        Ended::Failed(value) => Some(Err(Failure::new(
            Exit::DeviceError,
            format!("the script called exit({value}): it fails (exit 1)"),
        ))),
    }
}
