//! The rules a module's profile adds, through the validator.

use std::sync::Arc;

use super::spans;
use crate::dialect::tmcl::profile::{Profile, catalogue};
use crate::dialect::tmcl::protocol::error::{InputError, Warning};
use crate::dialect::tmcl::protocol::line::parse;
use crate::dialect::tmcl::protocol::validate::{Mode, validate};

fn check(profile: &Profile, text: &str, mode: Mode) -> Result<Vec<Warning>, InputError> {
    validate(&parse(text, profile)?, profile, mode)
}

fn refused(profile: &Profile, text: &str, mode: Mode) -> String {
    check(profile, text, mode).expect_err(text).to_string()
}

fn named(name: &str) -> Arc<Profile> {
    catalogue::by_name(name).unwrap()
}

#[test]
fn port_lists_are_short() {
    assert_eq!(spans(&[3, 4, 5, 6, 7, 8]), "3..8");
    assert_eq!(spans(&[0, 1]), "0, 1");
    assert_eq!(spans(&[0, 4, 8]), "0, 4, 8");
    assert_eq!(spans(&[0, 1, 2, 4, 10, 13, 14]), "0..2, 4, 10, 13, 14");
    assert_eq!(spans(&[]), "");
}

#[test]
fn motors_are_the_modules_own() {
    let six = named("tmcm-6110");
    for motor in 0..6 {
        let line = format!("GAP 4, {motor}");
        assert_eq!(check(&six, &line, Mode::Ascii), Ok(vec![]), "{line}");
    }
    assert_eq!(
        refused(&six, "MVP ABS, 6, 100", Mode::Binary),
        "motor 6 does not exist: the TMCM-6110 has 6 motors (0..5)"
    );
    assert!(check(&named("tmcm-3110"), "ROR 2, 100", Mode::Ascii).is_ok());
    assert_eq!(
        refused(&named("tmcm-1140"), "MST 1", Mode::Ascii),
        "motor 1 does not exist: the TMCM-1140 has one motor (0..0)"
    );
}

#[test]
fn stgp_and_rsgp_take_user_variables_only() {
    let p = Profile::builtin();
    for line in ["STGP 0, 2", "RSGP user_variable_55, 2"] {
        assert_eq!(check(&p, line, Mode::Ascii), Ok(vec![]), "{line}");
    }
    let e = refused(&p, "STGP 67, 0", Mode::Ascii);
    assert!(
        e.starts_with("STGP accepts bank 2 only on the TMCM-142, not bank 0 (bank 0 settings"),
        "{e}"
    );
    assert!(e.contains("kept by SGP itself"), "{e}");
    assert!(refused(&p, "RSGP 67, 0", Mode::Program).starts_with("RSGP accepts bank 2 only"));
    // SGP and GGP take every bank.
    assert!(check(&p, "SGP 67, 0, 0x21", Mode::Ascii).is_ok());
}

#[test]
fn io_ports_and_banks_come_from_the_io_map() {
    let p = Profile::builtin();
    for line in [
        "GIO 3, 0",
        "GIO 8, 0",
        "GIO 2, 1",
        "GIO 1, 2",
        "SIO 2, 2, 1",
    ] {
        assert_eq!(check(&p, line, Mode::Ascii), Ok(vec![]), "{line}");
    }
    assert_eq!(
        refused(&p, "GIO 0, 0", Mode::Ascii),
        "the TMCM-142 has no I/O port 0 in bank 0; it has bank 0 ports 3..8, bank 1 ports 0..2 \
         and bank 2 ports 0..2"
    );
    assert_eq!(
        refused(&p, "SIO 3, 2, 1", Mode::Binary),
        "the TMCM-142 has no I/O port 3 in bank 2; it has bank 2 ports 0..2"
    );
    assert_eq!(
        refused(&p, "SIO 3, 0, 1", Mode::Ascii),
        "SIO sets outputs (bank 2 ports 0..2); port 3 of bank 0 is IN3, an input"
    );
    assert!(refused(&p, "GIO 0, 5", Mode::Program).contains("no I/O port 0 in bank 5"));
    // A port no bank has is wrong whatever the bank: the refusal does not name one.
    for bank in [0, 1, 2, 7] {
        assert_eq!(
            refused(&p, &format!("GIO 9, {bank}"), Mode::Ascii),
            "the TMCM-142 has no I/O port 9 in any bank; it has bank 0 ports 3..8, bank 1 ports \
             0..2 and bank 2 ports 0..2"
        );
        assert_eq!(
            refused(&p, &format!("SIO 200, {bank}, 1"), Mode::Ascii),
            "the TMCM-142 has no I/O port 200 in any bank; it has bank 2 ports 0..2"
        );
    }
    let six = named("tmcm-6110");
    assert!(check(&six, "SIO 7, 2, 1", Mode::Ascii).is_ok());
    assert!(check(&six, "GIO 8, 1", Mode::Ascii).is_ok());
    assert!(refused(&six, "GIO 1, 1", Mode::Ascii).contains("bank 1 ports 0, 4, 8"));
    // Without an I/O map, any port goes.
    let g = catalogue::generic();
    assert!(check(&g, "SIO 9, 2, 1", Mode::Ascii).is_ok());
}

