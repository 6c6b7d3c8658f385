//! The serial line's options in the table: on a simulator's pseudo-terminal, which has no modem
//! lines, `--dtr`, `--rts`, `--rs485` and `--rs485-delay` are accepted, noted once as not
//! applied, and the session works; `--keep-latency` on a made-up FTDI adapter (a sysfs tree
//! whose device file is the pty) leaves its 16 ms timer unexplained, where without it tmclsh
//! explains the cost.

use std::os::unix::fs::symlink;

use crate::sim::Sim;
use crate::util::{stderr, tempdir};

use super::table::*;

/// The table for one modem-line option: every session face on a pty notes it once.
fn modem_option(option: &[&str], named: &str) {
    let sim = Sim::start(&["--pty"]);
    let pty = sim.first.clone();
    table(
        option,
        &SESSIONS,
        &|_| Setup::tmcl().with(&["--port", &pty]),
        &|face, out, _| {
            finished(face, out)?;
            let err = stderr(out);
            expect(err.matches("has no modem lines").count() == 1, || {
                "not noted exactly once that the pty has no modem lines".into()
            })?;
            says(out, &format!("{named} not applied"))
        },
        &no_special,
    );
}

#[test]
fn dtr() {
    modem_option(&["--dtr", "off"], "--dtr off");
}

#[test]
fn rts() {
    modem_option(&["--rts", "keep"], "--rts keep");
}

#[test]
fn rs485() {
    modem_option(&["--rs485"], "--rs485");
}

#[test]
fn rs485_delay() {
    modem_option(&["--rs485-delay", "1,2"], "--rs485");
}

#[test]
fn keep_latency() {
    let sim = Sim::start(&["--pty"]);
    let root = tempdir();
    let devices = root.join("sys/bus/usb-serial/devices/ttyUSB0");
    std::fs::create_dir_all(&devices).unwrap();
    std::fs::create_dir_all(root.join("dev")).unwrap();
    std::fs::write(devices.join("latency_timer"), "16\n").unwrap();
    let port = root.join("dev/ttyUSB0");
    symlink(&sim.first, &port).unwrap();
    let port = port.to_string_lossy().into_owned();
    let env = vec![(
        "TMCLSH_TEST_SYSFS".to_string(),
        root.to_string_lossy().into_owned(),
    )];
    let setup = || {
        let mut setup = Setup::tmcl().with(&["--port", &port]);
        setup.env = env.clone();
        setup
    };
    // Without the option every face explains the timer.
    for face in SESSIONS {
        let call = call(face, &setup());
        let out = run_guarded_env(
            &argv(&call, &[], Position::After),
            call.stdin.as_deref(),
            &call.env,
        )
        .unwrap();
        assert!(
            finished(face, &out).is_ok() && stderr(&out).contains("latency timer, 16 ms"),
            "{face:?} without --keep-latency: {}",
            stderr(&out)
        );
    }
    table(
        &["--keep-latency"],
        &SESSIONS,
        &|_| setup(),
        &|face, out, _| {
            finished(face, out)?;
            expect(!stderr(out).contains("latency"), || {
                "the timer was explained although left alone".into()
            })
        },
        &no_special,
    );
}

#[test]
fn over_tcp_the_modem_lines_are_noted_once_and_the_session_works() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    let out = crate::util::run(&[
        "--tcp", &sim.first, "--dtr", "on", "--rs485", "-c", "GAP 1, 0",
    ]);
    assert_eq!(crate::util::code(&out), 0, "{}", stderr(&out));
    let err = stderr(&out);
    assert_eq!(err.matches("no modem lines").count(), 1, "{err}");
    assert!(err.contains("--dtr on, --rs485 not applied"), "{err}");
    assert_eq!(crate::util::stdout(&out), "BA 100 0\n");
}
