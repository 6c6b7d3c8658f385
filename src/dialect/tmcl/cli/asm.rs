//! `tmclsh asm FILE.tmc [-o FILE.bin] [--list]`: assemble a stand-alone TMCL program.

use std::io::Write;
use std::path::PathBuf;

use crate::dialect::tmcl::asm::{self, Program};
use crate::dialect::tmcl::profile::Profile;
use crate::exit::{Exit, Failure};

/// Arguments of `asm`.
#[derive(Debug, clap::Args)]
pub struct AsmArgs {
    /// TMCL source file (as the TMCL-IDE writes it).
    #[arg(value_name = "FILE.tmc")]
    pub file: PathBuf,
    /// Write the program file (format in docs/programs.md); without it the source is only checked.
    #[arg(short, long, value_name = "FILE.bin")]
    pub output: Option<PathBuf>,
    /// Print the listing: address, the 7 instruction bytes and the source line.
    #[arg(long)]
    pub list: bool,
    /// The module's tables (its program memory, its commands).
    #[command(flatten)]
    pub profile: crate::cli::profile_option::ProfileOption,
}

/// Assembles the program: checks it against the profile, prints the listing or writes the
/// program file.
pub fn run(args: &AsmArgs, profile: &Profile, out: &mut dyn Write) -> Result<Exit, Failure> {
    let (name, bytes) = super::read_input(&args.file)?;
    if asm::is_program_file(&bytes) {
        return Err(Failure::new(
            Exit::Refused,
            format!("{name} is an assembled program file, not source; use `tmclsh disasm {name}`"),
        ));
    }
    let source = asm::source_text(&bytes);
    let program = match asm::assemble(&source, &name, profile) {
        Ok(program) => program,
        Err(errors) => {
            for warning in &errors.warnings {
                eprintln!("{warning}");
            }
            for error in &errors.errors {
                eprintln!("{error}");
            }
            let count = errors.errors.len();
            let plural = if count == 1 { "" } else { "s" };
            return Err(Failure::new(
                Exit::Refused,
                format!("{name}: {count} error{plural}, nothing assembled"),
            ));
        }
    };
    for warning in &program.warnings {
        eprintln!("{warning}");
    }
    if let Some(path) = &args.output {
        let bytes = asm::write_binary(&program.instructions)?;
        crate::file::write(path, &bytes)
            .map_err(|e| Failure::new(Exit::Refused, format!("cannot write {e}")))?;
    }
    report(args, &program, &source, profile, out)
        .map_err(|e| Failure::new(Exit::Refused, e.to_string()))?;
    Ok(Exit::Success)
}

fn report(
    args: &AsmArgs,
    program: &Program,
    source: &str,
    profile: &Profile,
    out: &mut dyn Write,
) -> std::io::Result<()> {
    if args.list {
        write!(out, "{}", program.listing(source))?;
    }
    let summary = format!(
        "{} of {} ({})",
        crate::count::counted(program.instructions.len(), "instruction"),
        profile.program_memory,
        crate::count::counted(program.byte_len(), "byte")
    );
    match &args.output {
        Some(path) => writeln!(out, "{}: {summary}", path.display()),
        None => writeln!(out, "{}: {summary}", args.file.display()),
    }
}
