//! What each module's own manual says, against the TMCM-142's table the others started from:
//! speed ranges, refused search modes, control functions, 136, user variables, the generic
//! profile as a simulated module, GP 67 only where there is an ASCII interface.

use crate::dialect::tmcl::protocol::Status;
use crate::dialect::tmcl::sim::control_cmd::Controlled;

use super::Sim;

const ROR: u8 = 1;
const ROL: u8 = 2;
const GAP: u8 = 6;

#[test]
fn a_signed_speed_range_turns_the_motor_the_other_way() {
    // TMCM-6212 manual p25 (the TMCM-6214's generation): -2147483648…2147483647.
    let mut sim = Sim::of("tmcm-6214");
    sim.ok(ROR, 0, 2, -500);
    sim.ok(ROL, 0, 3, -700);
    sim.wait(5.0);
    assert_eq!(sim.ok(GAP, 3, 2, 0), -500, "ROR -500 runs left");
    assert_eq!(sim.ok(GAP, 3, 3, 0), 700, "ROL -700 runs right");
    assert!(sim.ok(GAP, 1, 2, 0) < 0 && sim.ok(GAP, 1, 3, 0) > 0);
    // The most negative speed is in the range and does not overflow when ROL negates it.
    sim.ok(ROL, 0, 4, i32::MIN);
}

#[test]
fn tmc429_modules_take_0_to_2047_and_the_tmcm_142_0_to_2147483647() {
    for (name, top) in [
        ("tmcm-6110", 2047),
        ("tmcm-1140", 2047),
        ("tmcm-142", i32::MAX),
    ] {
        let mut sim = Sim::of(name);
        for command in [ROR, ROL] {
            assert_eq!(
                sim.status(command, 0, 0, -1),
                Status::InvalidValue,
                "{name}"
            );
            assert_eq!(sim.status(command, 0, 0, top), Status::Ok, "{name}");
            if top < i32::MAX {
                let over = sim.status(command, 0, 0, top + 1);
                assert_eq!(over, Status::InvalidValue, "{name}");
            }
        }
    }
}

#[test]
fn a_search_mode_the_module_lacks_is_refused_and_mode_4_ends_on_the_left_switch() {
    use crate::dialect::tmcl::profile::catalogue;
    use crate::dialect::tmcl::sim::{Bus, BusOptions, Switch};
    const SAP: u8 = 5;
    const RFS: u8 = 13;
    let options = BusOptions {
        motor_switches: vec![(0, Switch::Left, -2_000)],
        ..BusOptions::default()
    };
    let mut sim = Sim {
        bus: Bus::new(catalogue::by_name("tmcm-1140").unwrap(), options),
        now: std::time::Duration::ZERO,
    };
    // AP193 has no range on the TMCM-1140, so SAP takes 7; its values list 1…4.
    sim.ok(SAP, 193, 0, 7);
    assert_eq!(sim.status(RFS, 0, 0, 0), Status::InvalidValue);
    assert_eq!(sim.ok(RFS, 2, 0, 0), 0, "nothing was started");
    sim.ok(SAP, 193, 0, 4);
    sim.ok(RFS, 0, 0, 0);
    sim.wait(20.0);
    assert_eq!(sim.ok(RFS, 2, 0, 0), 0, "mode 4 ends");
    assert_eq!(sim.ok(GAP, 1, 0, 0), 0, "at the left switch's edge");
    // The TMCM-142 has modes 1…3 only (its p39): SAP refuses 4 by the range already.
    let mut sim = Sim::of("tmcm-142");
    assert_eq!(sim.status(SAP, 193, 0, 4), Status::InvalidValue);
}

#[test]
fn control_functions_take_any_motor_byte() {
    // Seed §6.5: "don't care"; the TMCM-1140 has one motor.
    let mut sim = Sim::of("tmcm-1140");
    assert_eq!(sim.ok(135, 0, 5, 0), 0);
    assert_eq!(sim.ok(131, 0, 200, 0), 0);
    sim.ok(136, 1, 9, 0);
    assert_eq!(
        sim.status(GAP, 1, 1, 0),
        Status::InvalidValue,
        "GAP's motor is one"
    );
}

#[test]
fn version_136_type_1_carries_the_module_number_where_the_family_s_manuals_show_it() {
    // TMCM-1310 p63: the type number 1310 = 0x051E in the upper bytes; version 1.31 below.
    let mut sim = Sim::of("tmcm-6110");
    let value = sim.ok(136, 1, 0, 0);
    assert_eq!((value >> 16, value & 0xFFFF), (6110, 0x011F));
    // The TMCM-142's own manual (p92): "type number … currently not used".
    assert_eq!(Sim::of("tmcm-142").ok(136, 1, 0, 0), 0x0106);
}

#[test]
fn user_variables_follow_each_module_s_bank_2() {
    const SGP: u8 = 9;
    const GGP: u8 = 10;
    const STGP: u8 = 11;
    // The TMC5xxx modules' manual template (TMCM-1690 §5.2): 256 variables, 0…55 in EEPROM.
    let mut sim = Sim::of("tmcm-6214");
    sim.ok(SGP, 200, 2, -5);
    assert_eq!(sim.ok(GGP, 200, 2, 0), -5);
    sim.ok(STGP, 55, 2, 0);
    assert_ne!(
        sim.status(STGP, 56, 2, 0),
        Status::Ok,
        "56… live in RAM only"
    );
    // The TMCM-142 has 56 (its 2009 firmware header).
    let mut sim = Sim::of("tmcm-142");
    assert_ne!(sim.status(SGP, 200, 2, 1), Status::Ok);
}

#[test]
fn the_generic_profile_serves_as_a_simulated_module() {
    const MVP: u8 = 4;
    const SAP: u8 = 5;
    let mut sim = Sim::of("generic");
    // The TMCM-142's numbering and defaults, so a motor moves; six motors.
    assert_eq!(sim.ok(GAP, 1, 0, 0), 0);
    sim.ok(MVP, 0, 5, 3000);
    sim.wait(10.0);
    assert_eq!(sim.ok(GAP, 1, 5, 0), 3000);
    // Numbers no table names are plain memory, as the profile sends them unchecked.
    sim.ok(SAP, 200, 3, 17);
    assert_eq!(sim.ok(GAP, 200, 3, 0), 17);
    assert_eq!(sim.status(GAP, 1, 6, 0), Status::InvalidValue, "no motor 6");
}

#[test]
fn a_binary_only_module_has_no_gp_67_to_be_locked_into_ascii_mode_by() {
    const SGP: u8 = 9;
    const GGP: u8 = 10;
    let mut sim = Sim::of("tmcm-6214");
    assert_eq!(sim.status(SGP, 67, 0, 1), Status::WrongType);
    assert_eq!(sim.status(GGP, 67, 0, 0), Status::WrongType);
    sim.bus.reset(sim.now, Some(1)).unwrap();
    assert_eq!(sim.bus.is_ascii(1), Some(false));
    assert_eq!(sim.ok(GAP, 1, 0, 0), 0, "still binary after a restart");
    assert!(sim.bus.images()[0].global.iter().all(|g| g.1 != 67));
    // A module with the interface keeps it.
    let mut sim = Sim::of("tmcm-6110");
    sim.ok(SGP, 67, 0, 0x20);
    assert_eq!(sim.ok(GGP, 67, 0, 0), 0x20);
}
