//! Helper commands: lines starting with `:`, shared by the REPL and non-interactive use. The table
//! drives dispatch, `:help` and completion; each helper says which dialects have it.

use crate::protocol::Dialect;

/// What a helper's argument is, for completion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArgKind {
    /// No argument.
    None,
    /// A file name.
    File,
    /// A parameter name or filter.
    Param,
    /// `char`, `line` or `none`.
    Echo,
    /// A module address or character.
    Module,
    /// A help topic.
    Topic,
    /// A program address.
    Address,
    /// `save`, `diff` or `restore`, then a snapshot file.
    Snapshot,
    /// A CSV file, then parameter names.
    Record,
}

/// Which dialects have a helper.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Only {
    /// Both.
    Both,
    /// TMCL modules.
    Tmcl,
    /// SMD4 drives.
    Smd4,
}

/// One helper command.
#[derive(Debug, Clone, Copy)]
pub struct Helper {
    /// Name without the colon.
    pub name: &'static str,
    /// Usage line.
    pub usage: &'static str,
    /// One-line description.
    pub summary: &'static str,
    /// What its argument is.
    pub arg: ArgKind,
    /// Where it exists.
    pub only: Only,
}

impl Helper {
    /// Whether the helper exists for `dialect`.
    pub fn available(&self, dialect: Dialect) -> bool {
        matches!(
            (self.only, dialect),
            (Only::Both, _) | (Only::Tmcl, Dialect::Tmcl) | (Only::Smd4, Dialect::Smd4)
        )
    }
}

const fn helper(
    name: &'static str,
    usage: &'static str,
    summary: &'static str,
    arg: ArgKind,
    only: Only,
) -> Helper {
    Helper {
        name,
        usage,
        summary,
        arg,
        only,
    }
}

/// Every helper command.
pub const HELPERS: &[Helper] = &[
    helper(
        "help",
        ":help [topic]",
        "this help; topics: a command, a helper, params, exit, ascii or addressing",
        ArgKind::Topic,
        Only::Both,
    ),
    helper(
        "params",
        ":params [filter]",
        "list the module's parameters or settings (matching filter)",
        ArgKind::Param,
        Only::Both,
    ),
    helper(
        "target",
        ":target N|CHAR",
        "address another module on the bus (TMCL: 2 or B; SMD4: @N, none for no prefix)",
        ArgKind::Module,
        Only::Both,
    ),
    helper(
        "echo",
        ":echo char|line|none",
        "set the module's echo (global parameter 67 bits 4/5, keeping bit 0)",
        ArgKind::Echo,
        Only::Tmcl,
    ),
    helper(
        "flags",
        ":flags",
        "the SFLAGS and EFLAGS bit tables with the drive's current flags",
        ArgKind::None,
        Only::Smd4,
    ),
    helper(
        "log",
        ":log FILE|off|time [on|off]",
        "append a transcript of every byte to FILE, or stop; time: the time before each reply",
        ArgKind::File,
        Only::Both,
    ),
    helper(
        "raw",
        ":raw",
        "toggle showing replies exactly as received",
        ArgKind::None,
        Only::Both,
    ),
    helper(
        "run",
        ":run [address]",
        "start the module's stored TMCL program (ASCII RUN, or command 129)",
        ArgKind::Address,
        Only::Tmcl,
    ),
    helper(
        "stop",
        ":stop",
        "stop the module's TMCL program (ASCII STOP, or command 128)",
        ArgKind::None,
        Only::Tmcl,
    ),
    helper(
        "step",
        ":step",
        "execute the program's next instruction (command 130)",
        ArgKind::None,
        Only::Tmcl,
    ),
    helper(
        "reset",
        ":reset",
        "program counter to 0, program stopped (command 131)",
        ArgKind::None,
        Only::Tmcl,
    ),
    helper(
        "status",
        ":status",
        "application status (135): stopped, running, stepping or reset",
        ArgKind::None,
        Only::Tmcl,
    ),
    helper(
        "download",
        ":download FILE [--run]",
        "store a program (.tmc source or .bin) in the module, verify it, optionally run it",
        ArgKind::File,
        Only::Tmcl,
    ),
    helper(
        "bin",
        ":bin",
        "leave ASCII mode; lines are then sent as binary frames (direct mode)",
        ArgKind::None,
        Only::Tmcl,
    ),
    helper(
        "ascii",
        ":ascii",
        "enter ASCII mode again (command 139)",
        ArgKind::None,
        Only::Tmcl,
    ),
    helper(
        "source",
        ":source SCRIPT.rhai [ARGS...]",
        "run a Rhai script against the session (Ctrl-C stops it and the motors)",
        ArgKind::File,
        Only::Both,
    ),
    helper(
        "snapshot",
        ":snapshot save|diff|restore FILE",
        "save the module's parameters to a TOML file, compare with one, or write one back",
        ArgKind::Snapshot,
        Only::Both,
    ),
    helper(
        "scan",
        ":scan [ADDRESSES] [TIME]",
        "find the modules on the bus (TMCL 1-26 with firmware and echo; SMD4 1-247)",
        ArgKind::Module,
        Only::Both,
    ),
    helper(
        "watch",
        ":watch PARAM[,PARAM…] [INTERVAL]",
        "live table of parameters; any key stops, Ctrl-C also stops the motor",
        ArgKind::Param,
        Only::Both,
    ),
    helper(
        "record",
        ":record FILE.csv PARAM[,…] [INTERVAL] [DURATION]",
        "sample parameters with timestamps into a CSV file",
        ArgKind::Record,
        Only::Both,
    ),
    helper(
        "plot",
        ":plot [FILE.csv]",
        "chart the last recording (or a CSV file) against time",
        ArgKind::File,
        Only::Both,
    ),
    helper(
        "quit",
        ":quit",
        "leave, putting the modules back in the mode they were found in",
        ArgKind::None,
        Only::Both,
    ),
];

