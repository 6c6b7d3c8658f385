//! Helper commands: lines starting with `:`, shared by the REPL and non-interactive use. This
//! table holds the helpers every dialect has; each dialect adds its own ([`Dialect::helpers`]).
//! Together they drive dispatch, `:help` and completion.

use crate::dialect::helper::{ArgKind, Helper, Section, helper};
use crate::dialect::{Dialect, all};

/// The helpers every dialect has (`:params` and `:target` are answered by the dialect).
pub const SHARED: &[Helper] = &[
    helper(
        ":help [topic]",
        "this help; topics: a command, a parameter, a helper, params, exit, ascii or addressing",
        ArgKind::Topic,
        Section::Session,
    ),
    helper(
        ":params [--values] [--motor N] [filter]",
        "list the module's parameters or settings (matching filter); --values reads them, --motor N (with --values) one motor's",
        ArgKind::Param,
        Section::Session,
    ),
    helper(
        ":target [N|CHAR]",
        "show the module addressed, or address another (TMCL: 2 or B; SMD4: @N, none for no prefix)",
        ArgKind::Module,
        Section::Session,
    ),
    helper(
        ":log FILE|off|time [on|off]",
        "append a transcript of every byte to FILE, or stop; time: the time before each reply",
        ArgKind::File,
        Section::Output,
    ),
    helper(
        ":line",
        "the link's state: rate, modem lines, latency timer, bytes and replies, error counters",
        ArgKind::None,
        Section::Output,
    ),
    helper(
        ":raw",
        "toggle showing replies exactly as received",
        ArgKind::None,
        Section::Output,
    ),
    helper(
        ":source SCRIPT.rhai [ARGS...]",
        "run a Rhai script against the session (Ctrl-C stops it and the motors)",
        ArgKind::File,
        Section::Tools,
    ),
    helper(
        ":snapshot save|diff|restore FILE",
        "save the module's parameters to a TOML file, compare with one, or write one back",
        ArgKind::Snapshot,
        Section::Tools,
    ),
    helper(
        ":scan [ADDRESSES] [TIME]",
        "find the modules on the bus (TMCL 1-26 with firmware and echo; SMD4 1-247)",
        ArgKind::Module,
        Section::Tools,
    ),
    helper(
        ":watch PARAM[,PARAM…] [INTERVAL]",
        "live table of parameters; any key stops, Ctrl-C also stops the motor",
        ArgKind::Param,
        Section::Tools,
    ),
    helper(
        ":record FILE.csv PARAM[,…] [INTERVAL] [DURATION]",
        "sample parameters with timestamps into a CSV file",
        ArgKind::Record,
        Section::Tools,
    ),
    helper(
        ":plot [FILE.csv]",
        "chart the last recording (or a CSV file) against time",
        ArgKind::File,
        Section::Tools,
    ),
    helper(
        ":quit",
        "leave, putting the modules back in the mode they were found in",
        ArgKind::None,
        Section::Tools,
    ),
];

