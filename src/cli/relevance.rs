//! Options that would change nothing are refused, not ignored: the shared group of connection
//! and session options is flattened into every subcommand that talks to a module, and these
//! tables say which of them a subcommand, a dialect or a connection has no use for. An option
//! given on the command line where it has no use ends the run with exit code 2 before anything
//! is sent; the same option from an environment variable (`TMCLSH_BAUD`, …) is left alone.

use clap::error::ErrorKind;
use clap::parser::ValueSource;
use clap::{ArgMatches, Args, Command};

use crate::dialect::{Dialect, all};

use super::connection::ModuleArgs;
use super::position::{flag, leaf_matches, subcommand_mut, subcommand_path};

/// Shared options a subcommand receives with the group but has no use for: hidden from its help
/// and refused when given. (subcommands, option ids, why) — the ids are checked by a test.
const UNUSED: &[(&[&str], &[&str], &str)] = &[
    (
        &["download"],
        &["no_validate"],
        "a program is checked when it is assembled or loaded",
    ),
    (
        &["download"],
        &["address", "prefix_comma", "quiet_gap"],
        "it stores TMCL programs",
    ),
    (
        &["upload"],
        &["no_validate"],
        "it sends only reads of program memory",
    ),
    (
        &["upload"],
        &["address", "prefix_comma", "quiet_gap"],
        "it reads TMCL programs",
    ),
    (
        &["scan"],
        &["module", "address"],
        "a scan tries every address in --addresses",
    ),
    (
        &["scan"],
        &["no_enter", "stay_ascii", "binary"],
        "a scan finds modules in either mode and leaves each in the mode it was found in",
    ),
    (
        &["scan"],
        &["say_module"],
        "a scan names every module it finds",
    ),
    (
        &["scan"],
        &["echo"],
        "a scan reads the echo of every module and leaves it as found",
    ),
    (
        &["scan", "params", "snapshot save", "snapshot diff"],
        &["no_validate", "quiet_gap"],
        "it sends no typed lines",
    ),
    (
        &["snapshot restore"],
        &["quiet_gap"],
        "it asks for no multi-line replies",
    ),
];

/// Subcommands that only one dialect has: (subcommand, dialect name).
const ONE_DIALECT: &[(&str, &str)] = &[("download", "tmcl"), ("upload", "tmcl")];

/// The subcommand that takes every shared option to show what it would set (`tmclsh config`).
const SHOWS_ALL: &str = "config";

/// Hides the options of [`UNUSED`] from the help of their subcommands (they are still parsed, so
/// that [`check`] can say why they are refused; clap_complete lists hidden options all the same).
pub(super) fn hide_unused(mut cmd: Command) -> Command {
    for (paths, ids, _) in UNUSED {
        for path in *paths {
            let words: Vec<&str> = path.split(' ').collect();
            cmd = in_subcommand(cmd, &words, &|sub: Command| {
                ids.iter()
                    .fold(sub, |sub, id| sub.mut_arg(*id, |a| a.hide(true)))
            });
        }
    }
    cmd
}

/// Applies `f` to the subcommand at `words`, keeping the subcommands in their order.
fn in_subcommand(cmd: Command, words: &[&str], f: &dyn Fn(Command) -> Command) -> Command {
    match words.split_first() {
        None => f(cmd),
        Some((first, rest)) => cmd.mut_subcommands(|sub| {
            if sub.get_name() == *first {
                in_subcommand(sub, rest, f)
            } else {
                sub
            }
        }),
    }
}

/// Refuses (with a usage error naming each) the options given on the command line that the
/// parsed command has no use for. `cmd` is the built command `matches` came from.
pub(super) fn check(cmd: &mut Command, matches: &ArgMatches) -> Result<(), clap::Error> {
    let path = subcommand_path(matches).unwrap_or_default();
    if path == [SHOWS_ALL] {
        return Ok(());
    }
    let refusals = refusals(&path.join(" "), leaf_matches(matches));
    if refusals.is_empty() {
        return Ok(());
    }
    let sub = subcommand_mut(cmd, &path);
    let lines: Vec<String> = refusals
        .iter()
        .map(|(id, why)| {
            let arg = sub
                .get_arguments()
                .find(|a| a.get_id().as_str() == id)
                .expect("a given option is an argument of its command");
            format!("{} {why}", flag(arg))
        })
        .collect();
    Err(sub.error(ErrorKind::ArgumentConflict, lines.join("\n")))
}

