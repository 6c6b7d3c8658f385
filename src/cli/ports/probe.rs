//! `tmclsh ports --probe`: each port is opened at `--baud` (9600) and scanned at `--module` (1)
//! in `--protocol` (TMCL) the way `tmclsh scan --first --addresses 1` does (TMCL: binary 136
//! first, then an ASCII line), so the answer names the module from its version string; a port
//! that cannot be opened (in use, no permission) is reported and skipped. Every wait is bounded:
//! about 0.3 s for a silent port.

use std::io::{self, Write};

use crate::dialect::{Configured, Dialect, Opening, Purpose};
use crate::session::SessionOptions;

use super::super::scan::SCAN_WAIT;
use super::super::target::Target;

/// What to ask on each port (by default the factory settings of TMCL modules: address 1 at
/// 9600 baud).
pub(super) struct Probe {
    /// The bit rate.
    pub baud: u32,
    /// The protocol.
    pub dialect: &'static Dialect,
    /// The address asked.
    pub address: u8,
}

/// Probes every port in `paths`, printing what answers on each.
pub(super) fn probe_all(
    paths: &[String],
    configs: &Configured,
    probe_with: &Probe,
    out: &mut dyn Write,
) -> io::Result<()> {
    if paths.is_empty() {
        return Ok(());
    }
    writeln!(
        out,
        "\nprobing address {} at {} baud in {} (at most {} ms per reply):",
        probe_with.address,
        probe_with.baud,
        probe_with.dialect.name,
        SCAN_WAIT.as_millis()
    )?;
    for path in paths {
        let answer = probe(path, configs, probe_with);
        let line = format!("{path}: {answer}");
        writeln!(out, "{}", crate::escape::escape_control(&line))?;
    }
    Ok(())
}

/// What answers on one port, in a few words.
fn probe(path: &str, configs: &Configured, with: &Probe) -> String {
    let config = configs.of(with.dialect);
    let options = SessionOptions {
        module: with.address,
        timeout: SCAN_WAIT,
        ..SessionOptions::default()
    };
    let link = match Target::of(Some(path), None).and_then(|t| t.open(with.baud, config, SCAN_WAIT))
    {
        Ok(link) => link,
        Err(failure) => return format!("not probed: {}", failure.message),
    };
    let opening = Opening {
        link,
        options,
        transcript: None,
        flags: None,
        purpose: Purpose::Scan,
    };
    let mut session = match config.open(opening) {
        Ok(session) => session,
        Err(e) => return format!("not probed: {e}"),
    };
    let result = session.scan_bus(&[with.address], SCAN_WAIT);
    let _ = session.take_notices();
    let _ = session.close();
    match result {
        Ok(scan) if scan.found > 0 => found(&scan.report),
        Ok(_) => "no module answered".into(),
        Err(e) => format!("no answer: {e}"),
    }
}

/// The scan's row for the module, without the address columns: `TMCM-6110 (6110V131), in
/// binary mode`; an SMD4 drive's `SMD4 (firmware 24044.12, serial 1234ABCD)`.
fn found(report: &str) -> String {
    let mut lines = report.lines();
    let header: Vec<&str> = lines
        .next()
        .unwrap_or_default()
        .split_whitespace()
        .collect();
    let row = lines.next().unwrap_or_default();
    let words: Vec<&str> = row.split_whitespace().collect();
    match (header.as_slice(), words.as_slice()) {
        // address, char, mode, firmware, echo, module…
        (_, [_, _, mode, firmware, _, module @ ..]) if !module.is_empty() => {
            format!("{} ({firmware}), in {mode} mode", module.join(" "))
        }
        (["address", "firmware", "serial"], [_, firmware, serial]) => {
            format!("SMD4 (firmware {firmware}, serial {serial})")
        }
        _ => row.trim().to_string(),
    }
}