/// The helpers `dialect` has.
pub fn available(dialect: Dialect) -> impl Iterator<Item = &'static Helper> {
    HELPERS.iter().filter(move |h| h.available(dialect))
}

/// The helper with this name (without colon), or the unique one it is a prefix of.
pub fn find(name: &str, dialect: Dialect) -> Result<&'static Helper, String> {
    let name = name.to_ascii_lowercase();
    if let Some(h) = available(dialect).find(|h| h.name == name) {
        return Ok(h);
    }
    if let Some(h) = HELPERS.iter().find(|h| h.name == name) {
        let which = if h.only == Only::Tmcl {
            "TMCL modules"
        } else {
            "SMD4 drives"
        };
        return Err(format!(":{name} works with {which} only"));
    }
    let matches: Vec<&Helper> = available(dialect)
        .filter(|h| h.name.starts_with(&name))
        .collect();
    match matches.as_slice() {
        [one] => Ok(one),
        [] => {
            let nearest = crate::suggest::nearest(&name, available(dialect).map(|h| h.name));
            Err(format!(
                "unknown helper ':{name}'{}; :help lists them",
                crate::suggest::did_you_mean(&nearest.map(|n| format!(":{n}")))
            ))
        }
        many => Err(format!(
            "':{name}' is ambiguous: {}",
            many.iter()
                .map(|h| format!(":{}", h.name))
                .collect::<Vec<_>>()
                .join(", ")
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn helpers_resolve_by_name_or_unique_prefix() {
        assert_eq!(find("params", Dialect::Tmcl).unwrap().name, "params");
        assert_eq!(find("par", Dialect::Tmcl).unwrap().name, "params");
        assert_eq!(find("QUIT", Dialect::Smd4).unwrap().name, "quit");
        assert!(
            find("r", Dialect::Tmcl)
                .unwrap_err()
                .contains("ambiguous: :raw, :run, :reset, :record")
        );
        assert!(
            find("r", Dialect::Smd4)
                .unwrap_err()
                .contains("ambiguous: :raw, :record")
        );
        assert_eq!(find("ra", Dialect::Smd4).unwrap().name, "raw");
        assert_eq!(
            find("prams", Dialect::Tmcl).unwrap_err(),
            "unknown helper ':prams'; did you mean :params?; :help lists them"
        );
    }

    #[test]
    fn dialect_specific_helpers_say_where_they_belong() {
        assert_eq!(
            find("flags", Dialect::Tmcl).unwrap_err(),
            ":flags works with SMD4 drives only"
        );
        assert_eq!(
            find("bin", Dialect::Smd4).unwrap_err(),
            ":bin works with TMCL modules only"
        );
        assert!(find("flags", Dialect::Smd4).is_ok());
    }

    #[test]
    fn every_helper_has_usage_starting_with_its_name() {
        for h in HELPERS {
            assert!(h.usage.starts_with(&format!(":{}", h.name)), "{}", h.name);
        }
    }
}
