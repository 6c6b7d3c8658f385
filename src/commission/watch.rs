//! `:watch`: a table of parameters redrawn in place at an interval while the user keeps control —
//! any key stops it, Ctrl-C stops it and the motor (the REPL's usual Ctrl-C handling).
//!
//! The loop talks to a [`Screen`]; the terminal one lives with the shell (`shell::terminal`), so
//! the commissioning core draws no terminal itself.

use std::io;
use std::time::{Duration, Instant};

use crate::session::{SessionError, interrupt};

use super::device::{ParamDevice, ParamRef};
use super::value::{ParamValue, Reading};

/// What a key press means to a watch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    /// Stop watching.
    Stop,
    /// Ctrl-C: stop watching and stop the motor.
    Interrupt,
}

/// Where a watch draws and listens.
pub trait Screen {
    /// Replaces the previous frame with `lines`.
    fn draw(&mut self, lines: &[String]) -> io::Result<()>;

    /// Waits up to `timeout` for a key.
    fn key(&mut self, timeout: Duration) -> io::Result<Option<Key>>;
}

/// Shows `params` of `device` every `interval` until a key; returns how many frames were drawn.
/// Ctrl-C (as a key, or the process flag) is [`SessionError::Interrupted`]; a parameter the module
/// refuses shows its error in the table; a lost link ends the watch.
pub fn watch(
    device: &mut dyn ParamDevice,
    params: &[ParamRef],
    interval: Duration,
    screen: &mut dyn Screen,
) -> Result<usize, SessionError> {
    let start = Instant::now();
    let mut frames = 0;
    loop {
        if interrupt::pending() {
            return Err(SessionError::Interrupted);
        }
        let mut values = Vec::with_capacity(params.len());
        for param in params {
            values.push(match device.read(param) {
                Ok(v) => Ok(v),
                Err(e @ SessionError::Device { .. }) => Err(e),
                Err(e) => return Err(e),
            });
        }
        let header = format!(
            "{} every {} ms, {:.1} s — any key stops, Ctrl-C stops the motor",
            device.who(),
            interval.as_millis(),
            start.elapsed().as_secs_f64()
        );
        screen.draw(&render(&header, params, &values))?;
        frames += 1;
        match screen.key(interval)? {
            Some(Key::Stop) => return Ok(frames),
            Some(Key::Interrupt) => return Err(SessionError::Interrupted),
            None => {}
        }
    }
}

/// One frame: the header, then a row per parameter (name, value, unit, and the real value of a
/// user/real pair).
pub fn render(
    header: &str,
    params: &[ParamRef],
    values: &[Result<Reading, SessionError>],
) -> Vec<String> {
    let name_width = params
        .iter()
        .map(|p| p.name.len())
        .chain(["parameter".len()])
        .max()
        .unwrap_or(9);
    let shown: Vec<String> = values
        .iter()
        .map(|v| match v {
            Ok(v) => v.text(),
            Err(_) => "error".into(),
        })
        .collect();
    let value_width = shown
        .iter()
        .map(|s| s.chars().count())
        .chain([5])
        .max()
        .unwrap_or(5);
    let mut lines = vec![
        header.to_string(),
        format!(
            "{:<name_width$}  {:>value_width$}  unit",
            "parameter", "value"
        ),
    ];
    for ((param, value), original) in params.iter().zip(&shown).zip(values) {
        let tail = match original {
            Err(e) => e.to_string(),
            Ok(Reading {
                real: Some(real), ..
            }) => format!("{} (real {})", param.unit, ParamValue::Float(*real)),
            Ok(_) => param.unit.clone(),
        };
        let line = format!("{:<name_width$}  {value:>value_width$}  {tail}", param.name);
        lines.push(line.trim_end().to_string());
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::super::fake::FakeDevice;
    use super::*;

    /// A screen that keeps the frames and presses `key` after `frames` frames.
    struct Scripted {
        frames: Vec<Vec<String>>,
        after: usize,
        key: Key,
    }

    impl Screen for Scripted {
        fn draw(&mut self, lines: &[String]) -> io::Result<()> {
            self.frames.push(lines.to_vec());
            Ok(())
        }
        fn key(&mut self, _: Duration) -> io::Result<Option<Key>> {
            Ok((self.frames.len() >= self.after).then_some(self.key))
        }
    }

    #[test]
    fn the_table_is_redrawn_until_a_key_and_shows_names_values_units() {
        let mut device = FakeDevice::new();
        device.set("actual_position", 1500);
        device.refuse_read.push("actual_speed".into());
        let params = vec![
            device.param("actual_position"),
            device.param("actual_speed"),
        ];
        let mut screen = Scripted {
            frames: Vec::new(),
            after: 3,
            key: Key::Stop,
        };
        let frames = watch(&mut device, &params, Duration::from_millis(10), &mut screen).unwrap();
        assert_eq!(frames, 3);
        assert_eq!(screen.frames.len(), 3);
        let frame = &screen.frames[2];
        assert!(frame[0].starts_with("module 1 (A) every 10 ms"));
        let row: Vec<&str> = frame[2].split_whitespace().collect();
        assert_eq!(row, ["actual_position", "1500", "usteps"]);
        assert!(
            frame[3].starts_with("actual_speed")
                && frame[3].contains("error  module 1 (A) refused")
        );
    }

    #[test]
    fn ctrl_c_as_a_key_ends_the_watch_as_an_interrupt() {
        let mut device = FakeDevice::new();
        let params = vec![device.param("actual_position")];
        let mut screen = Scripted {
            frames: Vec::new(),
            after: 1,
            key: Key::Interrupt,
        };
        let result = watch(&mut device, &params, Duration::from_millis(10), &mut screen);
        assert!(matches!(result, Err(SessionError::Interrupted)));
    }

    #[test]
    fn rows_are_aligned_whatever_the_value_widths() {
        let device = FakeDevice::new();
        let params = vec![device.param("max_current"), device.param("actual_position")];
        let lines = render(
            "h",
            &params,
            &[Ok(Reading::of(5)), Ok(Reading::of(-1234567))],
        );
        let end_of = |line: &str, value: &str| line.find(value).unwrap() + value.len();
        assert_eq!(end_of(&lines[2], " 5"), end_of(&lines[3], "-1234567"));
        assert_eq!(
            lines[1].find("value").unwrap() + 5,
            end_of(&lines[3], "-1234567")
        );
    }
}
