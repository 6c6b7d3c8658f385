//! Helper commands: lines starting with `:`, shared by the REPL and non-interactive use. The table
//! drives dispatch, `:help` and completion.

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
}

/// Every helper command.
pub const HELPERS: &[Helper] = &[
    Helper {
        name: "help",
        usage: ":help [topic]",
        summary: "this help; topics: a command (GAP), a helper (:run), params, exit, ascii",
        arg: ArgKind::Topic,
    },
    Helper {
        name: "params",
        usage: ":params [filter]",
        summary: "list the module's parameters (matching filter)",
        arg: ArgKind::Param,
    },
    Helper {
        name: "target",
        usage: ":target N|CHAR",
        summary: "address another module on the bus (2 or B)",
        arg: ArgKind::Module,
    },
    Helper {
        name: "echo",
        usage: ":echo char|line|none",
        summary: "set the module's echo (global parameter 67 bits 4/5, keeping bit 0)",
        arg: ArgKind::Echo,
    },
    Helper {
        name: "log",
        usage: ":log FILE|off",
        summary: "append a transcript of every byte to FILE, or stop",
        arg: ArgKind::File,
    },
    Helper {
        name: "raw",
        usage: ":raw",
        summary: "toggle showing replies exactly as received",
        arg: ArgKind::None,
    },
    Helper {
        name: "run",
        usage: ":run [address]",
        summary: "start the module's stored TMCL program (ASCII RUN, or command 129)",
        arg: ArgKind::Address,
    },
    Helper {
        name: "stop",
        usage: ":stop",
        summary: "stop the module's TMCL program (ASCII STOP, or command 128)",
        arg: ArgKind::None,
    },
    Helper {
        name: "bin",
        usage: ":bin",
        summary: "leave ASCII mode; lines are then sent as binary frames (direct mode)",
        arg: ArgKind::None,
    },
    Helper {
        name: "ascii",
        usage: ":ascii",
        summary: "enter ASCII mode again (command 139)",
        arg: ArgKind::None,
    },
    Helper {
        name: "snapshot",
        usage: ":snapshot save|diff|restore FILE",
        summary: "save the module's parameters to a TOML file, compare with one, or write one back",
        arg: ArgKind::Snapshot,
    },
    Helper {
        name: "scan",
        usage: ":scan [ADDRESSES] [TIME]",
        summary: "find the modules on the bus (default 1-26), with firmware and echo",
        arg: ArgKind::Module,
    },
    Helper {
        name: "watch",
        usage: ":watch PARAM[,PARAM…] [INTERVAL]",
        summary: "live table of parameters; any key stops, Ctrl-C also stops the motor",
        arg: ArgKind::Param,
    },
    Helper {
        name: "record",
        usage: ":record FILE.csv PARAM[,…] [INTERVAL] [DURATION]",
        summary: "sample parameters with timestamps into a CSV file",
        arg: ArgKind::Record,
    },
    Helper {
        name: "plot",
        usage: ":plot [FILE.csv]",
        summary: "chart the last recording (or a CSV file) against time",
        arg: ArgKind::File,
    },
    Helper {
        name: "quit",
        usage: ":quit",
        summary: "leave, putting the modules back in the mode they were found in",
        arg: ArgKind::None,
    },
];

/// The helper with this name (without colon), or the unique one it is a prefix of.
pub fn find(name: &str) -> Result<&'static Helper, String> {
    let name = name.to_ascii_lowercase();
    if let Some(h) = HELPERS.iter().find(|h| h.name == name) {
        return Ok(h);
    }
    let matches: Vec<&Helper> = HELPERS
        .iter()
        .filter(|h| h.name.starts_with(&name))
        .collect();
    match matches.as_slice() {
        [one] => Ok(one),
        [] => Err(format!(
            "unknown helper ':{name}'{}; :help lists them",
            crate::suggest::did_you_mean(
                &crate::suggest::nearest(&name, HELPERS.iter().map(|h| h.name))
                    .map(|n| format!(":{n}"))
            )
        )),
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
        assert_eq!(find("params").unwrap().name, "params");
        assert_eq!(find("par").unwrap().name, "params");
        assert_eq!(find("QUIT").unwrap().name, "quit");
        assert!(
            find("r")
                .unwrap_err()
                .contains("ambiguous: :raw, :run, :record")
        );
        assert_eq!(
            find("prams").unwrap_err(),
            "unknown helper ':prams'; did you mean :params?; :help lists them"
        );
    }

    #[test]
    fn every_helper_has_usage_starting_with_its_name() {
        for h in HELPERS {
            assert!(h.usage.starts_with(&format!(":{}", h.name)), "{}", h.name);
        }
    }
}
