//! `tmclsh scan [CONNECTION]`: which addresses on the bus answer, with firmware version and echo
//! setting; each reply is awaited at most `--timeout` milliseconds.

use std::io::Write;
use std::sync::Arc;

use crate::commission::scan;
use crate::exit::{Exit, ExitStatus};
use crate::profile::Profile;
use crate::session::interrupt;
use crate::session::tmcl::TmclSession;

use super::Failure;
use super::connection::{ConnectionArgs, SessionArgs};

/// Arguments of `scan`.
#[derive(Debug, Clone, clap::Args)]
pub struct ScanArgs {
    /// Addresses to try: numbers 1..255 and letters A..Z, single or as ranges (1-26, A,C,30-40).
    /// Addresses above 26 have no ASCII character and are tried with binary frames.
    #[arg(long, value_name = "LIST", default_value = "1-26")]
    pub addresses: String,
    #[command(flatten)]
    connection: ConnectionArgs,
    #[command(flatten)]
    session: SessionArgs,
}

/// Runs the scan; exit code 3 when no module answered.
pub fn run(args: ScanArgs, profile: &Arc<Profile>, out: &mut dyn Write) -> Result<Exit, Failure> {
    interrupt::install();
    let out = &mut super::snapshot::PipeSafe(out);
    if args.connection.protocol != crate::protocol::Dialect::Tmcl {
        return Err(Failure::new(
            Exit::Refused,
            "scan works with TMCL modules only",
        ));
    }
    let addresses = scan::parse_addresses(&args.addresses)
        .map_err(|e| Failure::new(Exit::Refused, format!("--addresses: {e}")))?;
    let options = args.session.options();
    let per_reply = options.timeout;
    let transcript = args.session.transcript()?;
    let link = args.connection.open(profile, per_reply)?;
    let mut session = TmclSession::open_idle(link, profile.clone(), options, transcript)
        .map_err(|e| Failure::new(e.exit(), e.to_string()))?;
    let quiet = scan::quiet_time(profile);
    let result = scan::scan(&mut session, &addresses, per_reply, quiet);
    for notice in session.take_notices() {
        eprintln!("tmclsh: {notice}");
    }
    interrupt::take();
    for message in session.close() {
        eprintln!("tmclsh: {message}");
    }
    let report = result.map_err(|e| Failure::new(e.exit(), e.to_string()))?;
    if report.found.is_empty() {
        return Err(Failure::new(Exit::Link, scan::summary(&report)));
    }
    scan::write_report(&report, out).map_err(|e| Failure::new(Exit::Link, e.to_string()))?;
    Ok(Exit::Success)
}
