//! ASCII mode (manual §6.6): entering and leaving, address characters, reply format, the three
//! echo behaviours, the command list, and the switchable choices.

use crate::dialect::tmcl::protocol::{CommandFrame, Instruction};
use crate::dialect::tmcl::sim::{Backspace, BusOptions, LineEnd, Quirks};

use super::Sim;

fn ascii(echo_bits: i32) -> Sim {
    let mut sim = Sim::new();
    sim.ok(9, 67, 0, echo_bits);
    sim.ok(139, 0, 0, 0);
    sim
}

#[test]
fn character_echo_repeats_each_character_then_replies() {
    let mut sim = ascii(0);
    assert_eq!(sim.send(b"A"), b"A");
    assert_eq!(sim.send(b"GAP 1,"), b"GAP 1,");
    assert_eq!(sim.send(b" 0\r"), b" 0\rBA 100 0\r");
}

#[test]
fn character_echo_erases_with_backspace() {
    let mut sim = ascii(0);
    let out = sim.send(b"AGAQ\x08P 4, 0\r");
    assert_eq!(out, b"AGAQ\x08 \x08P 4, 0\rBA 100 1000000\r");
}

#[test]
fn line_echo_repeats_the_line_after_cr() {
    let mut sim = ascii(0x10);
    assert!(sim.send(b"AGAP 4, 0").is_empty());
    assert_eq!(sim.send(b"\r"), b"AGAP 4, 0\rBA 100 1000000\r");
}

#[test]
fn no_echo_sends_only_the_reply() {
    let mut sim = ascii(0x20);
    assert_eq!(sim.line("A GAP 4, 0"), "BA 100 1000000\r");
    assert_eq!(sim.line("amst 0"), "BA 100 0\r", "case-insensitive");
}

#[test]
fn the_manual_example_reply_format() {
    let mut sim = ascii(0x20);
    sim.line("ASAP 1, 0, -5000");
    assert_eq!(sim.line("AGAP 1, 0"), "BA 100 -5000\r");
    assert_eq!(sim.line("AGAP actual_position, 0"), "BA 100 -5000\r");
    assert_eq!(sim.line("AMVP ABS, 0, 50000"), "BA 100 50000\r");
    assert_eq!(sim.line("AGGP 76, 0"), "BA 100 2\r");
}

#[test]
fn the_host_address_parameter_gives_the_first_reply_character() {
    let mut sim = ascii(0x20);
    sim.line("ASGP 76, 0, 8");
    assert_eq!(sim.line("AGAP 1, 0"), "HA 100 0\r");
}

#[test]
fn only_the_ascii_command_list_is_accepted() {
    let mut sim = ascii(0x20);
    assert_eq!(sim.line("A136 1"), "BA 2 0\r", "control functions");
    assert_eq!(sim.line("AJA 5"), "BA 2 5\r", "program-only");
    assert_eq!(sim.line("AAAP 4, 0"), "BA 2 0\r", "not in the §6.6.3 list");
    assert_eq!(sim.line("AFOO 1"), "BA 2 0\r", "unknown");
    assert_eq!(
        sim.line("AGAP nonsense, 0"),
        "BA 3 0\r",
        "unknown parameter name"
    );
    assert_eq!(
        sim.line("AGAP 99, 0"),
        "BA 3 0\r",
        "unknown parameter number"
    );
    assert_eq!(sim.line("AMVP SIDEWAYS, 0, 5"), "BA 4 0\r", "bad keyword");
    assert_eq!(sim.line("AGAP 1, 1"), "BA 4 0\r", "motor 1");
    assert_eq!(sim.line("ASAP 6, 0, 99"), "BA 4 99\r", "out of range");
    assert_eq!(sim.line("AUF0 0, 0, 0"), "BA 6 0\r");
}

#[test]
fn lines_for_other_modules_get_no_answer() {
    let mut sim = ascii(0);
    assert!(sim.line("BGAP 1, 0").is_empty());
    assert!(sim.line("CMST 0").is_empty());
    assert_eq!(sim.line("AMST 0"), "AMST 0\rBA 100 0\r");
}

#[test]
fn bin_replies_and_returns_to_binary_mode() {
    let mut sim = ascii(0x20);
    assert_eq!(sim.line("ABIN"), "BA 100 0\r");
    assert_eq!(sim.gap(4), 1_000_000, "binary again");
}

#[test]
fn run_and_stop_control_the_program() {
    let mut sim = ascii(0x20);
    assert_eq!(sim.line("ARUN"), "BA 100 0\r");
    assert_eq!(sim.line("ASTOP"), "BA 100 0\r");
}

#[test]
fn quirks_switch_replies_and_endings() {
    let quirks = Quirks {
        reply_to_139: false,
        reply_to_bin: false,
        reply_end: LineEnd::CrLf,
        echo_end: LineEnd::Lf,
        backspace: Backspace::Plain,
        ..Quirks::default()
    };
    let mut sim = Sim::with(BusOptions {
        quirks,
        ..BusOptions::default()
    });
    let enter = CommandFrame {
        address: 1,
        instruction: Instruction::new(139, 0, 0, 0),
    };
    assert!(sim.send(&enter.encode()).is_empty(), "139 without reply");
    assert_eq!(
        sim.send(b"AGAX\x08P 1, 0\r"),
        b"AGAX\x08P 1, 0\nBA 100 0\r\n"
    );
    assert_eq!(sim.line("ABIN"), "ABIN\n", "echo, then BIN without reply");
    assert_eq!(sim.gap(1), 0);
}

#[test]
fn a_line_that_changes_the_echo_or_the_address_rules_the_next_line_of_the_same_write() {
    // What the line input reads of the settings is read again after each line: one write of
    // several lines is answered as the same bytes written one at a time.
    let lines: &[u8] = b"ASGP 67, 0, 32\rAGAP 4, 0\rASGP 67, 0, 16\rAGAP 4, 0\r\
        ASGP 67, 0, 0\rAGAP 4, 0\rASGP 66, 0, 2\rAGAP 4, 0\rBGAP 4, 0\rBSGP 66, 0, 1\rAGAP 4, 0\r";
    let mut whole = ascii(0);
    let at_once = whole.send(lines);
    let mut bytes = ascii(0);
    let one_by_one: Vec<u8> = lines.iter().flat_map(|&b| bytes.send(&[b])).collect();
    assert_eq!(
        String::from_utf8_lossy(&at_once),
        String::from_utf8_lossy(&one_by_one)
    );
    let text = String::from_utf8(at_once).unwrap();
    assert!(
        text.starts_with("ASGP 67, 0, 32\r"),
        "character echo first: {text}"
    );
    assert!(
        text.contains("\rAGAP 4, 0\rBA 100 1000000\r"),
        "line echo later: {text}"
    );
    assert!(
        text.contains("BGAP 4, 0\r"),
        "module 2 after SGP 66: {text}"
    );
}

#[test]
fn a_repeated_reply_is_written_anew_when_anything_in_it_changes() {
    let mut sim = ascii(0x20);
    assert_eq!(sim.line("AGAP 4, 0"), "BA 100 1000000\r");
    assert_eq!(sim.line("AGAP 4, 0"), "BA 100 1000000\r");
    sim.line("ASAP 4, 0, 7");
    assert_eq!(sim.line("AGAP 4, 0"), "BA 100 7\r");
    assert_eq!(sim.line("AGAP 4, 0"), "BA 100 7\r");
    sim.line("ASGP 76, 0, 8");
    assert_eq!(sim.line("AGAP 4, 0"), "HA 100 7\r");
}
