//! `tmclsh download FILE.tmc|FILE.bin [CONNECTION] [--run]`: store a stand-alone program in the
//! module, verify it, optionally start it.

use crate::dialect::session::DialectSession;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use indicatif::{ProgressBar, ProgressStyle};

use crate::dialect::tmcl::asm;
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::program;
use crate::dialect::tmcl::protocol::Instruction;
use crate::dialect::tmcl::session::TmclSession;
use crate::exit::{Exit, ExitStatus};
use crate::session::interrupt;

use super::Failure;
use super::connection::ModuleArgs;

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

/// Loads a program file or assembles a source file, for `download` and `:download`.
pub fn load(path: &Path, profile: &Profile) -> Result<Vec<Instruction>, Failure> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path)
        .map_err(|e| Failure::new(Exit::Refused, format!("cannot read {name}: {e}")))?;
    asm::load_program(&bytes, &name, profile)
        .map_err(|e| Failure::new(Exit::Refused, e.to_string()))
}

/// Downloads with a progress bar on a terminal, then optionally runs; returns what to tell the
/// user.
pub fn download_and_run(
    session: &mut TmclSession,
    instructions: &[Instruction],
    run: bool,
) -> Result<String, Failure> {
    let failure = |e: crate::session::SessionError| Failure::new(e.exit(), e.to_string());
    let module = session.target();
    let bar = progress_bar(instructions.len() * 2);
    let report = program::download(session, module, instructions, |done, total| {
        if let Some(bar) = &bar {
            bar.set_length(total as u64);
            bar.set_position(done as u64);
        }
    });
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let report = report.map_err(failure)?;
    let mut text = format!(
        "downloaded {} instruction{} to module {}{}",
        report.stored,
        if report.stored == 1 { "" } else { "s" },
        module,
        if report.verified {
            ", verified by reading back"
        } else {
            " (the module does not read back; not verified)"
        }
    );
    if run {
        session
            .run_program(module, None)
            .and_then(|x| x.checked())
            .map_err(failure)?;
        text.push_str("; program started");
    }
    text.push_str(&format!(
        "; the module is in {} mode",
        program::mode_text(session, module)
    ));
    Ok(text)
}

fn progress_bar(total: usize) -> Option<ProgressBar> {
    if !std::io::stderr().is_terminal() || total < 64 {
        return None;
    }
    let bar = ProgressBar::new(total as u64);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}").ok()?);
    bar.set_message("download and verify");
    Some(bar)
}

/// Runs `download`.
pub fn run(
    args: DownloadArgs,
    profile: &Arc<Profile>,
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    interrupt::install();
    let instructions = load(&args.file, profile)?;
    let mut session = args.module.open_tmcl(profile)?;
    let result = download_and_run(&mut session, &instructions, args.run);
    for notice in session.take_notices() {
        super::diagnose(&notice);
    }
    for message in session.close() {
        super::diagnose(&message);
    }
    let text = result?;
    writeln!(out, "{text}").map_err(|e| Failure::new(Exit::Link, e.to_string()))?;
    Ok(Exit::Success)
}
