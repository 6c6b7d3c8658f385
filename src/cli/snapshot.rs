//! `tmclsh snapshot save|diff|restore`: a module's parameters in a TOML file, compared with a
//! module or another file, written back in a safe order and verified.

use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;
use std::sync::Arc;

use crate::commission::actions::{self, RestoreOptions};
use crate::commission::restore::{self, Plan};
use crate::commission::tmcl::profile_params;
use crate::exit::{Exit, ExitStatus};
use crate::profile::Profile;
use crate::session::tmcl::TmclSession;
use crate::session::{SessionError, interrupt};

use super::Failure;
use super::connection::{ConnectionArgs, SessionArgs, open_tmcl};

/// Arguments of `snapshot`.
#[derive(Debug, Clone, clap::Args)]
pub struct SnapshotArgs {
    #[command(subcommand)]
    action: Action,
}

#[derive(Debug, Clone, clap::Subcommand)]
enum Action {
    /// Read every readable parameter into FILE (TOML, keyed by parameter name).
    Save {
        /// The snapshot file to write.
        #[arg(value_name = "FILE")]
        file: PathBuf,
        #[command(flatten)]
        connection: ConnectionArgs,
        #[command(flatten)]
        session: SessionArgs,
    },
    /// Show the settings that differ between FILE and the module, or between FILE and FILE2
    /// (exit code 1 when they differ).
    Diff {
        /// The snapshot file.
        #[arg(value_name = "FILE")]
        file: PathBuf,
        /// A second snapshot file to compare with, instead of the module.
        #[arg(value_name = "FILE2")]
        other: Option<PathBuf>,
        #[command(flatten)]
        connection: ConnectionArgs,
        #[command(flatten)]
        session: SessionArgs,
    },
    /// Write FILE's settings back (unit mode and limits first), verifying each by reading it
    /// back; read-only, live and link settings are skipped and listed.
    Restore {
        /// The snapshot file.
        #[arg(value_name = "FILE")]
        file: PathBuf,
        /// Afterwards store the written parameters to EEPROM (STAP/STGP), after a confirmation.
        #[arg(long)]
        store: bool,
        /// Confirm --store without asking (for scripts).
        #[arg(long, requires = "store")]
        yes: bool,
        /// Only print the lines that would be sent.
        #[arg(long)]
        dry_run: bool,
        #[command(flatten)]
        connection: ConnectionArgs,
        #[command(flatten)]
        session: SessionArgs,
    },
}

/// Runs `snapshot`.
pub fn run(
    args: SnapshotArgs,
    profile: &Arc<Profile>,
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    interrupt::install();
    match args.action {
        Action::Save {
            file,
            connection,
            session,
        } => with_session(&connection, &session, profile, |s| {
            actions::save(s, &file, out).map(|_| ())
        }),
        Action::Diff {
            file,
            other: Some(other),
            ..
        } => {
            let params = profile_params(profile);
            finish(actions::diff_files(&file, &other, &params, out).map(|_| ()))
        }
        Action::Diff {
            file,
            other: None,
            connection,
            session,
        } => with_session(&connection, &session, profile, |s| {
            actions::diff(s, &file, out).map(|_| ())
        }),
        Action::Restore {
            file,
            store,
            yes,
            dry_run,
            connection,
            session,
        } => {
            let ask = store && !yes && !dry_run;
            if ask && !std::io::stdin().is_terminal() {
                return Err(Failure::new(
                    Exit::Refused,
                    "--store asks for a confirmation on a terminal; add --yes to store without asking",
                ));
            }
            let options = RestoreOptions { store, dry_run };
            let module = session.module;
            with_session(&connection, &session, profile, |s| {
                let mut confirm = |plan: &Plan| {
                    if ask {
                        confirm_store(plan, module)
                    } else {
                        Ok(true)
                    }
                };
                actions::restore(s, &file, options, &mut confirm, out).map(|_| ())
            })
        }
    }
}

/// Opens a session, runs `f`, and closes the session (modules back in their modes) whatever
/// happened.
fn with_session(
    connection: &ConnectionArgs,
    session: &SessionArgs,
    profile: &Arc<Profile>,
    f: impl FnOnce(&mut TmclSession) -> Result<(), SessionError>,
) -> Result<Exit, Failure> {
    let mut s = open_tmcl(connection, session, profile)?;
    let result = f(&mut s);
    for notice in s.take_notices() {
        eprintln!("tmclsh: {notice}");
    }
    interrupt::take();
    for message in s.close() {
        eprintln!("tmclsh: {message}");
    }
    finish(result)
}

fn finish(result: Result<(), SessionError>) -> Result<Exit, Failure> {
    match result {
        Ok(()) => Ok(Exit::Success),
        Err(e) => Err(Failure::new(e.exit(), e.to_string())),
    }
}

/// Output that ignores a closed pipe (`| head`): the work goes on, the rest of the report is
/// dropped, and the exit code stays that of the work.
pub(super) struct PipeSafe<'a>(pub &'a mut dyn Write);

impl Write for PipeSafe<'_> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        match self.0.write(buf) {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(buf.len()),
            other => other,
        }
    }

    fn flush(&mut self) -> std::io::Result<()> {
        match self.0.flush() {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
            other => other,
        }
    }
}

fn confirm_store(plan: &Plan, module: u8) -> Result<bool, SessionError> {
    let n = restore::storable(plan).count();
    eprint!("store {n} parameters to the EEPROM of module {module}? [y/N] ");
    let mut answer = String::new();
    std::io::stdin().lock().read_line(&mut answer)?;
    Ok(matches!(answer.trim(), "y" | "Y" | "yes" | "YES" | "Yes"))
}
