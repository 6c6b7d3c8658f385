//! The one list of script functions: each with its signature and one line of help. The engine's
//! registrations are checked against it by a test (every function registered is listed, every
//! listed function registered), and it feeds `:help NAME` in the shell, the list in
//! `tmclsh run --help`, the completion of `:help` topics, and the generated
//! docs/script-functions.md. Every script has [`SHARED`]; each dialect lists its own device
//! functions in its descriptor (`Dialect::script_functions`).

use std::fmt::Write;

/// A function scripts can call.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ScriptFn {
    /// How it is called, optional arguments in brackets, with what it returns (`-> int`).
    pub signature: &'static str,
    /// What it does, in one line.
    pub help: &'static str,
}

const fn f(signature: &'static str, help: &'static str) -> ScriptFn {
    ScriptFn { signature, help }
}

impl ScriptFn {
    /// Its name: the signature up to its parenthesis.
    pub fn name(&self) -> &'static str {
        let signature = self.signature;
        signature
            .split_once('(')
            .map_or(signature, |(name, _)| name)
    }
}

/// The functions every script has, whatever its dialect.
pub const SHARED: &[ScriptFn] = &[
    f(
        "test(name, || { … })",
        "runs the closure as one named test case: a failure is reported (run --junit), the motors stopped, and the next block runs",
    ),
    f(
        "assert(condition[, message])",
        "fails the script (exit 1) when the condition is false",
    ),
    f(
        "assert_eq(a, b[, message])",
        "fails the script (exit 1) unless a equals b (numbers compared as numbers), showing both",
    ),
    f(
        "assert_near(a, b, tolerance)",
        "fails the script (exit 1) unless a and b differ by at most tolerance",
    ),
    f(
        "wait_until(|| condition, timeout_ms)",
        "polls the closure until it is true; a timeout (exit 3) quotes the condition and its last value",
    ),
    f(
        "sleep(ms)",
        "waits ms milliseconds (Ctrl-C and --max-time end it)",
    ),
    f(
        "log(message)",
        "writes the message to the transcript (--log), or to stderr without one",
    ),
    f(
        "exit([value])",
        "ends the script: exit() or exit(0) passes, any other value fails it (exit 1)",
    ),
    f(
        "snapshot_save(path) -> int",
        "saves every readable parameter to a new snapshot file; returns how many",
    ),
    f(
        "snapshot_diff(path) -> [#{name, place, file, current, unit}]",
        "compares a snapshot file with the module; returns the settings that differ",
    ),
    f(
        "snapshot_restore(path[, store[, force]]) -> int",
        "writes a snapshot's settings back, each verified; store makes them permanent; returns how many",
    ),
    f(
        "record_csv(path, params, interval_ms, duration_ms) -> int",
        "samples parameters every interval_ms for duration_ms into a new CSV file; returns how many samples",
    ),
];

/// The function called `name` among `tables`.
pub fn find<'a>(tables: &[&'a [ScriptFn]], name: &str) -> Option<&'a ScriptFn> {
    tables
        .iter()
        .flat_map(|t| t.iter())
        .find(|f| f.name() == name)
}

/// `:help NAME` for a script function: its signature and help.
pub fn help_line(function: &ScriptFn) -> String {
    format!(
        "{} — {} (script function)",
        function.signature, function.help
    )
}

/// The functions of `tables` as an indented list under their titles, for `run --help`.
pub fn listing(tables: &[(String, &[ScriptFn])]) -> String {
    let mut out = String::new();
    for (title, functions) in tables {
        let _ = writeln!(out, "{title}:");
        for function in *functions {
            let _ = writeln!(out, "  {}", function.signature);
            let _ = writeln!(out, "      {}", function.help);
        }
    }
    out
}

/// docs/script-functions.md: every table as a Markdown section.
pub fn markdown(tables: &[(String, &[ScriptFn])]) -> String {
    let mut out = String::from(
        "# Script functions\n\n<!-- Generated from src/script/registry.rs and each dialect's list by the test \
         suite: do not edit; regenerate with `TMCLSH_REGENERATE=1 cargo test --lib dialect::functions`. -->\n\n\
         The functions a `tmclsh run` script or a `:source` in the shell can call, besides Rhai's own \
         (see [Scripts](scripts.md)). `:help NAME` in the shell and `tmclsh run --help` show the same.\n",
    );
    for (title, functions) in tables {
        let _ = write!(out, "\n## {title}\n\n| function | does |\n|---|---|\n");
        for function in *functions {
            let _ = writeln!(
                out,
                "| `{}` | {} |",
                function.signature.replace('|', "\\|"),
                function.help.replace('|', "\\|")
            );
        }
    }
    out
}
