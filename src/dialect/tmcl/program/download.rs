//! Downloading a program file or TMCL source to the module, with a progress bar on a terminal
//! (with the `cli` feature, which brings the terminal faces): what `tmclsh download` and the
//! shell's `:download` share.

use std::path::Path;

use crate::dialect::tmcl::asm;
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::{Instruction, ModuleName};
use crate::dialect::tmcl::session::TmclSession;
use crate::exit::Failure;
use crate::progress::Progress;
use crate::session::SessionError;

/// A failure of the download as a whole, with the exit code of what went wrong, never taken for a
/// lost link or Ctrl-C at the prompt (the download has already handled those).
fn failed(error: impl Into<Failure>) -> SessionError {
    SessionError::Failed(error.into())
}

/// Loads a program file or assembles a source file.
pub fn load(path: &Path, profile: &Profile) -> Result<Vec<Instruction>, SessionError> {
    let name = path.display().to_string();
    let bytes = crate::file::read(path, crate::file::READ_LIMIT)
        .map_err(|e| failed(Failure::refused(format!("cannot read {e}"))))?;
    asm::load_program(&bytes, &name, profile).map_err(failed)
}

/// Downloads with a progress bar on a terminal, then optionally runs; returns what to tell the
/// user.
pub fn download_and_run(
    session: &mut TmclSession,
    instructions: &[Instruction],
    run: bool,
) -> Result<String, SessionError> {
    let module = session.target();
    // Each instruction is written and read back; a short program is done before a bar shows.
    let progress = Progress::steps(instructions.len() * 2, 64, "download and verify");
    let report = super::download(session, module, instructions, |done, total| {
        progress.set(done, total)
    });
    drop(progress);
    let report = report.map_err(failed)?;
    let mut text = format!(
        "downloaded {} to {}{}",
        crate::count::counted(report.stored, "instruction"),
        ModuleName(module),
        if report.verified {
            ", verified by reading back"
        } else {
            "; not verified: the module does not read back"
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
