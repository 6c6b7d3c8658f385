//! A real third-party client: PyTrinamic (the vendor's Python library) over the pty in binary
//! mode, through its own serial TMCL interface, unchanged. Runs when python3 can import it;
//! otherwise it reports a skip — or fails, where PyTrinamic is required
//! (`TMCLSH_REQUIRE_PYTRINAMIC=1`, which `.ci/run` sets after installing it), so a CI run that
//! lost it cannot pass unnoticed.

use std::process::Command;

use super::Sim;
use crate::util::repo;

/// Set to 1 where PyTrinamic must be there.
const REQUIRE: &str = "TMCLSH_REQUIRE_PYTRINAMIC";

fn pytrinamic_available() -> Result<(), String> {
    let probe = Command::new("python3")
        .args(["-c", "import pytrinamic, serial"])
        .output()
        .map_err(|e| format!("python3 is not available ({e})"))?;
    if probe.status.success() {
        Ok(())
    } else {
        Err(
            "python3 cannot import pytrinamic and pyserial (pip install pytrinamic pyserial)"
                .into(),
        )
    }
}

#[test]
fn pytrinamic_reads_writes_and_moves_over_the_pty() {
    if let Err(reason) = pytrinamic_available() {
        assert!(
            std::env::var(REQUIRE).as_deref() != Ok("1"),
            "{REQUIRE}=1, but {reason}"
        );
        eprintln!("skipped pytrinamic_reads_writes_and_moves_over_the_pty: {reason}");
        return;
    }
    let sim = Sim::start(&["--pty"]);
    let script = repo().join("tests/peers/pytrinamic_peer.py");
    let out = Command::new("python3")
        .arg(&script)
        .arg(&sim.first)
        .output()
        .expect("python3 runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "PyTrinamic failed:\n{stdout}\n{stderr}"
    );
    for step in [
        "version",
        "move_to",
        "position after move_by",
        "rotate speed",
        "digital output",
    ] {
        assert!(
            stdout.contains(&format!("ok {step} ")),
            "{step} missing:\n{stdout}"
        );
    }
}
