//! The motion model through the Device API: ramps, cruise, stops, zero wait, limits, homing.
//! Expected values are computed here from the kinematics, independently of the simulator.

use super::Bench;
use crate::dialect::smd4::protocol::Sflags;
use crate::dialect::smd4::sim::Limit;

/// Position and velocity read back over the protocol.
fn state(b: &mut Bench, t: f64) -> (f64, f64) {
    b.at(t);
    (b.number("MOTOR:PACT"), b.number("MOTOR:VACT"))
}

fn close(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 0.01 + want.abs() * 1e-4,
        "{what}: got {got}, want {want}"
    );
}

fn profile(b: &mut Bench, vstart: f64, vstop: f64, vmax: f64, amax: f64, dmax: f64) {
    for line in [
        format!("MOTOR:VSTOP,{vstop}"),
        format!("MOTOR:VSTART,{vstart}"),
        format!("MOTOR:VMAX,{vmax}"),
        format!("MOTOR:AMAX,{amax}"),
        format!("MOTOR:DMAX,{dmax}"),
    ] {
        assert!(b.reply(&line).is_ok(), "{line}");
    }
}

#[test]
fn trapezoid_move_follows_the_profile() {
    let mut b = Bench::new();
    let (vs, ve, vm, a, d) = (100.0, 200.0, 1000.0, 1000.0, 500.0);
    profile(&mut b, vs, ve, vm, a, d);
    let (t0, target) = (1.0, 10_000.0);
    b.at(t0);
    b.send("MOTOR:RUNA,10000");
    let (t_up, d_up) = ((vm - vs) / a, (vm * vm - vs * vs) / (2.0 * a));
    let (t_down, d_down) = ((vm - ve) / d, (vm * vm - ve * ve) / (2.0 * d));
    let t_cruise = (target - d_up - d_down) / vm;
    let end = t0 + t_up + t_cruise + t_down;

    let (p, v) = state(&mut b, t0 + 0.5);
    close(v, vs + a * 0.5, "velocity while accelerating");
    close(p, vs * 0.5 + 0.5 * a * 0.25, "position while accelerating");
    let flags = b.sim.sflags(b.now);
    assert!(!flags.standby() && !flags.is_set(Sflags::AT_TARGET_VELOCITY));

    let (p, v) = state(&mut b, t0 + 4.0);
    close(v, vm, "cruise velocity");
    close(p, d_up + vm * (4.0 - t_up), "cruise position");
    assert!(b.reply("SYS:FW").sflags.is_set(Sflags::AT_TARGET_VELOCITY));

    let into = 0.8;
    let (p, v) = state(&mut b, t0 + t_up + t_cruise + into);
    close(v, vm - d * into, "velocity while decelerating");
    close(
        p,
        d_up + vm * t_cruise + vm * into - 0.5 * d * into * into,
        "position while decelerating",
    );
    assert!(!b.sim.sflags(b.now).is_set(Sflags::AT_TARGET_VELOCITY));

    b.at(end - 0.01);
    assert!(!b.standby());
    let (p, v) = state(&mut b, end + 0.01);
    assert_eq!((p, v), (target, 0.0));
    assert!(b.standby());
}

#[test]
fn short_moves_are_triangles_that_never_reach_vmax() {
    let mut b = Bench::new();
    let (vs, a) = (100.0, 1000.0);
    profile(&mut b, vs, vs, 1000.0, a, a);
    b.send("MOTOR:RUNR,200");
    // Equal ramps: each covers half the distance; peak² = vs² + 2·a·(d/2).
    let peak = (vs * vs + a * 200.0).sqrt();
    let t_up = (peak - vs) / a;
    let (_, v) = state(&mut b, t_up);
    close(v, peak, "peak velocity");
    assert!(!b.sim.sflags(b.now).is_set(Sflags::AT_TARGET_VELOCITY));
    b.at(2.0 * t_up - 0.005);
    assert!(!b.standby());
    let (p, _) = state(&mut b, 2.0 * t_up + 0.005);
    assert_eq!(p, 200.0);
    assert!(b.standby());
}

