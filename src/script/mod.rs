//! Rhai scripting: commissioning and test sequences with loops and assertions, run from a shell
//! or CI (`tmclsh run`) or from the REPL (`:source`), where the exit code is the verdict.
//!
//! Scripts reach the module only through the session, reach files only through their
//! [`sandbox::Sandbox`] (snapshots, recordings and programs, in the script's and the working
//! directory), cannot touch processes or the network (Rhai is built without modules, so an
//! `import` does not compile; there are no I/O functions), and run with capped operations, call
//! depth, memory and time ([`limits`]).
//! Device functions are registered as volatile, so Rhai's optimiser never runs them while
//! compiling.

/// Registers `name` as volatile (never evaluated at compile time by the optimiser).
macro_rules! volatile {
    ($engine:expr, $name:expr, $f:expr) => {
        rhai::FuncRegistration::new($name)
            .with_volatility(true)
            .register_into_engine($engine, $f)
    };
}
pub(crate) use volatile;

pub mod blocks;
pub mod commission;
pub(crate) mod common;
mod ending;
pub mod failure;
pub mod junit;
pub mod limits;
pub mod memory;
pub mod registry;
pub mod sandbox;
pub(crate) mod waiting;

use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use rhai::{Dynamic, Engine, EvalAltResult, INT, OptimizationLevel, Position, Scope};

use crate::escape::escape_control;
use crate::exit::{Exit, ExitStatus, Failure};
use crate::session::{SessionError, interrupt};

pub use limits::Limits;
use memory::Budget;
pub use memory::count_allocations_with;
use sandbox::Sandbox;

/// Where a script's `print` lines go, their control characters already escaped (see
/// [`print_to_stdout`]): stdout by default; tests and embedders capture them with their own.
pub type PrintSink = Rc<dyn Fn(&str)>;

/// A script ready to run: its text, its arguments, its limits, the files it may reach and where
/// it prints.
pub struct Script {
    name: String,
    source: String,
    args: Vec<String>,
    limits: Limits,
    sandbox: Rc<Sandbox>,
    print: PrintSink,
    elsewhere: Elsewhere,
    blocks: blocks::Blocks,
}

/// What a call of a function the engine lacks means, if the caller knows (a function of another
/// dialect's scripts: "this looks like a TMCL script — add `--protocol tmcl`"): such a script is
/// refused (exit 2).
pub type Elsewhere = Rc<dyn Fn(&str) -> Option<String>>;

/// The functions a dialect adds to the engine: over the session, with the sandbox for files.
pub type Registrar<S> = fn(&mut Engine, &Rc<RefCell<S>>, &Rc<Sandbox>);

impl Script {
    /// The script at `path` with `args`; its file functions reach the script's directory, the
    /// working directory and `limits.allow_dirs`.
    pub fn from_file(path: &Path, args: &[String], limits: Limits) -> Result<Script, Failure> {
        let name = path.display().to_string();
        let sandbox = Sandbox::for_script(path, &limits.allow_dirs, limits.overwrite);
        match read_source(path) {
            Ok(source) => Ok(Script {
                name,
                source,
                args: args.to_vec(),
                limits,
                sandbox: Rc::new(sandbox),
                print: Rc::new(print_to_stdout),
                elsewhere: Rc::new(|_| None),
                blocks: blocks::Blocks::default(),
            }),
            Err(e) => Err(Failure::refused(format!("cannot read script {e}"))),
        }
    }

    /// Script text; `name` labels messages. Its file functions reach the working directory and
    /// `limits.allow_dirs`.
    pub fn from_source(name: &str, source: &str, args: &[String], limits: Limits) -> Script {
        let dirs =
            std::iter::once(Path::new(".")).chain(limits.allow_dirs.iter().map(|d| d.as_path()));
        let sandbox = Sandbox::new(dirs, limits.overwrite);
        Script {
            name: name.to_string(),
            source: source.to_string(),
            args: args.to_vec(),
            limits,
            sandbox: Rc::new(sandbox),
            print: Rc::new(print_to_stdout),
            elsewhere: Rc::new(|_| None),
            blocks: blocks::Blocks::default(),
        }
    }

