//! Rhai scripting: commissioning and test sequences with loops and assertions, run from a shell
//! or CI (`tmclsh run`) or from the REPL (`:source`), where the exit code is the verdict.
//!
//! Scripts reach the module only through the session, cannot touch files (except the snapshot and
//! recording files they name), processes or the network (no module resolver, no I/O functions),
//! and run with capped operations and call depth.
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

mod commission;
mod common;
pub mod failure;
mod smd4;
mod tmcl;
mod waiting;

use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

use rhai::{Dynamic, Engine, EvalAltResult, INT, OptimizationLevel, Position, Scope};

use crate::exit::Exit;
use crate::session::Session;
use crate::session::interrupt;
use crate::session::smd4::Smd4Session;
use crate::session::tmcl::TmclSession;

pub use failure::ScriptFailure;

/// Limits a script runs under.
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// Operations before a runaway script is stopped (0 = no limit).
    pub max_operations: u64,
    /// Deepest function call nesting.
    pub max_call_depth: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_operations: 100_000_000,
            max_call_depth: 64,
        }
    }
}

/// A script's failure as reported: `file:line:column: message` and the exit code.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The exit code.
    pub exit: Exit,
    /// The message, with file, line and column where known.
    pub message: String,
}

/// Runs the script at `path` with `args` over `session`; returns the session and the outcome.
pub fn run_file(
    path: &Path,
    args: &[String],
    session: Session,
    limits: Limits,
) -> (Session, Result<(), Report>) {
    let name = path.display().to_string();
    match std::fs::read_to_string(path) {
        Ok(source) => run_source(&name, &source, args, session, limits),
        Err(e) => (
            session,
            Err(Report {
                exit: Exit::Refused,
                message: format!("cannot read script {name}: {e}"),
            }),
        ),
    }
}

/// Runs script text; `name` labels messages.
pub fn run_source(
    name: &str,
    source: &str,
    args: &[String],
    session: Session,
    limits: Limits,
) -> (Session, Result<(), Report>) {
    let script = Script {
        name,
        source,
        args,
        limits,
    };
    match session {
        Session::Tmcl(s) => {
            let (s, result) = script.run(s, TmclSession::annotate, |engine, s| {
                tmcl::register(engine, s);
                commission::register(engine, s);
            });
            (Session::Tmcl(s), result)
        }
        Session::Smd4(s) => {
            let (s, result) = script.run(s, Smd4Session::annotate, |engine, s| {
                smd4::register(engine, s);
                commission::register(engine, s);
            });
            (Session::Smd4(s), result)
        }
    }
}

/// A script about to run.
struct Script<'a> {
    name: &'a str,
    source: &'a str,
    args: &'a [String],
    limits: Limits,
}

impl Script<'_> {
    /// Runs over a session of type `S`: the engine holds the session for the run and gives it
    /// back when dropped.
    fn run<S: 'static>(
        &self,
        session: S,
        annotate: fn(&mut S, &str) -> bool,
        register: fn(&mut Engine, &Rc<RefCell<S>>),
    ) -> (S, Result<(), Report>) {
        let shared = Rc::new(RefCell::new(session));
        let result = {
            let mut engine = base_engine(self.limits);
            let log_session = shared.clone();
            common::register(&mut engine, move |message| {
                if !annotate(&mut log_session.borrow_mut(), &format!("script: {message}")) {
                    eprintln!("log: {message}");
                }
            });
            register(&mut engine, &shared);
            execute(&engine, self.name, self.source, self.args)
        };
        let session = Rc::try_unwrap(shared)
            .map(RefCell::into_inner)
            .unwrap_or_else(|_| unreachable!("the engine holding the other handles is dropped"));
        (session, result)
    }
}

/// Checks that a script compiles, before any connection is opened.
pub fn check_file(path: &Path) -> Result<(), Report> {
    let name = path.display().to_string();
    let source = std::fs::read_to_string(path).map_err(|e| Report {
        exit: Exit::Refused,
        message: format!("cannot read script {name}: {e}"),
    })?;
    compile(&base_engine(Limits::default()), &name, &source).map(|_| ())
}

