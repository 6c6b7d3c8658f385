//! The motion model of a simulated SMD4: trapezoid (or triangle) ramps from VSTART up to VMAX at
//! AMAX and down at DMAX to VSTOP, computed analytically from time — no ticks, so any query at
//! any time is exact. A motion is a list of phases of constant acceleration; the motor rests at
//! the end of the last one.

use crate::sim::ramp::trapezoid;

/// The ramp settings a plan uses (Hz, Hz/s, s): the drive's motion profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ramp {
    /// MOTOR:VSTART.
    pub vstart: f64,
    /// MOTOR:VSTOP.
    pub vstop: f64,
    /// MOTOR:VMAX.
    pub vmax: f64,
    /// MOTOR:AMAX.
    pub amax: f64,
    /// MOTOR:DMAX.
    pub dmax: f64,
    /// MOTOR:TZW: wait after a stop before the next move may start.
    pub tzw: f64,
}

/// A stretch of constant acceleration (seconds, steps, steps/s).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Phase {
    start: f64,
    duration: f64,
    p0: f64,
    v0: f64,
    accel: f64,
    at_target: bool,
}

impl Phase {
    fn end(&self) -> f64 {
        self.start + self.duration
    }

    fn at(&self, t: f64) -> (f64, f64) {
        let dt = (t - self.start).clamp(0.0, self.duration);
        (
            self.p0 + self.v0 * dt + 0.5 * self.accel * dt * dt,
            self.v0 + self.accel * dt,
        )
    }
}

/// What the motor is asked to do; kept so a plan can be recomputed when the profile changes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Goal {
    /// Nothing.
    Idle,
    /// Run at VMAX in direction +1/−1 until stopped.
    Velocity(f64),
    /// Go to this position.
    Position(f64),
    /// Ramp down and stop; remembers what the stop interrupted (a profile change resumes it).
    Stop(Option<Resumable>),
}

/// A goal a stop may give way to again.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Resumable {
    /// See [`Goal::Velocity`].
    Velocity(f64),
    /// See [`Goal::Position`].
    Position(f64),
}

/// The motor at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorState {
    /// Position in steps.
    pub position: f64,
    /// Velocity in steps/s, negative while the counter decreases.
    pub velocity: f64,
    /// No motion is running or pending.
    pub standby: bool,
    /// Cruising at VMAX.
    pub at_target_velocity: bool,
}

/// The motion of the motor over time.
#[derive(Debug, Clone)]
pub struct Motion {
    phases: Vec<Phase>,
    rest: f64,
    goal: Goal,
    /// Latest standstill known to lie before the last replan.
    stopped_at: f64,
    /// When the current plan brings the motor to a standstill.
    halts: Vec<f64>,
}

impl Motion {
    /// At rest at `position`; the last stop long ago.
    pub fn at_rest(position: f64) -> Motion {
        Motion {
            phases: Vec::new(),
            rest: position,
            goal: Goal::Idle,
            stopped_at: f64::NEG_INFINITY,
            halts: Vec::new(),
        }
    }

    /// The state at time `t`.
    pub fn at(&self, t: f64) -> MotorState {
        match self.phases.iter().find(|p| t < p.end()) {
            Some(phase) => {
                let (position, velocity) = phase.at(t);
                MotorState {
                    position,
                    velocity,
                    standby: false,
                    at_target_velocity: phase.at_target && t >= phase.start,
                }
            }
            None => MotorState {
                position: self.rest,
                velocity: 0.0,
                standby: true,
                at_target_velocity: false,
            },
        }
    }

    /// When the motor last came to a standstill, as seen at `t`.
    pub fn last_stop(&self, t: f64) -> f64 {
        self.halts
            .iter()
            .copied()
            .filter(|h| *h <= t)
            .fold(self.stopped_at, f64::max)
    }