    /// The script with its `print` lines sent to `sink` instead of stdout.
    pub fn print_to(mut self, sink: PrintSink) -> Script {
        self.print = sink;
        self
    }

    /// The script with what its `test` blocks did left in `blocks` when it has run.
    pub fn report_blocks_to(mut self, blocks: blocks::Blocks) -> Script {
        self.blocks = blocks;
        self
    }

    /// The script with calls of unknown functions explained by `elsewhere`.
    pub fn explain_unknown(mut self, elsewhere: Elsewhere) -> Script {
        self.elsewhere = elsewhere;
        self
    }

    /// Runs over a session of type `S`, with the functions `register` adds (a dialect's device
    /// functions) besides those every script has, the commissioning functions among them; `log` lines go to the transcript through
    /// `annotate` (to stderr when none is written). What the session noticed (`notices`: bytes
    /// discarded before a reply, an event) goes out before the next `print` line, which may show
    /// that reply; what is left when the script ends is the caller's. With
    /// `limits.needs_transcript`, the script ends (exit 3) at its next operation once
    /// `lost_transcript` says the transcript can no longer be written. After a failed `test`
    /// block, `stop` stops what the session set moving (its messages go to stderr). The engine
    /// holds the session for the run and gives it back when dropped.
    pub fn run<S: crate::commission::ParamDevice + 'static>(
        &self,
        session: S,
        annotate: fn(&mut S, &str) -> bool,
        notices: fn(&mut S) -> Vec<String>,
        lost_transcript: fn(&S) -> bool,
        stop: fn(&mut S) -> Vec<String>,
        register: Registrar<S>,
    ) -> (S, Result<(), Failure>) {
        let shared = Rc::new(RefCell::new(session));
        let watchdog = limits::Watchdog::start(self.limits.max_time);
        let result = {
            let budget = self.limits.max_memory.and_then(Budget::from_now);
            // Made here, so the handle on the session it holds is gone with the engine.
            let print: PrintSink = {
                let (session, print) = (shared.clone(), self.print.clone());
                Rc::new(move |text: &str| {
                    if let Ok(mut session) = session.try_borrow_mut() {
                        for text in notices(&mut session) {
                            notice_to_stderr(&escape_control(&text));
                        }
                    }
                    print(text);
                })
            };
            // `tmclsh run` ends, as a `-c` run does, once the transcript it asked for is lost.
            let halt: Halt = if self.limits.needs_transcript {
                let session = shared.clone();
                Box::new(move || session.try_borrow().is_ok_and(|s| lost_transcript(&s)))
            } else {
                never()
            };
            let mut engine = base_engine(&self.limits, budget, watchdog.flag(), &print, halt);
            let log_session = shared.clone();
            common::register(
                &mut engine,
                Rc::from(self.source.as_str()),
                move |message| {
                    if !annotate(&mut log_session.borrow_mut(), &format!("script: {message}")) {
                        eprintln!("log: {}", escape_control(message));
                    }
                },
            );
            register(&mut engine, &shared, &self.sandbox);
            commission::register(&mut engine, &shared, &self.sandbox);
            let record = blocks::Record::default();
            let session = shared.clone();
            let after_failure: Rc<dyn Fn()> = Rc::new(move || {
                if let Ok(mut session) = session.try_borrow_mut() {
                    for message in stop(&mut session) {
                        notice_to_stderr(&escape_control(&message));
                    }
                }
            });
            blocks::register(&mut engine, record.clone(), after_failure);
            execute(&engine, self, &record)
        };
        let result = if watchdog.stop(result.is_ok()) && result.is_err() {
            Err(Failure {
                exit: Exit::DeviceError,
                message: format!(
                    "{}: {}",
                    self.name,
                    limits::out_of_time(self.limits.max_time)
                ),
            })
        } else {
            result
        };
        let session = Rc::try_unwrap(shared)
            .map(RefCell::into_inner)
            .unwrap_or_else(|_| unreachable!("the engine holding the other handles is dropped"));
        (session, result)
    }
}

