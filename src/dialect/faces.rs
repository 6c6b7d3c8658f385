//! What the faces show of an open session (the REPL's prompt and line editor, the banner,
//! `:help`, the dialect's helper commands): presentation, kept apart from the wire the
//! [`DialectSession`](super::DialectSession) trait speaks. Only the shell, the REPL and the CLI
//! call it; each dialect implements it in its `session/faces.rs`.

use std::io::{self, Write};
use std::sync::Arc;

use crate::session::SessionError;

use super::{Grammar, Helper};

/// How one dialect's session looks to the user.
pub trait Faces {
    /// The REPL's prompt: which module typed lines go to, and how.
    fn prompt(&self) -> String;

    /// The banner's words for what is talked to (`TMCM-142, module 1`).
    fn banner(&self) -> String;

    /// What typed lines mean, for the line editor: a snapshot of the current state (the REPL
    /// asks again before each prompt).
    fn grammar(&self) -> Arc<dyn Grammar>;

    /// Runs a helper command the dialect answers: one of its own
    /// ([`Dialect::helpers`](super::Dialect::helpers)), or `:params` and `:target`, which every
    /// dialect has in its own way.
    fn run_helper(
        &mut self,
        helper: &Helper,
        arg: &str,
        out: &mut dyn Write,
    ) -> Result<(), SessionError>;

    /// The first lines of `:help`: how this dialect's lines are typed.
    fn help_intro(&self, out: &mut dyn Write) -> io::Result<()>;

    /// The topics `:help` names at its end (`:help COMMAND, :help exit …`).
    fn help_more(&self) -> &'static str;

    /// `:help TOPIC` for a topic of this dialect (`ascii`, `addressing`); false when `topic`
    /// (lower case) is none of them.
    fn help_topic(&self, topic: &str, out: &mut dyn Write) -> io::Result<bool>;

    /// `:help WORD` for one of its commands; false when `word` names none.
    fn help_command(&self, word: &str, out: &mut dyn Write) -> io::Result<bool>;
}
