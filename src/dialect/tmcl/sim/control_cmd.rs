//! Control commands for a running bus (the `tmclsh sim` console, tests): set inputs, move
//! switches, look at the motor. `@N` before a command selects the module with factory address N
//! (default: the first module).
//!
//! ```text
//! input PORT 0|1                digital input (GIO bank 0)
//! analog PORT VALUE             analog input (GIO bank 1), 0..adc_max
//! switch [M] left|right|home POS|off   move a virtual switch of motor M (default 0; physical
//!                               microsteps) or disconnect it
//! output PORT                   print an output's state (SIO bank 2)
//! motor [M]                     print position, target, velocity, target reached of motor M
//! reset [N]                     power-cycle module N (factory address) or every module
//! ```

use std::time::Duration;

use super::motion::{MotorState, Switch};
use crate::sim::console::Section;
use crate::sim::error::ConsoleError;

/// What the console's commands need of a running bus. The bus implements it (`bus.rs`) and hands
/// itself to [`run`], so this file does not name the bus back.
pub(crate) trait Controlled {
    /// Factory addresses of the modules, in bus order.
    fn slots(&self) -> Vec<u8>;
    /// Resets one module or all; says what it did.
    fn reset(&mut self, now: Duration, slot: Option<u8>) -> Result<String, ConsoleError>;
    /// Sets a digital input.
    fn set_input(
        &mut self,
        now: Duration,
        slot: u8,
        port: u8,
        high: bool,
    ) -> Result<(), ConsoleError>;
    /// Sets an analog input.
    fn set_analog(
        &mut self,
        now: Duration,
        slot: u8,
        port: u8,
        value: i32,
    ) -> Result<(), ConsoleError>;
    /// Places (or removes) a switch of a module's motor.
    fn set_switch(
        &mut self,
        now: Duration,
        slot: u8,
        motor: u8,
        which: Switch,
        position: Option<i64>,
    ) -> Result<(), ConsoleError>;
    /// The state of an output.
    fn output(&mut self, now: Duration, slot: u8, port: u8) -> Option<bool>;
    /// What a motor is doing.
    fn motor_of(&mut self, now: Duration, slot: u8, motor: u8) -> Option<MotorState>;
}

/// The console's commands, for `tmclsh sim --help` and the console's `help`.
pub(crate) const CONSOLE: Section = Section {
    heading: "TMCL module bus (--protocol tmcl)",
    commands: &[
        ("input PORT 0|1", "set a digital input (GIO bank 0)"),
        (
            "analog PORT VALUE",
            "set an analog input (GIO bank 1, 0..the ADC maximum)",
        ),
        (
            "switch [M] left|right|home POS|off",
            "move a virtual switch of motor M (default 0; physical\n\
             microsteps) or disconnect it",
        ),
        ("output PORT", "show an output (SIO bank 2)"),
        (
            "motor [M]",
            "show position, target, velocity, target reached of motor M",
        ),
        (
            "reset [N]",
            "power-cycle module N (factory address) or every module: RAM\n\
             back to the stored values, motion and program stopped, the\n\
             interface in the mode GP 67 bit 0 says (binary by default)",
        ),
        (
            "@N COMMAND",
            "any of the above for the module with factory address N",
        ),
    ],
};

/// Runs `command` if it is a bus command (`None` when it is not one).
pub(crate) fn run(
    bus: &mut dyn Controlled,
    now: Duration,
    command: &str,
) -> Option<Result<String, ConsoleError>> {
    let mut words: Vec<&str> = command.split_whitespace().collect();
    match words.as_slice() {
        ["reset"] => return Some(bus.reset(now, None)),
        ["reset", n] | [n, "reset"] => {
            let n = n.strip_prefix('@').unwrap_or(n);
            return Some(
                n.parse::<u8>()
                    .map_err(|_| ConsoleError::bad(n, "a module address"))
                    .and_then(|slot| bus.reset(now, Some(slot))),
            );
        }
        _ => {}
    }
    let slot = match take_module(bus, &mut words)? {
        Ok(slot) => slot,
        Err(e) => return Some(Err(e)),
    };
    let motor = match take_motor(&mut words) {
        Ok(motor) => motor,
        Err(e) => return Some(Err(e)),
    };
    let result = match words.as_slice() {
        ["input", port, level] => set_input(bus, now, slot, port, level),
        ["analog", port, value] => set_analog(bus, now, slot, port, value),
        ["switch", which, position] => set_switch(bus, now, (slot, motor), which, position),
        ["output", port] => number(port).and_then(|port| {
            bus.output(now, slot, port)
                .map(|on| format!("output {port} = {}", u8::from(on)))
                .ok_or(ConsoleError::NoOutput(port))
        }),
        ["motor"] => motor_state(bus, now, slot, motor),
        _ => return None,
    };
    Some(result)
}

