//! TMCL lines as the line editor sees them: completion and hints from the profile, and the
//! validator of the mode the module is in (ASCII, or binary after `:bin`). A line with an address
//! character is read as the session reads it: with the profile and mode of the module it names,
//! which the session hands over with the grammar (nothing is asked of the bus while typing).

use std::collections::BTreeMap;
use std::sync::Arc;

use crate::dialect::grammar::{Candidate, Check, Completion, Grammar, completes_further};
use crate::dialect::{Dialect, elsewhere};

use super::profile::Profile;
use super::protocol::ModuleName;
use super::protocol::error::InputError;
use super::protocol::line::{self, address_of};
use super::protocol::syntax::without_comment;
use super::protocol::validate::{Mode, validate};
use super::{complete, hint};
use crate::article::with_article;

/// How the lines to one module are read: its profile and the mode it takes them in.
#[derive(Debug, Clone)]
pub struct ModuleLines {
    /// The profile its lines are checked, completed and described with.
    pub profile: Arc<Profile>,
    /// The mode its lines are validated for.
    pub mode: Mode,
    /// The module is not identified yet: the profile is a guess until it answers, which the
    /// hint says.
    pub assumed: bool,
}

impl ModuleLines {
    /// Lines of a module known to be of `profile`, taken in `mode`.
    pub fn known(profile: Arc<Profile>, mode: Mode) -> Self {
        ModuleLines {
            profile,
            mode,
            assumed: false,
        }
    }
}

/// The target module's lines, and those of every module a line can name with its address
/// character.
pub struct TmclGrammar {
    target: ModuleLines,
    /// The other modules, by address; a module missing here is read as the target.
    addressed: BTreeMap<u8, ModuleLines>,
}

impl TmclGrammar {
    /// Lines for modules of `profile`, checked as `mode` takes them.
    pub fn new(profile: Arc<Profile>, mode: Mode) -> Self {
        TmclGrammar {
            target: ModuleLines::known(profile, mode),
            addressed: BTreeMap::new(),
        }
    }

    /// Lines naming `module` (its address character) are read as `lines` says.
    pub fn with_module(mut self, module: u8, lines: ModuleLines) -> Self {
        self.addressed.insert(module, lines);
        self
    }

    /// The module a typed line names and how its lines are read: the target's unless the line
    /// starts with another module's address character.
    fn lines_of(&self, text: &str) -> (Option<u8>, &ModuleLines) {
        match addressed(text, &self.target.profile) {
            Some(module) => (
                Some(module),
                self.addressed.get(&module).unwrap_or(&self.target),
            ),
            None => (None, &self.target),
        }
    }

    /// What the session says of `text` sent to a module read as `lines`: nothing, or why it
    /// refuses it.
    fn verdict(lines: &ModuleLines, text: &str) -> Result<(), InputError> {
        let parsed = line::parse(text, &lines.profile)?;
        validate(&parsed, &lines.profile, lines.mode).map(|_| ())
    }

