//! The control console of `tmclsh sim`: one command per line on stdin, one answer line on stdout
//! (`ok …` or `error: …`), so a test can change inputs and switches or trigger faults while the
//! simulator runs, and wait for the answer before going on.

use std::sync::Arc;
use std::time::Duration;

use super::clock::{Clock, ManualClock};
use super::inprocess::SharedDevice;

/// The console commands, for `--help` and `help`.
pub const HELP: &str = "\
Console commands (one per line on stdin; each is answered by one line, `ok ...` or `error: ...`):
 TMCL module bus (--protocol tmcl):
  input PORT 0|1                     set a digital input (GIO bank 0)
  analog PORT VALUE                  set an analog input (GIO bank 1, 0..1023)
  switch left|right|home POS|off     move a virtual switch (physical microsteps) or disconnect it
  output PORT                        show an output (SIO bank 2)
  motor                              show position, target, velocity, target reached
  @N COMMAND                         any of the above for the module with factory address N
 SMD4 drive (--protocol smd4):
  limit pos|neg 0|1                  set the level of a limit input (active after LIMIT:POL+/-)
  exten 0|1                          set the external enable input
  joystick 0|1                       plug a joystick in or out
  fault BIT|NAME                     latch an EFLAGS bit (e.g. 2 or TempOver); the motor stops
  flash-failure on|off               make STORE fail with -5 (worn-out flash) or work again
  power-cycle                        restart from the stored configuration
  motor                              show position, velocity, standby, target velocity reached
  flags                              show SFLAGS, EFLAGS and whether addressing mode is on
  setting MNEMONIC                   show a working setting (e.g. COMS:SERIAL:SLAVEADDR)
 Both:
  drop RATE | corrupt RATE           drop or corrupt replies from now on (RATE 0..1)
  delay RATE MS                      hold replies back by MS milliseconds
  seed N                             restart the fault decisions from seed N (and the counts)
  faults                             show the seed and the faults injected since it was set
  silent on|off                      stop or resume answering (commands still execute)
  hangup                             hang up the connection now
  advance DURATION                   with --manual-clock: let time pass (2s, 250ms, 1.5; plain = s)
  time                               show the simulation time
  quit                               end the simulator";

/// What a console line asks for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Answer {
    /// Done; the text says what.
    Ok(String),
    /// Refused; the text says why.
    Error(String),
    /// End the simulator.
    Quit,
}

impl Answer {
    /// The answer line (empty for `Quit`).
    pub fn line(&self) -> String {
        match self {
            Answer::Ok(text) if text.is_empty() => "ok".into(),
            Answer::Ok(text) => format!("ok {text}"),
            Answer::Error(text) => format!("error: {text}"),
            Answer::Quit => String::new(),
        }
    }
}

/// A console attached to a device and its clock.
pub struct Console {
    device: SharedDevice,
    clock: Arc<dyn Clock>,
    manual: Option<Arc<ManualClock>>,
}

impl Console {
    /// `manual` is the clock when time only moves on `advance`.
    pub fn new(
        device: SharedDevice,
        clock: Arc<dyn Clock>,
        manual: Option<Arc<ManualClock>>,
    ) -> Self {
        Console {
            device,
            clock,
            manual,
        }
    }

    /// Runs one line.
    pub fn run(&self, line: &str) -> Answer {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            [] => Answer::Ok(String::new()),
            ["quit" | "exit"] => Answer::Quit,
            ["help"] => Answer::Ok(summary()),
            ["time"] => Answer::Ok(format!("{:.6} s", self.clock.now().as_secs_f64())),
            ["advance", amount] => match (&self.manual, parse_duration(amount)) {
                (None, _) => Answer::Error("advance needs --manual-clock".into()),
                (_, Err(e)) => Answer::Error(e),
                (Some(clock), Ok(d)) => {
                    clock.advance(d);
                    Answer::Ok(format!("{:.6} s", clock.now().as_secs_f64()))
                }
            },
            _ => {
                let now = self.clock.now();
                let mut device = self.device.lock().unwrap_or_else(|e| e.into_inner());
                match device.control(now, line.trim()) {
                    Some(Ok(text)) => Answer::Ok(text),
                    Some(Err(text)) => Answer::Error(text),
                    None => Answer::Error(format!("unknown command '{}'; try help", words[0])),
                }
            }
        }
    }
}

