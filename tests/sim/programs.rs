//! Stand-alone programs in the simulator, over a real pty: download (132/133, read back with
//! 134), ASCII RUN and STOP, stepping, with a manual clock so the motion is exact.

use tmclsh::dialect::tmcl::protocol::Status;

use super::{Port, Sim};

/// test2.tmc (manual §5.2), assembled by hand.
const TEST2: [(u8, u8, u8, i32); 13] = [
    (2, 0, 0, 500_000),
    (27, 0, 0, 500),
    (3, 0, 0, 0),
    (1, 0, 0, 250_000),
    (27, 0, 0, 500),
    (3, 0, 0, 0),
    (5, 4, 0, 500_000),
    (5, 5, 0, 50_000),
    (4, 0, 0, 1_000_000),
    (27, 1, 0, 0),
    (4, 0, 0, -1_000_000),
    (27, 1, 0, 0),
    (22, 0, 0, 8),
];

fn download(port: &mut Port) {
    assert_eq!(port.transact(1, 132, 0, 0, 0).status, Status::Ok);
    for (c, t, m, v) in TEST2 {
        assert_eq!(port.transact(1, c, t, m, v).status, Status::Stored);
    }
    assert_eq!(port.transact(1, 133, 0, 0, 0).status, Status::Ok);
    for (address, (c, t, m, v)) in TEST2.iter().enumerate() {
        let packed = port.transact(1, 134, 1, 0, address as i32).value;
        let value = port.transact(1, 134, 0, 0, address as i32).value;
        let expected = i32::from(*c) << 16 | i32::from(*t) << 8 | i32::from(*m);
        assert_eq!(
            (packed, value),
            (expected, *v),
            "address {address} reads back"
        );
    }
}

fn ask(port: &mut Port, line: &str) -> String {
    port.send(format!("{line}\r").as_bytes());
    port.read_line()
}

#[test]
fn test2_runs_with_ascii_run_answers_gap_and_stops() {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let mut port = sim.pty();
    download(&mut port);
    assert_eq!(port.transact(1, 9, 67, 0, 0x20).status, Status::Ok);
    assert_eq!(port.transact(1, 139, 0, 0, 0).status, Status::Ok);
    assert_eq!(ask(&mut port, "ARUN"), "BA 100 0\r");
    assert!(sim.console("advance 2s").starts_with("ok"));
    assert!(
        ask(&mut port, "AGAP 3, 0").starts_with("BA 100 -"),
        "ROL turns left"
    );
    assert!(sim.console("advance 5s").starts_with("ok"));
    assert!(
        !ask(&mut port, "AGAP 3, 0").starts_with("BA 100 -"),
        "ROR turns right"
    );
    // The first swing to +1000000 starts at about 10 s and takes about 137 s.
    assert!(sim.console("advance 100s").starts_with("ok"));
    assert_eq!(ask(&mut port, "AGGP 130, 0"), "BA 100 9\r", "WAIT POS");
    assert_eq!(ask(&mut port, "AGAP 0, 0"), "BA 100 1000000\r");
    assert!(sim.console("advance 50s").starts_with("ok"));
    assert_eq!(
        ask(&mut port, "AGGP 130, 0"),
        "BA 100 11\r",
        "on the way back"
    );
    assert_eq!(ask(&mut port, "AGAP 0, 0"), "BA 100 -1000000\r");
    assert_eq!(ask(&mut port, "ASTOP"), "BA 100 0\r");
    assert!(sim.console("advance 400s").starts_with("ok"));
    assert_eq!(ask(&mut port, "AGGP 128, 0"), "BA 100 0\r", "stopped");
    assert_eq!(
        ask(&mut port, "AGGP 130, 0"),
        "BA 100 11\r",
        "halted where it was"
    );
    assert_eq!(ask(&mut port, "AGAP 1, 0"), "BA 100 -1000000\r");
}

#[test]
fn stepping_advances_one_instruction() {
    let mut sim = Sim::start(&["--listen", "127.0.0.1:0", "--manual-clock"]);
    let mut port = sim.tcp();
    download(&mut port);
    assert_eq!(port.transact(1, 131, 0, 0, 0).status, Status::Ok);
    assert_eq!(port.transact(1, 135, 0, 0, 0).value, 3, "reset");
    assert_eq!(port.transact(1, 130, 0, 0, 0).status, Status::Ok);
    assert_eq!(port.transact(1, 135, 0, 0, 0).value, 2, "step");
    assert_eq!(port.transact(1, 10, 130, 0, 0).value, 1);
    assert!(sim.console("advance 1s").starts_with("ok"));
    assert_eq!(
        port.transact(1, 10, 130, 0, 0).value,
        1,
        "one instruction only"
    );
    assert!(port.transact(1, 6, 3, 0, 0).value < 0, "ROL executed");
}
