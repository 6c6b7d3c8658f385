//! The kinds of link a command can be given, in one list: the refusal of a command run without
//! a terminal and without a link, the configuration keys and `tmclsh config`'s `# link:` line
//! are all made from it, so a new kind of link is one more row.
//!
//! Where several are set, the one from the highest source wins (command line > environment >
//! configuration file), `--sim` (or `sim = true`) counting as one more; two from the same
//! source are refused, since nobody can tell which was meant.

use clap::ArgMatches;

use crate::exit::{Exit, ExitStatus};
use clap::parser::ValueSource;

/// A kind of link to hardware: its option id (which is its long flag and its configuration key)
/// and its environment variable.
#[derive(Debug)]
pub(super) struct LinkKind {
    /// The option's id, its long flag without dashes and its key in the configuration files.
    pub(super) id: &'static str,
    /// Its environment variable.
    pub(super) env: &'static str,
}

/// Every kind of link to hardware, in the order messages name them.
pub(super) const LINK_KINDS: &[LinkKind] = &[
    LinkKind {
        id: "port",
        env: "TMCLSH_PORT",
    },
    LinkKind {
        id: "tcp",
        env: "TMCLSH_TCP",
    },
    LinkKind {
        id: "can",
        env: "TMCLSH_CAN",
    },
];

/// The id of `--sim`, the built-in simulator as an explicit choice.
pub(super) const SIM: &str = "sim";

/// Why a command run without a terminal will not start without a link (exit 2).
pub(super) fn no_link() -> String {
    let flags: Vec<String> = LINK_KINDS.iter().map(|k| format!("--{}", k.id)).collect();
    let vars: Vec<&str> = LINK_KINDS.iter().map(|k| k.env).collect();
    let keys: Vec<&str> = LINK_KINDS.iter().map(|k| k.id).collect();
    format!(
        "no module to talk to: give {} (or {}, or {} in tmclsh.toml), or --sim for the built-in \
         simulator",
        either(&flags),
        either(&vars),
        either(&keys)
    )
}

/// The flags that name hardware, for hints: `--port or --tcp`.
pub(super) fn hardware_flags() -> String {
    let flags: Vec<String> = LINK_KINDS.iter().map(|k| format!("--{}", k.id)).collect();
    either(&flags)
}

/// `a`, `a or b`, `a, b or c`.
fn either<S: AsRef<str>>(words: &[S]) -> String {
    match words {
        [] => String::new(),
        [one] => one.as_ref().to_string(),
        [rest @ .., last] => {
            let rest: Vec<&str> = rest.iter().map(AsRef::as_ref).collect();
            format!("{} or {}", rest.join(", "), last.as_ref())
        }
    }
}

/// Whether `name` is one of the link kinds' keys or `sim`.
pub(super) fn is_link_key(name: &str) -> bool {
    name == SIM || LINK_KINDS.iter().any(|k| k.id == name)
}

/// How high a source ranks: the command line over the environment over a file.
fn rank(source: Option<ValueSource>) -> u8 {
    match source {
        Some(ValueSource::CommandLine) => 3,
        Some(ValueSource::EnvVariable) => 2,
        _ => 1,
    }
}

/// Two settings of the same source naming different links (`--port` and `--tcp`): refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{} name different links; give one", named.join(" and "))]
pub(super) struct LinkClash {
    /// The settings, as the user gave them.
    named: Vec<String>,
}

impl ExitStatus for LinkClash {
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}

/// The link `matches` (a leaf command's) choose: the id of the winning kind or [`SIM`], `None`
/// when nothing chooses one; an error when two of the same source do.
pub(super) fn chosen(matches: &ArgMatches) -> Result<Option<&'static str>, LinkClash> {
    let has = |id: &str| matches.try_contains_id(id).unwrap_or(false);
    let mut set: Vec<(&'static str, u8)> = LINK_KINDS
        .iter()
        .filter(|k| {
            has(k.id)
                && matches
                    .get_raw(k.id)
                    .is_some_and(|mut v| v.next().is_some())
        })
        .map(|k| (k.id, rank(matches.value_source(k.id))))
        .collect();
    if has(SIM) && matches.get_flag(SIM) {
        set.push((SIM, rank(matches.value_source(SIM))));
    }
    let Some(top) = set.iter().map(|(_, r)| *r).max() else {
        return Ok(None);
    };
    let winners: Vec<&str> = set
        .iter()
        .filter(|(_, r)| *r == top)
        .map(|(id, _)| *id)
        .collect();
    match winners.as_slice() {
        [one] => Ok(Some(one)),
        several => {
            let named: Vec<String> = several
                .iter()
                .map(|id| match top {
                    3 => format!("--{id}"),
                    2 => env_of(id).unwrap_or(id).to_string(),
                    _ => format!("`{id}` in the configuration"),
                })
                .collect();
            Err(LinkClash { named })
        }
    }
}

/// The environment variable of the kind `id`.
fn env_of(id: &str) -> Option<&'static str> {
    LINK_KINDS.iter().find(|k| k.id == id).map(|k| k.env)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_refusal_names_every_kind_of_link() {
        assert_eq!(
            no_link(),
            "no module to talk to: give --port, --tcp or --can (or TMCLSH_PORT, TMCLSH_TCP or \
             TMCLSH_CAN, or port, tcp or can in tmclsh.toml), or --sim for the built-in simulator"
        );
    }

    #[test]
    fn lists_read_as_prose() {
        assert_eq!(either(&["a"]), "a");
        assert_eq!(either(&["a", "b"]), "a or b");
        assert_eq!(either(&["a", "b", "c"]), "a, b or c");
    }
}