    /// A refused line: still on its way (the input ran out, a word completes further, operands
    /// are missing but those given are fine), or invalid for good.
    fn judge(&self, lines: &ModuleLines, text: &str, error: InputError) -> Check {
        let ran_out = match &error {
            InputError::Syntax(e) => e.column > text.trim_end().len(),
            _ => false,
        };
        if ran_out || completes_further(self, text) {
            return Check::Incomplete;
        }
        if let InputError::ArgumentCount { got, mnemonic, .. } = &error {
            let operands = lines
                .profile
                .commands
                .by_mnemonic(mnemonic)
                .map_or(0, |spec| spec.operands.len());
            if *got < operands {
                return Self::with_operands_to_come(lines, text);
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
    fn with_operands_to_come(lines: &ModuleLines, text: &str) -> Check {
        let filled = |value: &str| {
            let mut line = text.trim_end().to_string();
            for _ in 0..3 {
                match Self::verdict(lines, &line) {
                    Err(InputError::ArgumentCount { got, .. }) if got < 3 => {
                        line.push(' ');
                        line.push_str(value);
                    }
                    other => return other.map_err(|e| e.to_string()),
                }
            }
            Self::verdict(lines, &line).map_err(|e| e.to_string())
        };
        match (filled("0"), filled("1")) {
            (Err(zero), Err(one)) if zero == one => Check::Invalid(zero),
            _ => Check::Incomplete,
        }
    }
}

/// What a hint or a refusal adds for a module not identified yet: the profile it is taken for.
fn assumption(module: Option<u8>, lines: &ModuleLines) -> Option<String> {
    let module = module.filter(|_| lines.assumed)?;
    Some(format!(
        "{} not identified yet, taken for {}",
        ModuleName(module),
        with_article(&lines.profile.module)
    ))
}

/// The module a typed line names with its address character, as far as the line is typed:
/// `BGAP …` and `B GAP …` name module 2, and so does `BGA` while its word is typed (no command
/// starts with `BGA`, one starts with `GA`) — the way the session and completion read them. A
/// whole command word (`RSAP`) is never an address.
fn addressed(text: &str, profile: &Profile) -> Option<u8> {
    let text = text.trim_start();
    let first = text.split([' ', ',', '\t']).next()?;
    let upper = first.to_ascii_uppercase();
    let mut chars = upper.chars();
    let leading = chars.next().filter(char::is_ascii_alphabetic)?;
    let tail = chars.as_str();
    let commands = &profile.commands;
    if commands.is_word(&upper) {
        return None;
    }
    let word_ended = text.len() > first.len();
    let names = if tail.is_empty() {
        word_ended
    } else {
        commands.is_word(tail)
            || tail.bytes().all(|b| b.is_ascii_digit())
            || !word_ended
                && !commands.words().any(|w| w.starts_with(&upper))
                && commands.words().any(|w| w.starts_with(tail))
    };
    names.then(|| address_of(leading)).flatten()
}

impl Grammar for TmclGrammar {
    fn dialect(&self) -> &'static Dialect {
        &super::DIALECT
    }

    fn complete(&self, line: &str, pos: usize) -> Completion {
        let (_, lines) = self.lines_of(line);
        complete::complete(line, pos, &lines.profile)
    }

    /// The hint from the profile of the module the line names, saying so when that module is
    /// not identified yet.
    fn hint(&self, line: &str) -> Option<String> {
        let (module, lines) = self.lines_of(line);
        let text = hint::hint(line, &lines.profile)?;
        Some(match assumption(module, lines) {
            Some(note) => format!("{text}; {note}"),
            None => text,
        })
    }

    fn check(&self, text: &str) -> Check {
        let text = without_comment(text);
        if text.trim().is_empty() {
            return Check::Incomplete;
        }
        let (module, lines) = self.lines_of(text);
        match Self::verdict(lines, text) {
            Ok(()) => Check::Valid,
            Err(error) => match (self.judge(lines, text, error), assumption(module, lines)) {
                (Check::Invalid(reason), Some(note)) => Check::Assumed(format!("{reason}; {note}")),
                (check, _) => check,
            },
        }
    }

    /// Parameter identifiers, axis then global.
    fn names(&self) -> Vec<String> {
        let profile = &self.target.profile;
        profile
            .axis
            .iter()
            .chain(&profile.global)
            .map(|p| p.ident.clone())
            .collect()
    }

    fn topics(&self) -> &'static [&'static str] {
        &["params", "io", "exit", "ascii"]
    }

    /// Command mnemonics and, once a lower-case word is typed, parameter names (`:help max_c`).
    fn topic_words(&self, word: &str) -> Vec<Candidate> {
        let mut out = complete::mnemonics(word, &self.target.profile);
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

    /// A TMCM-142 target with a TMCM-6110 as module 2 and, not identified yet, module 3.
    fn bus() -> TmclGrammar {
        let six = crate::dialect::tmcl::profile::catalogue::by_name("tmcm-6110").unwrap();
        let assumed = ModuleLines {
            profile: Profile::builtin(),
            mode: Mode::Ascii,
            assumed: true,
        };
        TmclGrammar::new(Profile::builtin(), Mode::Ascii)
            .with_module(2, ModuleLines::known(six, Mode::Ascii))
            .with_module(3, assumed)
    }

    fn offered(grammar: &TmclGrammar, line: &str) -> Vec<String> {
        match grammar.complete(line, line.len()) {
            Completion::Words { candidates, .. } => {
                candidates.into_iter().map(|c| c.replacement).collect()
            }
            Completion::File { .. } => panic!("a file for {line:?}"),
        }
    }

    #[test]
    fn the_address_character_is_read_as_the_session_reads_it() {
        let p = Profile::builtin();
        for (line, module) in [
            ("BGAP 4, 5", Some(2)),
            ("b gap 4", Some(2)),
            ("B ", Some(2)),
            ("  BGAP", Some(2)),
            ("BGA", Some(2)),
            ("B136", Some(2)),
            ("ZMST 0", Some(26)),
            ("GAP 4, 0", None),
            // A whole command word is never an address: RSAP, not SAP to module R.
            ("RSAP 4, 0", None),
            ("B", None),
            ("1 GAP", None),
            ("", None),
            ("é GAP", None),
            ("BXYZ 1", None),
        ] {
            assert_eq!(addressed(line, &p), module, "{line:?}");
        }
    }

    #[test]
    fn a_line_to_another_module_is_completed_checked_and_hinted_with_its_profile() {
        let g = bus();
        // Parameters only the TMCM-6110 has, after B and not without it.
        assert!(offered(&g, "BGAP chopper_").contains(&"chopper_off_time, ".to_string()));
        assert!(offered(&g, "B GAP chopp").contains(&"chopper_mode, ".to_string()));
        assert!(offered(&g, "GAP chopper_").is_empty());
        assert!(offered(&g, "AGAP chopper_").is_empty());
        // Motor 5 is on the TMCM-6110, not on the TMCM-142.
        assert_eq!(g.check("BGAP 4, 5"), Check::Valid);
        assert_eq!(g.check("B SAP 4, 5,"), Check::Incomplete);
        assert!(reason(g.check("AGAP 4, 5")).starts_with("motor 5 does not exist"));
        assert!(reason(g.check("GAP 4, 5")).starts_with("motor 5 does not exist"));
        assert!(reason(g.check("BGAP 4, 6")).starts_with("motor 6 does not exist"));
        // RSAP stays a command of the target, whatever module 18 would be.
        let g18 = TmclGrammar::new(Profile::builtin(), Mode::Ascii).with_module(
            18,
            ModuleLines::known(
                crate::dialect::tmcl::profile::catalogue::by_name("tmcm-6110").unwrap(),
                Mode::Ascii,
            ),
        );
        assert!(reason(g18.check("RSAP 4, 5")).starts_with("motor 5 does not exist"));
        // The hint describes the module's own parameter and port.
        let hint = g.hint("BGAP 4, 5").unwrap();
        assert!(hint.contains("#4 max_positioning_speed [0..2047"), "{hint}");
        assert!(g.hint("GAP 4").unwrap().contains("[0..2147483647"));
        assert!(g.hint("BGIO 8, 1").unwrap().contains("VIN"));
        assert_eq!(g.hint("GIO 8, 1"), None);
        // Each module's mode: CALC goes to a module in binary mode, not in ASCII mode.
        let binary = bus().with_module(
            2,
            ModuleLines::known(
                crate::dialect::tmcl::profile::catalogue::by_name("tmcm-6110").unwrap(),
                Mode::Binary,
            ),
        );
        assert_eq!(binary.check("BCALC ADD, 5"), Check::Valid);
        assert!(matches!(binary.check("CALC ADD, 5"), Check::Invalid(_)));
        assert!(matches!(bus().check("BCALC ADD, 5"), Check::Invalid(_)));
    }

    #[test]
    fn a_module_not_identified_yet_is_taken_for_the_target_and_the_hint_says_so() {
        let g = bus();
        let note = "; module 3 (C) not identified yet, taken for a TMCM-142";
        let hint = g.hint("CGAP 4").unwrap();
        assert!(hint.contains("#4 max_positioning_speed"), "{hint}");
        assert!(hint.ends_with(note), "{hint}");
        assert!(g.hint("C GAP ").unwrap().ends_with(note));
        // A refusal by the assumed profile is not final: the module decides once asked.
        match g.check("CGAP 4, 5") {
            Check::Assumed(reason) => {
                assert!(reason.starts_with("motor 5 does not exist"), "{reason}");
                assert!(reason.ends_with(note), "{reason}");
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(g.check("CGAP 4, 0"), Check::Valid);
        // Lines to identified modules and the target say nothing of it.
        assert!(!g.hint("BGAP 4").unwrap().contains("identified"));
        assert!(!g.hint("GAP 4").unwrap().contains("identified"));
    }
}
