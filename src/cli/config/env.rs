//! The options' environment variables (each option's `env`, listed by the manual page's
//! ENVIRONMENT section): an empty one counts as unset, as a missing one does, for every variable
//! alike (`TMCLSH_PORT= tmclsh` is the built-in simulator, `TMCLSH_TIMEOUT=` the built-in
//! timeout); a value its option would refuse is refused with exit 2 naming the variable, before
//! anything is opened.

use clap::Command;
use clap::error::ErrorKind;

use super::super::ports::usb::UsbSpec;
use super::file::option_accepts;

/// `cmd` with the empty variables' options reading no variable, or the error naming the first
/// variable whose value its option refuses.
pub(in crate::cli) fn apply(cmd: Command) -> Result<Command, clap::Error> {
    let mut cmd = unset_empty(cmd);
    let set: Vec<(String, String)> = cmd
        .get_arguments()
        .filter_map(|arg| {
            let name = arg.get_env()?.to_string_lossy().into_owned();
            Some((arg.get_id().to_string(), name))
        })
        .collect();
    for (id, name) in set {
        let Some(value) = std::env::var_os(&name) else {
            continue;
        };
        let refused = match value.to_str() {
            None => Some("not UTF-8 text".to_string()),
            // A usb: name is checked as a file's port is.
            Some(text) => match UsbSpec::parse(text) {
                Some(Err(why)) if id == "port" => Some(why.to_string()),
                _ => option_accepts(&cmd, &id, text).err(),
            },
        };
        if let Some(why) = refused {
            let message = format!(
                "environment variable {name}: {}",
                crate::escape::escape_control(&why)
            );
            return Err(cmd.error(ErrorKind::ValueValidation, message));
        }
    }
    cmd.build();
    Ok(cmd)
}

/// Drops the variable of every option (here and in the subcommands) whose variable is empty.
fn unset_empty(cmd: Command) -> Command {
    cmd.mut_args(|arg| match arg.get_env() {
        Some(name) if std::env::var_os(name).is_some_and(|v| v.is_empty()) => arg.env(None::<&str>),
        _ => arg,
    })
    .mut_subcommands(unset_empty)
}

/// Variables of tmclsh's test harness (`TMCLSH_TEST_PORT` …), set around the runs they steer.
const HARNESS: &[&str] = &["TMCLSH_TEST_", "TMCLSH_REQUIRE_"];

/// The `TMCLSH_*` variables set in the environment that no option of `cmd` (or of its
/// subcommands) reads, each named with the nearest one that is read: a misspelt
/// `TMCLSH_POTR` would otherwise leave the port unset without a word.
pub(in crate::cli) fn unknown(cmd: &Command) -> Vec<String> {
    let mut known = Vec::new();
    collect(cmd, &mut known);
    let mut set: Vec<String> = std::env::vars_os()
        .filter_map(|(name, _)| name.into_string().ok())
        .filter(|name| name.starts_with(PREFIX) && !known.contains(name))
        .filter(|name| !HARNESS.iter().any(|h| name.starts_with(h)))
        .collect();
    set.sort();
    let tails: Vec<&str> = known.iter().map(|k| &k[PREFIX.len()..]).collect();
    set.iter()
        .map(|name| {
            let nearest = crate::suggest::nearest(&name[PREFIX.len()..], tails.iter().copied());
            format!(
                "unknown environment variable {}, ignored{}",
                crate::escape::escape_control(name),
                crate::suggest::did_you_mean(&nearest.map(|n| format!("{PREFIX}{n}")))
            )
        })
        .collect()
}

/// What every tmclsh variable starts with.
const PREFIX: &str = "TMCLSH_";

/// The variables the options of `cmd` and its subcommands read.
fn collect(cmd: &Command, into: &mut Vec<String>) {
    for arg in cmd.get_arguments() {
        if let Some(name) = arg.get_env().and_then(|n| n.to_str()) {
            if !into.iter().any(|k| k == name) {
                into.push(name.to_string());
            }
        }
    }
    for sub in cmd.get_subcommands() {
        collect(sub, into);
    }
}
