//! The control console of `tmclsh sim`: one command per line on stdin, one answer line on stdout
//! (`ok …` or `error: …`), so a test can change inputs and switches or trigger faults while the
//! simulator runs, and wait for the answer before going on.

use std::sync::{Arc, Mutex};
use std::time::Duration;

use super::Device;
use super::error::ConsoleError;
use super::inprocess::SharedDevice;
use crate::clock::{Clock, ManualClock};

/// What every console says before the commands of its simulator.
const HELP_TITLE: &str = "Console commands (one per line on stdin; each is answered by one line, `ok ...` or `error: ...`):";

/// The commands of one simulator's console (or of every console) under a heading: the table
/// both `tmclsh sim --help` and the console's `help` read.
#[derive(Debug, Clone, Copy)]
pub struct Section {
    /// Whose commands they are (`SMD4 drive (--protocol smd4)`).
    pub heading: &'static str,
    /// The commands in the order the help lists them, each its syntax (alternatives joined by
    /// ` | `, the first word of each a name `help` lists) and what it does, in lines as
    /// `tmclsh sim --help` shows them.
    pub commands: &'static [(&'static str, &'static str)],
}

/// The commands every simulator's console has (faults, time, quitting).
const SHARED: Section = Section {
    heading: "Both",
    commands: &[
        (
            "drop RATE | corrupt RATE",
            "drop or corrupt replies from now on (RATE 0..1)",
        ),
        ("delay RATE MS", "hold replies back by MS milliseconds"),
        (
            "seed N",
            "restart the fault decisions from seed N (and the counts)",
        ),
        (
            "faults",
            "show the seed and the faults injected since it was set",
        ),
        (
            "silent on|off",
            "stop or resume answering (commands still execute)",
        ),
        ("hangup", "hang up the connection now"),
        (
            "unplug SECS",
            "with --pty: the adapter goes away (the pty closes, the client\n\
             reads EOF or EIO) and comes back after SECS on a new pty, another\n\
             number, its path printed as `pty PATH` and behind --link; the\n\
             modules keep their state (only the adapter was unplugged)",
        ),
        (
            "advance DURATION",
            "with --manual-clock: let time pass (2s, 250ms, 1.5s; plain = ms)",
        ),
        ("time", "show the simulation time"),
        ("quit", "end the simulator"),
    ],
};

/// The column a command's description starts at.
const DOES_AT: usize = 37;

/// The console commands, for `tmclsh sim --help`: those of each simulator's section, then those
/// every console has, each section a heading line and one line per command (its description's
/// further lines indented to its column).
pub fn help<'a>(sections: impl IntoIterator<Item = &'a Section>) -> String {
    let mut text = HELP_TITLE.to_string();
    for section in sections.into_iter().chain([&SHARED]) {
        text.push_str(&format!("\n {}:", section.heading));
        for (syntax, does) in section.commands {
            let syntax = format!("  {syntax}");
            let mut lines = does.lines();
            let first = lines.next().unwrap_or_default();
            text.push_str(&format!("\n{syntax:<width$}{first}", width = DOES_AT));
            for line in lines {
                text.push_str(&format!("\n{:DOES_AT$}{line}", ""));
            }
        }
    }
    text
}

/// What a console line asks for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Answer {
    /// Done; the text says what.
    Ok(String),
    /// Refused, and why.
    Error(ConsoleError),
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

/// The longest outage `unplug` simulates.
const LONGEST_UNPLUG: Duration = Duration::from_secs(3600);

/// An `unplug` asked for on the console and not yet acted on by the pty server: the adapter, not
/// the module, goes away, so it is the server's business rather than the device's.
#[derive(Debug, Default)]
pub struct Unplug(Mutex<Option<Duration>>);

impl Unplug {
    /// Asks for an outage of `secs`.
    fn ask(&self, outage: Duration) {
        *self.0.lock().unwrap_or_else(|e| e.into_inner()) = Some(outage);
    }

