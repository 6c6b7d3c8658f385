//! A real third-party client: PyTrinamic (the vendor's Python library) over the pty in binary
//! mode, through its own serial TMCL interface, unchanged. Runs when python3 can import it.

use std::process::Command;

use super::Sim;
use crate::util::repo;

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
