//! Which axis parameter plays which part in the simulated motion: `[simulation.axis_roles]` of a
//! profile. The same number means different things in different generations (AP 130 is the
//! TMCM-142's "velocity reached" and a Gen-A module's minimum speed; AP 41 the TMCM-142's encoder
//! and a TMCM-6214's position-compare distance), so the simulator asks the profile instead of
//! assuming one numbering. A parameter no role names is plain memory.

use serde::Deserialize;

/// The axis parameter number of each part of the simulated motion (`None`: the module has none).
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxisRoles {
    /// Target position: SAP starts a move there; MVP sets it.
    pub target_position: Option<u8>,
    /// Position counter: GAP reads it live; SAP redefines it without moving.
    pub actual_position: Option<u8>,
    /// Target speed: SAP turns at it; ROR/ROL/MST set it.
    pub target_speed: Option<u8>,
    /// Actual speed: GAP reads it live; SAP sets it at once.
    pub actual_speed: Option<u8>,
    /// Maximum positioning speed of a move.
    pub max_speed: Option<u8>,
    /// Acceleration of every ramp.
    pub max_acceleration: Option<u8>,
    /// Target position reached flag (read only).
    pub target_reached: Option<u8>,
    /// Reference (home) switch state (read only).
    pub home_switch: Option<u8>,
    /// Right limit switch state (read only).
    pub right_switch: Option<u8>,
    /// Left limit switch state (read only).
    pub left_switch: Option<u8>,
    /// 1 disables the right limit switch's stop.
    pub right_limit_disable: Option<u8>,
    /// 1 disables the left limit switch's stop.
    pub left_limit_disable: Option<u8>,
    /// Reference search mode (1 left switch, 2 right then left, 3 right then home).
    pub search_mode: Option<u8>,
    /// Reference search speed.
    pub search_speed: Option<u8>,
    /// Reference switch speed (the slow approach to the edge).
    pub switch_speed: Option<u8>,
    /// Distance between the end switches found by the last search (read only).
    pub end_distance: Option<u8>,
    /// 1 takes speeds and accelerations in microsteps per second (TMCM-142 AP 255).
    pub unit_mode: Option<u8>,
    /// Encoder position (read only, from the simulated encoder).
    pub encoder_position: Option<u8>,
    /// Encoder constant (scales the encoder position).
    pub encoder_constant: Option<u8>,
    /// Encoder mode (bit 13: decimal encoder constant).
    pub encoder_mode: Option<u8>,
    /// Position error, encoder minus counter (read only).
    pub position_error: Option<u8>,
    /// Regulator speed, read as the actual speed.
    pub regulator_speed: Option<u8>,
    /// Regulator integrator sum: any write clears it.
    pub integrator_sum: Option<u8>,
    /// Status flags: bit 0 target reached, bit 1 speed reached, bit 2 standing (read only).
    pub status_flags: Option<u8>,
    /// Speed reached flag (read only).
    pub speed_reached: Option<u8>,
    /// Pulse divisor (TMC429): each step above its default halves the velocity unit.
    pub pulse_divisor: Option<u8>,
    /// Ramp divisor (TMC429): each step above its default halves the acceleration unit.
    pub ramp_divisor: Option<u8>,
}

impl AxisRoles {
    /// Every role with its name and number, for checks and documentation.
    pub fn all(&self) -> [(&'static str, Option<u8>); 27] {
        [
            ("target_position", self.target_position),
            ("actual_position", self.actual_position),
            ("target_speed", self.target_speed),
            ("actual_speed", self.actual_speed),
            ("max_speed", self.max_speed),
            ("max_acceleration", self.max_acceleration),
            ("target_reached", self.target_reached),
            ("home_switch", self.home_switch),
            ("right_switch", self.right_switch),
            ("left_switch", self.left_switch),
            ("right_limit_disable", self.right_limit_disable),
            ("left_limit_disable", self.left_limit_disable),
            ("search_mode", self.search_mode),
            ("search_speed", self.search_speed),
            ("switch_speed", self.switch_speed),
            ("end_distance", self.end_distance),
            ("unit_mode", self.unit_mode),
            ("encoder_position", self.encoder_position),
            ("encoder_constant", self.encoder_constant),
            ("encoder_mode", self.encoder_mode),
            ("position_error", self.position_error),
            ("regulator_speed", self.regulator_speed),
            ("integrator_sum", self.integrator_sum),
            ("status_flags", self.status_flags),
            ("speed_reached", self.speed_reached),
            ("pulse_divisor", self.pulse_divisor),
            ("ramp_divisor", self.ramp_divisor),
        ]
    }

    /// Whether no role is given (a profile without the table).
    pub fn is_empty(&self) -> bool {
        self.all().iter().all(|(_, n)| n.is_none())
    }
}
