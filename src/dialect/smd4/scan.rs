//! Finding SMD4 drives on an RS232/RS485 bus: `@N SYS:FW` to every address (1..247 by default),
//! each reply awaited at most the given time; a drive that answers is asked for its serial number
//! (SYS:BSN) too. A drive answers only the address in its COMS:SERIAL:SLAVEADDR, so one probe per
//! address is all it takes — no modes to enter or restore, unlike TMCL.
//!
//! The document's addressing rules have a lasting effect: the first packet with an `@N` prefix a
//! drive sees puts it in addressing mode until it restarts, and from then on it ignores packets
//! without a prefix. Every drive on the bus sees the probes, so after a scan they all must be
//! talked to with `--address N`; the report says so.

use std::io::{self, Write};
use std::time::Duration;

use crate::dialect::smd4::protocol::{MAX_ADDRESS, Request};
use crate::dialect::smd4::session::Smd4Session;
use crate::json::json;
use crate::session::SessionError;

use crate::commission::scan::scan_summary;
use crate::dialect::session::{BusScan, DialectSession};
use crate::progress::Progress;

/// A drive that answered.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FoundDrive {
    /// Its bus address (COMS:SERIAL:SLAVEADDR).
    pub address: u32,
    /// Its firmware version (SYS:FW), unless it answered with an error code.
    pub firmware: Option<String>,
    /// Its board serial number (SYS:BSN), where it told it.
    pub serial: Option<String>,
}

/// What a scan found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Smd4Scan {
    /// The addresses tried.
    pub scanned: Vec<u32>,
    /// The drives that answered, by address.
    pub found: Vec<FoundDrive>,
    /// How long each reply was awaited.
    pub per_reply: Duration,
}

/// Tries every address in `addresses` (1..247), waiting at most `per_reply` for each reply.
/// Silence or garbage at an address means nobody is there; Ctrl-C and a lost link end the scan.
pub fn scan(
    session: &mut Smd4Session,
    addresses: &[u32],
    per_reply: Duration,
) -> Result<Smd4Scan, SessionError> {
    let mut addresses = addresses.to_vec();
    addresses.sort_unstable();
    addresses.dedup();
    if let Some(bad) = addresses.iter().find(|a| !(1..=MAX_ADDRESS).contains(*a)) {
        return Err(SessionError::Usage(format!(
            "SMD4 addresses are 1..{MAX_ADDRESS}, not {bad}"
        )));
    }
    let progress = Progress::steps(addresses.len(), 2, "scanning");
    let mut found = Vec::new();
    for &address in &addresses {
        progress.step(&format!("@{address}"));
        let probe = session.with_timeout(per_reply, |s| ask(s, address, "SYS:FW"))?;
        let Some(firmware) = probe else { continue };
        let serial = session
            .with_timeout(per_reply, |s| ask(s, address, "SYS:BSN"))?
            .flatten();
        found.push(FoundDrive {
            address,
            firmware,
            serial,
        });
    }
    Ok(Smd4Scan {
        scanned: addresses,
        found,
        per_reply,
    })
}

/// Asks drive `address` for `mnemonic`: `None` when nobody answered, `Some(None)` when the drive
/// answered with an error code, `Some(Some(text))` with its data.
fn ask(
    session: &mut Smd4Session,
    address: u32,
    mnemonic: &str,
) -> Result<Option<Option<String>>, SessionError> {
    match session.request(Request::new(mnemonic).to(address)) {
        Ok(exchange) => Ok(exchange.reply.map(|r| {
            r.is_ok()
                .then(|| r.data_strings().join(","))
                .filter(|t| !t.is_empty())
        })),
        Err(e) if e.is_echo_mismatch() => Err(e),
        Err(SessionError::Timeout { .. } | SessionError::Link(_) | SessionError::Noise { .. }) => {
            Ok(None)
        }
        Err(e) => Err(e),
    }
}

/// [`scan`] of the bus addresses `addresses`, its report ready to print.
pub fn bus_scan(
    session: &mut Smd4Session,
    addresses: &[u8],
    per_reply: Duration,
) -> Result<BusScan, SessionError> {
    let addresses: Vec<u32> = addresses.iter().copied().map(u32::from).collect();
    let report = scan(session, &addresses, per_reply)?;
    let mut text = Vec::new();
    write_report(&report, &mut text).expect("writing to memory cannot fail");
    Ok(BusScan {
        found: report.found.len(),
        summary: summary(&report),
        report: String::from_utf8_lossy(&text).into_owned(),
        modules: report
            .found
            .iter()
            .map(|d| json!({ "address": d.address, "firmware": d.firmware, "serial": d.serial }))
            .collect(),
    })
}

/// Prints the table of drives found, a summary line, and what the probes left behind.
pub fn write_report(report: &Smd4Scan, out: &mut dyn Write) -> io::Result<()> {
    if !report.found.is_empty() {
        writeln!(out, "address  firmware  serial")?;
    }
    for d in &report.found {
        let firmware = d.firmware.as_deref().unwrap_or("?");
        let serial = d.serial.as_deref().unwrap_or("?");
        writeln!(out, "{:>7}  {firmware:<8}  {serial}", d.address)?;
    }
    writeln!(out, "{}", summary(report))?;
    writeln!(out, "{}", ADDRESSING_NOTE)
}

/// What every drive that saw the probes does from now on.
pub const ADDRESSING_NOTE: &str = "note: the drives on this bus saw @N packets and stay in \
addressing mode until they restart: talk to them with --address N (:target N)";

/// "2 drives answered at 1-247 (at most 100 ms per reply)".
pub fn summary(report: &Smd4Scan) -> String {
    let scanned: Vec<u8> = report
        .scanned
        .iter()
        .filter_map(|a| u8::try_from(*a).ok())
        .collect();
    scan_summary(report.found.len(), "drive", &scanned, report.per_reply)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scan_list_names_the_addresses_the_protocol_has() {
        assert_eq!(
            u32::from(crate::dialect::smd4::DIALECT.max_address),
            MAX_ADDRESS
        );
    }

    #[test]
    fn the_table_lists_each_drive_and_the_note_on_addressing_mode() {
        let report = Smd4Scan {
            scanned: (1..=247).collect(),
            found: vec![
                FoundDrive {
                    address: 3,
                    firmware: Some("24044.12".into()),
                    serial: Some("1234ABCD".into()),
                },
                FoundDrive {
                    address: 200,
                    firmware: None,
                    serial: None,
                },
            ],
            per_reply: Duration::from_millis(50),
        };
        let mut out = Vec::new();
        write_report(&report, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let rows: Vec<Vec<&str>> = text
            .lines()
            .map(|l| l.split_whitespace().collect())
            .collect();
        assert_eq!(rows[0], ["address", "firmware", "serial"]);
        assert_eq!(rows[1], ["3", "24044.12", "1234ABCD"]);
        assert_eq!(rows[2], ["200", "?", "?"]);
        assert_eq!(
            text.lines().nth(3).unwrap(),
            "2 drives answered at 1-247 (at most 50 ms per reply)"
        );
        assert!(text.lines().nth(4).unwrap().contains("--address N"));
    }
}
