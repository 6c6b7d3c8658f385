//! Where the machine's `sys/`, `dev/` and `var/lock/` are: `/`, or the directory in
//! `TMCLSH_TEST_SYSFS`, a made-up tree standing for them. Adapters cannot be plugged in on
//! demand, nor their latency timers set without root; the override lets the tests (of debug and
//! release builds alike) and a user diagnosing a listing point tmclsh at a tree of their own.

use std::path::{Path, PathBuf};

/// The environment variable naming the tree.
pub const ROOT_VAR: &str = "TMCLSH_TEST_SYSFS";

/// The root of the machine's tree.
pub fn root() -> PathBuf {
    std::env::var_os(ROOT_VAR)
        .filter(|root| !root.is_empty())
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/"))
}

/// The kernel's name of the tty behind `path`: the name of the device file itself
/// (`/dev/ttyUSB0`), else of what it links to (`/dev/serial/by-id/…` → `ttyUSB0`).
pub fn tty_names(path: &Path) -> Vec<String> {
    let mut names = Vec::new();
    if let Some(name) = path.file_name() {
        names.push(name.to_string_lossy().into_owned());
    }
    let target = path
        .canonicalize()
        .ok()
        .and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()));
    if let Some(name) = target.filter(|name| !names.contains(name)) {
        names.push(name);
    }
    names
}
