//! Executing one request: the same validation a client runs (so both agree by construction),
//! mapped to the drive's error codes, then the standby, mode and disabled-motor gates, then the
//! command. Plain settings need no code here: they are stored and echoed as the table says.

use crate::dialect::smd4::protocol::{
    Action, ArgValue, Eflags, ErrorCode, Request, Smd4Command, ValidationError, validate,
};

use super::Smd4Sim;
use super::config::{self, Setting};
use super::motion::Goal;
use super::reply::Outcome;

/// What a handler returns: the value to echo, or the error code.
type Handled = Result<Option<Setting>, ErrorCode>;

fn code_of(error: &ValidationError) -> ErrorCode {
    match error {
        ValidationError::UnknownMnemonic { .. } => ErrorCode::InvalidMnemonic,
        ValidationError::NotReadable { .. } => ErrorCode::UnableToGet,
        ValidationError::NotWritable { .. } | ValidationError::ArgumentCount { .. } => {
            ErrorCode::ArgumentCount
        }
        ValidationError::ArgumentType { .. } => ErrorCode::ArgumentType,
        ValidationError::OutOfRange { .. } | ValidationError::NotAllowed { .. } => {
            ErrorCode::ArgumentValidation
        }
        ValidationError::BadAddress(_) => ErrorCode::PacketError,
    }
}

impl Smd4Sim {
    pub(super) fn execute(&mut self, t: f64, request: &Request) -> Outcome {
        let unaddressed = Request {
            address: None,
            ..request.clone()
        };
        let spec = self.spec;
        let checked = match validate(&unaddressed, &spec.commands) {
            Ok(checked) => checked,
            Err(error) => return Outcome::Failed(code_of(&error)),
        };
        let spec = checked.spec;
        let result = match checked.action {
            Action::Read => self.read(t, spec),
            access => self.gate(t, spec).and_then(|()| match access {
                Action::Write(value) => self.write(t, spec, value),
                _ => self.run(t, spec),
            }),
        };
        match result {
            Err(code) => Outcome::Failed(code),
            Ok(_) if spec.no_response => Outcome::Silent,
            Ok(_) if spec.multi_line() => Outcome::Lines(match spec.mnemonic.as_str() {
                "SYS:FLAGSV" => self.flag_listing(t),
                _ => self.ip_summary(),
            }),
            Ok(value) => Outcome::Items(self.items(spec, value.as_ref())),
        }
    }

    /// The documented refusals of writes and actions: −1, −6, −7.
    fn gate(&self, t: f64, spec: &Smd4Command) -> Result<(), ErrorCode> {
        if spec.requires_standby && !self.motion.at(t).standby {
            return Err(ErrorCode::StopMotorFirst);
        }
        if !spec.modes.is_empty() && !spec.modes.contains(&self.mode()) {
            return Err(ErrorCode::NotPossibleInMode);
        }
        if spec.starts_motion && self.eflags.any() {
            return Err(ErrorCode::MotorDisabled);
        }
        Ok(())
    }

    fn read(&self, t: f64, spec: &Smd4Command) -> Handled {
        let now = self.motion.at(t);
        let value = match spec.mnemonic.as_str() {
            "SYS:UPTIME" => Setting::Int(((t - self.boot) * 1000.0) as i64),
            "MOTOR:VACT" => Setting::Float(now.velocity),
            "MOTOR:PACT" => Setting::Float(now.position),
            "MOTOR:PREL" => Setting::Float(now.position + self.prel_offset),
            "BAKE:ELAPSED" => Setting::Float(self.bake_seconds(t)),
            "COMS:NET:IP" | "COMS:NET:NETMASK" | "COMS:NET:GATEWAY" => {
                Setting::Text(self.network(&spec.mnemonic))
            }
            name => match (&spec.sim_value, self.working.get(name)) {
                (Some(fixed), _) => Setting::Text(fixed.clone()),
                (None, Some(value)) => value.clone(),
                (None, None) => return Ok(None),
            },
        };
        Ok(Some(value))
    }