#[test]
fn velocity_mode_then_stop_and_soft_stop() {
    let mut b = Bench::new();
    let (vs, ve, vm, a, d) = (100.0, 300.0, 2000.0, 4000.0, 1000.0);
    profile(&mut b, vs, ve, vm, a, d);
    b.send("MOTOR:RUNV,-");
    let t_up = (vm - vs) / a;
    let d_up = (vm * vm - vs * vs) / (2.0 * a);
    let (p, v) = state(&mut b, 2.0);
    close(v, -vm, "negative cruise");
    close(p, -(d_up + vm * (2.0 - t_up)), "position decreases");
    assert!(b.reply("MOTOR:STOP").is_ok());
    let (t_down, d_down) = ((vm - ve) / d, (vm * vm - ve * ve) / (2.0 * d));
    let (_, v) = state(&mut b, 2.0 + t_down / 2.0);
    close(v, -(vm - d * t_down / 2.0), "STOP ramps down at DMAX");
    let (p, v) = state(&mut b, 2.0 + t_down + 0.01);
    assert_eq!(v, 0.0);
    close(
        p,
        -(d_up + vm * (2.0 - t_up) + d_down),
        "stopped after the ramp",
    );

    // SSTOP: from cruise to standstill in one second, linearly: half the cruise speed × 1 s.
    b.send("MOTOR:RUNV,+");
    let from = b.now.as_secs_f64();
    let (p0, _) = state(&mut b, from + 3.0);
    b.send("MOTOR:SSTOP");
    let (_, v) = state(&mut b, from + 3.5);
    close(v, vm / 2.0, "SSTOP halfway");
    let (p, v) = state(&mut b, from + 4.01);
    assert_eq!(v, 0.0);
    close(p, p0 + vm * 0.5, "SSTOP distance");
}

#[test]
fn zero_wait_time_delays_the_next_move() {
    let mut b = Bench::new();
    let (vs, a) = (100.0, 1000.0);
    profile(&mut b, vs, vs, 1000.0, a, a);
    b.send("MOTOR:TZW,0.5");
    b.send("MOTOR:RUNR,100");
    // A triangle: peak² = vs² + 2·a·50; up and down take equally long.
    let end = 2.0 * ((vs * vs + a * 100.0).sqrt() - vs) / a;
    b.at(end + 0.1);
    assert!(b.standby());
    b.send("MOTOR:RUNR,100");
    let (p, v) = state(&mut b, end + 0.4);
    assert_eq!((p, v), (100.0, 0.0), "waiting out TZW after the stop");
    assert!(!b.standby(), "a pending move clears standby");
    let (p, v) = state(&mut b, end + 0.6);
    assert!(p > 100.0 && v > 0.0, "moving again after TZW: {p} {v}");
    let (p, _) = state(&mut b, end + 0.5 + end + 0.01);
    assert_eq!(p, 200.0);
}

#[test]
fn reversing_ramps_down_first() {
    let mut b = Bench::new();
    let (vs, vm, a) = (100.0, 1000.0, 1000.0);
    profile(&mut b, vs, vs, vm, a, a);
    b.send("MOTOR:RUNV,+");
    b.at(2.0);
    b.send("MOTOR:RUNA,-5000");
    let t_down = (vm - vs) / a;
    let (_, v) = state(&mut b, 2.0 + t_down / 2.0);
    assert!(v > 0.0, "still going forward while ramping down");
    let (_, v) = state(&mut b, 2.0 + t_down + 0.1);
    assert!(v < 0.0, "then backwards");
    let d_up = (vm * vm - vs * vs) / (2.0 * a);
    let far = 2.0 + t_down + 20.0;
    let (p, _) = state(&mut b, far);
    assert_eq!(p, -5000.0);
    assert!(d_up > 0.0);
}

