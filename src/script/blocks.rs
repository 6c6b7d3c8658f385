//! Named test blocks: `test("homing", || { … })` runs its closure as one test case. A block that
//! fails (an assertion, a device error, a timeout) is recorded with its message and script
//! position, the motors the session set moving are stopped as after any failed script, and the
//! run goes on with the next block: a CI report lists every case, and the run fails (the worst
//! exit code of the failed blocks) when any did. What ends a whole run — Ctrl-C, a signal,
//! `--max-time`, the memory cap, `exit()` — still ends it inside a block.

use std::cell::RefCell;
use std::rc::Rc;
use std::time::{Duration, Instant};

use rhai::{Dynamic, Engine, EvalAltResult, FnPtr, NativeCallContext};

use crate::exit::{Exit, Failure};

/// One test case of a run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Case {
    /// The name the script gave it.
    pub name: String,
    /// How long it ran.
    pub time: Duration,
    /// Why it failed (message with `script:line:column`, and exit code); `None` if it passed.
    pub failure: Option<Failure>,
}

/// What a run's blocks did, filled in when the run ends.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Report {
    /// The blocks in the order they ran.
    pub cases: Vec<Case>,
    /// A failure outside every block (a compile error, an error between blocks), if any.
    pub outside: Option<Failure>,
}

/// Where a run leaves its [`Report`]: handed to the script by the caller, read after the run.
pub type Blocks = Rc<RefCell<Report>>;

/// A block as it ran, before its error is put in words.
pub(super) struct Ran {
    pub name: String,
    pub time: Duration,
    pub end: End,
}

/// How a block ended.
pub(super) enum End {
    Passed,
    Failed(Box<EvalAltResult>),
    /// The whole run ended inside it: it gets the run's outcome.
    EndedTheRun,
}

/// What the blocks of a run record into.
pub(super) type Record = Rc<RefCell<Vec<Ran>>>;

/// Registers `test(name, closure)`; `after_failure` runs after each failed block (stopping the
/// motors).
pub(super) fn register(engine: &mut Engine, record: Record, after_failure: Rc<dyn Fn()>) {
    volatile!(
        engine,
        "test",
        move |context: NativeCallContext, name: &str, body: FnPtr| {
            let start = Instant::now();
            let result = body.call_within_context::<Dynamic>(&context, ());
            let (end, passed_on) = match result {
                Ok(_) => (End::Passed, Ok(())),
                Err(error) if ends_the_run(&error) => (End::EndedTheRun, Err(error)),
                Err(error) => (End::Failed(error), Ok(())),
            };
            let failed = matches!(end, End::Failed(_));
            record.borrow_mut().push(Ran {
                name: name.to_string(),
                time: start.elapsed(),
                end,
            });
            if failed {
                after_failure();
            }
            passed_on
        }
    );
}

/// Whether an error ends the whole run rather than one block: Ctrl-C, a signal, a limit, a lost
/// transcript, `exit()` (all `ErrorTerminated`), runaway operations or nesting.
fn ends_the_run(error: &EvalAltResult) -> bool {
    match error {
        EvalAltResult::ErrorInFunctionCall(_, _, inner, _) => ends_the_run(inner),
        EvalAltResult::ErrorTerminated(..)
        | EvalAltResult::ErrorTooManyOperations(..)
        | EvalAltResult::ErrorStackOverflow(..) => true,
        _ => false,
    }
}

/// The error without the wrapping of the block's own closure (`anon$…`), which says nothing.
pub(super) fn unwrapped(error: EvalAltResult) -> EvalAltResult {
    match error {
        EvalAltResult::ErrorInFunctionCall(function, _, inner, _)
            if function.starts_with("anon$") =>
        {
            unwrapped(*inner)
        }
        other => other,
    }
}

/// The failure a run ends with when blocks failed and nothing else did: "2 of 5 tests failed:
/// homing, limits", with the worst exit code among them ([`Exit::worse`]).
pub(super) fn verdict(name: &str, cases: &[Case]) -> Option<Failure> {
    let failed: Vec<&Case> = cases.iter().filter(|c| c.failure.is_some()).collect();
    if failed.is_empty() {
        return None;
    }
    let exit = failed
        .iter()
        .filter_map(|c| c.failure.as_ref().map(|f| f.exit))
        .reduce(Exit::worse)
        .unwrap_or(Exit::DeviceError);
    let names: Vec<&str> = failed.iter().map(|c| c.name.as_str()).collect();
    Some(Failure::new(
        exit,
        format!(
            "{name}: {} of {} failed: {}",
            failed.len(),
            crate::count::counted(cases.len(), "test"),
            names.join(", ")
        ),
    ))
}