/// The options given on the command line of subcommand `words` ("" for the shell) that it has no
/// use for, each once, with why.
fn refusals(words: &str, leaf: &ArgMatches) -> Vec<(String, String)> {
    let given = |id: &str| {
        leaf.ids().any(|i| i.as_str() == id)
            && leaf.value_source(id) == Some(ValueSource::CommandLine)
    };
    let mut refusals: Vec<(String, String)> = Vec::new();
    let mut refuse = |ids: &[&str], why: String| {
        for id in ids.iter().filter(|id| given(id)) {
            if refusals.iter().all(|(seen, _)| seen != id) {
                refusals.push((id.to_string(), why.clone()));
            }
        }
    };
    let named = if words.is_empty() {
        "the shell".to_string()
    } else {
        format!("`tmclsh {words}`")
    };
    for (at, ids, why) in UNUSED {
        if at.contains(&words) {
            refuse(ids, format!("does not apply to {named}: {why}"));
        }
    }
    if let Some(chosen) = dialect(leaf) {
        for other in all().iter().filter(|d| !std::ptr::eq(**d, chosen)) {
            let why = other.refusal(chosen);
            let ids = other.owned_options();
            refuse(&strs(&ids), why);
        }
        for (at, owner) in ONE_DIALECT {
            let owner = crate::dialect::by_name(owner).expect("a listed dialect");
            if *at == words && owner != chosen {
                let why = format!(
                    "{} does not apply to {named}: it works with {} only",
                    chosen.name, owner.devices
                );
                refuse(&["protocol"], why);
            }
        }
    }
    if given("sim") && (given("port") || given("tcp")) {
        refuse(
            &["sim"],
            "and a link to hardware name two modules; give one".into(),
        );
    }
    if given("port") && given("tcp") {
        refuse(&["tcp"], "and --port name two links; give one".into());
    }
    if words == "ports" {
        if !given("probe") {
            refuse(&["baud", "protocol", "module"], "goes with --probe".into());
        }
        return refusals;
    }
    let can = can_kind(leaf);
    if can.is_none() {
        let why = "is a setting of a CAN link; give it with --can";
        refuse(&["can_bitrate", "can_reply_id"], why.into());
    }
    if can == Some(CanKind::SocketCan) {
        let why = "is not tmclsh's to set on SocketCAN: the interface has its rate (`ip link set \
                   can0 type can bitrate 1000000`)";
        refuse(&["can_bitrate"], why.into());
    }
    let slcan = can == Some(CanKind::Slcan);
    if (!has_value(leaf, "port") && !slcan) || given("tcp") {
        let why = "is the bit rate of a serial port; give it with --port (or --can slcan:PATH)";
        refuse(&["baud"], why.into());
    }
    if !has_value(leaf, "port") && !has_value(leaf, "tcp") && !slcan {
        let why = "is a setting of a serial line; give it with --port";
        refuse(&LINE_IDS, why.into());
    }
    if words == "params" && !given("values") {
        let why =
            "does not apply to `tmclsh params` without --values: the table comes from the profile";
        refuse(&strs(&link_ids()), why.into());
    }
    if words == "snapshot diff" && has_value(leaf, "other") {
        refuse(
            &strs(&link_ids()),
            "does not apply to comparing two snapshot files".into(),
        );
    }
    refusals
}

/// The serial line's settings: they need a port (or a serial server, where they are noted as
/// not applied).
const LINE_IDS: [&str; 5] = ["dtr", "rts", "rs485", "rs485_delay", "keep_latency"];

/// The kind of CAN link `--can` (or `TMCLSH_CAN`, or a file) names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum CanKind {
    Slcan,
    SocketCan,
}

fn can_kind(matches: &ArgMatches) -> Option<CanKind> {
    let spec = matches
        .try_get_one::<super::can::CanSpec>("can")
        .ok()
        .flatten()?;
    Some(match spec {
        super::can::CanSpec::Slcan(_) => CanKind::Slcan,
        super::can::CanSpec::SocketCan(_) => CanKind::SocketCan,
    })
}

/// The protocol in effect, for commands that have the option.
fn dialect(matches: &ArgMatches) -> Option<&'static Dialect> {
    matches
        .try_get_one::<&'static Dialect>("protocol")
        .ok()
        .flatten()
        .copied()
}

/// Whether `id` has a value from anywhere (command line or environment).
fn has_value(matches: &ArgMatches, id: &str) -> bool {
    matches.try_contains_id(id).unwrap_or(false) && matches.value_source(id).is_some()
}

/// The ids as `refuse` takes them.
fn strs(ids: &[String]) -> Vec<&str> {
    ids.iter().map(String::as_str).collect()
}

/// The ids of the shared connection and session options that need a module: all but
/// `--protocol` and `--profile`, which also choose the tables read offline.
fn link_ids() -> Vec<String> {
    ModuleArgs::augment_args(Command::new("module"))
        .get_arguments()
        .map(|a| a.get_id().to_string())
        .filter(|id| !["protocol", "profile"].contains(&id.as_str()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_unused_option_names_a_subcommand_and_an_option_it_has() {
        let cmd = <crate::cli::Cli as clap::CommandFactory>::command();
        for (path, ids, _) in UNUSED
            .iter()
            .flat_map(|(paths, ids, why)| paths.iter().map(move |path| (path, ids, why)))
        {
            let sub = path
                .split(' ')
                .try_fold(&cmd, |cmd, word| cmd.find_subcommand(word))
                .unwrap_or_else(|| panic!("no subcommand `{path}`"));
            for id in *ids {
                assert!(
                    sub.get_arguments().any(|a| a.get_id() == id),
                    "`{path}` has no option {id}"
                );
            }
        }
    }

    #[test]
    fn the_dialect_options_are_options_of_the_shell() {
        let cmd = <crate::cli::Cli as clap::CommandFactory>::command();
        for id in all().iter().flat_map(|d| d.owned_options()) {
            assert!(cmd.get_arguments().any(|a| a.get_id() == &id), "{id}");
        }
    }

    #[test]
    fn hiding_keeps_the_subcommands_in_their_order() {
        let names = |cmd: &Command| -> Vec<String> {
            cmd.get_subcommands()
                .map(|s| s.get_name().to_string())
                .collect()
        };
        let plain = <crate::cli::Cli as clap::CommandFactory>::command();
        assert_eq!(names(&hide_unused(plain.clone())), names(&plain));
    }
}
