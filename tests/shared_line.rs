//! A host-address clash on a shared line (`tmclsh sim --shared-line`): module 2's address is the
//! host address 2, so it takes module 1's replies for commands — as on a real RS-485 bus.

use crate::sim::Sim;
use crate::util::{code, run, stderr, stdout};

#[test]
fn a_module_at_the_host_address_answers_other_replies_and_garbles_the_line() {
    let sim = Sim::start(&["--pty", "--shared-line", "--modules", "1,2:tmcm-6110"]);
    let args = ["--binary", "--timeout", "400", "-c", "SAP 4, 0, 1000"];
    let out = run(&[&["--port", sim.first.as_str()][..], &args[..]].concat());
    // Module 1's answer to 136 reaches module 2 as a frame to itself; its own answer follows.
    let err = stderr(&out);
    assert_eq!(code(&out), 3, "{}\n{err}", stdout(&out));
    assert!(
        err.contains("line noise") && err.contains("followed by 02 02 "),
        "{err}"
    );
    // Without the shared line (or with distinct addresses) the same line is answered.
    let calm = Sim::start(&["--pty", "--modules", "1,2:tmcm-6110"]);
    let out = run(&[&["--port", calm.first.as_str()][..], &args[..]].concat());
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn scan_warns_about_a_module_at_the_host_address_and_how_to_fix_it() {
    let sim = Sim::start(&["--pty", "--modules", "1,2,4"]);
    let out = run(&[
        "--port",
        &sim.first,
        "--timeout",
        "200",
        "scan",
        "--addresses",
        "1-4",
    ]);
    let err = stderr(&out);
    assert_eq!(code(&out), 0, "{}\n{err}", stdout(&out));
    assert!(
        err.contains("module 2 (B) is at the host address of module 1 (A) (2, ")
            && err.contains("host address of module 4 (D)")
            && err.contains("SGP 76, 0, N"),
        "{err}"
    );
    // Distinct addresses: module 2 moved to 3, no warning.
    let calm = Sim::start(&["--pty", "--modules", "1,3"]);
    let out = run(&[
        "--port",
        &calm.first,
        "--timeout",
        "200",
        "scan",
        "--addresses",
        "1-4",
    ]);
    assert!(!stderr(&out).contains("host address"), "{}", stderr(&out));
}

#[test]
fn identification_warns_once_when_a_second_module_sits_at_the_host_address() {
    let sim = Sim::start(&["--pty", "--modules", "1,2"]);
    let out = run(&[
        "--port",
        &sim.first,
        "-c",
        "GAP 4, 0",
        "-c",
        "BGAP 4, 0",
        "-c",
        "BGAP 4, 0",
    ]);
    let err = stderr(&out);
    assert_eq!(code(&out), 0, "{err}");
    assert_eq!(
        err.matches("module 2 (B) is at the host address of module 1 (A)")
            .count(),
        1,
        "{err}"
    );
}
