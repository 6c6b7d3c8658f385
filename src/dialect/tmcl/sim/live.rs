//! What a module's motors read and how their units convert, by the profile's axis roles
//! (`[simulation.axis_roles]`): the live values GAP reads (position, speed, switches, flags,
//! encoder) and the speed and acceleration units, with the TMC429 divisors where a module has them.

use super::machine::Machine;
use super::motion::{Switch, encoder_position};
use super::params::Slot;

impl Machine {
    /// The RAM value of a motor's parameter in `role` (0 where the module has no such role).
    pub(super) fn role(&self, motor: u8, role: Option<u8>) -> i32 {
        role.map_or(0, |n| self.params.get(Slot::Axis(motor, n)))
    }

    /// Sets the RAM value of a motor's parameter in `role`, if the module has it.
    pub(super) fn set_role(&mut self, motor: u8, role: Option<u8>, value: i32) {
        if let Some(n) = role {
            self.params.set(Slot::Axis(motor, n), value);
        }
    }

    fn pps_mode(&self, motor: u8) -> bool {
        self.role(motor, self.roles.unit_mode) == 1
    }

    /// How far a divisor parameter of `motor` is above its profile default (0 without one):
    /// the unit constants of the profile hold at the defaults.
    fn divisor_shift(&self, motor: u8, role: Option<u8>) -> i32 {
        let Some(number) = role else { return 0 };
        let slot = Slot::Axis(motor, number);
        let default = self.params.spec(slot).and_then(|p| p.default).unwrap_or(0);
        (i64::from(self.params.get(slot)) - default).clamp(-31, 31) as i32
    }

    /// Microsteps per second per velocity unit of `motor`: 1 in unit mode, else the profile's
    /// constant, halved for each step the pulse divisor is above its default (TMC429).
    pub(super) fn velocity_factor(&self, motor: u8) -> f64 {
        if self.pps_mode(motor) {
            return 1.0;
        }
        let shift = self.divisor_shift(motor, self.roles.pulse_divisor);
        self.profile.sim.velocity_pps_per_unit * 2f64.powi(-shift)
    }

    /// Microsteps per second² per acceleration unit of `motor`: as the velocity, with the pulse
    /// and ramp divisors both (TMC429).
    fn acceleration_factor(&self, motor: u8) -> f64 {
        if self.pps_mode(motor) {
            return 1.0;
        }
        let shift = self.divisor_shift(motor, self.roles.pulse_divisor)
            + self.divisor_shift(motor, self.roles.ramp_divisor);
        self.profile.sim.acceleration_pps2_per_unit * 2f64.powi(-shift)
    }

    /// A velocity of `motor` in the user's unit as microsteps per second.
    pub(super) fn pps(&self, motor: u8, value: i32) -> f64 {
        f64::from(value) * self.velocity_factor(motor)
    }

    /// An acceleration of `motor` in the user's unit as microsteps per second².
    pub(super) fn pps2(&self, motor: u8, value: i32) -> f64 {
        f64::from(value) * self.acceleration_factor(motor)
    }

    fn velocity_units(&self, motor: u8, pps: f64) -> i32 {
        let units = (pps / self.velocity_factor(motor)).round();
        units.clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32
    }

    /// Maximum positioning speed (AP 4) and acceleration (AP 5) of `motor` in pps, pps².
    pub(super) fn move_limits(&self, motor: u8) -> (f64, f64) {
        (
            self.pps(motor, self.role(motor, self.roles.max_speed)),
            self.pps2(motor, self.role(motor, self.roles.max_acceleration)),
        )
    }

    /// The value GAP reads for `motor` at `t` (parameters with live values computed, others
    /// from RAM).
    pub(super) fn axis_value(&self, motor: u8, number: u8, t: f64) -> i32 {
        let Some(axis) = self.axes.get(usize::from(motor)) else {
            return 0;
        };
        let state = axis.state(t);
        let counter = axis.counter(t);
        let r = &self.roles;
        let is = |role: Option<u8>| role == Some(number);
        if is(r.actual_position) {
            counter
        } else if is(r.actual_speed) || is(r.regulator_speed) {
            self.velocity_units(motor, state.v)
        } else if is(r.target_reached) {
            i32::from(self.target_reached(motor, t))
        } else if is(r.home_switch) {
            i32::from(axis.switch_active(t, Switch::Home))
        } else if is(r.right_switch) {
            i32::from(axis.switch_active(t, Switch::Right))
        } else if is(r.left_switch) {
            i32::from(axis.switch_active(t, Switch::Left))
        } else if is(r.position_error) {
            (self.encoder(motor, t) as i64 - counter as i64).clamp(-(1 << 23), 1 << 23) as i32
        } else if is(r.encoder_position) {
            self.encoder(motor, t)
        } else if is(r.status_flags) {
            i32::from(self.target_reached(motor, t))
                | i32::from(state.a == 0.0) << 1
                | i32::from(state.v == 0.0) << 2
        } else if is(r.speed_reached) {
            i32::from(state.a == 0.0)
        } else if is(r.end_distance) {
            axis.end_distance()
        } else {
            self.params.get(Slot::Axis(motor, number))
        }
    }

    /// Whether `motor` stands at its target position.
    pub(super) fn target_reached(&self, motor: u8, t: f64) -> bool {
        let axis = &self.axes[usize::from(motor)];
        axis.state(t).v == 0.0 && axis.counter(t) == self.role(motor, self.roles.target_position)
    }

    fn encoder(&self, motor: u8, t: f64) -> i32 {
        let constant = match self.roles.encoder_constant {
            Some(n) => self.params.get(Slot::Axis(motor, n)),
            None => 65536,
        };
        encoder_position(
            self.axes[usize::from(motor)].counter(t),
            constant,
            self.role(motor, self.roles.encoder_mode),
            self.profile.sim.encoder_usteps_per_count,
        )
    }
}
