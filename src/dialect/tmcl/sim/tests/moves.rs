//! Motion through the command interface: trapezoid timing, velocity ramps, units, limit
//! switches, reference search, encoder.

use crate::dialect::tmcl::sim::control_cmd::Controlled;
use crate::dialect::tmcl::sim::{BusOptions, Switch, Switches};

use super::Sim;

/// A module with pps units, the given maximum speed and acceleration.
fn module(vmax: i32, accel: i32) -> Sim {
    let mut sim = Sim::with(BusOptions {
        switches: Switches {
            left: Some(-50_000),
            right: Some(50_000),
            home: Some(10_000),
        },
        ..BusOptions::default()
    });
    sim.sap(255, 1);
    sim.sap(4, vmax);
    sim.sap(5, accel);
    sim
}

#[test]
fn a_move_lasts_as_long_as_the_trapezoid_from_speed_and_acceleration() {
    let (v, a, d) = (8000.0, 16_000.0, 40_000.0);
    let mut sim = module(v as i32, a as i32);
    sim.ok(4, 0, 0, d as i32);
    // Worked out independently: accelerate v/a, cruise (d - v²/a)/v, decelerate v/a.
    let ramp = v / a;
    let total = 2.0 * ramp + (d - v * v / a) / v;
    sim.at(ramp / 2.0);
    assert_eq!(
        sim.gap(1),
        (0.5 * a * (ramp / 2.0) * (ramp / 2.0)).round() as i32
    );
    assert_eq!(sim.gap(130), 0, "still accelerating");
    sim.at(ramp + 0.1);
    assert_eq!(sim.gap(3), v as i32);
    assert_eq!(sim.gap(130), 1, "cruising");
    sim.at(total - 0.01);
    assert_eq!(sim.gap(8), 0);
    assert!(sim.gap(1) < d as i32);
    sim.at(total);
    assert_eq!(sim.gap(8), 1);
    assert_eq!(sim.gap(1), d as i32);
    assert_eq!(sim.gap(3), 0);
    assert_eq!(
        sim.gap(129) & 0b111,
        0b111,
        "reached, velocity reached, standing"
    );
}

#[test]
fn a_short_move_never_reaches_full_speed() {
    let mut sim = module(100_000, 1000);
    sim.ok(4, 0, 0, 4000);
    // Triangle: peak sqrt(a·d) = 2000 pps after 2 s, arrival after 4 s.
    sim.at(2.0);
    assert_eq!(sim.gap(3), 2000);
    sim.at(4.0);
    assert_eq!(sim.gap(8), 1);
}

#[test]
fn rotation_ramps_with_the_acceleration() {
    let mut sim = module(0, 500);
    sim.ok(2, 0, 0, 1000); // ROL 1000 pps
    sim.at(1.0);
    assert_eq!(sim.gap(3), -500);
    assert_eq!(sim.gap(1), -250);
    sim.at(3.0);
    assert_eq!(sim.gap(3), -1000);
    assert_eq!(sim.gap(1), -1000 - 1000);
    assert_eq!(sim.gap(130), 1);
    sim.ok(3, 0, 0, 0);
    sim.at(5.0);
    assert_eq!(sim.gap(3), 0);
    assert_eq!(sim.gap(1), -3000);
}

#[test]
fn internal_units_convert_with_the_profile_constants() {
    let mut sim = Sim::new();
    // 2^20 internal units = 15625 pps (profile: 15625 / 2^20 pps per unit); acceleration 1:1.
    sim.sap(5, 15625);
    sim.ok(1, 0, 0, 1 << 20);
    sim.at(1.0);
    assert_eq!(sim.gap(3), 1 << 20);
    assert_eq!(sim.gap(1), 7813, "7812.5 rounds up");
}

#[test]
fn limit_switches_stop_the_motor_unless_disabled() {
    let mut sim = module(100_000, 1_000_000);
    sim.ok(1, 0, 0, 10_000);
    sim.at(10.0);
    assert_eq!(sim.gap(1), 50_000);
    assert_eq!(sim.gap(10), 1, "right switch active");
    assert_eq!(sim.gap(11), 0);
    assert_eq!(sim.gap(3), 0);
    // Disabled: the motor runs on through the switch.
    sim.sap(12, 1);
    sim.ok(1, 0, 0, 10_000);
    sim.at(11.0);
    assert!(sim.gap(1) > 55_000);
    sim.sap(12, 0);
    // Enabling it while inside the switch stops the motor now, not in the past.
    let here = sim.gap(1);
    sim.wait(0.001);
    assert!(sim.gap(1) >= here);
    sim.wait(1.0);
    assert_eq!(sim.gap(3), 0);
}

