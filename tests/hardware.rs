//! Tests against a real module, run only with `--features hardware` and the port in
//! `TMCLSH_TEST_PORT` (baud in `TMCLSH_TEST_BAUD`, default 9600). They only read: no motion, no
//! EEPROM writes.

use crate::util::{code, run, stderr, stdout};

/// One module, one port: the tests take turns.
static PORT: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn port() -> (String, String) {
    let port = std::env::var("TMCLSH_TEST_PORT")
        .expect("set TMCLSH_TEST_PORT to the module's serial port");
    let baud = std::env::var("TMCLSH_TEST_BAUD").unwrap_or_else(|_| "9600".into());
    (port, baud)
}

#[test]
fn reads_parameters_and_the_firmware_version() {
    let _turn = PORT.lock().unwrap_or_else(|e| e.into_inner());
    let (port, baud) = port();
    let out = run(&[
        "--port",
        &port,
        "--baud",
        &baud,
        "-c",
        "GAP 4, 0",
        "-c",
        "GGP 67, 0",
        "-c",
        ":bin",
        "-c",
        "136 0",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("BA 100 "), "{text}");
    assert!(lines[1].starts_with("BA 100 "), "{text}");
    assert!(!lines[3].is_empty(), "a version string: {text}");
}

#[test]
fn a_snapshot_can_be_saved() {
    let _turn = PORT.lock().unwrap_or_else(|e| e.into_inner());
    let (port, baud) = port();
    let file = crate::util::tempdir().join("module.toml");
    let out = run(&[
        "snapshot",
        "save",
        file.to_str().unwrap(),
        "--port",
        &port,
        "--baud",
        &baud,
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        std::fs::read_to_string(&file)
            .unwrap()
            .contains("max_current")
    );
}
