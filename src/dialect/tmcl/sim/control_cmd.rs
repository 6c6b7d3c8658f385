//! Control commands for a running bus (the `tmclsh sim` console, tests): set inputs, move
//! switches, look at the motor. `@N` before a command selects the module with factory address N
//! (default: the first module).
//!
//! ```text
//! input PORT 0|1                digital input (GIO bank 0)
//! analog PORT VALUE             analog input (GIO bank 1), 0..adc_max
//! switch left|right|home POS|off   move a virtual switch (physical microsteps) or disconnect it
//! output PORT                   print an output's state (SIO bank 2)
//! motor                         print position, target, velocity, target reached
//! ```

use std::time::Duration;

use super::bus::Bus;
use super::motion::Switch;

/// Runs `command` if it is a bus command (`None` when it is not one).
pub(crate) fn run(bus: &mut Bus, now: Duration, command: &str) -> Option<Result<String, String>> {
    let mut words: Vec<&str> = command.split_whitespace().collect();
    let slot = match words.first().and_then(|w| w.strip_prefix('@')) {
        Some(n) => match n.parse::<u8>() {
            Ok(n) => {
                words.remove(0);
                n
            }
            Err(_) => return Some(Err(format!("'@{n}' is not a module address"))),
        },
        None => *bus.slots().first()?,
    };
    let result = match words.as_slice() {
        ["input", port, level] => number(port).and_then(|port| {
            let high = match *level {
                "0" | "low" | "off" => false,
                "1" | "high" | "on" => true,
                other => return Err(format!("'{other}' is not a level; use 0 or 1")),
            };
            bus.set_input(now, slot, port, high)
                .map(|()| format!("input {port} = {}", u8::from(high)))
        }),
        ["analog", port, value] => number(port).and_then(|port| {
            let value: i32 = value
                .parse()
                .map_err(|_| format!("'{value}' is not a number"))?;
            bus.set_analog(now, slot, port, value)
                .map(|()| format!("analog {port} = {value}"))
        }),
        ["switch", which, position] => {
            let which = match *which {
                "left" => Switch::Left,
                "right" => Switch::Right,
                "home" | "ref" | "reference" => Switch::Home,
                other => {
                    return Some(Err(format!(
                        "'{other}' is not a switch; use left, right or home"
                    )));
                }
            };
            let position = match *position {
                "off" | "none" => Ok(None),
                p => p
                    .parse::<i64>()
                    .map(Some)
                    .map_err(|_| format!("'{p}' is not a position (or 'off')")),
            };
            position.and_then(|position| {
                bus.set_switch(now, slot, which, position).map(|()| {
                    let at = position.map_or("off".to_string(), |p| p.to_string());
                    format!("switch {which:?} at {at}").to_lowercase()
                })
            })
        }
        ["output", port] => number(port).and_then(|port| {
            bus.output(slot, port)
                .map(|on| format!("output {port} = {}", u8::from(on)))
                .ok_or_else(|| format!("no output {port}"))
        }),
        ["motor"] => bus
            .motor(now, slot)
            .map(|m| {
                format!(
                    "position {} target {} velocity {:.3} pps reached {}",
                    m.position,
                    m.target,
                    m.velocity,
                    u8::from(m.target_reached)
                )
            })
            .ok_or_else(|| format!("no module {slot}")),
        _ => return None,
    };
    Some(result)
}

fn number(text: &str) -> Result<u8, String> {
    text.parse()
        .map_err(|_| format!("'{text}' is not a port number"))
}
