//! `tmclsh scan [CONNECTION]`: which addresses on the bus answer — TMCL modules with firmware
//! version and echo setting, SMD4 drives (`--protocol smd4`) with firmware version and serial
//! number; each reply is awaited at most `--timeout` milliseconds.

use std::io::Write;
use std::sync::Arc;

use crate::commission::{scan, smd4_scan};
use crate::exit::{Exit, ExitStatus};
use crate::profile::Profile;
use crate::protocol::Dialect;
use crate::session::interrupt;
use crate::session::smd4::Smd4Session;
use crate::session::tmcl::TmclSession;

use super::Failure;
use super::connection::{Audience, ModuleArgs};

/// Arguments of `scan`.
#[derive(Debug, Clone, clap::Args)]
pub struct ScanArgs {
    /// Addresses to try: numbers and (TMCL) letters A..Z, single or as ranges (1-26, A,C,30-40).
    /// TMCL: 1-26 by default; addresses above 26 have no ASCII character and are tried with
    /// binary frames. SMD4: 1-247 by default, one @N SYS:FW each (an empty bus takes 247 times
    /// --timeout).
    #[arg(long, value_name = "LIST")]
    pub addresses: Option<String>,
    /// Which bus, and how to talk to it.
    #[command(flatten)]
    module: ModuleArgs,
}

/// Runs the scan; exit code 3 when nothing answered.
pub fn run(args: ScanArgs, profile: &Arc<Profile>, out: &mut dyn Write) -> Result<Exit, Failure> {
    interrupt::install();
    let out = &mut super::snapshot::PipeSafe(out);
    let smd4 = args.module.protocol() == Dialect::Smd4;
    let default = if smd4 { "1-247" } else { "1-26" };
    let list = args.addresses.as_deref().unwrap_or(default);
    let addresses = scan::parse_addresses(list)
        .map_err(|e| Failure::new(Exit::Refused, format!("--addresses: {e}")))?;
    let options = args.module.session.options();
    let per_reply = options.timeout;
    let header = crate::session::transcript::Header::new(args.module.protocol(), profile);
    let (transcript, link) = args
        .module
        .connect(&header, profile, per_reply, Audience::Batch)?;
    let failed = |e: crate::session::SessionError| Failure::new(e.exit(), e.to_string());
    if smd4 {
        let mut session = Smd4Session::open(link, options, args.module.smd4.options(), transcript)
            .map_err(failed)?;
        let addresses: Vec<u32> = addresses.into_iter().map(u32::from).collect();
        let result = smd4_scan::scan(&mut session, &addresses, per_reply);
        for notice in session.take_notices() {
            super::diagnose(&notice);
        }
        interrupt::take();
        session.close();
        let report = result.map_err(failed)?;
        if report.found.is_empty() {
            return Err(Failure::new(Exit::Link, smd4_scan::summary(&report)));
        }
        smd4_scan::write_report(&report, out)
            .map_err(|e| Failure::new(Exit::Link, e.to_string()))?;
        return Ok(Exit::Success);
    }
    let mut session =
        TmclSession::open_idle(link, profile.clone(), options, transcript).map_err(failed)?;
    let quiet = scan::quiet_time(profile);
    let result = scan::scan(&mut session, &addresses, per_reply, quiet);
    for notice in session.take_notices() {
        super::diagnose(&notice);
    }
    interrupt::take();
    for message in session.close() {
        super::diagnose(&message);
    }
    let report = result.map_err(failed)?;
    if report.found.is_empty() {
        return Err(Failure::new(Exit::Link, scan::summary(&report)));
    }
    scan::write_report(&report, out).map_err(|e| Failure::new(Exit::Link, e.to_string()))?;
    Ok(Exit::Success)
}
