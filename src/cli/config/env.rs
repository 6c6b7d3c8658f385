//! The options' environment variables (`TMCLSH_PORT`, `TMCLSH_BAUD`, `TMCLSH_PROTOCOL`,
//! `TMCLSH_PROFILE`, `TMCLSH_MODULE`, `TMCLSH_TIMEOUT`): an empty one counts as unset, as a
//! missing one does, for every variable alike (`TMCLSH_PORT= tmclsh` is the built-in simulator,
//! `TMCLSH_TIMEOUT=` the built-in timeout); a value its option would refuse is refused with exit
//! 2 naming the variable, before anything is opened.

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
                Some(Err(why)) if id == "port" => Some(why),
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
