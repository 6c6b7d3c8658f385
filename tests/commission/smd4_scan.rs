//! Bus scans of SMD4 drives: three simulated drives on one in-process bus with gaps between their
//! addresses (on a manual clock, so silent addresses cost no time), and the real binary against
//! `tmclsh sim --protocol smd4` at a non-default address, over its pty.

use std::sync::Arc;
use std::time::Duration;

use tmclsh::clock::ManualClock;
use tmclsh::dialect::session::DialectSession;
use tmclsh::dialect::smd4::protocol::Smd4Spec;
use tmclsh::dialect::smd4::scan as smd4_scan;
use tmclsh::dialect::smd4::session::Smd4Session;
use tmclsh::dialect::smd4::sim::{Smd4Sim, Smd4SimOptions};
use tmclsh::session::{SessionError, SessionOptions};
use tmclsh::sim::Device;
use tmclsh::sim::inprocess::SimLink;
use tmclsh::sim::store::{MemoryStore, Store};

use crate::smd4::{Drive, Via, assert_exit, client, lines};

/// Drives wired to one RS485 pair: each hears every byte, their replies share the line.
struct Bus(Vec<Smd4Sim>);

impl Device for Bus {
    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        for drive in &mut self.0 {
            drive.receive(now, bytes);
        }
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        for drive in &mut self.0 {
            drive.poll_output(now, out);
        }
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        self.0.iter().filter_map(|d| d.next_due(now)).min()
    }
}

/// A drive that powers up with `address` stored as its COMS:SERIAL:SLAVEADDR.
fn drive_at(address: u32) -> Smd4Sim {
    let mut store = MemoryStore::default();
    store
        .save(&format!(
            "format = 1\n[stored]\n\"COMS:SERIAL:SLAVEADDR\" = {address}\n"
        ))
        .unwrap();
    Smd4Sim::with_store(Smd4SimOptions::default(), Box::new(store))
}

fn sim_value(mnemonic: &str) -> String {
    let command = Smd4Spec::builtin().commands.get(mnemonic).unwrap();
    command.sim_value.clone().unwrap()
}

#[test]
fn three_drives_with_gaps_are_found_with_firmware_and_serial() {
    let bus = Bus(vec![drive_at(2), drive_at(3), drive_at(7)]);
    let link = SimLink::new(Box::new(bus), Arc::new(ManualClock::new()));
    let mut session = Smd4Session::open(
        Box::new(link),
        SessionOptions::default(),
        tmclsh::dialect::smd4::session::Smd4SessionOptions::default(),
        None,
    )
    .unwrap();
    let addresses: Vec<u32> = (1..=10).collect();
    let report = smd4_scan::scan(&mut session, &addresses, Duration::from_millis(100)).unwrap();
    let found: Vec<u32> = report.found.iter().map(|d| d.address).collect();
    assert_eq!(found, [2, 3, 7]);
    for drive in &report.found {
        assert_eq!(drive.firmware, Some(sim_value("SYS:FW")));
        assert_eq!(drive.serial, Some(sim_value("SYS:BSN")));
    }
    assert_eq!(
        smd4_scan::summary(&report),
        "3 drives answered at 1-10 (at most 100 ms per reply)"
    );
    // As documented: after the probes, every drive ignores packets without a prefix.
    let unprefixed = session.execute("SYS:FW");
    assert!(
        matches!(unprefixed, Err(SessionError::Timeout { .. })),
        "{unprefixed:?}"
    );
    session.set_address(Some(7));
    assert!(session.execute("SYS:FW").unwrap().ok());
}

/// `tmclsh scan CONNECTION ARGS`.
fn scan(drive: &Drive, args: &[&str]) -> std::process::Output {
    let mut all = vec!["scan".to_string()];
    all.extend(drive.connection());
    all.extend(args.iter().map(|a| a.to_string()));
    let all: Vec<&str> = all.iter().map(String::as_str).collect();
    client(&[], &all, "")
}

#[test]
fn the_binary_finds_a_drive_at_its_address_and_reports_an_empty_range() {
    let drive = Drive::start(Via::Pty, &[]);
    assert_exit(&drive.run(&["-c", "COMS:SERIAL:SLAVEADDR,5"]), 0);
    let out = scan(&drive, &["--addresses", "1-8", "--timeout", "100"]);
    assert_exit(&out, 0);
    let rows: Vec<Vec<String>> = lines(&out)
        .iter()
        .map(|l| l.split_whitespace().map(String::from).collect())
        .collect();
    assert_eq!(rows[0], ["address", "firmware", "serial"]);
    assert_eq!(rows[1], ["5", &sim_value("SYS:FW"), &sim_value("SYS:BSN")]);
    let text = lines(&out).join("\n");
    assert!(
        text.contains("1 drive answered at 1-8 (at most 100 ms per reply)"),
        "{text}"
    );
    assert!(text.contains("--address N"), "{text}");

    let empty = scan(&drive, &["--addresses", "1-3", "--timeout", "50"]);
    assert_exit(&empty, 3);
    let err = String::from_utf8_lossy(&empty.stderr);
    assert!(err.contains("no drive answered at 1-3"), "{err}");

    let beyond = scan(&drive, &["--addresses", "250", "--timeout", "50"]);
    assert_exit(&beyond, 2);
    let err = String::from_utf8_lossy(&beyond.stderr);
    assert!(
        err.contains("'250' is not a bus address (1..247 or A..Z)"),
        "{err}"
    );

    // The shell helper, from a session addressing the drive found.
    let out = drive.run(&["--address", "5", "-c", ":scan 4-6 100ms"]);
    assert_exit(&out, 0);
    assert!(lines(&out)[1].starts_with("      5  "), "{:?}", lines(&out));
}