#[test]
fn a_switch_moved_at_run_time_acts_from_then_on() {
    let mut sim = module(100_000, 1_000_000);
    sim.ok(2, 0, 0, 1000);
    sim.at(5.0);
    let now = sim.now;
    sim.bus
        .set_switch(now, 1, 0, Switch::Left, Some(-4000))
        .unwrap();
    // The motor is at about -4990 already, inside the moved switch: it stops at once.
    sim.wait(1.0);
    assert_eq!(sim.gap(3), 0);
    assert!(sim.gap(1) < -4000);
    assert_eq!(sim.gap(11), 1);
}

#[test]
fn reference_search_modes_zero_the_position_at_their_switch() {
    for (mode, distance) in [(1, 0), (2, 100_000), (3, 40_000)] {
        let mut sim = module(100_000, 1_000_000);
        sim.sap(193, mode);
        sim.sap(194, 20_000);
        sim.sap(195, 1000);
        sim.ok(13, 0, 0, 0);
        assert_ne!(sim.ok(13, 2, 0, 0), 0, "mode {mode}: running");
        sim.at(60.0);
        assert_eq!(sim.ok(13, 2, 0, 0), 0, "mode {mode}: finished");
        assert_eq!(sim.gap(1), 0, "mode {mode}");
        assert_eq!(sim.gap(8), 1, "mode {mode}: at target 0");
        assert_eq!(sim.gap(196), distance, "mode {mode}");
        let home_or_left = if mode == 3 { 9 } else { 11 };
        assert_eq!(sim.gap(home_or_left), 1, "mode {mode}: on the switch edge");
    }
}

#[test]
fn rfs_stop_brakes_the_search() {
    let mut sim = module(100_000, 10_000);
    sim.bus
        .set_switch(sim.now, 1, 0, Switch::Left, None)
        .unwrap();
    sim.sap(194, 5000);
    sim.ok(13, 0, 0, 0);
    sim.at(2.0);
    sim.ok(13, 1, 0, 0);
    assert_eq!(sim.ok(13, 2, 0, 0), 0);
    sim.at(3.0);
    assert_eq!(sim.gap(3), 0);
}

#[test]
fn the_encoder_follows_the_motor() {
    let mut sim = module(10_000, 100_000);
    sim.ok(4, 0, 0, 12_345);
    sim.at(0.5);
    assert_eq!(sim.gap(41), sim.gap(1));
    sim.at(10.0);
    assert_eq!(sim.gap(41), 12_345);
    assert_eq!(sim.gap(38), 0);
    sim.sap(42, 2 * 65536);
    assert_eq!(sim.gap(41), 24_690);
    assert_eq!(sim.gap(38), 12_345);
}

#[test]
fn sap_writes_that_move() {
    let mut sim = module(10_000, 100_000);
    sim.sap(0, 5000); // SAP 0 starts a move like MVP ABS
    sim.at(5.0);
    assert_eq!(sim.gap(1), 5000);
    sim.sap(1, -20); // SAP 1 redefines the position without moving
    assert_eq!(sim.gap(1), -20);
    assert_eq!(sim.gap(3), 0);
    sim.sap(2, -3000); // SAP 2: velocity mode
    sim.at(6.0);
    assert_eq!(sim.gap(3), -3000);
    sim.sap(5, 1000); // a new acceleration applies to the ramp in progress
    sim.ok(3, 0, 0, 0);
    sim.at(7.0);
    assert_eq!(sim.gap(3), -2000);
}

#[test]
fn a_new_maximum_speed_changes_a_move_in_progress() {
    let mut sim = module(1000, 1_000_000);
    sim.ok(4, 0, 0, 100_000);
    sim.at(1.0);
    sim.sap(4, 5000);
    sim.at(2.0);
    assert_eq!(sim.gap(3), 5000);
}
