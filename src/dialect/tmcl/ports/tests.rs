//! The port descriptions against the built-in profiles' maps, and against a hostile one.

use super::*;
use crate::dialect::tmcl::profile::catalogue;

fn named(name: &str) -> std::sync::Arc<Profile> {
    catalogue::by_name(name).unwrap()
}

fn table(profile: &Profile) -> String {
    let mut out = Vec::new();
    write_table(profile, &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

#[test]
fn the_table_lists_every_mapped_port_with_direction_pin_and_kind() {
    let p = Profile::builtin();
    let text = table(&p);
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("I/O ports of the TMCM-142"), "{text}");
    assert!(lines[1].starts_with("bank/port"), "{text}");
    assert!(lines[1].ends_with("pin  kind"), "{text}");
    // One row per mapped port, in bank and port order.
    let rows: Vec<&str> = lines[2..2 + p.io_ports.len()].to_vec();
    for (row, port) in rows.iter().zip(&p.io_ports) {
        assert!(
            row.starts_with(&format!("{}/{}", port.bank, port.port)),
            "{row}"
        );
        assert!(row.contains(&format!(" {} ", port.name)), "{row}");
        assert!(row.contains(&port.kind), "{row}");
    }
    let in7 = rows.iter().find(|r| r.starts_with("0/7")).unwrap();
    assert!(in7.contains("IN7") && in7.contains("input"), "{in7}");
    assert!(in7.contains(" 11  digital input, opto-isolated"), "{in7}");
    let out1 = rows.iter().find(|r| r.starts_with("2/1")).unwrap();
    assert!(out1.contains("output"), "{out1}");
    // The uncertain rows are marked, and the mark explained once, at the end.
    assert!(rows.iter().all(|r| r.contains(&format!(" {UNCERTAIN}  "))));
    assert_eq!(text.matches("does not confirm").count(), 1);
    assert!(
        lines.last().unwrap().starts_with(UNCERTAIN),
        "{}",
        lines.last().unwrap()
    );
    // Signals GIO cannot reach are not rows.
    assert!(!text.contains("REF L"), "{text}");
}

#[test]
fn a_profile_without_pins_has_no_pin_column_and_shows_adc_ranges() {
    let text = table(&named("tmcm-1141"));
    assert!(!text.contains("pin"), "{text}");
    let adc = text.lines().find(|l| l.starts_with("1/0")).unwrap();
    assert!(
        adc.contains("ADC0") && adc.ends_with("analog input, 0..4095"),
        "{adc}"
    );
    // Digital ports read 0 or 1: nothing to add.
    let in0 = text.lines().find(|l| l.starts_with("0/0")).unwrap();
    assert!(in0.ends_with("digital input"), "{in0}");
}

#[test]
fn without_a_map_the_profile_says_so() {
    let generic = catalogue::generic();
    let text = table(&generic);
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(
        text.starts_with("The generic profile has no port map"),
        "{text}"
    );
    assert_eq!(help_line(&generic, false), text.trim_end());
}

#[test]
fn the_summary_names_each_bank_s_ports() {
    let p = Profile::builtin();
    assert_eq!(
        summary(&p, false).unwrap(),
        "bank 0 ports 3..8 (IN3..IN8, digital input), bank 1 ports 0..2 (IN0_A/D, IN1_A/D, \
         IN2_A/D, analog input) and bank 2 ports 0..2 (OUT_0, OUT_1, OUT_2, user output)"
    );
    assert_eq!(
        summary(&p, true).unwrap(),
        "bank 2 ports 0..2 (OUT_0, OUT_1, OUT_2, user output)"
    );
    // Gaps in the numbers, and kinds that differ within a bank, on a six-axis module.
    let six = summary(&named("tmcm-6214"), false).unwrap();
    assert!(
        six.starts_with("bank 0 ports 0..7, 10, 13, 14 (AIN0, IN1, …, STO2), bank 1 ports 0, 4 (AIN0, AIN4, analog input)"),
        "{six}"
    );
    assert!(
        help_line(&named("tmcm-1140"), true).starts_with(
            "Outputs on this TMCM-1140: bank 2 ports 0, 1 (OUT0, OUT1, digital output)"
        ),
    );
}

#[test]
fn a_port_is_described_by_its_row() {
    let p = Profile::builtin();
    assert_eq!(
        describe(p.io_port(0, 7).unwrap()),
        "IN7, digital input, opto-isolated, active low (needs +5V on pin 15), pin 11"
    );
    assert_eq!(
        describe(p.io_port(2, 1).unwrap()),
        "OUT_1, user output, pin 9"
    );
    let temperature = named("tmcm-1021");
    assert_eq!(
        describe(temperature.io_port(1, 9).unwrap()),
        "TEMPERATURE, temperature, degC"
    );
    // Before the bank: every bank's port of that number, or the outputs only for SIO.
    let six = named("tmcm-6110");
    assert_eq!(
        describe_any_bank(&six, 0, false).unwrap(),
        "bank 0: AIN0; bank 1: AIN0; bank 2: OUT0"
    );
    assert_eq!(
        describe_any_bank(&six, 0, true).unwrap(),
        "bank 2: OUT0, digital output"
    );
    assert_eq!(describe_any_bank(&six, 9, false), None);
}

#[test]
fn a_reading_is_named_after_its_port() {
    let p = Profile::builtin();
    assert_eq!(reading(&p, 0, 7, 1).unwrap(), "IN7 = 1");
    assert_eq!(reading(&p, 1, 0, 512).unwrap(), "IN0_A/D = 512");
    assert_eq!(reading(&p, 0, 0, 1), None);
    assert_eq!(
        reading(&named("tmcm-1021"), 1, 9, 31).unwrap(),
        "TEMPERATURE = 31 degC"
    );
    assert_eq!(reading(&catalogue::generic(), 0, 0, 1), None);
}

#[test]
fn no_research_note_reaches_the_port_rows_of_any_builtin_profile() {
    use crate::dialect::tmcl::help::research_note;
    for profile in catalogue::all() {
        let text = table(profile);
        // The last line explains the mark, as `:help params` does; the rows are the module's.
        let rows: Vec<&str> = text.lines().filter(|l| !l.starts_with(UNCERTAIN)).collect();
        for row in rows {
            assert_eq!(research_note(row), None, "{}: {row}", profile.name);
        }
        for writes in [false, true] {
            let line = help_line(profile, writes);
            assert_eq!(research_note(&line), None, "{line}");
        }
    }
}
