//! SocketCAN: a missing interface (or a kernel without CAN) is a clear error everywhere on
//! Linux; where a `vcan0` interface exists, a session opens on it and, with no module on the
//! virtual bus, ends with exit 3 naming the module rather than hanging.

use crate::util::{code, run, stderr};

#[test]
fn a_missing_interface_is_named() {
    let out = run(&["--can", "socketcan:tmclshnone0", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    let why = stderr(&out);
    assert!(why.contains("socketcan:tmclshnone0"), "{why}");
    assert!(
        why.contains("no such CAN interface") || why.contains("no SocketCAN support"),
        "{why}"
    );
}

#[test]
fn a_session_on_vcan0_names_an_absent_module() {
    if !std::path::Path::new("/sys/class/net/vcan0").exists() {
        eprintln!(
            "skipped a_session_on_vcan0_names_an_absent_module: no vcan0 interface here \
             (ip link add dev vcan0 type vcan && ip link set up vcan0)"
        );
        return;
    }
    let out = run(&[
        "--can",
        "socketcan:vcan0",
        "--timeout",
        "200",
        "-c",
        "GAP 4, 0",
    ]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(stderr(&out).contains("module 1 (A)"), "{}", stderr(&out));
}