    /// The outage asked for, once.
    pub fn take(&self) -> Option<Duration> {
        self.0.lock().unwrap_or_else(|e| e.into_inner()).take()
    }
}

/// The line a console command must not overtake. The console reads stdin on its own thread while
/// the server reads the line on another, so a command (`quit`, `power-cycle`) could act before
/// bytes a client wrote earlier had been read; every command first hands the device whatever the
/// line has readable now, under the device's lock, as the server does with what it reads.
pub trait Line: Send + Sync {
    /// Hands `device` the bytes waiting on the line, without waiting for more.
    fn catch_up(&self, device: &mut dyn Device, now: Duration);
}

/// A console attached to a device and its clock.
pub struct Console {
    device: SharedDevice,
    clock: Arc<dyn Clock>,
    manual: Option<Arc<ManualClock>>,
    /// The simulator's own commands, which `help` names before every console's.
    commands: &'static Section,
    /// Where `unplug` goes: the pty server's (none on TCP).
    unplug: Option<Arc<Unplug>>,
    /// The line served, whose waiting bytes go to the device before each command.
    line: Option<Arc<dyn Line>>,
}

impl Console {
    /// `manual` is the clock when time only moves on `advance`; `commands` are the simulator's
    /// own, which the console's `help` names.
    pub fn new(
        device: SharedDevice,
        clock: Arc<dyn Clock>,
        manual: Option<Arc<ManualClock>>,
        commands: &'static Section,
    ) -> Self {
        Console {
            device,
            clock,
            manual,
            commands,
            unplug: None,
            line: None,
        }
    }

    /// Lets `unplug` reach the pty server.
    pub fn with_unplug(mut self, unplug: Arc<Unplug>) -> Self {
        self.unplug = Some(unplug);
        self
    }

    /// Orders each command after what a client already wrote on `line`.
    pub fn with_line(mut self, line: Arc<dyn Line>) -> Self {
        self.line = Some(line);
        self
    }

    /// Runs one line, after the bytes already waiting on the line have reached the device.
    pub fn run(&self, line: &str) -> Answer {
        let mut device = self.device.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(served) = &self.line {
            served.catch_up(&mut *device, self.clock.now());
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            [] => Answer::Ok(String::new()),
            ["quit" | "exit"] => Answer::Quit,
            ["help"] => Answer::Ok(summary([self.commands, &SHARED])),
            ["time"] => Answer::Ok(format!("{:.6} s", self.clock.now().as_secs_f64())),
            ["advance", amount] => match (&self.manual, crate::duration::parse(amount)) {
                (None, _) => Answer::Error(ConsoleError::Needs {
                    command: "advance",
                    what: "--manual-clock",
                }),
                (_, Err(e)) => Answer::Error(ConsoleError::Time(e)),
                (Some(clock), Ok(d)) => {
                    clock.advance(d);
                    Answer::Ok(format!("{:.6} s", clock.now().as_secs_f64()))
                }
            },
            ["unplug", secs] => match (&self.unplug, unplug_time(secs)) {
                (None, _) => Answer::Error(ConsoleError::Needs {
                    command: "unplug",
                    what: "a pseudo-terminal (--pty); on TCP use hangup",
                }),
                (_, Err(e)) => Answer::Error(e),
                (Some(unplug), Ok(outage)) => {
                    unplug.ask(outage);
                    Answer::Ok(format!(
                        "unplugged for {} s; the pty comes back on a new number",
                        outage.as_secs_f64()
                    ))
                }
            },
            _ => {
                let now = self.clock.now();
                match device.control(now, line.trim()) {
                    Some(Ok(text)) => Answer::Ok(text),
                    Some(Err(e)) => Answer::Error(e),
                    None => Answer::Error(ConsoleError::Unknown(words[0].to_string())),
                }
            }
        }
    }
}

