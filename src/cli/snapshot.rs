//! `tmclsh snapshot save|diff|restore`: a module's parameters in a TOML file, compared with a
//! module or another file, written back in a safe order and verified — TMCL modules and SMD4
//! drives alike (`--protocol smd4`).

use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;

use crate::commission::ParamDevice;
use crate::commission::actions::{self, RestoreOptions};
use crate::commission::snapshot::Snapshot;
use crate::dialect::{Configured, Purpose};
use crate::exit::{Exit, Failure};
use crate::session::{SessionError, interrupt};

use super::connection::{Audience, ModuleArgs};

/// Arguments of `snapshot`.
#[derive(Debug, Clone, clap::Args)]
pub(super) struct SnapshotArgs {
    #[command(subcommand)]
    action: Action,
}

#[derive(Debug, Clone, clap::Subcommand)]
enum Action {
    /// Read every readable parameter into FILE (TOML, keyed by parameter name).
    Save {
        /// The snapshot file to write.
        #[arg(value_name = "FILE", value_hint = clap::ValueHint::FilePath)]
        file: PathBuf,
        /// Replace FILE if it exists.
        #[arg(long)]
        force: bool,
        #[command(flatten)]
        module: ModuleArgs,
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
        /// Print one JSON document instead of the table (fields in docs/machine-output.md).
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        module: ModuleArgs,
    },
    /// Write FILE's settings back (unit mode and limits first; SMD4: resolution, currents and
    /// frequencies first, the mode last, only while the motor stands still), verifying each by
    /// reading it back; read-only, live and link settings are skipped and listed.
    Restore {
        /// The snapshot file.
        #[arg(value_name = "FILE")]
        file: PathBuf,
        /// Afterwards make the written parameters permanent, after a confirmation: EEPROM
        /// (STAP/STGP) on TMCL modules; STORE on an SMD4, which saves its whole working
        /// configuration.
        #[arg(long)]
        store: bool,
        /// Confirm --store without asking (for scripts).
        #[arg(long, requires = "store")]
        yes: bool,
        /// Only print the lines that would be sent.
        #[arg(long)]
        dry_run: bool,
        /// Restore a file with problems that allow it: of another module type, with numbers
        /// that disagree with the names (written by name), with names, motors or banks the
        /// module lacks (skipped). Values the module would refuse are never forced.
        #[arg(long)]
        force: bool,
        #[command(flatten)]
        module: ModuleArgs,
    },
}

/// Runs `snapshot`.
pub(super) fn run(
    args: SnapshotArgs,
    configs: &Configured,
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    interrupt::install();
    match args.action {
        Action::Save {
            file,
            force,
            module,
        } => {
            // Refused before the link is opened: nothing is sent for a save that cannot be kept.
            actions::check_new(&file, force)?;
            with_device(&module, configs, |d| {
                actions::save_new(d, &file, force, out).map(|_| ())
            })
        }
        Action::Diff {
            file,
            other: Some(other),
            json,
            module,
        } => {
            let params = configs.of(module.protocol()).snapshot_params();
            let output = diff_output(json);
            finish(actions::diff_files_as(&file, &other, &params, output, out).map(|_| ()))
        }
        Action::Diff {
            file,
            other: None,
            json,
            module,
        } => {
            // Read before the link is opened: nothing is sent for a file that is not a snapshot.
            let snapshot = Snapshot::load(&file)?;
            with_device(&module, configs, |d| {
                actions::diff_snapshot_as(d, &snapshot, &file, diff_output(json), out).map(|_| ())
            })
        }
        Action::Restore {
            file,
            store,
            yes,
            dry_run,
            force,
            module,
        } => {
            let ask = store && !yes && !dry_run;
            if ask && !std::io::stdin().is_terminal() {
                return Err(Failure::new(
                    Exit::Refused,
                    "--store asks for a confirmation on a terminal; add --yes to store without asking",
                ));
            }
            let options = RestoreOptions {
                store,
                dry_run,
                force,
                redact: false,
            };
            let snapshot = Snapshot::load(&file)?;
            let label = file.display().to_string();
            with_device(&module, configs, |d| {
                let mut confirm = |question: &str| {
                    if ask {
                        confirm_store(question)
                    } else {
                        Ok(true)
                    }
                };
                actions::restore_snapshot(d, &snapshot, &label, options, &mut confirm, out)
                    .map(|_| ())
            })
        }
    }
}

/// Opens a session in the dialect the flags say, runs `f` on its module, and closes the session
/// (TMCL modules back in their modes) whatever happened.
fn with_device(
    module: &ModuleArgs,
    configs: &Configured,
    f: impl FnOnce(&mut dyn ParamDevice) -> Result<(), SessionError>,
) -> Result<Exit, Failure> {
    let mut session = module.open(configs, Audience::Batch, Purpose::Talk)?;
    let result = f(session.param_device());
    for notice in session.take_notices() {
        super::diagnose(&notice);
    }
    interrupt::take();
    for message in session.close() {
        super::diagnose(&message);
    }
    finish(result)
}

fn diff_output(json: bool) -> actions::DiffOutput {
    if json {
        actions::DiffOutput::Json
    } else {
        actions::DiffOutput::Table
    }
}

fn finish(result: Result<(), SessionError>) -> Result<Exit, Failure> {
    result?;
    Ok(Exit::Success)
}

fn confirm_store(question: &str) -> Result<bool, SessionError> {
    eprint!("{question} [y/N] ");
    let mut answer = String::new();
    std::io::stdin().lock().read_line(&mut answer)?;
    Ok(matches!(answer.trim(), "y" | "Y" | "yes" | "YES" | "Yes"))
}