/// The module a leading `@N` names, taken off `words`; without one, the first module (`None`
/// on a bus without modules).
fn take_module(bus: &dyn Controlled, words: &mut Vec<&str>) -> Option<Result<u8, ConsoleError>> {
    let first: Option<&str> = words.first().copied();
    let Some(n) = first.and_then(|w| w.strip_prefix('@')) else {
        return bus.slots().first().map(|slot| Ok(*slot));
    };
    let slot = n
        .parse::<u8>()
        .map_err(|_| ConsoleError::bad(&format!("@{n}"), "a module address"));
    if slot.is_ok() {
        words.remove(0);
    }
    Some(slot)
}

/// The motor `switch M WHICH POS` and `motor M` name, taken off `words`; without one, motor 0.
fn take_motor(words: &mut Vec<&str>) -> Result<u8, ConsoleError> {
    let m = match words.as_slice() {
        ["switch", m, _, _] | ["motor", m] => *m,
        _ => return Ok(0),
    };
    let motor = m
        .parse::<u8>()
        .map_err(|_| ConsoleError::bad(m, "a motor number"))?;
    words.remove(1);
    Ok(motor)
}

/// `input PORT 0|1`.
fn set_input(
    bus: &mut dyn Controlled,
    now: Duration,
    slot: u8,
    port: &str,
    level: &str,
) -> Result<String, ConsoleError> {
    let port = number(port)?;
    let high = match level {
        "0" | "low" | "off" => false,
        "1" | "high" | "on" => true,
        other => return Err(ConsoleError::bad(other, "a level; use 0 or 1")),
    };
    bus.set_input(now, slot, port, high)
        .map(|()| format!("input {port} = {}", u8::from(high)))
}

/// `analog PORT VALUE`.
fn set_analog(
    bus: &mut dyn Controlled,
    now: Duration,
    slot: u8,
    port: &str,
    value: &str,
) -> Result<String, ConsoleError> {
    let port = number(port)?;
    let value: i32 = value
        .parse()
        .map_err(|_| ConsoleError::bad(value, "a number"))?;
    bus.set_analog(now, slot, port, value)
        .map(|()| format!("analog {port} = {value}"))
}

/// `switch [M] left|right|home POS|off` for motor `motor` of the module at `slot`.
fn set_switch(
    bus: &mut dyn Controlled,
    now: Duration,
    (slot, motor): (u8, u8),
    which: &str,
    position: &str,
) -> Result<String, ConsoleError> {
    let which = match which {
        "left" => Switch::Left,
        "right" => Switch::Right,
        "home" | "ref" | "reference" => Switch::Home,
        other => {
            return Err(ConsoleError::bad(
                other,
                "a switch; use left, right or home",
            ));
        }
    };
    let position = match position {
        "off" | "none" => None,
        p => Some(
            p.parse::<i64>()
                .map_err(|_| ConsoleError::bad(p, "a position (or 'off')"))?,
        ),
    };
    bus.set_switch(now, slot, motor, which, position)?;
    let at = position.map_or("off".to_string(), |p| p.to_string());
    let text = format!("switch {which:?} at {at}").to_lowercase();
    Ok(match motor {
        0 => text,
        m => format!("motor {m} {text}"),
    })
}

/// `motor [M]`: position, target, velocity and target reached.
fn motor_state(
    bus: &mut dyn Controlled,
    now: Duration,
    slot: u8,
    motor: u8,
) -> Result<String, ConsoleError> {
    bus.motor_of(now, slot, motor)
        .map(|m| {
            format!(
                "position {} target {} velocity {:.3} pps reached {}",
                m.position,
                m.target,
                m.velocity,
                u8::from(m.target_reached)
            )
        })
        .ok_or(ConsoleError::NoModuleMotor { slot, motor })
}

fn number(text: &str) -> Result<u8, ConsoleError> {
    text.parse()
        .map_err(|_| ConsoleError::bad(text, "a port number"))
}
