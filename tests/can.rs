//! TMCL over CAN through the real binary: `tmclsh --can slcan:PTY` against `tmclsh sim --slcan`
//! (the simulated bus served as an slcan adapter on a pseudo-terminal), each session path, each
//! acknowledgement style, foreign frames, an absent module, two modules on one bus; PyTrinamic's
//! own slcan interface against the same simulator; SocketCAN where a `vcan0` exists.

mod pytrinamic;
mod sessions;
mod socketcan;

use std::process::Output;

use crate::sim::Sim;
use crate::util::run;

/// `tmclsh sim --slcan ARGS`.
fn slcan_sim(args: &[&str]) -> Sim {
    let mut all = vec!["--slcan"];
    all.extend_from_slice(args);
    Sim::start(&all)
}

/// `tmclsh --can slcan:PTY ARGS` (the options before any subcommand's words).
fn over_can(sim: &Sim, args: &[&str]) -> Output {
    let can = format!("slcan:{}", sim.first);
    let mut all = vec!["--can", can.as_str()];
    all.extend_from_slice(args);
    run(&all)
}