/// The answer to `help`: the command names on one line (the console answers every command with
/// one line; `tmclsh sim --help` describes them).
fn summary() -> String {
    let mut names: Vec<&str> = Vec::new();
    for line in HELP.lines().filter(|l| l.starts_with("  ")) {
        let syntax = line.trim().split("  ").next().unwrap_or_default();
        for form in syntax.split(" | ") {
            let name = form.split_whitespace().next().unwrap_or_default();
            if !name.is_empty() && !names.contains(&name) {
                names.push(name);
            }
        }
    }
    format!(
        "commands: {} (tmclsh sim --help describes them)",
        names.join(" ")
    )
}

/// `2s`, `250ms`, `10us`, `1.5` (seconds); decimal digits are taken exactly, to the
/// nanosecond.
pub fn parse_duration(text: &str) -> Result<Duration, String> {
    let (number, unit_ns) = if let Some(n) = text.strip_suffix("ms") {
        (n, 1_000_000u128)
    } else if let Some(n) = text.strip_suffix("us") {
        (n, 1_000)
    } else if let Some(n) = text.strip_suffix('s') {
        (n, 1_000_000_000)
    } else {
        (text, 1_000_000_000)
    };
    let bad = || format!("'{text}' is not a duration (e.g. 2s, 250ms)");
    let (whole, fraction) = number.split_once('.').unwrap_or((number, ""));
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if (whole.is_empty() && fraction.is_empty()) || !digits(whole) || !digits(fraction) {
        return Err(bad());
    }
    let whole: u128 = if whole.is_empty() {
        0
    } else {
        whole.parse().map_err(|_| bad())?
    };
    let mut nanos = whole.checked_mul(unit_ns).ok_or_else(bad)?;
    let mut scale = unit_ns;
    for digit in fraction.bytes() {
        scale /= 10;
        nanos += u128::from(digit - b'0') * scale;
    }
    u64::try_from(nanos)
        .map(Duration::from_nanos)
        .map_err(|_| bad())
}

#[cfg(test)]
mod tests {
    use std::sync::Mutex;

    use super::*;
    use crate::sim::tmcl::Bus;

    fn console(manual: bool) -> (Console, Arc<ManualClock>) {
        let clock = Arc::new(ManualClock::new());
        let device: SharedDevice = Arc::new(Mutex::new(Bus::builtin()));
        let console = Console::new(device, clock.clone(), manual.then(|| clock.clone()));
        (console, clock)
    }

    #[test]
    fn durations_take_units() {
        assert_eq!(parse_duration("2s"), Ok(Duration::from_secs(2)));
        assert_eq!(parse_duration("250ms"), Ok(Duration::from_millis(250)));
        assert_eq!(parse_duration("1.5"), Ok(Duration::from_millis(1500)));
        assert_eq!(parse_duration("18.75ms"), Ok(Duration::from_micros(18_750)));
        assert_eq!(parse_duration("5.24s"), Ok(Duration::from_millis(5240)));
        assert!(parse_duration("-1s").is_err());
        assert!(parse_duration("soon").is_err());
    }

    #[test]
    fn advance_moves_only_a_manual_clock() {
        let (console, clock) = console(true);
        assert_eq!(
            console.run("advance 1.25s"),
            Answer::Ok("1.250000 s".into())
        );
        assert_eq!(clock.now(), Duration::from_millis(1250));
        let (console, _) = console_without_manual();
        assert!(matches!(console.run("advance 1s"), Answer::Error(_)));
    }

    fn console_without_manual() -> (Console, Arc<ManualClock>) {
        console(false)
    }

    #[test]
    fn device_commands_and_errors_are_answered() {
        let (console, _) = console(true);
        assert_eq!(console.run("input 3 1").line(), "ok input 3 = 1");
        assert_eq!(
            console.run("switch left -500").line(),
            "ok switch left at -500"
        );
        assert!(console.run("motor").line().starts_with("ok position 0 "));
        assert!(
            console
                .run("input 99 1")
                .line()
                .starts_with("error: no digital input 99")
        );
        assert!(
            console
                .run("fly")
                .line()
                .starts_with("error: unknown command 'fly'")
        );
        let help = console.run("help").line();
        assert!(!help.contains('\n'), "one line: {help}");
        for name in [
            "input",
            "@N",
            "limit",
            "flash-failure",
            "drop",
            "corrupt",
            "seed",
            "faults",
            "quit",
        ] {
            assert!(
                help.split_whitespace().any(|w| w == name),
                "{name} in {help}"
            );
        }
        assert_eq!(console.run("quit"), Answer::Quit);
        assert_eq!(console.run("").line(), "ok");
    }
}
