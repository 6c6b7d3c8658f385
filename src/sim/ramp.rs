//! The one ramp planner of the simulators: the trapezoid (or triangle) a motor moves a distance
//! by, from the speed it has to the speed it stops at, never faster than its top speed. Each
//! simulator lays the stretches it gives out as phases of its own motion model (TMCL brakes and
//! turns back when it cannot stop in time; an SMD4 starts at VSTART and waits out TZW first).

/// The stretches of a move at constant acceleration: speeding up (or slowing down) to `peak`,
/// cruising at it, slowing down to the end speed. Speeds are magnitudes, times seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trapezoid {
    /// The highest speed of the move.
    pub peak: f64,
    /// The acceleration from the start speed to `peak`: positive speeding up, negative slowing
    /// down (a start above the top speed).
    pub change: f64,
    /// How long that takes.
    pub change_time: f64,
    /// How long the move cruises at `peak`.
    pub cruise_time: f64,
    /// How long it slows down from `peak` to the end speed.
    pub stop_time: f64,
}

/// A move of `distance` (a magnitude) starting at speed `start`, ending at `end`, at most `top`,
/// speeding up at `accel` and slowing down at `decel`. The peak is where speeding up from
/// `start` and slowing down to `end` meet, if that is below `top`; a caller whose distance is
/// shorter than the ramps to `end` handles that itself (the peak is then below `end`).
pub fn trapezoid(
    distance: f64,
    start: f64,
    end: f64,
    top: f64,
    accel: f64,
    decel: f64,
) -> Trapezoid {
    let peak = if start > top {
        top
    } else {
        let squared = (distance + start * start / (2.0 * accel) + end * end / (2.0 * decel))
            / (1.0 / (2.0 * accel) + 1.0 / (2.0 * decel));
        squared.sqrt().min(top)
    };
    let rate = if peak >= start { accel } else { decel };
    let ramp_up = (peak * peak - start * start).abs() / (2.0 * rate);
    let ramp_down = (peak * peak - end * end) / (2.0 * decel);
    let cruise = (distance - ramp_up - ramp_down).max(0.0);
    Trapezoid {
        peak,
        change: (peak - start).signum() * rate,
        change_time: (peak - start).abs() / rate,
        cruise_time: if peak > 0.0 { cruise / peak } else { 0.0 },
        stop_time: (peak - end) / decel,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    #[test]
    fn a_long_move_cruises_and_a_short_one_is_a_triangle() {
        // 20000 steps at 10000 pps, 20000 pps² up, 10000 pps² down: 0.5 s up, 1 s down.
        let long = trapezoid(20_000.0, 0.0, 0.0, 10_000.0, 20_000.0, 10_000.0);
        assert_eq!(long.peak, 10_000.0);
        assert!(close(long.change_time, 0.5) && close(long.stop_time, 1.0));
        let cruise = 20_000.0 - 2_500.0 - 5_000.0;
        assert!(close(long.cruise_time, cruise / 10_000.0));
        let short = trapezoid(1000.0, 0.0, 0.0, 10_000.0, 1000.0, 1000.0);
        assert!(close(short.peak, 1000.0) && close(short.cruise_time, 0.0));
    }

    #[test]
    fn a_start_above_the_top_speed_slows_down_first_and_the_end_speed_is_kept() {
        let t = trapezoid(10_000.0, 2000.0, 100.0, 1000.0, 500.0, 250.0);
        assert_eq!((t.peak, t.change), (1000.0, -250.0));
        assert!(close(t.change_time, 4.0) && close(t.stop_time, 3.6));
        let nothing = trapezoid(0.0, 0.0, 0.0, 1000.0, 500.0, 500.0);
        assert_eq!((nothing.peak, nothing.cruise_time), (0.0, 0.0));
    }
}
