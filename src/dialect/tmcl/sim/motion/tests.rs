use super::*;

const BOTH: Limits = Limits {
    left: true,
    right: true,
};

/// Handles every event up to `t`, returning what happened.
fn run(axis: &mut Axis, t: f64, limits: Limits) -> Vec<Happened> {
    let mut seen = Vec::new();
    while let Some(h) = axis.handle_event(t, limits) {
        seen.push(h);
        assert!(seen.len() < 100, "runaway events: {seen:?}");
    }
    seen
}

fn switches(left: i64, right: i64, home: i64) -> Switches {
    Switches {
        left: Some(left),
        right: Some(right),
        home: Some(home),
    }
}

#[test]
fn a_limit_switch_stops_the_motor_at_its_position() {
    let mut axis = Axis::new(switches(-1000, 5000, 0));
    axis.rotate(0.0, -1000.0, 1000.0);
    // -500 t² up to 1 s, then -1000 pps: reaches -1000 at 1.5 s.
    assert_eq!(axis.next_event(BOTH), Some(1.5));
    assert_eq!(run(&mut axis, 10.0, BOTH), [Happened::LimitStop]);
    assert_eq!(axis.counter(10.0), -1000);
    assert_eq!(axis.state(10.0).v, 0.0);
    assert!(axis.switch_active(10.0, Switch::Left));
    // Driving further in is refused at once; driving out works.
    axis.rotate(10.0, -100.0, 1000.0);
    assert_eq!(run(&mut axis, 10.0, BOTH), [Happened::LimitStop]);
    axis.rotate(10.0, 100.0, 1000.0);
    assert!(run(&mut axis, 20.0, BOTH).is_empty());
    assert!(axis.counter(20.0) > -1000);
}

#[test]
fn a_disabled_limit_switch_does_not_stop_the_motor() {
    let mut axis = Axis::new(switches(-1000, 5000, 0));
    axis.rotate(0.0, -1000.0, 1000.0);
    let left_disabled = Limits {
        left: false,
        right: true,
    };
    assert!(run(&mut axis, 10.0, left_disabled).is_empty());
    assert_eq!(axis.counter(10.0), -500 - 9000);
}

#[test]
fn a_move_into_a_switch_stops_short_of_its_target() {
    let mut axis = Axis::new(switches(-1000, 5000, 0));
    axis.move_to(0.0, 10_000, 2000.0, 4000.0);
    assert_eq!(run(&mut axis, 100.0, BOTH), [Happened::LimitStop]);
    assert_eq!(axis.counter(100.0), 5000);
    assert!(!axis.is_positioning());
}

#[test]
fn a_move_arrives_once() {
    let mut axis = Axis::new(Switches::default());
    axis.move_to(0.0, 3000, 1000.0, 1000.0);
    let arrival = axis.arrival().unwrap();
    assert!((arrival - 4.0).abs() < 1e-9, "{arrival}");
    assert!(run(&mut axis, 3.9, BOTH).is_empty());
    assert_eq!(run(&mut axis, 4.0, BOTH), [Happened::Arrived]);
    assert!(run(&mut axis, 100.0, BOTH).is_empty());
    assert_eq!(axis.counter(100.0), 3000);
}

#[test]
fn redefining_the_counter_keeps_the_motor_where_it_is() {
    let mut axis = Axis::new(switches(-1000, 5000, 0));
    axis.set_counter(0.0, 70_000);
    assert_eq!(axis.counter(0.0), 70_000);
    // The switches stay where they physically are.
    axis.move_to(0.0, 60_000, 1000.0, 1000.0);
    assert_eq!(run(&mut axis, 100.0, BOTH), [Happened::LimitStop]);
    assert_eq!(axis.counter(100.0), 69_000);
}

#[test]
fn the_counter_wraps_and_moves_take_the_shorter_way() {
    let mut axis = Axis::new(Switches::default());
    axis.set_counter(0.0, i32::MAX - 10);
    axis.move_to(0.0, i32::MIN + 10, 1000.0, 1000.0);
    run(&mut axis, 100.0, BOTH);
    assert_eq!(axis.counter(100.0), i32::MIN + 10);
    assert_eq!(
        axis.state(100.0).x,
        21.0,
        "21 steps right, not 2^32 - 21 left"
    );
}

#[test]
fn reference_search_mode_1_zeroes_at_the_left_switch() {
    let mut axis = Axis::new(switches(-3000, 8000, 2000));
    axis.set_counter(0.0, 12345);
    axis.start_search(0.0, 1, 2000.0, 100.0, 10_000.0);
    assert_eq!(axis.search_status(), 1);
    let seen = run(&mut axis, 1000.0, BOTH);
    assert_eq!(seen.last(), Some(&Happened::SearchDone), "{seen:?}");
    assert_eq!(axis.search_status(), 0);
    assert_eq!(axis.counter(1000.0), 0);
    assert_eq!(axis.state(1000.0).x, -3000.0);
}

#[test]
fn reference_search_mode_2_measures_the_distance_between_the_end_switches() {
    let mut axis = Axis::new(switches(-3000, 8000, 2000));
    axis.start_search(0.0, 2, 4000.0, 200.0, 20_000.0);
    let mut legs_seen = vec![axis.search_status()];
    let mut t = 0.0;
    while axis.search_status() != 0 {
        t += 0.01;
        run(&mut axis, t, BOTH);
        if legs_seen.last() != Some(&axis.search_status()) {
            legs_seen.push(axis.search_status());
        }
        assert!(t < 100.0, "search never ends");
    }
    assert_eq!(legs_seen, [1, 2, 3, 0]);
    assert_eq!(axis.end_distance(), 11_000);
    assert_eq!(axis.state(t).x, -3000.0);
    assert_eq!(axis.counter(t), 0);
}

#[test]
fn reference_search_mode_3_zeroes_at_the_home_switch() {
    let mut axis = Axis::new(switches(-3000, 8000, 2000));
    axis.start_search(0.0, 3, 4000.0, 200.0, 20_000.0);
    let seen = run(&mut axis, 100.0, BOTH);
    assert_eq!(seen.last(), Some(&Happened::SearchDone));
    assert_eq!(axis.state(100.0).x, 2000.0);
    assert_eq!(axis.counter(100.0), 0);
    assert_eq!(axis.end_distance(), 6000);
    assert!(axis.switch_active(100.0, Switch::Home));
}

#[test]
fn a_search_without_its_switch_runs_until_stopped() {
    let mut axis = Axis::new(Switches::default());
    axis.start_search(0.0, 1, 1000.0, 100.0, 1000.0);
    assert!(run(&mut axis, 50.0, BOTH).is_empty());
    assert_eq!(axis.search_status(), 1);
    axis.stop_search(50.0);
    assert_eq!(axis.search_status(), 0);
    run(&mut axis, 100.0, BOTH);
    assert_eq!(axis.state(100.0).v, 0.0);
}

#[test]
fn the_encoder_follows_the_counter_scaled_by_its_constant() {
    assert_eq!(encoder_position(1000, 65536, 0, 1.0), 1000);
    assert_eq!(encoder_position(1000, 2 * 65536, 0, 1.0), 2000);
    assert_eq!(encoder_position(1000, 65536, 0, 4.0), 250);
    // Decimal mode: 1.5 = integer 1, fraction 5000/10000.
    assert_eq!(encoder_position(1000, (1 << 16) | 5000, 1 << 13, 1.0), 1500);
}
