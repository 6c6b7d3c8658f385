//! Control commands for a running simulated SMD4 (the `tmclsh sim --protocol smd4` console,
//! tests): move its inputs, latch faults, break its flash, cycle its power, look at the motor.
//! The commands and their help are the table [`CONSOLE`].

use std::time::Duration;

use super::{Limit, Smd4Sim};
use crate::sim::console::Section;
use crate::sim::error::ConsoleError;

/// The console's commands, for `tmclsh sim --help` and the console's `help`.
pub(crate) const CONSOLE: Section = Section {
    heading: "SMD4 drive (--protocol smd4)",
    commands: &[
        (
            "limit pos|neg 0|1",
            "set the level of a limit input (active after LIMIT:POL+/-)",
        ),
        ("exten 0|1", "set the external enable input"),
        ("joystick 0|1", "plug a joystick in or out"),
        (
            "fault BIT|NAME",
            "latch an EFLAGS bit (e.g. 2 or TempOver); the motor stops",
        ),
        (
            "flash-failure on|off",
            "make STORE fail with -5 (worn-out flash) or work again",
        ),
        ("power-cycle", "restart from the stored configuration"),
        (
            "motor",
            "show position, velocity, standby, target velocity reached",
        ),
        (
            "flags",
            "show SFLAGS, EFLAGS and whether addressing mode is on",
        ),
        (
            "setting MNEMONIC",
            "show a working setting (e.g. COMS:SERIAL:SLAVEADDR)",
        ),
    ],
};

/// Runs `command` if it is an SMD4 console command (`None` when it is not one).
pub(super) fn run(
    sim: &mut Smd4Sim,
    now: Duration,
    command: &str,
) -> Option<Result<String, ConsoleError>> {
    let words: Vec<&str> = command.split_whitespace().collect();
    let result = match words.as_slice() {
        ["limit", side, level] => side_of(side).and_then(|side| {
            let high = level_of(level)?;
            sim.set_limit_input(now, side, high);
            let name = match side {
                Limit::Positive => "pos",
                Limit::Negative => "neg",
            };
            Ok(format!("limit {name} = {}", u8::from(high)))
        }),
        ["exten", level] => level_of(level).map(|active| {
            sim.set_external_enable(now, active);
            format!("exten = {}", u8::from(active))
        }),
        ["joystick", level] => level_of(level).map(|connected| {
            sim.set_joystick(now, connected);
            format!("joystick = {}", u8::from(connected))
        }),
        ["fault", name @ ..] if !name.is_empty() => fault_bit(sim, &name.join(" ")).map(|bit| {
            sim.inject_fault(now, bit);
            format!("fault bit {bit} latched, eflags {:#06X}", sim.eflags().0)
        }),
        ["flash-failure", switch] => match *switch {
            "on" => {
                sim.set_flash_failure(true);
                Ok("STORE fails from now on".to_string())
            }
            "off" => {
                sim.set_flash_failure(false);
                Ok("STORE works again".to_string())
            }
            other => Err(ConsoleError::bad(other, "on or off")),
        },
        ["power-cycle"] => {
            sim.power_cycle(now);
            Ok("powered up from the stored configuration".to_string())
        }
        ["motor"] => {
            let m = sim.motion_state(now);
            Ok(format!(
                "position {:.2} velocity {:.3} standby {} at-target-velocity {}",
                m.position,
                m.velocity,
                u8::from(m.standby),
                u8::from(m.at_target_velocity)
            ))
        }
        ["flags"] => Ok(format!(
            "sflags {:#06X} eflags {:#06X} addressing {}",
            sim.sflags(now).0,
            sim.eflags().0,
            u8::from(sim.addressing_mode())
        )),
        ["setting", mnemonic] => sim
            .setting(mnemonic)
            .map(|value| format!("{} = {}", mnemonic.to_ascii_uppercase(), value.text()))
            .ok_or_else(|| ConsoleError::NoSetting(mnemonic.to_string())),
        _ => return None,
    };
    Some(result)
}

fn side_of(text: &str) -> Result<Limit, ConsoleError> {
    match text {
        "pos" | "positive" | "+" | "1" => Ok(Limit::Positive),
        "neg" | "negative" | "-" | "2" => Ok(Limit::Negative),
        other => Err(ConsoleError::bad(other, "a limit; use pos or neg")),
    }
}

