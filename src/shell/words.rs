//! Words everyone tries at a prompt — `help`, `?`, `exit`, `quit`, `clear` — taken for what they
//! mean instead of being refused as unknown commands. None of them is a command of either dialect
//! (a test checks every built-in table), so nothing a module understands is taken away.

/// What an everyday word stands for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Everyday {
    /// The helper line it means (`:help GAP`, `:quit`).
    Helper(String),
    /// Clear the screen (the interactive shell only).
    Clear,
}

/// The everyday word `text` is, if it is one (any case; `help` and `?` may name a topic). `exit`
/// and `quit` leave whatever follows them (`exit now`), as `:quit` does: no module has such a
/// command, so nothing is sent, and the words after them mean nothing else (not an exit code).
pub fn everyday(text: &str) -> Option<Everyday> {
    let text = text.trim();
    let (word, rest) = match text.split_once(char::is_whitespace) {
        Some((word, rest)) => (word, rest.trim()),
        None => (text, ""),
    };
    match word.to_ascii_lowercase().as_str() {
        "help" | "?" if rest.is_empty() => Some(Everyday::Helper(":help".into())),
        "help" | "?" => Some(Everyday::Helper(format!(":help {rest}"))),
        "exit" | "quit" => Some(Everyday::Helper(":quit".into())),
        "clear" | "cls" if rest.is_empty() => Some(Everyday::Clear),
        _ => None,
    }
}

/// Whether a typed line is only a remark: empty, or a comment (`# …` as in shell scripts,
/// `// …` as in `.tmc` files), which no dialect's line starts with.
pub fn only_remark(text: &str) -> bool {
    let text = text.trim();
    text.is_empty() || text.starts_with('#') || text.starts_with("//")
}

/// The words, for the test that they are no module's commands.
#[cfg(test)]
const WORDS: &[&str] = &["help", "exit", "quit", "clear", "cls"];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::protocol::Smd4Spec;
    use crate::dialect::tmcl::profile::Profile;

    #[test]
    fn the_words_mean_their_helpers() {
        let helper = |s: &str| Some(Everyday::Helper(s.into()));
        assert_eq!(everyday("help"), helper(":help"));
        assert_eq!(everyday(" HELP "), helper(":help"));
        assert_eq!(everyday("?"), helper(":help"));
        assert_eq!(everyday("help GAP"), helper(":help GAP"));
        assert_eq!(everyday("? exit"), helper(":help exit"));
        assert_eq!(everyday("exit"), helper(":quit"));
        assert_eq!(everyday("Quit"), helper(":quit"));
        for leave in ["exit now", "quit please", "EXIT 1", "quit\t!"] {
            assert_eq!(everyday(leave), helper(":quit"), "{leave}");
        }
        assert_eq!(everyday("clear"), Some(Everyday::Clear));
        for line in ["exit,0", "quitter", "GAP 1, 0", "MOTOR:VMAX", "clear 1", ""] {
            assert_eq!(everyday(line), None, "{line}");
        }
    }

    #[test]
    fn remarks_are_empty_lines_and_comments() {
        for remark in ["", "  ", "# note", "// note", "  //"] {
            assert!(only_remark(remark), "{remark:?}");
        }
        for line in ["GAP 4, 0 // speed", "MOTOR:VMAX", "/ 2"] {
            assert!(!only_remark(line), "{line}");
        }
    }

    #[test]
    fn no_word_is_a_command_of_any_builtin_table() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/data/profiles");
        let mut profiles = vec![Profile::builtin()];
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "toml") {
                profiles.push(std::sync::Arc::new(Profile::from_file(&path).unwrap()));
            }
        }
        let smd4 = &Smd4Spec::builtin().commands;
        for word in WORDS {
            for profile in &profiles {
                assert!(
                    profile.commands.by_mnemonic(word).is_none(),
                    "{word} is a {} command",
                    profile.module
                );
            }
            assert!(smd4.get(word).is_none(), "{word} is an SMD4 command");
            assert!(
                smd4.get(&word.to_ascii_uppercase()).is_none(),
                "{word} is an SMD4 command"
            );
        }
    }
}