/// The outage of `unplug SECS`: seconds, fractions allowed, at most an hour.
fn unplug_time(secs: &str) -> Result<Duration, ConsoleError> {
    secs.parse::<f64>()
        .ok()
        .filter(|s| s.is_finite() && *s >= 0.0)
        .map(Duration::from_secs_f64)
        .filter(|d| *d <= LONGEST_UNPLUG)
        .ok_or_else(|| {
            ConsoleError::bad(
                secs,
                "a time in seconds from 0 to 3600 (unplug 2, unplug 0.5)",
            )
        })
}

/// The answer to `help`: the command names on one line (the console answers every command with
/// one line; `tmclsh sim --help` describes them).
fn summary(sections: [&Section; 2]) -> String {
    let mut names: Vec<&str> = Vec::new();
    let commands = sections.iter().flat_map(|s| s.commands);
    for form in commands.flat_map(|(syntax, _)| syntax.split(" | ")) {
        let name = form.split_whitespace().next().unwrap_or_default();
        if !name.is_empty() && !names.contains(&name) {
            names.push(name);
        }
    }
    format!(
        "commands: {} (tmclsh sim --help describes them)",
        names.join(" ")
    )
}

#[cfg(test)]
mod tests {
    use std::sync::Mutex;
    use std::time::Duration;

    use super::*;
    use crate::dialect::tmcl::sim::Bus;

    fn console(manual: bool) -> (Console, Arc<ManualClock>) {
        let clock = Arc::new(ManualClock::new());
        let device: SharedDevice = Arc::new(Mutex::new(Bus::builtin()));
        let section = crate::dialect::tmcl::DIALECT.console;
        let console = Console::new(
            device,
            clock.clone(),
            manual.then(|| clock.clone()),
            section,
        );
        (console, clock)
    }

    #[test]
    fn advance_reads_times_as_everything_else_does() {
        // The grammar is `crate::duration`'s (tested there): a bare number is milliseconds.
        let (console, clock) = console(true);
        assert_eq!(console.run("advance 1.5"), Answer::Ok("0.001500 s".into()));
        assert_eq!(console.run("advance 2s"), Answer::Ok("2.001500 s".into()));
        assert_eq!(clock.now(), Duration::from_micros(2_001_500));
        for refused in ["-1s", "soon", "8days"] {
            assert!(
                matches!(console.run(&format!("advance {refused}")), Answer::Error(_)),
                "{refused}"
            );
        }
        assert_eq!(clock.now(), Duration::from_micros(2_001_500));
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

    #[test]
    fn unplug_hands_its_outage_to_the_server_once() {
        let (console, _) = console(true);
        let unplug = Arc::new(Unplug::default());
        let console = console.with_unplug(unplug.clone());
        assert!(
            console
                .run("unplug 1.5")
                .line()
                .starts_with("ok unplugged for 1.5 s")
        );
        assert_eq!(unplug.take(), Some(Duration::from_millis(1500)));
        assert_eq!(unplug.take(), None);
        for refused in ["-1", "soon", "NaN", "3601"] {
            assert!(
                matches!(console.run(&format!("unplug {refused}")), Answer::Error(_)),
                "{refused}"
            );
        }
        assert_eq!(unplug.take(), None);
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
        let names: Vec<&str> = help.split_whitespace().collect();
        for name in ["limit", "flash-failure", "microsteps)", "back", "reads"] {
            assert!(!names.contains(&name), "{name} in {help}");
        }
        for name in [
            "input", "@N", "switch", "reset", "drop", "corrupt", "seed", "faults", "quit",
        ] {
            assert!(
                help.split_whitespace().any(|w| w == name),
                "{name} in {help}"
            );
        }
        assert!(
            console
                .run("unplug 2")
                .line()
                .starts_with("error: unplug needs a pseudo-terminal")
        );
        assert_eq!(console.run("quit"), Answer::Quit);
        assert_eq!(console.run("").line(), "ok");
    }
}
