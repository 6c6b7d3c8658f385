//! A shared bus through the real binary on a pty (`tmclsh sim --pty --modules …`): every module
//! identified before it is talked to, whatever the line held before; a module that does not
//! identify itself is sent nothing on a guess; binary-only modules stay binary.

mod binary_only;
mod identify;
mod scan_pause;
mod upload;

use std::process::Output;

use crate::sim::Sim;
use crate::util::run;

/// The bus: a TMCM-1140, a TMCM-6110 and the binary-only TMCM-6214.
pub const BUS: &str = "1:tmcm-1140,2:tmcm-6110,3:tmcm-6214";

/// `tmclsh sim --pty --modules BUS EXTRA…`.
pub fn bus_sim(extra: &[&str]) -> Sim {
    let mut args = vec!["--pty", "--modules", BUS];
    args.extend_from_slice(extra);
    Sim::start(&args)
}

/// `tmclsh --port PTY ARGS…`.
pub fn on(sim: &Sim, args: &[&str]) -> Output {
    run(&[&["--port", sim.first.as_str()][..], args].concat())
}

/// The transcript lines that sent something.
pub fn sent(log: &str) -> Vec<&str> {
    log.lines().filter(|l| l.contains(" tx ")).collect()
}
