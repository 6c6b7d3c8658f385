//! `tmclsh download FILE.tmc|FILE.bin [CONNECTION] [--run]`: store a stand-alone program in the
//! module, verify it, optionally start it. A TMCL subcommand: it names TMCL.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::dialect::tmcl::asm::load_program;
use crate::dialect::tmcl::profile::catalogue;
use crate::dialect::tmcl::program::download::download_and_run;
use crate::dialect::{Configured, Purpose, tmcl};
use crate::exit::{Exit, Failure};
use crate::session::SessionError;

use crate::cli::connection::{Audience, ModuleArgs};

/// Arguments of `download`.
#[derive(Debug, Clone, clap::Args)]
pub struct DownloadArgs {
    /// The program: TMCL source (assembled first) or a program file from `tmclsh asm -o`.
    #[arg(value_name = "FILE")]
    pub file: PathBuf,
    /// Which module, and how to talk to it.
    #[command(flatten)]
    pub module: ModuleArgs,
    /// Start the program after downloading it.
    #[arg(long)]
    pub run: bool,
}

/// Runs `download`.
pub fn run(args: DownloadArgs, configs: &Configured, out: &mut dyn Write) -> Result<Exit, Failure> {
    super::start_module_command(&args.module)?;
    // A file that cannot be read, or a program no module could take, is refused before the port
    // is opened.
    let bytes = crate::file::read(&args.file, crate::file::READ_LIMIT)
        .map_err(|e| Failure::refused(format!("cannot read {e}")))?;
    precheck(&bytes, &args.file, configs)?;
    let mut session = args.module.open(configs, Audience::Batch, Purpose::Talk)?;
    let tmcl = tmcl::session(&mut *session).expect("a TMCL session");
    // Checked against the module identified (its own command set: EI, VECT … where it has
    // them), not the default profile; a given --profile is what identification settled on.
    let profile = tmcl.profile().clone();
    // The bytes read and checked above, not the file read again.
    let name = args.file.display().to_string();
    let result = load_program(&bytes, &name, &profile)
        .map_err(|e| SessionError::Failed(e.into()))
        .and_then(|program| download_and_run(tmcl, &program, args.run));
    for notice in session.take_notices() {
        crate::cli::diagnose(&notice);
    }
    for message in session.close() {
        crate::cli::diagnose(&message);
    }
    let text = result?;
    writeln!(out, "{text}")?;
    Ok(Exit::Success)
}

/// Refuses a program that the profile in effect and every built-in profile refuse (a syntax
/// error, an unknown label, a command no module has) without touching the module; whether the
/// module identified takes it is decided once it is identified.
fn precheck(bytes: &[u8], file: &Path, configs: &Configured) -> Result<(), Failure> {
    let name = file.display().to_string();
    let refusal = match load_program(bytes, &name, super::profile(configs)) {
        Ok(_) => return Ok(()),
        Err(e) => e,
    };
    let any = catalogue::all()
        .iter()
        .any(|profile| load_program(bytes, &name, profile).is_ok());
    if any {
        Ok(())
    } else {
        Err(Failure::refused(refusal.to_string()))
    }
}