/// A script's text: a regular file of at most [`crate::file::READ_LIMIT`] bytes; a UTF-8 byte
/// order mark at its start (some Windows editors write one) is skipped, not shown to Rhai as an
/// invisible character it refuses.
fn read_source(path: &Path) -> Result<String, crate::file::FileError> {
    let text = crate::file::read_text(path, crate::file::READ_LIMIT)?;
    Ok(match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_string(),
        None => text,
    })
}

/// Checks that a script compiles, before any connection is opened.
pub fn check_file(path: &Path) -> Result<(), Failure> {
    let name = path.display().to_string();
    let source = read_source(path).map_err(|e| Failure {
        exit: Exit::Refused,
        message: format!("cannot read script {e}"),
    })?;
    let engine = base_engine(
        &Limits::default(),
        None,
        Arc::default(),
        &(Rc::new(print_to_stdout) as PrintSink),
        never(),
    );
    compile(&engine, &name, &source).map(|_| ())
}

/// Why the progress callback ended a script.
const MEMORY: &str = "memory";
const TIME: &str = "time";
const TRANSCRIPT: &str = "transcript";
const STDOUT: &str = "stdout";

/// Whether the run must end before its next operation (a transcript it needs was lost).
type Halt = Box<dyn Fn() -> bool>;

/// Never halts: runs that need no transcript, and compiling.
fn never() -> Halt {
    Box::new(|| false)
}

/// The engine with limits and sandboxing, printing to `print`, without device functions. Rhai's data-size limits are
/// not set: they walk whole values after every call (see [`memory`]); `budget` bounds memory
/// instead, checked at every operation like Ctrl-C and the deadline (`expired`).
fn base_engine(
    limits: &Limits,
    budget: Option<Budget>,
    expired: Arc<AtomicBool>,
    print: &PrintSink,
    halt: Halt,
) -> Engine {
    let mut engine = Engine::new();
    engine.set_optimization_level(OptimizationLevel::Simple);
    engine.set_max_operations(limits.max_operations);
    engine.set_max_call_levels(limits.max_call_depth);
    engine.set_max_expr_depths(128, 64);
    engine.disable_symbol("eval");
    let print = print.clone();
    engine.on_print(move |text| print(&escape_control(text)));
    engine.on_debug(|text, _, pos| eprintln!("debug {pos}: {}", escape_control(text)));
    engine.on_progress(move |_| {
        if expired.load(Ordering::Relaxed) {
            Some(Dynamic::from(TIME))
        } else if interrupt::pending() {
            Some(Dynamic::from("interrupted"))
        } else if budget.is_some_and(Budget::exceeded) {
            Some(Dynamic::from(MEMORY))
        } else if halt() {
            Some(Dynamic::from(TRANSCRIPT))
        } else if crate::stdout::closed() {
            Some(Dynamic::from(STDOUT))
        } else {
            None
        }
    });
    if let Some(budget) = budget {
        memory::register_builders(&mut engine, budget);
    }
    ending::register(&mut engine);
    engine.register_type_with_name::<Failure>("Failure");
    engine.register_fn("to_string", |f: &mut Failure| f.message.clone());
    // `catch (e)` can tell a timeout or noise (3) from a device error (1) by the exit code.
    engine.register_get("exit", |f: &mut Failure| INT::from(f.exit.code()));
    engine
}

/// Rhai's `print` by default: the line on stdout. Every sink gets the text with its control
/// characters escaped like all other output (a line feed stays a line break). A script's strings
/// routinely carry device text — a reply's `raw`, its items, a caught error's message — and by
/// then nothing tells those bytes from the script's own, so a device could retitle or clear the
/// terminal, or hide a failed verdict behind a carriage return, in the output a user or a CI log
/// trusts. The price is that a script cannot colour its output or move the cursor; a verdict needs
/// neither.
pub fn print_to_stdout(escaped: &str) {
    crate::stdout::line(escaped);
}

