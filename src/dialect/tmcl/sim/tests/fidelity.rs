//! What each module's own manual says, against the TMCM-142's table the others started from:
//! speed ranges, refused search modes, control functions, 136, user variables, the generic
//! profile as a simulated module, GP 67 only where there is an ASCII interface.

use crate::dialect::tmcl::protocol::Status;

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
