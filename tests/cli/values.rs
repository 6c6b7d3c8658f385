//! Values people can read: what the profile knows of a value is decoded, `:help PARAM` describes
//! a parameter, `:params --values` reads them, and an uncertain row carries one sign that
//! `:help params` explains (no research notes in the help).

use crate::repl::repl;
use crate::util::{code, run, stderr, stdout, terminal};

fn ok(args: &[&str]) -> String {
    let out = run(args);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    stdout(&out)
}

#[test]
fn params_values_reads_the_matching_parameters_with_their_meaning() {
    let text = ok(&["--sim", "-c", "SGP 65, 0, 7", "-c", ":params --values baud"]);
    assert!(
        text.contains("global 0/65  serial_baud_rate  7 (115200 baud)"),
        "{text}"
    );
    let text = ok(&["--sim", "-c", ":params status --values"]);
    assert!(text.contains("status_flags"), "{text}");
    assert!(text.contains("standing"), "{text}");
    assert!(
        !text.contains("target_position"),
        "only the matches: {text}"
    );
    let text = ok(&[
        "--sim",
        "--protocol",
        "smd4",
        "-c",
        ":params --values MOTOR:VMAX",
    ]);
    assert_eq!(text.trim(), "MOTOR:VMAX  1000 Hz");
}

#[test]
fn help_describes_a_parameter_and_explains_the_uncertain_sign_once() {
    let text = ok(&["--sim", "-c", ":help serial_baud_rate"]);
    assert!(
        text.starts_with("serial_baud_rate — global parameter, bank 0, 65*"),
        "{text}"
    );
    assert!(text.contains("     0  9600 baud"), "{text}");
    assert!(text.contains("(*: see :help params)"), "{text}");
    let text = ok(&["--sim", "-c", ":help params"]);
    assert!(
        text.contains(
            "* after the access letters (or the number in :help NAME): the TMCM-142 manual"
        ),
        "{text}"
    );
    let text = ok(&["--sim", "-c", ":help MVP"]);
    assert!(!text.contains("sibling"), "{text}");
    let text = ok(&[
        "--sim",
        "--protocol",
        "smd4",
        "-c",
        ":help MOTOR:VMAX",
        "-c",
        ":help params",
    ]);
    assert!(!text.contains("uncertain:"), "{text}");
    assert!(text.contains("MOTOR:VMAX[,<FLOAT Hz>] *"), "{text}");
    assert!(text.contains("* after a mnemonic"), "{text}");
}

#[test]
fn a_read_value_is_decoded_in_the_repl() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line("GGP serial_baud_rate, 0").unwrap();
    p.exp_string("serial_baud_rate = 0 (9600 baud)").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("SGP ascii_mode, 0, 17").unwrap();
    p.exp_string("ok, value 17").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GGP ascii_mode, 0").unwrap();
    p.exp_string("ascii_mode = 17 (start-up: ASCII; echo: line after CR)")
        .unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP status_flags, 0").unwrap();
    p.exp_string("status_flags = ").unwrap();
    p.exp_string("standing)").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_wait_until_timeout_names_its_condition_and_the_last_value() {
    let dir = crate::util::tempdir();
    let script = dir.join("wait.rhai");
    std::fs::write(
        &script,
        "let motor = 0;\nwait_until(|| gap(\"actual_position\", motor) == 100, 50);\n",
    )
    .unwrap();
    let out = run(&["--sim", "run", script.to_str().unwrap()]);
    let err = stderr(&out);
    assert_eq!(code(&out), 1, "{err}");
    assert!(
        err.contains(
            "timed out after 50 ms waiting for `gap(\"actual_position\", motor) == 100` (last value: false)"
        ),
        "{err}"
    );
    assert!(!err.contains("anon$"), "{err}");
    std::fs::write(&script, "wait_until(|| gap(1, 0), 30);\n").unwrap();
    let err = stderr(&run(&["--sim", "run", script.to_str().unwrap()]));
    assert!(err.contains("`gap(1, 0)` (last value: 0)"), "{err}");
}

