//! `tmclsh ports --probe`: each port is opened at 9600 baud and scanned at address 1 the way
//! `tmclsh scan --first --addresses 1` does (binary 136 first, then an ASCII line), so the answer
//! names the module from its version string; a port that cannot be opened (in use, no
//! permission) is reported and skipped. Every wait is bounded: about 0.3 s for a silent port.

use std::io::{self, Write};

use crate::dialect::{Configured, Opening, Purpose, default_dialect};
use crate::session::SessionOptions;

use super::super::scan::SCAN_WAIT;
use super::super::target::Target;

/// The bit rate and address probed: the factory settings of TMCL modules.
const BAUD: u32 = 9600;
const ADDRESS: u8 = 1;

/// Probes every port in `paths`, printing what answers on each.
pub(super) fn probe_all(
    paths: &[String],
    configs: &Configured,
    out: &mut dyn Write,
) -> io::Result<()> {
    if paths.is_empty() {
        return Ok(());
    }
    writeln!(
        out,
        "\nprobing address {ADDRESS} at {BAUD} baud (at most {} ms per reply):",
        SCAN_WAIT.as_millis()
    )?;
    for path in paths {
        let answer = probe(path, configs);
        let line = format!("{path}: {answer}");
        writeln!(out, "{}", crate::escape::escape_control(&line))?;
    }
    Ok(())
}

/// What answers on one port, in a few words.
pub(super) fn probe(path: &str, configs: &Configured) -> String {
    let config = configs.of(default_dialect());
    let options = SessionOptions {
        module: ADDRESS,
        timeout: SCAN_WAIT,
        ..SessionOptions::default()
    };
    let link = match Target::of(Some(path), None).and_then(|t| t.open(BAUD, config, SCAN_WAIT)) {
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
    let result = session.scan_bus(&[ADDRESS], SCAN_WAIT);
    let _ = session.take_notices();
    let _ = session.close();
    match result {
        Ok(scan) if scan.found > 0 => found(&scan.report),
        Ok(_) => "no module answered".into(),
        Err(e) => format!("no answer: {e}"),
    }
}

/// The scan's row for the module, without the address columns: `6110V131 … TMCM-6110`.
fn found(report: &str) -> String {
    let row = report.lines().nth(1).unwrap_or_default();
    let words: Vec<&str> = row.split_whitespace().collect();
    match words.as_slice() {
        // address, char, mode, firmware, echo, module…
        [_, _, mode, firmware, _, module @ ..] if !module.is_empty() => {
            format!("{} ({firmware}), in {mode} mode", module.join(" "))
        }
        _ => row.trim().to_string(),
    }
}
