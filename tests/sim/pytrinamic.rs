//! A real third-party client: PyTrinamic (the vendor's Python library) over the pty in binary
//! mode, through its own serial TMCL interface and its own module classes, unchanged. Runs when
//! python3 can import it; otherwise it reports a skip — or fails, where PyTrinamic is required
//! (`TMCLSH_REQUIRE_PYTRINAMIC=1`, which `.ci/run` sets after installing it), so a CI run that
//! lost it cannot pass unnoticed.

use std::process::Command;

use super::Sim;
use crate::util::repo;

/// Set to 1 where PyTrinamic must be there.
const REQUIRE: &str = "TMCLSH_REQUIRE_PYTRINAMIC";

/// Whether PyTrinamic can run; without it the tests report a skip, unless [`REQUIRE`] is 1, which
/// makes that a failure.
fn pytrinamic_available() -> Result<(), String> {
    let probe = Command::new("python3")
        .args(["-c", "import pytrinamic, serial"])
        .output()
        .map_err(|e| format!("python3 is not available ({e})"));
    let result = match probe {
        Ok(out) if out.status.success() => Ok(()),
        Ok(_) => Err(
            "python3 cannot import pytrinamic and pyserial (pip install pytrinamic pyserial)"
                .to_string(),
        ),
        Err(reason) => Err(reason),
    };
    if let Err(reason) = &result {
        assert!(
            std::env::var(REQUIRE).as_deref() != Ok("1"),
            "{REQUIRE}=1, but {reason}"
        );
    }
    result
}

/// Runs a peer script against `port`; returns its stdout after checking it succeeded.
fn run_peer(script: &str, port: &str) -> String {
    let out = Command::new("python3")
        .arg(repo().join("tests/peers").join(script))
        .arg(port)
        .output()
        .expect("python3 runs");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "PyTrinamic failed:\n{stdout}\n{stderr}"
    );
    stdout
}

#[test]
fn pytrinamic_reads_writes_and_moves_over_the_pty() {
    if let Err(reason) = pytrinamic_available() {
        eprintln!("skipped pytrinamic_reads_writes_and_moves_over_the_pty: {reason}");
        return;
    }
    let sim = Sim::start(&["--pty"]);
    let stdout = run_peer("pytrinamic_peer.py", &sim.first);
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

#[test]
fn pytrinamics_tmcm1140_tmcm6110_and_tmcm6214_classes_drive_a_mixed_bus() {
    if let Err(reason) = pytrinamic_available() {
        eprintln!("skipped pytrinamics_tmcm1140_and_tmcm6110_classes_drive_a_mixed_bus: {reason}");
        return;
    }
    let sim = Sim::start(&["--pty", "--modules", "1:tmcm-1140,2:tmcm-6110,3:tmcm-6214"]);
    let stdout = run_peer("pytrinamic_family_peer.py", &sim.first);
    for step in [
        "1140 version '1140V127'",
        "1140 position after move_by -2000",
        "6110 version '6110V131'",
        "6110 axis 5 standby_current 15",
        "6110 axis 3 position 4000",
        "6110 axis 4 unmoved 0",
        "6110 axis 5 still turning 400",
        "6110 digital output 7 1",
        "6214 version '6214V117'",
        "6214 axis 5 position -8000",
        "6214 axis 0 unmoved 0",
        "6214 axis 2 turning left -3000",
        "6214 axis 2 ran left True",
    ] {
        assert!(
            stdout.contains(&format!("ok {step}")),
            "{step} missing:\n{stdout}"
        );
    }
}