#[test]
fn every_built_in_profile_names_its_baud_rate_code() {
    let list = ok(&["profiles"]);
    let names: Vec<&str> = list
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|w| w.starts_with("tmcm-"))
        .collect();
    assert!(names.len() >= 9, "{list}");
    for name in names {
        let text = ok(&[
            "--sim",
            "--profile",
            name,
            "-c",
            ":params --values serial_baud",
        ]);
        assert!(
            text.contains("serial_baud_rate  0 (9600 baud)"),
            "{name}: {text}"
        );
    }
}

#[test]
fn a_tmcm_1140_reply_names_its_code_and_a_changed_code_reads_anew() {
    let mut p = terminal(&["--profile", "tmcm-1140"], &[]);
    p.exp_string("simulated TMCM-1140").unwrap();
    p.send_line("GGP 65, 0").unwrap();
    p.exp_string("serial_baud_rate = 0 (9600 baud)").unwrap();
    // The decoding follows the value read, not the power-up one.
    p.send_line("SGP serial_baud_rate, 0, 3").unwrap();
    p.exp_string("ok, value 3").unwrap();
    p.send_line("GGP 65, 0").unwrap();
    p.exp_string("serial_baud_rate = 3 (28800 baud)").unwrap();
    p.send_line("GAP microstep_resolution, 0").unwrap();
    p.exp_string("microstep_resolution = 8 (256 microsteps)")
        .unwrap();
    // A value the table does not name is shown as it is, with no meaning made up.
    p.send_line("SAP reference_search_mode, 0, 65").unwrap();
    p.exp_string("ok, value 65").unwrap();
    p.send_line("GAP reference_search_mode, 0").unwrap();
    let (_, shown) = p.exp_regex(r"reference_search_mode = 65[^\r\n]*").unwrap();
    assert_eq!(shown, "reference_search_mode = 65", "{shown}");
    p.send_line(":params --values serial_baud").unwrap();
    p.exp_regex(r"global 0/65 +serial_baud_rate +3 \(28800 baud\)")
        .unwrap();
    p.send_line(":help serial_baud_rate").unwrap();
    p.exp_string("Baud rate code of RS485/RS232").unwrap();
    p.exp_regex(r"7 +115200 baud").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn an_smd4_shows_labels_and_its_flag_words_bit_by_bit() {
    let mut p = terminal(&["--protocol", "smd4"], &[]);
    p.exp_string("simulated SMD4").unwrap();
    p.send_line(":params --values SYS:FLAGS").unwrap();
    p.exp_regex(r"SYS:FLAGS +0x0888 0x0000 \(status: External Enable, Standby, Boost Operational; errors: none\)")
        .unwrap();
    // An error flag set by the drive is read back by name, then gone once cleared.
    p.send_line("MOTOR:ESTOP").unwrap();
    p.exp_string("errors: Emergency Stop").unwrap();
    p.send_line(":params --values SYS:FLAGS").unwrap();
    p.exp_regex(r"SYS:FLAGS +0x0888 0x0020 \(status: [^;]*; errors: Emergency Stop\)")
        .unwrap();
    p.send_line("SYS:CLR").unwrap();
    p.exp_string("ok [External Enable").unwrap();
    p.send_line(":params --values SYS:FLAGS").unwrap();
    p.exp_regex(r"SYS:FLAGS +0x0888 0x0000 \([^)]*errors: none\)")
        .unwrap();
    // An enumerated setting: its label in the table and in the reply to a single read.
    p.send_line(":params --values MOTOR:F").unwrap();
    p.exp_regex(r"MOTOR:F +2 \(Phases shorted to GND\)")
        .unwrap();
    p.send_line("MOTOR:F,1").unwrap();
    p.exp_string("1 (Freewheel) [").unwrap();
    p.send_line("MOTOR:F").unwrap();
    p.exp_string("1 (Freewheel) [").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}
