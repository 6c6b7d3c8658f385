//! TMCL lines as the line editor sees them: completion and hints from the profile, and the
//! validator of the mode the target module is in (ASCII, or binary after `:bin`).

use std::sync::Arc;

use crate::dialect::grammar::{Candidate, Check, Completion, Grammar, completes_further};
use crate::dialect::{Dialect, elsewhere};

use super::profile::Profile;
use super::protocol::error::InputError;
use super::protocol::line;
use super::protocol::syntax::without_comment;
use super::protocol::validate::{Mode, validate};
use super::{complete, hint};

/// The profile, and the mode lines are validated for.
pub struct TmclGrammar {
    profile: Arc<Profile>,
    mode: Mode,
}

impl TmclGrammar {
    /// Lines for modules of `profile`, checked as `mode` takes them.
    pub fn new(profile: Arc<Profile>, mode: Mode) -> Self {
        TmclGrammar { profile, mode }
    }

    /// What the session says of `text`: nothing, or why it refuses it.
    fn verdict(&self, text: &str) -> Result<(), InputError> {
        let parsed = line::parse(text, &self.profile)?;
        validate(&parsed, &self.profile, self.mode).map(|_| ())
    }

    /// A refused line: still on its way (the input ran out, a word completes further, operands
    /// are missing but those given are fine), or invalid for good.
    fn judge(&self, text: &str, error: InputError) -> Check {
        let ran_out = match &error {
            InputError::Syntax(e) => e.column > text.trim_end().len(),
            _ => false,
        };
        if ran_out || completes_further(self, text) {
            return Check::Incomplete;
        }
        if let InputError::ArgumentCount { got, mnemonic, .. } = &error {
            let operands = self
                .profile
                .commands
                .by_mnemonic(mnemonic)
                .map_or(0, |spec| spec.operands.len());
            if *got < operands {
                return self.with_operands_to_come(text);
            }
        }
        match elsewhere::line_dialect(&super::DIALECT, text) {
            Some(other) => Check::Invalid(elsewhere::line_message(other)),
            None => Check::Invalid(error.to_string()),
        }
    }

    /// A line short of operands: invalid only when what is given already fails whatever comes
    /// next — the same refusal with the missing operands as 0 and as 1 (`SAP 4, 7`: no motor
    /// 7).
    fn with_operands_to_come(&self, text: &str) -> Check {
        let filled = |value: &str| {
            let mut line = text.trim_end().to_string();
            for _ in 0..3 {
                match self.verdict(&line) {
                    Err(InputError::ArgumentCount { got, .. }) if got < 3 => {
                        line.push(' ');
                        line.push_str(value);
                    }
                    other => return other.map_err(|e| e.to_string()),
                }
            }
            self.verdict(&line).map_err(|e| e.to_string())
        };
        match (filled("0"), filled("1")) {
            (Err(zero), Err(one)) if zero == one => Check::Invalid(zero),
            _ => Check::Incomplete,
        }
    }
}

impl Grammar for TmclGrammar {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn complete(&self, line: &str, pos: usize) -> Completion {
        complete::complete(line, pos, &self.profile)
    }

    fn hint(&self, line: &str) -> Option<String> {
        hint::hint(line, &self.profile)
    }

    fn check(&self, text: &str) -> Check {
        let text = without_comment(text);
        if text.trim().is_empty() {
            return Check::Incomplete;
        }
        match self.verdict(text) {
            Ok(()) => Check::Valid,
            Err(error) => self.judge(text, error),
        }
    }

    /// Parameter identifiers, axis then global.
    fn names(&self) -> Vec<String> {
        self.profile
            .axis
            .iter()
            .chain(&self.profile.global)
            .map(|p| p.ident.clone())
            .collect()
    }

