//! What the faces show of an echo session: the prompt, the banner, `:help`, the helpers every
//! dialect answers in its own way, and the grammar the line editor completes and checks with.

use std::io::{self, Write};
use std::sync::Arc;

use tmclsh::dialect::grammar::{Candidate, Check, Completion};
use tmclsh::dialect::{Dialect, Faces, Grammar, Helper};
use tmclsh::session::SessionError;

use super::protocol::{KEYWORD, parse, recognises};
use super::session::{EchoSession, NO_PARAMS};
use super::{DIALECT, MODULE};

impl Faces for EchoSession {
    fn prompt(&self) -> String {
        "echo> ".to_string()
    }

    fn banner(&self) -> String {
        MODULE.to_string()
    }

    fn grammar(&self) -> Arc<dyn Grammar> {
        Arc::new(EchoGrammar)
    }

    /// `:params` and `:target`, which every dialect answers: the loopback has neither.
    fn run_helper(
        &mut self,
        helper: &Helper,
        _: &str,
        out: &mut dyn Write,
    ) -> Result<(), SessionError> {
        match helper.name() {
            "params" => Ok(writeln!(out, "{NO_PARAMS}")?),
            name => Err(SessionError::Usage(format!(
                ":{name} has nothing to do on the {MODULE}"
            ))),
        }
    }

    fn help_intro(&self, out: &mut dyn Write) -> io::Result<()> {
        writeln!(out, "Type ECHO text: the loopback sends the text back.")
    }

    fn help_more(&self) -> &'static str {
        ":help echo, :help exit, :help time"
    }

    fn help_topic(&self, _: &str, _: &mut dyn Write) -> io::Result<bool> {
        Ok(false)
    }

    fn help_command(&self, word: &str, out: &mut dyn Write) -> io::Result<bool> {
        if !word.eq_ignore_ascii_case(KEYWORD) {
            return Ok(false);
        }
        writeln!(out, "ECHO text    sends text; the loopback answers with it")?;
        Ok(true)
    }
}

/// Echo lines for the line editor: the one word completed, the text checked.
struct EchoGrammar;

impl Grammar for EchoGrammar {
    fn dialect(&self) -> &'static Dialect {
        &DIALECT
    }

    fn complete(&self, line: &str, pos: usize) -> Completion {
        let typed = &line[..pos];
        let word = !typed.contains(' ') && KEYWORD.starts_with(&typed.to_ascii_uppercase());
        let candidates = match word {
            true => vec![Candidate {
                display: KEYWORD.to_string(),
                replacement: format!("{KEYWORD} "),
            }],
            false => Vec::new(),
        };
        Completion::Words {
            start: 0,
            candidates,
        }
    }

    fn hint(&self, line: &str) -> Option<String> {
        (recognises(line) && parse(line).is_err()).then(|| "  ← ECHO text".to_string())
    }

    fn check(&self, line: &str) -> Check {
        match parse(line) {
            Ok(_) => Check::Valid,
            Err(_) if recognises(line) || KEYWORD.starts_with(&line.to_ascii_uppercase()) => {
                Check::Incomplete
            }
            Err(why) => Check::Invalid(why),
        }
    }

    fn names(&self) -> Vec<String> {
        Vec::new()
    }

    fn topics(&self) -> &'static [&'static str] {
        &[]
    }
}
