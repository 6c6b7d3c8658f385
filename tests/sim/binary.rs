//! Binary TMCL over a real pty and over loopback TCP.

use tmclsh::dialect::tmcl::protocol::Status;
use tmclsh::dialect::tmcl::protocol::frame::decode_version_string;

use super::{Sim, decode, frame};

#[test]
fn binary_frames_over_the_pty() {
    let sim = Sim::start(&["--pty"]);
    assert!(
        sim.first.starts_with("/dev/"),
        "pty path first: {}",
        sim.first
    );
    let mut port = sim.pty();
    let reply = port.transact(1, 6, 4, 0, 0);
    assert_eq!((reply.host, reply.module, reply.status), (2, 1, Status::Ok));
    assert_eq!(reply.value, 1_000_000);
    assert_eq!(port.transact(1, 5, 4, 0, 31_000).status, Status::Ok);
    assert_eq!(port.transact(1, 6, 4, 0, 0).value, 31_000);
    assert_eq!(port.transact(1, 5, 8, 0, 1).status, Status::WrongType);
    assert_eq!(port.transact(1, 5, 6, 0, 99).status, Status::InvalidValue);
    assert_eq!(port.transact(1, 29, 0, 0, 0).status, Status::NotAvailable);
    // JA is for programs only; CALC may also be sent directly (manual 6.4.4 / 6.4.5).
    assert_eq!(port.transact(1, 22, 0, 0, 0).status, Status::InvalidCommand);
    assert_eq!(port.transact(1, 19, 9, 0, 5).status, Status::Ok);

    port.send(&frame(1, 136, 0, 0, 0));
    let version = port.read_n(9);
    assert_eq!(
        decode_version_string(version[..].try_into().unwrap()),
        (2, "142V1.06".to_string())
    );

    let mut bad = frame(1, 6, 4, 0, 0);
    bad[8] ^= 0xFF;
    port.send(&bad);
    let reply = decode(&port.read_n(9));
    assert_eq!(
        (reply.status, reply.command.number()),
        (Status::WrongChecksum, 0)
    );

    // Frames for module 2 and 137 (factory reset) get no answer: the next bytes are the reply to
    // the command after them.
    port.send(&frame(2, 6, 4, 0, 0));
    port.send(&frame(1, 137, 0, 0, 1234));
    let reply = port.transact(1, 6, 4, 0, 0);
    assert_eq!(reply.value, 1_000_000, "factory value after 137");
}

#[test]
fn binary_frames_over_tcp_and_the_next_client() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    assert!(sim.first.starts_with("127.0.0.1:"), "{}", sim.first);
    assert!(!sim.first.ends_with(":0"), "the chosen port is printed");
    let mut first = sim.tcp();
    assert_eq!(first.transact(1, 5, 4, 0, 777).status, Status::Ok);
    drop(first);
    let mut second = sim.tcp();
    assert_eq!(second.transact(1, 6, 4, 0, 0).value, 777, "same module");
    // A third client takes over from the second.
    let mut third = sim.tcp();
    assert_eq!(third.transact(1, 6, 4, 0, 0).value, 777);
}

#[test]
fn the_pty_serves_a_client_that_reopens_it() {
    let sim = Sim::start(&[]);
    let mut port = sim.pty();
    assert_eq!(port.transact(1, 5, 4, 0, 4444).status, Status::Ok);
    drop(port);
    let mut again = sim.pty();
    assert_eq!(again.transact(1, 6, 4, 0, 0).value, 4444);
}

#[test]
fn verbose_logs_decoded_traffic() {
    let sim = Sim::start_capturing_stderr(&["--listen", "127.0.0.1:0", "--verbose"]);
    let mut port = sim.tcp();
    assert_eq!(port.transact(1, 6, 4, 0, 0).status, Status::Ok);
    drop(port);
    let log = sim.quit();
    assert!(
        log.contains("<- 01 06 04 00 00 00 00 00 0B  GAP 4, 0"),
        "{log}"
    );
    assert!(log.contains("status 100 value 1000000"), "{log}");
    assert!(log.contains("connected"), "{log}");
}

#[test]
fn bad_flags_are_refused_and_the_console_is_documented() {
    use crate::util::{code, run, stderr};
    let out = run(&["sim", "--modules", "1,1"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("given twice"));
    let out = run(&["sim", "--drop-rate", "1.5"]);
    assert_eq!(code(&out), 2);
    let out = run(&["sim", "--help"]);
    let help = crate::util::stdout(&out);
    assert!(
        help.contains("switch left|right|home"),
        "console documented"
    );
    assert!(help.contains("--hangup-after"));
}