    fn topics(&self) -> &'static [&'static str] {
        &["params", "io", "exit", "ascii"]
    }

    /// Command mnemonics and, once a lower-case word is typed, parameter names (`:help max_c`).
    fn topic_words(&self, word: &str) -> Vec<Candidate> {
        let mut out = complete::mnemonics(word, &self.profile);
        if word.starts_with(|c: char| c.is_ascii_lowercase()) {
            out.extend(
                self.names()
                    .into_iter()
                    .filter(|n| n.starts_with(word))
                    .map(|n| Candidate {
                        display: n.clone(),
                        replacement: n,
                    }),
            );
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::{Smd4Grammar, protocol::Smd4Spec};

    fn tmcl(line: &str) -> Check {
        TmclGrammar::new(Profile::builtin(), Mode::Ascii).check(line)
    }

    fn smd4(line: &str) -> Check {
        Smd4Grammar::new(Smd4Spec::builtin()).check(line)
    }

    fn reason(check: Check) -> String {
        match check {
            Check::Invalid(reason) => reason,
            other => panic!("not invalid: {other:?}"),
        }
    }

    #[test]
    fn lines_on_their_way_are_incomplete_not_invalid() {
        for line in [
            "",
            "G",
            "GA",
            "GAP",
            "GAP ",
            "GAP 4",
            "GAP 4,",
            "GAP max_cur",
            "GAP max_current, ",
            "SAP 4, 0,",
            "MVP ABS, 0",
            "A",
            "AGA",
            "SAP 6, 0",
        ] {
            assert_eq!(tmcl(line), Check::Incomplete, "{line:?}");
        }
        for line in [
            "",
            "M",
            "MOTOR:",
            "MOTOR:VM",
            "MOTOR:RES,",
            "@3",
            "@3MOTOR:V",
            "SYS:",
        ] {
            assert_eq!(smd4(line), Check::Incomplete, "{line:?}");
        }
        for line in ["GAP 4, 0", "gap 4 0 // speed", "MST 0", "SAP 6, 0, 10"] {
            assert_eq!(tmcl(line), Check::Valid, "{line}");
        }
        for line in ["MOTOR:VMAX", "MOTOR:VMAX,2000 // top", "@3SYS:FW"] {
            assert_eq!(smd4(line), Check::Valid, "{line}");
        }
    }

    #[test]
    fn help_completes_commands_and_parameter_names() {
        let grammar = TmclGrammar::new(Profile::builtin(), Mode::Ascii);
        let words = |w: &str| -> Vec<String> {
            grammar
                .topic_words(w)
                .into_iter()
                .map(|c| c.display)
                .collect()
        };
        assert!(words("max_c").contains(&"max_current".to_string()));
        assert!(words("GA").contains(&"GAP".to_string()));
        assert!(!words("GA").iter().any(|w| w.starts_with("ga")));
    }

    #[test]
    fn an_invalid_line_says_why() {
        assert!(reason(tmcl("GAP 4, 7")).starts_with("motor 7 does not exist"));
        // The operands given are wrong whatever comes next.
        assert!(reason(tmcl("SAP 4, 7")).starts_with("motor 7 does not exist"));
        assert!(reason(tmcl("SAP 6, 0, 99")).contains("out of range for max_current"));
        assert!(reason(tmcl("XYZ 1")).contains("unknown command 'XYZ'"));
        assert!(reason(tmcl("GAP 4, 0, 1, 2")).contains("GAP takes 2 arguments"));
        assert_eq!(
            reason(tmcl("MOTOR:VMAX")),
            "this looks like an SMD4 command — add `--protocol smd4`"
        );
        assert!(reason(smd4("MOTOR:VMAX,99999")).contains("out of range"));
        assert!(reason(smd4("MOTOR:FOO")).contains("unknown mnemonic"));
        assert!(reason(smd4("MOTOR:VMAX 2000")).contains("did you mean MOTOR:VMAX,2000?"));
        assert_eq!(
            reason(smd4("GAP 4, 0")),
            "this looks like a TMCL command — add `--protocol tmcl`"
        );
    }
}