#[test]
fn acceleration_change_cancels_a_stop_but_vmax_does_not() {
    let mut b = Bench::new();
    profile(&mut b, 100.0, 100.0, 1000.0, 1000.0, 100.0);
    b.send("MOTOR:RUNV,+");
    b.at(2.0);
    b.send("MOTOR:STOP");
    b.at(3.0);
    b.send("MOTOR:VMAX,1500");
    let (_, v) = state(&mut b, 4.0);
    close(
        v,
        1000.0 - 100.0 * 2.0,
        "VMAX change leaves the stop running",
    );
    b.send("MOTOR:AMAX,500");
    let (_, v) = state(&mut b, 5.0);
    close(v, 800.0 + 500.0, "AMAX change resumes the run towards VMAX");
    let (_, v) = state(&mut b, 10.0);
    close(v, 1500.0, "back at the target velocity");
    assert!(b.reply("SYS:FW").sflags.is_set(Sflags::AT_TARGET_VELOCITY));
}

#[test]
fn enabled_limits_stop_motion_hard_or_soft() {
    let mut b = Bench::new();
    profile(&mut b, 100.0, 100.0, 1000.0, 1000.0, 500.0);
    // Globally disabled (the default): an active input shows in SFLAGS but stops nothing.
    b.send("MOTOR:RUNV,+");
    b.at(2.0);
    b.sim.set_limit_input(b.now, Limit::Positive, true);
    assert!(b.reply("SYS:FW").sflags.is_set(Sflags::LIMIT_POSITIVE));
    assert!(!b.standby());
    // Enabled with hard stop: the motor stops where it is.
    b.send("LIMIT:EN,1");
    assert!(b.standby());
    let (p, _) = state(&mut b, 2.0);
    let (p_later, _) = state(&mut b, 3.0);
    assert_eq!(p, p_later);
    // Motion towards the active limit stops at once; away from it runs.
    b.send("MOTOR:RUNV,+");
    assert!(b.standby());
    b.send("MOTOR:RUNV,-");
    b.at(4.0);
    assert!(!b.standby());
    b.send("MOTOR:STOP");
    b.at(8.0);
    // Per-side enable, and soft stop: ramps down at DMAX.
    b.sim.set_limit_input(b.now, Limit::Positive, false);
    b.send("LIMIT:EN+,0");
    b.send("LIMIT:STOPMODE,1");
    b.send("MOTOR:RUNV,+");
    b.at(10.0);
    b.sim.set_limit_input(b.now, Limit::Positive, true);
    assert!(!b.standby(), "positive limit disabled");
    b.send("LIMIT:EN+,1");
    let (_, v) = state(&mut b, 10.5);
    close(v, 1000.0 - 500.0 * 0.5, "soft stop decelerates at DMAX");
    b.at(12.0);
    assert!(b.standby());
}

#[test]
fn homing_runs_to_the_limit_and_prel_counts_along() {
    let mut b = Bench::new();
    b.send("MOTOR:PREL,0");
    b.send("MOTOR:PACT,1000");
    b.send("MOTOR:RUNR,500");
    b.at(10.0);
    assert_eq!(b.data("MOTOR:PACT"), ["1500.00"]);
    assert_eq!(b.data("MOTOR:PREL"), ["500.00"], "PREL kept its own origin");
    // Homing uses the limit input whatever LIMIT:EN says.
    assert!(b.reply("MOTOR:RUNH,-").is_ok());
    b.at(12.0);
    assert!(!b.standby());
    b.sim.set_limit_input(b.now, Limit::Negative, true);
    assert!(b.standby(), "stopped on the home switch");
    let (p, _) = state(&mut b, 12.0);
    assert!(p < 1500.0);
    b.send("MOTOR:RUNH,-");
    assert!(b.standby(), "already home");
}
