//! `tmclsh transcript to-rhai LOG`: a `--log` transcript turned into a Rhai script that sends the
//! same commands and checks the values received — of a TMCL or an SMD4 session, as the
//! transcript's header says. What it cannot read, or what replays nothing, is refused (exit 2).

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::dialect::{Configured, replay};
use crate::exit::{Exit, Failure};

/// Arguments of `transcript`.
#[derive(Debug, Clone, clap::Args)]
pub(super) struct TranscriptArgs {
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
        /// The module's tables.
        #[command(flatten)]
        profile: super::profile_option::ProfileOption,
    },
}

/// Runs `transcript`.
pub(super) fn run(
    args: TranscriptArgs,
    configs: &Configured,
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    let Action::ToRhai {
        log, output, wait, ..
    } = args.action;
    let refused = |what: &dyn std::fmt::Display| {
        Failure::new(Exit::Refused, format!("{}: {what}", log.display()))
    };
    let text = read_transcript(&log).map_err(|e| refused(&e))?;
    let entries = replay::parse::parse(&text).map_err(|e| refused(&e))?;
    let kind = replay::recognise(&entries).map_err(|e| refused(&e))?;
    if let Some(notice) = &kind.notice {
        eprintln!("tmclsh: {}: {notice}", log.display());
    }
    let name = log.file_name().map_or_else(
        || log.display().to_string(),
        |n| n.to_string_lossy().escape_debug().to_string(),
    );
    let script = configs
        .of(kind.dialect)
        .replay(&entries, kind.header.as_ref(), &name, wait)
        .map_err(|e| refused(&e))?;
    let written = match &output {
        Some(path) => crate::file::write(path, script.as_bytes()).map_err(std::io::Error::other),
        None => out.write_all(script.as_bytes()),
    };
    match written {
        Ok(()) => Ok(Exit::Success),
        Err(e) => Err(Failure::new(
            Exit::Refused,
            format!("cannot write the script: {e}"),
        )),
    }
}

/// The largest transcript read: hours of logging fit; `/dev/zero` does not.
const MAX_TRANSCRIPT: u64 = 256 << 20;

/// The transcript's text, refused when it is not text or larger than [`MAX_TRANSCRIPT`].
fn read_transcript(path: &Path) -> Result<String, Unreadable> {
    let bytes = crate::file::read(path, MAX_TRANSCRIPT).map_err(Unreadable::File)?;
    String::from_utf8(bytes).map_err(|e| {
        let line = e.as_bytes()[..e.utf8_error().valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count()
            + 1;
        Unreadable::NotText { line }
    })
}

/// Why a transcript cannot be read (its path goes before the message).
#[derive(Debug, thiserror::Error)]
enum Unreadable {
    /// Not a regular file, missing, too large, not allowed.
    #[error("{}", .0.reason)]
    File(crate::file::FileError),
    /// Bytes that are not UTF-8: a transcript escapes every byte it records.
    #[error("line {line}: not text (transcripts escape every byte they record)")]
    NotText {
        /// The line of the first such byte, from 1.
        line: usize,
    },
}
