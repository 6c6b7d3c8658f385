//! The scan's quiet pause (issue 24): whatever the line carried just before — the last bytes of
//! another session, half a frame another program left — a module in its boot loader is found,
//! because the scan's first frame waits until the line has been quiet for twice the module's
//! partial-frame time-out, counted from the opening, not after a fixed sleep.

use std::path::{Path, PathBuf};

use crate::sim::Sim;
use crate::util::{code, repo, run, stderr, stdout, tempdir};

/// A TMCM-142 profile whose modules drop a partial frame only after `ms` of quiet (so that a
/// test program starts well within it); the session reads the same value from the same file.
fn slow_receiver(dir: &Path, ms: u32) -> PathBuf {
    let text = std::fs::read_to_string(repo().join("data/profiles/tmcm-142.toml")).unwrap();
    let text = text.replacen(
        "[simulation]\n",
        &format!("[simulation]\nframe_timeout_ms = {ms}\n"),
        1,
    );
    let path = dir.join("slow-receiver.toml");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_scan_right_after_other_traffic_finds_a_module_in_its_boot_loader() {
    let dir = tempdir();
    let profile = slow_receiver(&dir, 1000);
    let profile = profile.to_str().unwrap();
    let sim = Sim::start(&[
        "--pty",
        "--profile",
        profile,
        "--modules",
        "1,3",
        "--boot-loader=3",
    ]);
    {
        // Half a frame to module 3, as a program cut short leaves it: its receiver holds it for
        // a second, and a frame sent within it is misread (without the pause, the scan found
        // nobody at all: module 1's reply came to a frame module 3 misread too).
        let mut port = sim.pty();
        port.send(&[3, 136, 1, 0]);
    }
    let out = run(&[
        "--port",
        &sim.first,
        "--profile",
        profile,
        "scan",
        "--addresses",
        "1-3",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("(boot loader)"), "{text}");
    assert!(text.contains("2 modules answered"), "{text}");
}
