//! What the faces show of an SMD4 session ([`Faces`]): the prompt, the banner, the grammar,
//! helpers and help.

use std::io::{self, Write};
use std::sync::Arc;

use crate::dialect::smd4::{Smd4Grammar, help, helpers};
use crate::dialect::{Faces, Grammar, Helper};
use crate::session::SessionError;

use super::Smd4Session;

impl Faces for Smd4Session {
    /// `smd4>`, with the address prefix requests get.
    fn prompt(&self) -> String {
        match self.smd4.address {
            Some(address) => format!("smd4 @{address}> "),
            None => "smd4> ".to_string(),
        }
    }

    fn banner(&self) -> String {
        "SMD4".to_string()
    }

    fn grammar(&self) -> Arc<dyn Grammar> {
        Arc::new(Smd4Grammar::new(self.spec))
    }

    fn run_helper(
        &mut self,
        helper: &Helper,
        arg: &str,
        out: &mut dyn Write,
    ) -> Result<(), SessionError> {
        helpers::run(self, helper, arg, out)
    }

    fn help_intro(&self, out: &mut dyn Write) -> io::Result<()> {
        help::intro(out)
    }

    fn help_more(&self) -> &'static str {
        help::MORE
    }

    fn help_topic(&self, topic: &str, out: &mut dyn Write) -> io::Result<bool> {
        help::topic(topic, out)
    }

    fn help_command(&self, word: &str, out: &mut dyn Write) -> io::Result<bool> {
        help::command(self.spec, word, out)
    }
}
