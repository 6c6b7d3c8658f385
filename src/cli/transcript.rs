//! `tmclsh transcript to-rhai LOG`: a `--log` transcript turned into a Rhai script that sends the
//! same commands and checks the values received — of a TMCL or an SMD4 session, as the transcript
//! says.

use std::io::Write;
use std::path::PathBuf;

use crate::commission::replay;
use crate::exit::Exit;
use crate::profile::Profile;

use super::Failure;

/// Arguments of `transcript`.
#[derive(Debug, Clone, clap::Args)]
pub struct TranscriptArgs {
    #[command(subcommand)]
    action: Action,
}

#[derive(Debug, Clone, clap::Subcommand)]
enum Action {
    /// Write a Rhai script replaying the commands of LOG, with assert_eq on the values received.
    ToRhai {
        /// The transcript written by --log or :log.
        #[arg(value_name = "LOG")]
        log: PathBuf,
        /// Write the script to FILE instead of stdout.
        #[arg(short, long, value_name = "FILE")]
        output: Option<PathBuf>,
        /// Milliseconds the script waits for a live value (position, switch) to reach the value
        /// the transcript saw.
        #[arg(long, value_name = "MS", default_value_t = 10_000)]
        wait: u64,
    },
}

/// Runs `transcript`.
pub fn run(args: TranscriptArgs, profile: &Profile, out: &mut dyn Write) -> Result<Exit, Failure> {
    let Action::ToRhai { log, output, wait } = args.action;
    let text = std::fs::read_to_string(&log).map_err(|e| {
        Failure::new(
            Exit::Refused,
            format!("cannot read transcript {}: {e}", log.display()),
        )
    })?;
    let entries = replay::parse::parse(&text)
        .map_err(|e| Failure::new(Exit::Refused, format!("{}: {e}", log.display())))?;
    let name = log.file_name().map_or_else(
        || log.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let script = if replay::smd4::is_smd4(&entries) {
        let spec = crate::protocol::smd4::Smd4Spec::builtin();
        replay::smd4::to_rhai(&replay::smd4::steps(&entries, spec), spec, &name, wait)
    } else {
        replay::to_rhai(&replay::steps(&entries, profile), profile, &name, wait)
    };
    let written = match &output {
        Some(path) => std::fs::write(path, &script),
        None => out.write_all(script.as_bytes()),
    };
    match written {
        Ok(()) => Ok(Exit::Success),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(Exit::Success),
        Err(e) => Err(Failure::new(
            Exit::Refused,
            format!("cannot write the script: {e}"),
        )),
    }
}
