use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::line::parse;

use super::*;

fn check(text: &str, mode: Mode) -> Result<Vec<Warning>, InputError> {
    let profile = Profile::builtin();
    validate(&parse(text, &profile).unwrap(), &profile, mode)
}

fn refused(text: &str, mode: Mode) -> String {
    check(text, mode).unwrap_err().to_string()
}

#[test]
fn valid_lines_pass_without_warnings() {
    for line in [
        "GAP 1, 0",
        "SAP 6, 0, 15",
        "MVP ABS, 0, -5000",
        "ROR 0, 1000",
        "STAP 4, 0",
        "SGP 5, 2, -7",
        "GGP ascii_mode, 0",
        "RFS START, 0",
        "SIO 0, 2, 1",
        "BIN",
        "RUN",
        "STOP",
        "SCO 20, 0, 5",
        "MVP COORD, 0, 20",
    ] {
        assert_eq!(check(line, Mode::Ascii), Ok(vec![]), "{line}");
    }
}

#[test]
fn program_only_commands_are_refused_in_ascii_and_direct_mode() {
    assert_eq!(
        refused("COMP 5", Mode::Ascii),
        "COMP only exists inside stand-alone TMCL programs"
    );
    assert_eq!(
        refused("JA 0", Mode::Binary),
        "JA only exists inside stand-alone TMCL programs"
    );
    assert!(check("CALC ADD, 5", Mode::Program).is_ok());
}

#[test]
fn calculation_commands_share_one_rule_direct_yes_ascii_no() {
    // Manual 6.4.5: CALC, CALCX, AAP, AGP and ACO "could also be used in direct mode".
    for line in [
        "CALC ADD, 5",
        "CALCX SWAP",
        "AAP 4, 0",
        "AGP 0, 2",
        "ACO 1, 0",
    ] {
        assert!(check(line, Mode::Binary).is_ok(), "{line}");
        let e = refused(line, Mode::Ascii);
        assert!(e.contains("is not available in ASCII mode"), "{line}: {e}");
    }
}

#[test]
fn direct_only_commands_are_refused_in_ascii_mode_with_a_hint() {
    let e = refused("AAP 4, 0", Mode::Ascii);
    assert!(
        e.contains("AAP — accumulator to axis parameter — is not available in ASCII mode"),
        "{e}"
    );
    assert!(e.contains(":bin"), "{e}");
    let e = refused("136 1", Mode::Ascii);
    assert!(
        e.starts_with("136 — get firmware version — is not available in ASCII mode"),
        "{e}"
    );
    assert!(check("136 1", Mode::Binary).is_ok());
    assert!(check("AAP 4, 0", Mode::Binary).is_ok());
}

#[test]
fn control_functions_cannot_go_into_programs() {
    let e = refused("135", Mode::Program);
    assert!(e.contains("cannot be stored in a program"), "{e}");
}

#[test]
fn ascii_words_only_in_ascii_mode() {
    assert!(refused("BIN", Mode::Binary).contains("only exists in ASCII mode"));
    assert!(refused("RUN", Mode::Program).contains("not a program instruction"));
}

#[test]
fn keywords_given_by_number_must_exist() {
    let e = refused("MVP 7, 0, 5", Mode::Ascii);
    assert_eq!(
        e,
        "'7' is not a keyword of MVP; use ABS (0), REL (1), COORD (2)"
    );
}

#[test]
fn motors_the_module_does_not_have() {
    // The manual's ASCII examples use motors 1 and 2, inherited from multi-axis modules.
    assert_eq!(
        refused("MVP ABS, 1, 50000", Mode::Ascii),
        "motor 1 does not exist: the TMCM-142 has one motor (0..0)"
    );
    assert!(refused("ROL 2, 500", Mode::Ascii).starts_with("motor 2 does not exist"));
}

