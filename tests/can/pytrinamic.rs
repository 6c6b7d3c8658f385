//! PyTrinamic's `SlcanTmclInterface` (python-can's slcan bus), unchanged, against `tmclsh sim
//! --slcan`: set and get parameters, a move, position reached. Skips where python3 cannot import
//! pytrinamic and python-can, unless `TMCLSH_REQUIRE_PYTRINAMIC=1` (as `.ci/run` sets) makes that
//! a failure.

use std::process::Command;

use super::slcan_sim;
use crate::util::repo;

const REQUIRE: &str = "TMCLSH_REQUIRE_PYTRINAMIC";

fn available() -> Result<(), String> {
    let probe = Command::new("python3")
        .args(["-c", "import pytrinamic, can, serial"])
        .output();
    let result = match probe {
        Ok(out) if out.status.success() => Ok(()),
        Ok(_) => Err("python3 cannot import pytrinamic, python-can and pyserial".to_string()),
        Err(e) => Err(format!("python3 is not available ({e})")),
    };
    if let Err(reason) = &result {
        assert!(
            std::env::var(REQUIRE).as_deref() != Ok("1"),
            "{REQUIRE}=1, but {reason}"
        );
    }
    result
}

#[test]
fn pytrinamics_slcan_interface_sets_gets_and_moves() {
    if let Err(reason) = available() {
        eprintln!("skipped pytrinamics_slcan_interface_sets_gets_and_moves: {reason}");
        return;
    }
    for extra in [&[][..], &["--foreign-frames", "--slcan-ack", "cr"][..]] {
        let sim = slcan_sim(extra);
        let out = Command::new("python3")
            .arg(repo().join("tests/peers/pytrinamic_slcan_peer.py"))
            .arg(&sim.first)
            .output()
            .expect("python3 runs");
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{extra:?}: PyTrinamic failed:\n{stdout}\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        for step in [
            "version",
            "set_axis_parameter 4",
            "position reached",
            "position after move_to",
        ] {
            assert!(stdout.contains(&format!("ok {step} ")), "{step}: {stdout}");
        }
    }
}