    /// The goal being worked on at `t` (Idle once the motion has ended).
    pub fn goal(&self, t: f64) -> Goal {
        if self.at(t).standby {
            Goal::Idle
        } else {
            self.goal
        }
    }

    /// Direction of the motion running or pending at `t`: +1, −1, or 0 in standby.
    pub fn direction(&self, t: f64) -> f64 {
        self.phases
            .iter()
            .filter(|p| t < p.end())
            .map(|p| p.at(t.max(p.start)).1)
            .find(|v| *v != 0.0)
            .map_or(0.0, f64::signum)
    }

    /// Sets the position counter (only sensible in standby).
    pub fn set_position(&mut self, t: f64, position: f64) {
        if self.at(t).standby {
            self.stopped_at = self.last_stop(t);
            self.halts.clear();
            self.phases.clear();
            self.rest = position;
        }
    }

    /// Starts running towards `goal` from the state at `t`.
    pub fn plan(&mut self, t: f64, goal: Goal, profile: &Ramp) {
        let mut plan = self.plan_from(t);
        match goal {
            Goal::Idle => plan.halt(),
            Goal::Velocity(direction) => plan.velocity(direction, profile),
            Goal::Position(target) => plan.position(target, profile),
            Goal::Stop(_) => plan.ramp_down(profile.dmax, profile.vstop),
        }
        self.install(plan, goal);
    }

    /// MOTOR:SSTOP: decelerates linearly to standstill in `seconds`.
    pub fn stop_within(&mut self, t: f64, seconds: f64) {
        let mut plan = self.plan_from(t);
        plan.ramp_down(plan.v.abs() / seconds, 0.0);
        self.install(plan, Goal::Stop(None));
    }

    /// Stops at once where the motor is (ESTOP, hard limit stop, motor disabled).
    pub fn halt(&mut self, t: f64) {
        let mut plan = self.plan_from(t);
        plan.halt();
        self.install(plan, Goal::Idle);
    }

    /// The profile changed at `t`: a running move is replanned with it. A stop ramp is cancelled
    /// and the interrupted goal resumed only when `cancel_stop` (AMAX/DMAX changes, as documented).
    pub fn profile_changed(&mut self, t: f64, profile: &Ramp, cancel_stop: bool) {
        let goal = match self.goal(t) {
            Goal::Idle => return,
            Goal::Stop(Some(Resumable::Velocity(d))) if cancel_stop => Goal::Velocity(d),
            Goal::Stop(Some(Resumable::Position(p))) if cancel_stop => Goal::Position(p),
            Goal::Stop(_) => return,
            goal => goal,
        };
        self.plan(t, goal, profile);
    }

    /// The resumable form of the goal at `t`, for a stop to remember.
    pub fn resumable(&self, t: f64) -> Option<Resumable> {
        match self.goal(t) {
            Goal::Velocity(d) => Some(Resumable::Velocity(d)),
            Goal::Position(p) => Some(Resumable::Position(p)),
            Goal::Stop(resume) => resume,
            Goal::Idle => None,
        }
    }

    fn plan_from(&self, t: f64) -> Plan {
        let now = self.at(t);
        Plan {
            origin: t,
            t,
            p: now.position,
            v: now.velocity,
            stopped_at: self.last_stop(t),
            halts: Vec::new(),
            phases: Vec::new(),
        }
    }

    fn install(&mut self, plan: Plan, goal: Goal) {
        self.stopped_at = self.last_stop(plan.origin);
        self.phases = plan.phases;
        self.halts = plan.halts;
        self.rest = plan.p;
        self.goal = goal;
    }
}

/// Builds phases forward from a state.
struct Plan {
    origin: f64,
    t: f64,
    p: f64,
    v: f64,
    stopped_at: f64,
    halts: Vec<f64>,
    phases: Vec<Phase>,
}

