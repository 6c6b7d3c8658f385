//! Bus scans against a simulated bus with modules at 1, 2 and 4 (a gap at 3), and one at 40 that
//! has no ASCII address character.

use tmclsh::dialect::tmcl::protocol::Status;

use super::expect;
use crate::sim::Sim;
use crate::util::{stderr, stdout};

/// The table rows as words, without the header and the summary.
fn table(text: &str) -> Vec<Vec<String>> {
    let lines: Vec<&str> = text.lines().collect();
    lines[1..lines.len() - 1]
        .iter()
        .map(|l| l.split_whitespace().map(String::from).collect())
        .collect()
}

#[test]
fn a_bus_with_three_modules_and_a_gap() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0", "--modules", "1,2,4,40"]);
    {
        let mut port = sim.tcp();
        assert_eq!(
            port.transact(2, 9, 67, 0, 0x20).status,
            Status::Ok,
            "B: no echo"
        );
        assert_eq!(
            port.transact(4, 9, 67, 0, 0x10).status,
            Status::Ok,
            "D: line echo"
        );
    }
    let out = expect(
        &[
            "scan",
            "--tcp",
            &sim.first,
            "--timeout",
            "200",
            "--addresses",
            "1-5",
        ],
        0,
    );
    let text = stdout(&out);
    assert_eq!(
        table(&text),
        [
            ["1", "A", "binary", "142V1.06", "char", "TMCM-142"],
            ["2", "B", "binary", "142V1.06", "none", "TMCM-142"],
            ["4", "D", "binary", "142V1.06", "line", "TMCM-142"],
        ],
        "{text}"
    );
    assert_eq!(
        text.lines().last().unwrap(),
        "3 modules answered at 1-5 (at most 200 ms per reply)"
    );
    assert!(
        text.lines()
            .next()
            .unwrap()
            .starts_with("address  char  found in")
    );

    // Everything was left in binary mode, as found.
    let mut port = sim.tcp();
    for address in [1, 2, 4] {
        let reply = port.transact(address, 6, 4, 0, 0);
        assert_eq!((reply.module, reply.status), (address, Status::Ok));
    }
}

#[test]
fn addresses_without_a_character_are_probed_in_binary() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0", "--modules", "1,40"]);
    let out = expect(
        &[
            "scan",
            "--tcp",
            &sim.first,
            "--timeout",
            "200",
            "--addresses",
            "1,39-41",
        ],
        0,
    );
    assert_eq!(
        table(&stdout(&out)),
        [
            ["1", "A", "binary", "142V1.06", "char", "TMCM-142"],
            ["40", "-", "binary", "142V1.06", "char", "TMCM-142"],
        ]
    );
    let mut port = sim.tcp();
    assert_eq!(port.transact(1, 6, 4, 0, 0).status, Status::Ok);
    assert_eq!(port.transact(40, 6, 4, 0, 0).status, Status::Ok);
}

#[test]
fn a_module_found_in_ascii_mode_is_left_in_it_and_the_repl_scans_too() {
    let sim = Sim::start(&["--pty", "--modules", "1,3"]);
    {
        let mut port = sim.pty();
        assert_eq!(port.transact(3, 9, 67, 0, 0x21).status, Status::Ok);
        assert_eq!(port.transact(3, 139, 0, 0, 0).status, Status::Ok);
    }
    let out = expect(
        &[
            "--port",
            &sim.first,
            "--timeout",
            "200",
            "-c",
            ":scan 1-3",
            "-c",
            "GAP 4, 0",
        ],
        0,
    );
    let text = stdout(&out);
    assert_eq!(
        table(&text.lines().take(4).collect::<Vec<_>>().join("\n")),
        [
            ["1", "A", "binary", "142V1.06", "char", "TMCM-142"],
            ["3", "C", "ASCII", "142V1.06", "none", "TMCM-142"],
        ],
        "{text}"
    );
    assert_eq!(
        text.lines().nth(4),
        Some("BA 100 1000000"),
        "the target is A again"
    );
    let mut port = sim.pty();
    port.send(b"CGAP 4, 0\r");
    assert_eq!(
        port.read_line(),
        "BC 100 1000000\r",
        "C still in ASCII mode"
    );
}

#[test]
fn an_empty_range_exits_3_with_a_summary() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0", "--modules", "1"]);
    let out = expect(
        &[
            "scan",
            "--tcp",
            &sim.first,
            "--timeout",
            "100",
            "--addresses",
            "5-6",
        ],
        3,
    );
    assert!(stdout(&out).is_empty());
    assert!(
        stderr(&out).contains("no module answered at 5-6 (at most 100 ms per reply)"),
        "{}",
        stderr(&out)
    );
    let bad = expect(&["scan", "--addresses", "0-3"], 2);
    assert!(stderr(&bad).contains("'0' is not a bus address"));
}

/// Each module is named from its version string; the table's last column.
fn modules_named(text: &str) -> Vec<String> {
    table(text).iter().map(|row| row[5..].join(" ")).collect()
}

#[test]
fn every_module_found_is_named_by_the_built_in_profiles() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110", "--modules", "1,2"]);
    let out = expect(&["scan", "--port", &sim.first, "--addresses", "1-3"], 0);
    let text = stdout(&out);
    assert_eq!(modules_named(&text), ["TMCM-6110", "TMCM-6110"], "{text}");
    // No --timeout: the scan's own short wait, not the session's second.
    assert!(
        text.ends_with("2 modules answered at 1-3 (at most 100 ms per reply)\n"),
        "{text}"
    );
    // A timeout from the environment is the user's.
    let out = std::process::Command::new(crate::util::bin())
        .args(["scan", "--port", &sim.first, "--addresses", "1-3"])
        .env("TMCLSH_TIMEOUT", "150")
        .output()
        .unwrap();
    assert!(
        stdout(&out).contains("(at most 150 ms per reply)"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn first_stops_at_the_first_module_and_asks_no_further_address() {
    let sim = Sim::start_capturing_stderr(&["--pty", "--verbose", "--modules", "3,5"]);
    let out = expect(
        &["scan", "--port", &sim.first, "--first", "--timeout", "1000"],
        0,
    );
    let text = stdout(&out);
    assert_eq!(
        table(&text),
        [["3", "C", "binary", "142V1.06", "char", "TMCM-142"]],
        "{text}"
    );
    let traffic = sim.quit();
    assert!(traffic.contains("module 3 <- "), "{traffic}");
    assert!(!traffic.contains("module 5 <- "), "{traffic}");
    // Nobody there: exit 3 with the addresses tried.
    let empty = Sim::start(&["--pty", "--modules", "9"]);
    let out = expect(
        &[
            "scan",
            "--port",
            &empty.first,
            "--first",
            "--addresses",
            "1-2",
        ],
        3,
    );
    assert!(
        stderr(&out).contains("no module answered at 1-2 (at most 100 ms per reply)"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn on_a_terminal_a_scan_shows_a_labelled_bar_with_the_time_left() {
    let sim = Sim::start(&["--pty", "--modules", "2"]);
    let mut p = crate::util::terminal(&["scan", "--port", &sim.first, "--addresses", "1-8"], &[]);
    // The bar is drawn on stderr, here the terminal: its label, its count and the time left.
    p.exp_string("/8").unwrap();
    p.exp_string("left)").unwrap();
    let rest = p.exp_eof().unwrap();
    assert!(rest.contains("1 module answered at 1-8"), "{rest}");
}
