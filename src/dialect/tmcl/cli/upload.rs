//! `tmclsh upload [-o FILE.tmc|FILE.bin] [CONNECTION]`: read the stored program back (command
//! 134) and print it as source with labels, or write it. A TMCL subcommand: it names TMCL.

use std::io::Write;
use std::path::PathBuf;

use crate::dialect::tmcl::program::upload::{Output, upload_to};
use crate::dialect::{Configured, Purpose, tmcl};
use crate::exit::{Exit, Failure};

use crate::cli::connection::{Audience, ModuleArgs};

/// Arguments of `upload`.
#[derive(Debug, Clone, clap::Args)]
pub struct UploadArgs {
    /// Write the program to FILE.tmc (source) or FILE.bin (a program file) instead of printing it.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Read at most N instructions (default: the module's program memory).
    #[arg(long, value_name = "N")]
    pub max: Option<usize>,
    /// Which module, and how to talk to it.
    #[command(flatten)]
    pub module: ModuleArgs,
}

/// Runs `upload`.
pub fn run(args: UploadArgs, configs: &Configured, out: &mut dyn Write) -> Result<Exit, Failure> {
    super::start_module_command(&args.module)?;
    let output = match &args.output {
        Some(path) => Output::for_file(path).map_err(Failure::from)?,
        None => Output::Print,
    };
    let mut session = args.module.open(configs, Audience::Batch, Purpose::Talk)?;
    let tmcl = tmcl::session(&mut *session).expect("a TMCL session");
    let result = upload_to(tmcl, output, args.max);
    for notice in session.take_notices() {
        crate::cli::diagnose(&notice);
    }
    for message in session.close() {
        crate::cli::diagnose(&message);
    }
    let text = result.map_err(Failure::from)?;
    // A closed stdout is decided in `cli::main` (quietly, 141).
    out.write_all(text.as_bytes())
        .map(|()| Exit::Success)
        .map_err(Failure::from)
}