/// The helpers `dialect` has, in the order they are listed: by section, the shared ones of a
/// section before the dialect's own.
pub fn available(dialect: &'static Dialect) -> impl Iterator<Item = &'static Helper> {
    let mut all: Vec<(Section, usize, &'static Helper)> = SHARED
        .iter()
        .map(|h| (h.section, 0, h))
        .chain(dialect.helpers.iter().map(|h| (h.section, 1, h)))
        .collect();
    all.sort_by_key(|&(section, own, _)| (section, own));
    all.into_iter().map(|(_, _, h)| h)
}

/// Why a helper line is refused, like any usage mistake: its name names no helper, or its
/// arguments are not what it takes.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HelperError {
    /// A helper of another dialect.
    #[error(":{name} works with {devices} only")]
    Elsewhere {
        /// The name typed, lower case.
        name: String,
        /// The devices of the dialect that has it.
        devices: &'static str,
    },
    /// No helper has this name or prefix.
    #[error(
        "unknown helper ':{name}' (:help lists them){}",
        crate::suggest::did_you_mean(&nearest.as_ref().map(|n| format!(":{n}")))
    )]
    Unknown {
        /// The name typed, lower case.
        name: String,
        /// The nearest helper's name, if one is close.
        nearest: Option<String>,
    },
    /// The prefix fits several helpers.
    #[error(
        "':{name}' is ambiguous: {}",
        candidates.iter().map(|c| format!(":{c}")).collect::<Vec<_>>().join(", ")
    )]
    Ambiguous {
        /// The name typed, lower case.
        name: String,
        /// The helpers it could mean.
        candidates: Vec<&'static str>,
    },
    /// A helper that reads parameters was given none.
    #[error("name at least one parameter")]
    NoParameter,
    /// A parameter name that fits none, or more than one.
    #[error(transparent)]
    Parameter(#[from] crate::commission::ParamError),
    /// A parameter the module cannot read, given to a helper that reads it.
    #[error("{0} cannot be read")]
    Unreadable(String),
    /// A time that is not one, or too long.
    #[error(transparent)]
    Time(#[from] crate::duration::DurationError),
    /// A time of 0 where time must pass.
    #[error("a time of 0 makes no sense here")]
    ZeroTime,
}

/// The helper with this name (without colon), or the unique one it is a prefix of.
pub fn find(name: &str, dialect: &'static Dialect) -> Result<&'static Helper, HelperError> {
    let name = name.to_ascii_lowercase();
    if let Some(h) = available(dialect).find(|h| h.name() == name) {
        return Ok(h);
    }
    let elsewhere = all()
        .iter()
        .find(|d| d.helpers.iter().any(|h| h.name() == name));
    if let Some(other) = elsewhere {
        return Err(HelperError::Elsewhere {
            name,
            devices: other.devices,
        });
    }
    let matches: Vec<&Helper> = available(dialect)
        .filter(|h| h.name().starts_with(&name))
        .collect();
    match matches.as_slice() {
        [one] => Ok(one),
        [] => {
            let nearest = crate::suggest::nearest(&name, available(dialect).map(|h| h.name()));
            Err(HelperError::Unknown { name, nearest })
        }
        many => Err(HelperError::Ambiguous {
            name,
            candidates: many.iter().map(|h| h.name()).collect(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::DIALECT as SMD4;
    use crate::dialect::tmcl::DIALECT as TMCL;

    #[test]
    fn helpers_resolve_by_name_or_unique_prefix() {
        assert_eq!(find("params", &TMCL).unwrap().name(), "params");
        assert_eq!(find("par", &TMCL).unwrap().name(), "params");
        assert_eq!(find("QUIT", &SMD4).unwrap().name(), "quit");
        assert!(
            find("r", &TMCL)
                .unwrap_err()
                .to_string()
                .contains("ambiguous: :raw, :run, :reset, :record")
        );
        assert!(
            find("r", &SMD4)
                .unwrap_err()
                .to_string()
                .contains("ambiguous: :raw, :record")
        );
        assert_eq!(find("ra", &SMD4).unwrap().name(), "raw");
        assert_eq!(
            find("prams", &TMCL).unwrap_err().to_string(),
            "unknown helper ':prams' (:help lists them); did you mean :params?"
        );
    }

    #[test]
    fn dialect_specific_helpers_say_where_they_belong() {
        assert_eq!(
            find("flags", &TMCL).unwrap_err().to_string(),
            ":flags works with SMD4 drives only"
        );
        assert_eq!(
            find("bin", &SMD4).unwrap_err().to_string(),
            ":bin works with TMCL modules only"
        );
        assert!(find("flags", &SMD4).is_ok());
    }

    #[test]
    fn every_helper_s_usage_and_summary_are_single_spaced() {
        for dialect in all() {
            for h in available(dialect) {
                for text in [h.usage, h.summary] {
                    assert!(!text.contains("  "), "{}: {text:?}", dialect.name);
                    assert_eq!(text.trim(), text, "{}: {text:?}", dialect.name);
                }
            }
        }
    }

    #[test]
    fn every_helper_s_usage_starts_with_a_colon_and_its_name() {
        let all = SHARED.iter().chain(all().iter().flat_map(|d| d.helpers));
        for h in all {
            assert!(h.usage.starts_with(':'), "{}", h.usage);
            assert!(!h.name().is_empty(), "{}", h.usage);
            assert!(
                h.name().chars().all(|c| c.is_ascii_lowercase()),
                "{}",
                h.usage
            );
        }
    }
}