/// Where the session's notices go during a run: stderr, as the other diagnostics.
fn notice_to_stderr(escaped: &str) {
    eprintln!("tmclsh: {escaped}");
}

fn compile(engine: &Engine, name: &str, source: &str) -> Result<rhai::AST, Failure> {
    engine.compile(source).map_err(|e| Failure {
        exit: Exit::Refused,
        message: at(
            name,
            e.position(),
            &format!("does not compile: {}", e.err_type()),
        ),
    })
}

/// Runs the script and puts what its `test` blocks did in words (in `script.blocks`); blocks
/// that failed fail a run that otherwise passed.
fn execute(engine: &Engine, script: &Script, record: &blocks::Record) -> Result<(), Failure> {
    let name = script.name.as_str();
    let ast = match compile(engine, name, &script.source) {
        Ok(ast) => ast,
        Err(failure) => {
            *script.blocks.borrow_mut() = blocks::Report {
                cases: Vec::new(),
                outside: Some(failure.clone()),
            };
            return Err(failure);
        }
    };
    let context = Context {
        name,
        engine,
        ast: &ast,
        elsewhere: &script.elsewhere,
    };
    let outcome = run_ast(engine, script, &ast, &context);
    let mut ended_in_a_block = false;
    let cases: Vec<blocks::Case> = std::mem::take(&mut *record.borrow_mut())
        .into_iter()
        .map(|ran| blocks::Case {
            name: ran.name,
            time: ran.time,
            failure: match ran.end {
                blocks::End::Passed => None,
                blocks::End::Failed(error) => Some(report(&context, blocks::unwrapped(*error))),
                blocks::End::EndedTheRun => {
                    ended_in_a_block = true;
                    outcome.clone().err()
                }
            },
        })
        .collect();
    let outside = outcome.clone().err().filter(|_| !ended_in_a_block);
    let outcome = match outcome {
        Ok(()) => blocks::verdict(name, &cases).map_or(Ok(()), Err),
        failed => failed,
    };
    *script.blocks.borrow_mut() = blocks::Report { cases, outside };
    outcome
}

/// Runs the compiled script with its arguments; the failure it ended with, in words.
fn run_ast(
    engine: &Engine,
    script: &Script,
    ast: &rhai::AST,
    context: &Context<'_>,
) -> Result<(), Failure> {
    let name = script.name.as_str();
    let mut scope = Scope::new();
    let args: rhai::Array = script
        .args
        .iter()
        .map(|a| Dynamic::from(a.clone()))
        .collect();
    scope.push_constant("args", args);
    let Err(error) = engine.run_ast_with_scope(&mut scope, ast) else {
        return Ok(());
    };
    if let Some(outcome) = ending::outcome(&error) {
        return outcome.map_err(|failure| Failure {
            exit: failure.exit,
            message: at(name, error.position(), &failure.message),
        });
    }
    Err(report(context, *error))
}

/// What a failure is reported with: the script's name, and what explains a call of an unknown
/// function (the functions the engine and the script define, and the caller's [`Elsewhere`]).
struct Context<'a> {
    name: &'a str,
    engine: &'a Engine,
    ast: &'a rhai::AST,
    elsewhere: &'a Elsewhere,
}

