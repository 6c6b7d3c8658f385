//! `tmclsh scan [CONNECTION]`: which addresses on the bus answer — TMCL modules with firmware
//! version and echo setting, SMD4 drives (`--protocol smd4`) with firmware version and serial
//! number; each reply is awaited at most `--timeout` milliseconds.

use std::io::Write;

use crate::commission::scan::parse_addresses;
use crate::dialect::{Configured, Purpose};
use crate::exit::{Exit, Failure};
use crate::session::interrupt;

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
pub fn run(args: ScanArgs, configs: &Configured, out: &mut dyn Write) -> Result<Exit, Failure> {
    interrupt::install();
    let out = &mut super::snapshot::PipeSafe(out);
    let dialect = args.module.protocol();
    let list = args.addresses.as_deref().unwrap_or(dialect.scan_addresses);
    let addresses = parse_addresses(list)
        .map_err(|e| Failure::new(Exit::Refused, format!("--addresses: {e}")))?;
    let per_reply = args.module.session.options().timeout;
    let mut session = args.module.open(configs, Audience::Batch, Purpose::Scan)?;
    let result = session.scan_bus(&addresses, per_reply);
    for notice in session.take_notices() {
        super::diagnose(&notice);
    }
    interrupt::take();
    for message in session.close() {
        super::diagnose(&message);
    }
    let scan = result?;
    if scan.found == 0 {
        return Err(Failure::new(Exit::Link, scan.summary));
    }
    out.write_all(scan.report.as_bytes())
        .map_err(|e| Failure::new(Exit::Link, e.to_string()))?;
    Ok(Exit::Success)
}