fn level_of(text: &str) -> Result<bool, ConsoleError> {
    match text {
        "0" | "low" | "off" | "out" => Ok(false),
        "1" | "high" | "on" | "in" => Ok(true),
        other => Err(ConsoleError::bad(other, "a level; use 0 or 1")),
    }
}

/// An EFLAGS bit by number or by name (`TempOver`, `Temp Over`), from the flag table.
fn fault_bit(sim: &Smd4Sim, text: &str) -> Result<u8, ConsoleError> {
    if let Ok(bit) = text.parse::<u8>() {
        return if bit < 16 {
            Ok(bit)
        } else {
            Err(ConsoleError::NoBit(bit))
        };
    }
    let squash = |s: &str| {
        s.chars()
            .filter(|c| c.is_ascii_alphanumeric())
            .collect::<String>()
            .to_ascii_lowercase()
    };
    let wanted = squash(text);
    let bits = sim.spec.eflags.bits();
    bits.iter()
        .find(|b| squash(&b.name) == wanted || squash(&b.label) == wanted)
        .map(|b| b.bit)
        .ok_or_else(|| ConsoleError::NoFlag {
            name: text.to_string(),
            known: bits
                .iter()
                .filter(|b| !b.label.starts_with("reserved"))
                .map(|b| format!("{} {}", b.bit, b.label))
                .collect(),
        })
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use crate::dialect::smd4::sim::{Smd4Sim, Smd4SimOptions};
    use crate::sim::Device;
    use crate::sim::error::ConsoleError;

    fn control(sim: &mut Smd4Sim, command: &str) -> Result<String, ConsoleError> {
        sim.control(Duration::ZERO, command)
            .expect("an SMD4 console command")
    }

    #[test]
    fn inputs_change_the_status_word() {
        let mut sim = Smd4Sim::new(Smd4SimOptions::default());
        assert_eq!(control(&mut sim, "limit pos 1"), Ok("limit pos = 1".into()));
        assert_eq!(control(&mut sim, "limit - 1"), Ok("limit neg = 1".into()));
        assert_eq!(control(&mut sim, "exten 0"), Ok("exten = 0".into()));
        assert_eq!(control(&mut sim, "joystick 1"), Ok("joystick = 1".into()));
        assert_eq!(
            sim.sflags(Duration::ZERO).0 & 0b1111,
            0b0111,
            "joystick, both limits, no external enable"
        );
        assert!(control(&mut sim, "limit up 1").is_err());
        assert!(control(&mut sim, "exten maybe").is_err());
    }

    #[test]
    fn faults_by_number_or_name() {
        let mut sim = Smd4Sim::new(Smd4SimOptions::default());
        assert_eq!(
            control(&mut sim, "fault TempOver"),
            Ok("fault bit 2 latched, eflags 0x0004".into())
        );
        assert!(control(&mut sim, "fault Motor Short").is_ok());
        assert!(control(&mut sim, "fault 1").is_ok());
        assert_eq!(sim.eflags().0, 0b1110);
        let err = control(&mut sim, "fault warp core")
            .unwrap_err()
            .to_string();
        assert!(err.contains("5 EmergencyStop"), "{err}");
        assert!(control(&mut sim, "fault 16").is_err());
        assert!(control(&mut sim, "power-cycle").is_ok());
        assert_eq!(sim.eflags().0, 0, "power cycle clears latched errors");
    }

    #[test]
    fn flash_failure_and_state_queries() {
        let mut sim = Smd4Sim::new(Smd4SimOptions::default());
        assert!(control(&mut sim, "flash-failure on").is_ok());
        sim.receive(Duration::ZERO, b"STORE\r\n");
        let mut out = Vec::new();
        sim.poll_output(Duration::ZERO, &mut out);
        assert!(String::from_utf8(out).unwrap().contains("-5"));
        assert!(control(&mut sim, "flash-failure maybe").is_err());
        assert_eq!(
            control(&mut sim, "motor"),
            Ok("position 0.00 velocity 0.000 standby 1 at-target-velocity 0".into())
        );
        assert_eq!(
            control(&mut sim, "flags"),
            Ok("sflags 0x0888 eflags 0x0000 addressing 0".into())
        );
        assert_eq!(
            control(&mut sim, "setting coms:serial:slaveaddr"),
            Ok("COMS:SERIAL:SLAVEADDR = 1".into())
        );
        assert!(control(&mut sim, "setting NOPE").is_err());
        assert_eq!(sim.control(Duration::ZERO, "input 1 1"), None);
    }
}
