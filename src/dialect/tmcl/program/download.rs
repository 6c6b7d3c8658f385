//! Downloading a program file or TMCL source to the module, with a progress bar on a terminal
//! (with the `cli` feature, which brings the terminal faces): what `tmclsh download` and the
//! shell's `:download` share.

#[cfg(feature = "cli")]
use std::io::IsTerminal;
use std::path::Path;

#[cfg(feature = "cli")]
use indicatif::{ProgressBar, ProgressStyle};

use crate::dialect::tmcl::asm;
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::Instruction;
use crate::dialect::tmcl::session::TmclSession;
use crate::exit::{Exit, ExitStatus};
use crate::session::SessionError;

/// A failure of the download as a whole: its exit code and message, never taken for a lost link
/// or Ctrl-C at the prompt (the download has already handled those).
fn failure(exit: Exit, message: String) -> SessionError {
    SessionError::Script { exit, message }
}

/// Loads a program file or assembles a source file.
pub fn load(path: &Path, profile: &Profile) -> Result<Vec<Instruction>, SessionError> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path)
        .map_err(|e| failure(Exit::Refused, format!("cannot read {name}: {e}")))?;
    asm::load_program(&bytes, &name, profile).map_err(|e| failure(Exit::Refused, e.to_string()))
}

/// Downloads with a progress bar on a terminal, then optionally runs; returns what to tell the
/// user.
pub fn download_and_run(
    session: &mut TmclSession,
    instructions: &[Instruction],
    run: bool,
) -> Result<String, SessionError> {
    let failed = |e: SessionError| failure(e.exit(), e.to_string());
    let module = session.target();
    #[cfg(feature = "cli")]
    let report = {
        let bar = progress_bar(instructions.len() * 2);
        let report = super::download(session, module, instructions, |done, total| {
            if let Some(bar) = &bar {
                bar.set_length(total as u64);
                bar.set_position(done as u64);
            }
        });
        if let Some(bar) = &bar {
            bar.finish_and_clear();
        }
        report
    };
    #[cfg(not(feature = "cli"))]
    let report = super::download(session, module, instructions, |_, _| {});
    let report = report.map_err(failed)?;
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
            .map_err(failed)?;
        text.push_str("; program started");
    }
    text.push_str(&format!(
        "; the module is in {} mode",
        super::mode_text(session, module)
    ));
    Ok(text)
}

#[cfg(feature = "cli")]
fn progress_bar(total: usize) -> Option<ProgressBar> {
    if !std::io::stderr().is_terminal() || total < 64 {
        return None;
    }
    let bar = ProgressBar::new(total as u64);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}").ok()?);
    bar.set_message("download and verify");
    Some(bar)
}