#[test]
fn a_conditional_range_widens_nothing_silently() {
    let p = Profile::builtin();
    // AP255 = 1 makes velocities pps in 0..31999999: inside both ranges, no notice.
    assert_eq!(check(&p, "ROR 0, 31999999", Mode::Ascii), Ok(vec![]));
    assert_eq!(check(&p, "SAP 4, 0, 1000", Mode::Ascii), Ok(vec![]));
    // In the usual range only: sent, with a notice naming the range it misses.
    let warnings = check(&p, "ROL 0, 32000000", Mode::Ascii).unwrap();
    assert_eq!(
        warnings.iter().map(ToString::to_string).collect::<Vec<_>>(),
        [
            "the value of ROL: 32000000 is outside 0..31999999 usteps/s when axis parameter 255 = 1; \
          sent, as it lies in the usual range 0..2147483647 (which applies depends on a setting \
          only the module knows)"
        ]
    );
    let warnings = check(
        &p,
        "SAP max_positioning_speed, 0, 2147483647",
        Mode::Program,
    )
    .unwrap();
    assert_eq!(warnings.len(), 1);
    assert!(warnings[0].to_string().starts_with(
        "max_positioning_speed (axis parameter 4): 2147483647 is outside 0..31999999 usteps/s"
    ));
    // In neither: refused with the usual range.
    assert_eq!(
        refused(&p, "SAP 4, 0, -1", Mode::Ascii),
        "-1 is out of range for max_positioning_speed (axis parameter 4): allowed 0..2147483647 \
         (usteps/t)"
    );
}

#[test]
fn a_conditional_range_wider_than_the_usual_one_lets_its_values_through_with_a_notice() {
    let text = "[meta]\nmodule = \"TMCM-9\"\n\
                [[axis_parameter]]\nnumber = 255\nname = \"u\"\nident = \"unit\"\naccess = \"RW\"\n\
                [[axis_parameter]]\nnumber = 4\nname = \"v\"\nident = \"speed\"\naccess = \"RW\"\n\
                range = [0, 2047]\n\
                range_when = [{ axis_parameter = 255, equals = 1, range = [0, 100000], unit = \"pps\" }]\n";
    let p = Profile::from_toml(text, Some(&Profile::builtin().commands)).unwrap();
    assert_eq!(check(&p, "SAP 4, 0, 2000", Mode::Ascii), Ok(vec![]));
    let warnings = check(&p, "SAP 4, 0, 5000", Mode::Ascii).unwrap();
    assert_eq!(
        warnings[0].to_string(),
        "speed (axis parameter 4): 5000 is outside the usual range 0..2047; sent, as it lies in \
         0..100000 pps when axis parameter 255 = 1 (which applies depends on a setting only the \
         module knows)"
    );
    assert!(refused(&p, "SAP 4, 0, 100001", Mode::Ascii).contains("allowed 0..2047"));
}

#[test]
fn the_ascii_list_is_the_modules() {
    // A module whose list leaves out SIO: refused in ASCII mode with the way out, sent in binary.
    let text = "[meta]\nmodule = \"TMCM-9\"\n[ascii]\nallowed_commands = [\"GAP\", \"SAP\"]\n";
    let p = Profile::from_toml(text, Some(&Profile::builtin().commands)).unwrap();
    let e = refused(&p, "SIO 0, 2, 1", Mode::Ascii);
    assert_eq!(
        e,
        "SIO — set output — is not available in ASCII mode: the TMCM-9's ASCII command list \
         lacks it; switch to binary mode with :bin to send it"
    );
    assert!(check(&p, "SIO 0, 2, 1", Mode::Binary).is_ok());
    assert!(check(&p, "GAP 1, 0", Mode::Ascii).is_ok());
    // The TMCM-1140 family has no SAC at all: named as a command the module lacks, in any mode.
    let p = named("tmcm-1140");
    for mode in [Mode::Ascii, Mode::Binary] {
        let e = parse("SAC 0, 0, 0", &p).unwrap_err().to_string();
        assert!(
            e.starts_with(
                "SAC (29) is not a command of the TMCM-1140; its profile says: the TMCM-1140's \
                 manual does not list it"
            ),
            "{mode:?}: {e}"
        );
    }
    assert!(check(&Profile::builtin(), "SAC 0, 0, 0", Mode::Ascii).is_ok());
    // CALC is for direct mode and programs on every module, never ASCII mode.
    let e = refused(&p, "CALC ADD, 1", Mode::Ascii);
    assert!(
        e.contains("the TMCM-1140's ASCII command list lacks it") && e.contains(":bin"),
        "{e}"
    );
    assert!(check(&p, "CALC ADD, 1", Mode::Binary).is_ok());
}

#[test]
fn the_generic_profile_sends_parameter_numbers_without_notices() {
    let g = catalogue::generic();
    assert_eq!(check(&g, "GAP 4, 0", Mode::Ascii), Ok(vec![]));
    assert_eq!(check(&g, "SAP 200, 5, -7", Mode::Binary), Ok(vec![]));
    assert_eq!(check(&g, "SGP 255, 3, 1", Mode::Ascii), Ok(vec![]));
    let e = parse("GAP max_speed, 0", &g).unwrap_err().to_string();
    assert!(
        e.starts_with("the generic TMCL module profile has no parameter names"),
        "{e}"
    );
    assert!(!e.contains(":params"), "{e}");
    assert!(refused(&g, "GAP 4, 6", Mode::Ascii).contains("motor 6 does not exist"));
    // Outside the generic profile an unknown number is sent with a notice.
    let w = check(&Profile::builtin(), "GAP 199, 0", Mode::Ascii).unwrap();
    assert_eq!(w.len(), 1);
}
