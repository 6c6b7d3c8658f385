//! Motion plans as pieces of constant acceleration, computed analytically from the start state,
//! so a position at any time is exact and independent of how often it is looked at.
//!
//! Units: seconds, microsteps, microsteps per second (pps) and pps per second. A plan's last
//! phase has no acceleration and lasts forever (standing still, or turning at constant speed).

use crate::sim::ramp::trapezoid;

/// A stretch of constant acceleration starting at `start` (seconds since power-up).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Phase {
    /// When the phase begins.
    pub start: f64,
    /// When it ends (`f64::INFINITY` for the last phase).
    pub end: f64,
    /// Position at `start`.
    pub x: f64,
    /// Velocity at `start`.
    pub v: f64,
    /// Constant acceleration.
    pub a: f64,
}

impl Phase {
    fn at(&self, t: f64) -> (f64, f64) {
        let dt = (t.min(self.end) - self.start).max(0.0);
        (
            self.x + self.v * dt + 0.5 * self.a * dt * dt,
            self.v + self.a * dt,
        )
    }
}

const MAX_PHASES: usize = 6;

/// A motion plan: consecutive phases, the last one unbounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Plan {
    phases: [Phase; MAX_PHASES],
    len: usize,
}

/// The kinematic state at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct State {
    /// Position.
    pub x: f64,
    /// Velocity.
    pub v: f64,
    /// Acceleration of the phase the instant belongs to.
    pub a: f64,
}

/// Builds a plan phase by phase from a start state.
struct Builder {
    plan: Plan,
    t: f64,
    x: f64,
    v: f64,
}

impl Builder {
    fn new(t: f64, x: f64, v: f64) -> Self {
        let idle = Phase {
            start: t,
            end: f64::INFINITY,
            x,
            v,
            a: 0.0,
        };
        Builder {
            plan: Plan {
                phases: [idle; MAX_PHASES],
                len: 0,
            },
            t,
            x,
            v,
        }
    }

    /// Accelerates with `a` for `duration` seconds (skipped when empty).
    fn push(&mut self, a: f64, duration: f64) {
        if duration <= 0.0 || !duration.is_finite() {
            return;
        }
        let phase = Phase {
            start: self.t,
            end: self.t + duration,
            x: self.x,
            v: self.v,
            a,
        };
        (self.x, self.v) = phase.at(phase.end);
        self.t = phase.end;
        self.plan.phases[self.plan.len] = phase;
        self.plan.len += 1;
    }

    /// Ends with an unbounded phase at constant velocity `v` from position `x`.
    fn finish(mut self, x: f64, v: f64) -> Plan {
        self.plan.phases[self.plan.len] = Phase {
            start: self.t,
            end: f64::INFINITY,
            x,
            v,
            a: 0.0,
        };
        self.plan.len += 1;
        self.plan
    }
}

impl Plan {
    /// Standing still at `x` from `t` on.
    pub(super) fn hold(t: f64, x: f64) -> Plan {
        Builder::new(t, x, 0.0).finish(x, 0.0)
    }

    /// Ramps from velocity `v0` to `target` with acceleration magnitude `accel`, then turns at
    /// `target` forever (velocity mode, and stopping when `target` is 0).
    pub(super) fn velocity(t: f64, x: f64, v0: f64, target: f64, accel: f64) -> Plan {
        let mut b = Builder::new(t, x, v0);
        let dv = target - v0;
        if accel.is_finite() && accel > 0.0 {
            b.push(accel * dv.signum(), dv.abs() / accel);
        }
        let x_end = b.x;
        b.finish(x_end, target)
    }