/// The engine with limits and sandboxing, without device functions.
fn base_engine(limits: Limits) -> Engine {
    let mut engine = Engine::new();
    engine.set_optimization_level(OptimizationLevel::Simple);
    engine.set_max_operations(limits.max_operations);
    engine.set_max_call_levels(limits.max_call_depth);
    engine.set_max_expr_depths(128, 64);
    engine.set_max_string_size(1 << 20);
    engine.set_max_array_size(1 << 20);
    engine.set_max_map_size(1 << 16);
    engine.set_module_resolver(rhai::module_resolvers::DummyModuleResolver::new());
    engine.disable_symbol("eval");
    engine.on_print(|text| println!("{text}"));
    engine.on_debug(|text, _, pos| eprintln!("debug {pos}: {text}"));
    engine.on_progress(|_| interrupt::pending().then(|| Dynamic::from("interrupted")));
    engine.register_type_with_name::<ScriptFailure>("Failure");
    engine.register_fn("to_string", |f: &mut ScriptFailure| f.message.clone());
    // `catch (e)` can tell a timeout or noise (3) from a device error (1) by the exit code.
    engine.register_get("exit", |f: &mut ScriptFailure| INT::from(f.exit.code()));
    engine
}

fn compile(engine: &Engine, name: &str, source: &str) -> Result<rhai::AST, Report> {
    engine.compile(source).map_err(|e| Report {
        exit: Exit::Refused,
        message: at(
            name,
            e.position(),
            &format!("does not compile: {}", e.err_type()),
        ),
    })
}

fn execute(engine: &Engine, name: &str, source: &str, args: &[String]) -> Result<(), Report> {
    let ast = compile(engine, name, source)?;
    let mut scope = Scope::new();
    let args: rhai::Array = args.iter().map(|a| Dynamic::from(a.clone())).collect();
    scope.push_constant("args", args);
    engine
        .run_ast_with_scope(&mut scope, &ast)
        .map_err(|e| report(name, *e))
}

/// Maps a Rhai error to the exit code and message the user sees.
fn report(name: &str, error: EvalAltResult) -> Report {
    let position = error.position();
    match error {
        EvalAltResult::ErrorInFunctionCall(function, _, inner, _) => {
            let mut inner = report(name, *inner);
            if !function.is_empty() && !inner.message.contains(" in function ") {
                inner
                    .message
                    .push_str(&format!(" (in function {function})"));
            }
            inner
        }
        EvalAltResult::ErrorRuntime(value, _) if value.is::<ScriptFailure>() => {
            let failure = value.cast::<ScriptFailure>();
            Report {
                exit: failure.exit,
                message: at(name, position, &failure.message),
            }
        }
        EvalAltResult::ErrorTerminated(..) => Report {
            exit: Exit::Interrupted,
            message: at(name, position, "interrupted"),
        },
        EvalAltResult::ErrorTooManyOperations(..) => Report {
            exit: Exit::DeviceError,
            message: at(
                name,
                position,
                "runaway script: too many operations (raise the cap with --max-operations)",
            ),
        },
        EvalAltResult::ErrorStackOverflow(..) => Report {
            exit: Exit::DeviceError,
            message: at(
                name,
                position,
                "calls nested too deeply (raise the cap with --max-call-depth)",
            ),
        },
        EvalAltResult::ErrorRuntime(value, _) => Report {
            exit: Exit::DeviceError,
            message: at(name, position, &format!("error: {value}")),
        },
        other => Report {
            exit: Exit::DeviceError,
            message: at(name, position, &strip_position(&other.to_string())),
        },
    }
}

fn at(name: &str, position: Position, message: &str) -> String {
    match (position.line(), position.position()) {
        (Some(line), Some(column)) => format!("{name}:{line}:{column}: {message}"),
        (Some(line), None) => format!("{name}:{line}: {message}"),
        _ => format!("{name}: {message}"),
    }
}

/// Rhai appends " (line L, position P)" to its messages; the position is already in front.
fn strip_position(message: &str) -> String {
    match message.rfind(" (line ") {
        Some(i) if message.ends_with(')') => message[..i].to_string(),
        _ => message.to_string(),
    }
}

#[cfg(test)]
mod tests;
