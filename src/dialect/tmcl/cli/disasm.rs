//! `tmclsh disasm FILE.bin`: a program file back to TMCL source, on stdout.

use std::io::Write;
use std::path::PathBuf;

use crate::dialect::tmcl::asm;
use crate::dialect::tmcl::profile::Profile;
use crate::exit::{Exit, Failure};

/// Arguments of `disasm`.
#[derive(Debug, clap::Args)]
pub struct DisasmArgs {
    /// Program file written by `tmclsh asm -o`.
    #[arg(value_name = "FILE.bin")]
    pub file: PathBuf,
    /// The module's tables (its commands).
    #[command(flatten)]
    pub profile: crate::cli::profile_option::ProfileOption,
}

/// Turns the program file back into source for the profile, warning of instructions no program
/// may hold.
pub fn run(args: &DisasmArgs, profile: &Profile, out: &mut dyn Write) -> Result<Exit, Failure> {
    let (name, bytes) = super::read_input(&args.file)?;
    let instructions = asm::read_binary(&bytes)
        .map_err(|e| Failure::new(Exit::Refused, format!("{name}: {e}")))?;
    let disassembly = asm::disassemble(&instructions, profile);
    for (address, error) in &disassembly.problems {
        eprintln!("{name}: warning: instruction {address} is not valid in a program: {error}");
    }
    let written = writeln!(
        out,
        "// {name}: {} instructions, disassembled for the {}",
        instructions.len(),
        profile.module
    )
    .and_then(|()| out.write_all(disassembly.source.as_bytes()));
    written
        .map(|()| Exit::Success)
        .map_err(|e| Failure::new(Exit::Refused, e.to_string()))
}