    /// Moves from (`x0`, `v0`) to rest at `target` with at most `vmax` and `accel`: the shared
    /// trapezoid, or a triangle when the distance is too short to reach `vmax`. A motor moving
    /// away from the target, or too fast to stop in time, first brakes to a stop. Without speed
    /// the motor only brakes and then stays where it is.
    pub(super) fn position(t: f64, x0: f64, v0: f64, target: f64, vmax: f64, accel: f64) -> Plan {
        let accel = if accel.is_finite() && accel > 0.0 {
            accel
        } else {
            f64::MAX
        };
        let mut b = Builder::new(t, x0, v0);
        let stopping = v0 * v0 / (2.0 * accel);
        let d = target - x0;
        if v0 != 0.0 && (v0.signum() != d.signum() || stopping > d.abs()) {
            b.push(-accel * v0.signum(), v0.abs() / accel);
            b.v = 0.0;
        }
        if vmax <= 0.0 {
            let x = b.x;
            return b.finish(x, 0.0);
        }
        let s = (target - b.x).signum();
        let ramp = trapezoid((target - b.x).abs(), b.v.abs(), 0.0, vmax, accel, accel);
        b.push(s * ramp.change, ramp.change_time);
        b.push(0.0, ramp.cruise_time);
        b.push(-s * accel, ramp.stop_time);
        b.finish(target, 0.0)
    }

    /// Every phase in order.
    pub(super) fn phases(&self) -> &[Phase] {
        &self.phases[..self.len]
    }

    /// When the plan's last (unbounded) phase begins: the end of the move or ramp.
    pub(super) fn settles_at(&self) -> f64 {
        self.phases()[self.len - 1].start
    }

    /// The state at `t` (times before the plan count as its start). A phase is over a
    /// nanosecond (the clock's resolution) before its computed end, so that an end time rounded
    /// to the clock finds the motor where the plan says it arrives.
    pub(super) fn at(&self, t: f64) -> State {
        let phase = self
            .phases()
            .iter()
            .find(|p| t < p.end - 1e-9)
            .unwrap_or(&self.phases[self.len - 1]);
        let (x, v) = phase.at(t);
        State { x, v, a: phase.a }
    }

    /// The earliest time at or after `from` at which the motor is at or beyond `level` in
    /// direction `dir` (+1 right, -1 left) while moving that way (or starting to). This is when
    /// a switch at `level` stops a motor driving into it.
    pub(super) fn reaches(&self, from: f64, level: f64, dir: f64) -> Option<f64> {
        self.phases()
            .iter()
            .filter(|p| p.end > from)
            .find_map(|p| entry_time(p, from.max(p.start), level, dir))
    }
}

/// Tolerances for comparisons after floating-point arithmetic.
const POS_EPS: f64 = 1e-7;
const VEL_EPS: f64 = 1e-9;

fn entry_time(p: &Phase, from: f64, level: f64, dir: f64) -> Option<f64> {
    // Mirror so that "beyond" is always "greater" and "moving into" is positive velocity.
    let (y, w, b, goal) = (dir * p.x, dir * p.v, dir * p.a, dir * level);
    let y_at = |tau: f64| y + w * tau + 0.5 * b * tau * tau;
    let w_at = |tau: f64| w + b * tau;
    let inside = |tau: f64| {
        let v = w_at(tau);
        y_at(tau) >= goal - POS_EPS && (v > VEL_EPS || (v.abs() <= VEL_EPS && b > 0.0))
    };
    let lo = from - p.start;
    let hi = p.end - p.start;
    let mut candidates = [lo, f64::NAN, f64::NAN, f64::NAN];
    if b != 0.0 {
        candidates[1] = -w / b;
    }
    let (r1, r2) = roots(0.5 * b, w, y - goal);
    candidates[2] = r1;
    candidates[3] = r2;
    candidates
        .iter()
        .copied()
        .filter(|tau| tau.is_finite() && *tau >= lo && *tau <= hi)
        .filter(|&tau| inside(tau))
        .fold(None, |best: Option<f64>, tau| {
            Some(best.map_or(tau, |b| b.min(tau)))
        })
        .map(|tau| p.start + tau)
}

/// Real roots of `a t² + b t + c` (NaN where there is none).
fn roots(a: f64, b: f64, c: f64) -> (f64, f64) {
    if a == 0.0 {
        return if b == 0.0 {
            (f64::NAN, f64::NAN)
        } else {
            (-c / b, f64::NAN)
        };
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return (f64::NAN, f64::NAN);
    }
    // Numerically stable form.
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return (0.0, f64::NAN);
    }
    (q / a, c / q)
}

#[cfg(test)]
mod tests;
