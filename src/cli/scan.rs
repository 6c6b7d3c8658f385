//! `tmclsh scan [CONNECTION]`: which addresses on the bus answer — TMCL modules with firmware
//! version, echo setting and module type, SMD4 drives (`--protocol smd4`) with firmware version
//! and serial number; each reply is awaited at most `--timeout` milliseconds, by default a short
//! [`SCAN_WAIT`] (a module answers at once; the session's long default is for slow commands).
//! `--first` stops at the first module found.

use std::io::Write;

use std::time::Duration;

use crate::commission::scan::{describe_addresses, parse_addresses};
use crate::dialect::DialectSession;
use crate::dialect::session::BusScan;
use crate::dialect::{Configured, Purpose};
use crate::exit::{Exit, Failure};
use crate::json::json;
use crate::session::interrupt;

use super::connection::{Audience, ModuleArgs};

/// Arguments of `scan`.
#[derive(Debug, Clone, clap::Args)]
pub(super) struct ScanArgs {
    /// Addresses to try: numbers and (TMCL) letters A..Z, single or as ranges (1-26, A,C,30-40).
    /// TMCL: 1-26 by default; addresses above 26 have no ASCII character and are tried with
    /// binary frames. SMD4: 1-247 by default, one @N SYS:FW each. Each reply is awaited 100 ms
    /// unless --timeout is set.
    #[arg(long, value_name = "LIST")]
    pub addresses: Option<String>,
    /// Stop at the first module found, trying the addresses in ascending order.
    #[arg(long)]
    pub first: bool,
    /// Print one JSON document instead of the table (fields in docs/machine-output.md), also
    /// when nothing answered.
    #[arg(long)]
    pub json: bool,
    /// Which bus, and how to talk to it.
    #[command(flatten)]
    module: ModuleArgs,
}

/// Runs the scan; exit code 3 when nothing answered.
pub(super) fn run(
    args: ScanArgs,
    configs: &Configured,
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    interrupt::install();
    let out = &mut crate::stdout::PipeSafe(out);
    let dialect = args.module.protocol();
    let list = args.addresses.as_deref().unwrap_or(dialect.scan_addresses);
    let addresses = parse_addresses(list, dialect.max_address)
        .map_err(|e| Failure::new(Exit::Refused, format!("--addresses: {e}")))?;
    let per_reply = if args.module.timeout_given() {
        args.module.session.options().timeout
    } else {
        SCAN_WAIT
    };
    let mut session = args.module.open(configs, Audience::Batch, Purpose::Scan)?;
    let result = if args.first {
        first_found(session.as_mut(), &addresses, per_reply)
    } else {
        session.scan_bus(&addresses, per_reply)
    };
    for notice in session.take_notices() {
        super::diagnose(&notice);
    }
    interrupt::take();
    for message in session.close() {
        super::diagnose(&message);
    }
    let scan = result?;
    if args.json {
        let document = json!({
            "protocol": dialect.name,
            "found": scan.found,
            "summary": scan.summary,
            "modules": scan.modules,
        });
        crate::json::write(&document, out)?;
    }
    if scan.found == 0 {
        return Err(Failure::new(Exit::Link, scan.summary));
    }
    if !args.json {
        out.write_all(scan.report.as_bytes())?;
    }
    Ok(Exit::Success)
}

pub(super) use crate::commission::scan::SCAN_WAIT;

/// Scans one address after another until a module answers.
fn first_found(
    session: &mut dyn DialectSession,
    addresses: &[u8],
    per_reply: Duration,
) -> Result<BusScan, crate::session::SessionError> {
    let mut sorted = addresses.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    for &address in &sorted {
        let scan = session.scan_bus(&[address], per_reply)?;
        if scan.found > 0 {
            return Ok(scan);
        }
    }
    Ok(BusScan {
        found: 0,
        summary: format!(
            "no module answered at {} (at most {} ms per reply)",
            describe_addresses(&sorted),
            per_reply.as_millis()
        ),
        report: String::new(),
        modules: Vec::new(),
    })
}