impl Plan {
    /// Adds a phase of `duration` at `accel`, starting from the current state.
    fn push(&mut self, duration: f64, accel: f64, at_target: bool) {
        if duration <= 0.0 {
            return;
        }
        let phase = Phase {
            start: self.t,
            duration,
            p0: self.p,
            v0: self.v,
            accel,
            at_target,
        };
        if duration.is_finite() {
            (self.p, self.v) = phase.at(phase.end());
            self.t = phase.end();
        }
        self.phases.push(phase);
    }

    /// The motor stops dead here.
    fn halt(&mut self) {
        if self.v != 0.0 {
            self.v = 0.0;
            self.stopped_at = self.t;
            self.halts.push(self.t);
        }
    }

    /// Ramps down at `decel` to `floor`, then stops.
    fn ramp_down(&mut self, decel: f64, floor: f64) {
        let speed = self.v.abs();
        if speed > floor {
            self.push((speed - floor) / decel, -self.v.signum() * decel, false);
        }
        self.halt();
    }

    /// Waits out MOTOR:TZW after the last stop.
    fn zero_wait(&mut self, tzw: f64) {
        let ready = self.stopped_at + tzw;
        if ready > self.t {
            self.push(ready - self.t, 0.0, false);
        }
    }

    /// Speed a move starts at, and the direction it goes: from standstill VSTART (after TZW).
    fn start(&mut self, direction: f64, profile: &Ramp) -> f64 {
        if self.v != 0.0 && self.v.signum() != direction {
            self.ramp_down(profile.dmax, profile.vstop);
        }
        if self.v == 0.0 {
            self.zero_wait(profile.tzw);
            profile.vstart.min(profile.vmax).max(f64::MIN_POSITIVE)
        } else {
            self.v.abs()
        }
    }

    fn velocity(&mut self, direction: f64, profile: &Ramp) {
        let u0 = self.start(direction, profile);
        self.v = direction * u0;
        let rate = if u0 < profile.vmax {
            profile.amax
        } else {
            profile.dmax
        };
        self.push(
            (profile.vmax - u0).abs() / rate,
            direction * (profile.vmax - u0).signum() * rate,
            false,
        );
        self.push(f64::INFINITY, 0.0, true);
    }

    fn position(&mut self, target: f64, profile: &Ramp) {
        let distance = target - self.p;
        if distance == 0.0 && self.v == 0.0 {
            return;
        }
        let direction = if distance == 0.0 {
            -self.v.signum()
        } else {
            distance.signum()
        };
        let u0 = self.start(direction, profile);
        if self.p == target {
            return;
        }
        self.v = direction * u0;
        let d = (target - self.p).abs();
        let (a, b) = (profile.amax, profile.dmax);
        let ve = profile.vstop.min(profile.vmax);
        let stopping = if u0 > ve {
            (u0 * u0 - ve * ve) / (2.0 * b)
        } else {
            0.0
        };
        if stopping >= d {
            // Too close to stop at DMAX: decelerate harder (or keep speed) to land on the target.
            if u0 > ve {
                let rate = (u0 * u0 - ve * ve) / (2.0 * d);
                self.push((u0 - ve) / rate, -direction * rate, false);
            } else {
                self.push(d / u0, 0.0, false);
            }
            return self.arrive(target);
        }
        let ramp = trapezoid(d, u0, ve, profile.vmax, a, b);
        if ramp.peak < ve {
            // A move shorter than the ramp up to VSTOP: accelerate all the way, then stop.
            let v_end = (u0 * u0 + 2.0 * a * d).sqrt();
            self.push((v_end - u0) / a, direction * a, false);
            return self.arrive(target);
        }
        self.push(ramp.change_time, direction * ramp.change, false);
        self.push(ramp.cruise_time, 0.0, ramp.peak >= profile.vmax);
        self.push(ramp.stop_time, -direction * b, false);
        self.arrive(target);
    }

    /// Ends a position move exactly on its target.
    fn arrive(&mut self, target: f64) {
        self.p = target;
        self.halt();
    }
}