impl Context<'_> {
    /// Every function name a script can call here: the engine's, its packages' and the
    /// script's own.
    fn function_names(&self) -> Vec<String> {
        let mut names = function_names(self.engine);
        names.extend(self.ast.iter_functions().map(|f| f.name.to_string()));
        names
    }

    /// The failure for a call of `signature` (`gapp (i64, i64)`), which the engine has no
    /// function for: another dialect's function is refused with what to do (exit 2), a
    /// misspelt one gets the nearest name.
    fn function_not_found(&self, signature: &str, position: Position) -> Failure {
        let function = signature
            .split(|c: char| c == '(' || c.is_whitespace())
            .next()
            .unwrap_or_default();
        if let Some(advice) = (self.elsewhere)(function) {
            return Failure::refused(at(
                self.name,
                position,
                &format!("{function}() is not a function here: {advice}"),
            ));
        }
        let names = self.function_names();
        let suggestion = if names.iter().any(|n| n == function) {
            format!("; {function} takes other arguments")
        } else {
            crate::suggest::did_you_mean(&crate::suggest::nearest(
                function,
                names.iter().map(String::as_str),
            ))
        };
        Failure {
            exit: Exit::DeviceError,
            message: at(
                self.name,
                position,
                &format!("function not found: {signature}{suggestion}"),
            ),
        }
    }
}

/// The names of the functions registered in `engine`, its standard packages included.
fn function_names(engine: &Engine) -> Vec<String> {
    let mut names: Vec<String> = engine
        .gen_fn_signatures(true)
        .iter()
        .filter_map(|signature| signature.split('(').next())
        .map(str::trim)
        .filter(|name| name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
        .map(str::to_string)
        .collect();
    names.sort();
    names.dedup();
    names
}

/// Maps a Rhai error to the exit code and message the user sees.
fn report(context: &Context<'_>, error: EvalAltResult) -> Failure {
    let name = context.name;
    let position = error.position();
    match error {
        EvalAltResult::ErrorFunctionNotFound(signature, _) => {
            context.function_not_found(&signature, position)
        }
        EvalAltResult::ErrorInFunctionCall(function, _, inner, _) => {
            let mut inner = report(context, *inner);
            if !function.is_empty() && !inner.message.contains(" in function ") {
                inner
                    .message
                    .push_str(&format!(" (in function {function})"));
            }
            inner
        }
        EvalAltResult::ErrorRuntime(value, _) if value.is::<Failure>() => {
            let failure = value.cast::<Failure>();
            Failure {
                exit: failure.exit,
                message: at(name, position, &failure.message),
            }
        }
        EvalAltResult::ErrorTerminated(token, _) if token.to_string() == MEMORY => Failure {
            exit: Exit::DeviceError,
            message: at(name, position, memory::MESSAGE),
        },
        EvalAltResult::ErrorTerminated(token, _) if token.to_string() == TRANSCRIPT => {
            let lost = SessionError::TranscriptLost;
            Failure {
                exit: lost.exit(),
                message: at(name, position, &lost.to_string()),
            }
        }
        EvalAltResult::ErrorTerminated(token, _) if token.to_string() == STDOUT => Failure {
            exit: crate::stdout::EXIT,
            message: at(name, position, "stdout was closed"),
        },
        EvalAltResult::ErrorTerminated(..) => Failure {
            exit: Exit::Interrupted,
            message: at(name, position, "interrupted"),
        },
        EvalAltResult::ErrorTooManyOperations(..) => Failure {
            exit: Exit::DeviceError,
            message: at(
                name,
                position,
                "runaway script: too many operations (raise the cap with --max-operations)",
            ),
        },
        EvalAltResult::ErrorStackOverflow(..) => Failure {
            exit: Exit::DeviceError,
            message: at(
                name,
                position,
                "calls nested too deeply (raise the cap with --max-call-depth)",
            ),
        },
        EvalAltResult::ErrorRuntime(value, _) => Failure {
            exit: Exit::DeviceError,
            message: at(name, position, &format!("error: {value}")),
        },
        mut other => {
            // Rhai writes the position after the message; it is already in front.
            other.clear_position();
            Failure {
                exit: Exit::DeviceError,
                message: at(name, position, &other.to_string()),
            }
        }
    }
}

fn at(name: &str, position: Position, message: &str) -> String {
    match (position.line(), position.position()) {
        (Some(line), Some(column)) => format!("{name}:{line}:{column}: {message}"),
        (Some(line), None) => format!("{name}:{line}: {message}"),
        _ => format!("{name}: {message}"),
    }
}

#[cfg(test)]
mod tests;
