//! `tmclsh completions SHELL`: completion scripts generated from the clap definition.

use std::io::{self, Write};

use clap_complete::Shell;

/// Arguments of `completions`.
#[derive(Debug, clap::Args)]
pub struct CompletionsArgs {
    /// The shell to generate for.
    pub shell: Shell,
}

pub fn run(args: &CompletionsArgs, out: &mut dyn Write) -> io::Result<()> {
    out.write_all(&generate(args.shell))
}

/// The completion script for `shell`.
pub fn generate(shell: Shell) -> Vec<u8> {
    let mut buf = Vec::new();
    clap_complete::generate(shell, &mut super::command(), "tmclsh", &mut buf);
    buf
}