#[test]
fn read_only_parameters_refuse_writes_with_a_hint() {
    assert_eq!(
        refused("SAP 8, 0, 1", Mode::Ascii),
        "axis parameter 8 (target_position_reached) is read-only; use GAP 8, 0 to read it"
    );
    assert_eq!(
        refused("SGP 128, 0, 1", Mode::Ascii),
        "global parameter 128 (application_status) is read-only; use GGP 128, 0 to read it"
    );
}

#[test]
fn stores_of_volatile_parameters_are_refused() {
    assert_eq!(
        refused("STAP 1, 0", Mode::Ascii),
        "axis parameter 1 (actual_position) is not stored in EEPROM, so STAP does not apply to it"
    );
    assert!(refused("RSGP 132, 0", Mode::Ascii).contains("tick_timer"));
}

#[test]
fn unreadable_parameters_refuse_reads() {
    let mut profile = (*Profile::builtin()).clone();
    profile
        .axis
        .iter_mut()
        .find(|p| p.number == 4)
        .unwrap()
        .access
        .read = false;
    let line = parse("GAP 4, 0", &profile).unwrap();
    let e = validate(&line, &profile, Mode::Ascii).unwrap_err();
    assert_eq!(
        e.to_string(),
        "axis parameter 4 (max_positioning_speed) cannot be read"
    );
}

#[test]
fn values_out_of_range() {
    assert_eq!(
        refused("SAP 6, 0, 16", Mode::Ascii),
        "16 is out of range for max_current (axis parameter 6): allowed 0..15 (1/15 of full scale (0 = 0 %, 15 = 100 %))"
    );
    assert!(refused("ROR 0, -5", Mode::Ascii).contains("-5 is out of range for the value of ROR"));
    assert!(refused("SIO 0, 2, 2", Mode::Ascii).contains("allowed 0..1"));
    assert!(refused("SCO 21, 0, 5", Mode::Ascii).contains("coordinate number: allowed 0..20"));
    assert!(refused("MVP COORD, 0, 21", Mode::Ascii).contains("coordinate number"));
    assert!(refused("137 0, 0, 1", Mode::Binary).contains("allowed 1234..1234"));
}

#[test]
fn unknown_parameter_numbers_pass_with_a_warning() {
    let warnings = check("GAP 200, 0", Mode::Ascii).unwrap();
    assert_eq!(warnings.len(), 1);
    assert_eq!(
        warnings[0].to_string(),
        "axis parameter 200 is not in the TMCM-142 profile; sending it anyway"
    );
    let warnings = check("GGP 3, 1", Mode::Ascii).unwrap();
    assert!(
        warnings[0]
            .to_string()
            .contains("global parameter 3 in bank 1")
    );
}

#[test]
fn a_control_function_takes_any_motor_byte() {
    // Seed §6.5: the motor/bank byte of 128–139 is "don't care"; the TMCM-142 has one motor.
    for line in ["135 0, 5, 0", "136 1, 255, 0", "128 0, 1, 0"] {
        assert!(check(line, Mode::Binary).is_ok(), "{line}");
    }
    assert!(refused("GAP 1, 1", Mode::Binary).contains("motor"));
}

#[test]
fn a_binary_only_module_never_gets_the_ascii_start_bit() {
    // The TMCM-6214 has no ASCII interface: GP 67 written or stored could make it start in a
    // mode it lacks. A read is only the usual unknown-parameter warning.
    let profile = crate::dialect::tmcl::profile::catalogue::by_name("tmcm-6214").unwrap();
    for text in ["SGP 67, 0, 1", "SGP 67, 0, 32", "STGP 67, 0"] {
        let line = parse(text, &profile).unwrap();
        let e = validate(&line, &profile, Mode::Binary).unwrap_err();
        assert!(
            e.to_string().contains("has no ASCII interface"),
            "{text}: {e}"
        );
    }
    let line = parse("GGP 67, 0", &profile).unwrap();
    assert!(validate(&line, &profile, Mode::Binary).is_ok());
    // A module with the interface takes it.
    assert!(check("SGP 67, 0, 32", Mode::Ascii).is_ok());
}
