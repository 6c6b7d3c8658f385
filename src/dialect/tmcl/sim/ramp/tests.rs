use super::*;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

#[test]
fn a_trapezoid_takes_the_time_its_speed_and_acceleration_give() {
    // 20000 steps at 10000 pps and 20000 pps²: 0.5 s up, 1.5 s cruise, 0.5 s down.
    let (d, v, a) = (20_000.0, 10_000.0, 20_000.0);
    let plan = Plan::position(0.0, 0.0, 0.0, d, v, a);
    let expected = d / v + v / a;
    assert!(close(plan.settles_at(), expected), "{}", plan.settles_at());
    assert!(close(plan.at(0.25).x, 0.5 * a * 0.25 * 0.25));
    assert!(close(plan.at(1.5).x, v * v / (2.0 * a) + v * 1.0));
    assert_eq!(plan.at(expected).x, d, "the end is exact");
    assert_eq!(plan.at(expected + 10.0).x, d);
    assert!(plan.at(expected - 0.01).x < d);
}

#[test]
fn a_short_move_is_a_triangle() {
    let plan = Plan::position(10.0, 0.0, 0.0, -1000.0, 10_000.0, 1000.0);
    // Peak speed sqrt(a·d) = 1000 pps, reached after 1 s; 2 s in all.
    assert!(close(plan.settles_at(), 12.0));
    let mid = plan.at(11.0);
    assert!(close(mid.x, -500.0) && close(mid.v, -1000.0));
    assert_eq!(plan.at(12.0).x, -1000.0);
}

#[test]
fn velocity_ramps_then_turns_at_constant_speed() {
    let plan = Plan::velocity(0.0, 100.0, 0.0, 5000.0, 1000.0);
    assert!(close(plan.settles_at(), 5.0));
    let end = plan.at(5.0);
    assert!(close(end.x, 100.0 + 12_500.0) && close(end.v, 5000.0));
    let later = plan.at(6.0);
    assert!(close(later.x, 100.0 + 17_500.0) && later.a == 0.0);
    assert!(plan.at(2.0).a > 0.0);
}

#[test]
fn a_motor_moving_away_brakes_and_comes_back() {
    // Moving right at 1000 pps, target at 0 behind: brake 1 s (500 steps), then 500 back.
    let plan = Plan::position(0.0, 0.0, 1000.0, 0.0, 1000.0, 1000.0);
    assert!(close(plan.at(1.0).x, 500.0));
    let back = 2.0 * (500.0f64 / 1000.0).sqrt();
    assert!(close(plan.settles_at(), 1.0 + back));
    assert_eq!(plan.at(100.0).x, 0.0);
}

#[test]
fn a_motor_too_fast_to_stop_in_time_overshoots_and_returns() {
    let plan = Plan::position(0.0, 0.0, 2000.0, 100.0, 2000.0, 1000.0);
    assert!(plan.at(2.0).x > 100.0);
    assert_eq!(plan.at(1000.0).x, 100.0);
}

#[test]
fn a_faster_motor_slows_down_to_the_new_maximum() {
    let plan = Plan::position(0.0, 0.0, 3000.0, 1_000_000.0, 1000.0, 1000.0);
    assert!(close(plan.at(2.0).v, 1000.0));
    assert_eq!(plan.at(10_000.0).x, 1_000_000.0);
}

#[test]
fn no_speed_means_no_move() {
    let plan = Plan::position(0.0, 5.0, 0.0, 1000.0, 0.0, 1000.0);
    assert_eq!(plan.at(100.0).x, 5.0);
}

#[test]
fn a_switch_is_reached_when_the_motor_drives_into_it() {
    // x(t) = -500 t² for t < 1, then -500 - 1000 (t - 1).
    let plan = Plan::velocity(0.0, 0.0, 0.0, -1000.0, 1000.0);
    assert!(close(plan.reaches(0.0, -2000.0, -1.0).unwrap(), 2.5));
    assert!(close(plan.reaches(0.0, -125.0, -1.0).unwrap(), 0.5));
    assert_eq!(plan.reaches(0.0, 10.0, 1.0), None, "never moves right");
    // Already beyond the level and moving on: at once.
    assert_eq!(plan.reaches(3.0, -10.0, -1.0), Some(3.0));
}

#[test]
fn standing_on_a_switch_blocks_only_the_way_into_it() {
    let into = Plan::velocity(0.0, -2000.0, 0.0, -1000.0, 1000.0);
    assert_eq!(into.reaches(0.0, -2000.0, -1.0), Some(0.0));
    let away = Plan::velocity(0.0, -2000.0, 0.0, 1000.0, 1000.0);
    assert_eq!(away.reaches(0.0, -2000.0, -1.0), None);
    let still = Plan::hold(0.0, -2000.0);
    assert_eq!(still.reaches(0.0, -2000.0, -1.0), None);
}