    fn write(&mut self, t: f64, spec: &Smd4Command, value: ArgValue) -> Handled {
        let name = spec.mnemonic.as_str();
        let mut setting = Setting::from_arg(&value);
        match name {
            "MOTOR:RUNV" | "MOTOR:RUNH" => {
                let direction = if value.canonical() == "+" { 1.0 } else { -1.0 };
                return Ok(self.start(t, Goal::Velocity(direction), name == "MOTOR:RUNH"));
            }
            "MOTOR:RUNA" => return Ok(self.start(t, Goal::Position(setting.number()), false)),
            "MOTOR:RUNR" => {
                let target = self.motion.at(t).position + setting.number();
                return Ok(self.start(t, Goal::Position(target), false));
            }
            "MOTOR:PACT" | "MOTOR:PREL" => {
                let steps = setting.number().round();
                let position = self.motion.at(t).position;
                if name == "MOTOR:PACT" {
                    // PREL is a counter of its own: setting PACT leaves it where it was.
                    self.prel_offset += position - steps;
                    self.motion.set_position(t, steps);
                } else {
                    self.prel_offset = steps - position;
                }
                return Ok(Some(Setting::Float(steps)));
            }
            "LIMIT:POL" => {
                self.working.insert("LIMIT:POL+".into(), setting.clone());
                self.working.insert("LIMIT:POL-".into(), setting.clone());
                self.update(t);
                return Ok(Some(setting));
            }
            _ => {}
        }
        if let (Some(levels), true) = (
            spec.arg.as_ref().and_then(|a| a.levels),
            self.options.current_rounding,
        ) {
            let max = spec.arg.as_ref().and_then(|a| a.max).unwrap_or(1.0);
            let step = max / f64::from(levels);
            setting = Setting::Float(((setting.number() / step).round() * step).clamp(0.0, max));
        }
        self.working.insert(name.to_string(), setting.clone());
        self.couple(t, name, setting.number());
        Ok(Some(match name {
            "COMS:NET:IP" | "COMS:NET:NETMASK" | "COMS:NET:GATEWAY" => {
                Setting::Text(self.network(name))
            }
            _ => setting,
        }))
    }

    /// The documented couplings and side effects of a setting that was just written.
    fn couple(&mut self, t: f64, name: &str, value: f64) {
        let mut raise = |other: &str, above: bool| {
            let current = self.number(other);
            if (above && value > current) || (!above && value < current) {
                self.working.insert(other.into(), Setting::Float(value));
            }
        };
        match name {
            "MOTOR:IR" => raise("MOTOR:IA", true),
            "MOTOR:VSTART" => raise("MOTOR:VSTOP", true),
            "MOTOR:VSTOP" => raise("MOTOR:VSTART", false),
            _ => {}
        }
        match name {
            "MOTOR:AMAX" | "MOTOR:DMAX" => self.motion.profile_changed(t, &self.profile(), true),
            "MOTOR:VSTART" | "MOTOR:VSTOP" | "MOTOR:VMAX" | "MOTOR:TZW" => {
                self.motion.profile_changed(t, &self.profile(), false)
            }
            "SYS:MODE" if value != 3.0 => self.end_bake(t),
            _ => {}
        }
        if name.starts_with("LIMIT:") || name == "SYS:EXTEN" {
            self.update(t);
        }
    }

    fn run(&mut self, t: f64, spec: &Smd4Command) -> Handled {
        match spec.mnemonic.as_str() {
            "SYS:CLR" => {
                self.eflags = Eflags::default();
                self.update(t);
            }
            "SYS:LOAD" => {
                self.working.extend(self.stored.clone());
                self.motion.profile_changed(t, &self.profile(), false);
            }
            "SYS:LOADFD" => {
                let factory = config::persistent(&self.spec.commands, &self.factory);
                self.working.extend(factory);
                self.motion.profile_changed(t, &self.profile(), false);
            }
            "STORE" => {
                let stored = config::persistent(&self.spec.commands, &self.working);
                if self.flash_fails || self.store.save(&config::to_text(&stored)).is_err() {
                    return Err(ErrorCode::ActionFailed);
                }
                self.stored = stored;
                self.config_damaged = false;
            }
            "SYS:PROG" => self.silent = true,
            "SYS:RESET" => self.power_up(t),
            "MOTOR:STOP" => {
                self.end_bake(t);
                self.homing = None;
                let resume = self.motion.resumable(t);
                if !self.motion.at(t).standby {
                    self.motion.plan(t, Goal::Stop(resume), &self.profile());
                }
            }
            "MOTOR:SSTOP" => {
                self.end_bake(t);
                self.homing = None;
                self.motion.stop_within(t, self.spec.sim.sstop_seconds);
            }
            "MOTOR:ESTOP" => {
                self.end_bake(t);
                self.homing = None;
                self.motion.halt(t);
                self.eflags.latch(Eflags::EMERGENCY_STOP);
            }
            "BAKE:RUN" => {
                self.bake_started.get_or_insert(t);
            }
            _ => {}
        }
        Ok(None)
    }

    /// Starts a motion (homing towards the limit on the goal's side) and applies the limits.
    fn start(&mut self, t: f64, goal: Goal, homing: bool) -> Option<Setting> {
        self.homing = match goal {
            Goal::Velocity(direction) if homing => Some(direction),
            _ => None,
        };
        self.motion.plan(t, goal, &self.profile());
        self.update(t);
        None
    }

    fn bake_seconds(&self, t: f64) -> f64 {
        match self.bake_started {
            Some(start) => t - start,
            None => self.bake_elapsed,
        }
    }
}
