//! What the REPL and non-interactive use share: a session plus display settings, and the helper
//! commands (`:help`, `:target`, `:run` …).

pub mod batch;
pub mod helpers;
pub mod render;

use std::io::{self, Write};
use std::path::Path;

use crate::cli::download;
use crate::cli::params::write_table;
use crate::program;
use crate::protocol::tmcl::Instruction;
use crate::protocol::tmcl::line::{address_char, address_of};
use crate::script::{self, Limits};
use crate::session::tmcl::{Echo, Exchange, TmclSession, WireMode};
use crate::session::{SessionError, Transcript, interrupt};

use helpers::ArgKind;

/// Whether to go on after a helper command.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flow {
    /// Read the next line.
    Continue,
    /// Leave.
    Quit,
}

/// A session and how its results are shown.
pub struct Shell {
    /// The conversation with the modules; lent out while a script runs (`:source`).
    session: Option<TmclSession>,
    /// Show replies exactly as received (`:raw`).
    pub raw: bool,
}

impl Shell {
    /// A shell over an open session.
    pub fn new(session: TmclSession) -> Self {
        Shell {
            session: Some(session),
            raw: false,
        }
    }

    /// The session.
    pub fn session(&mut self) -> &mut TmclSession {
        self.session
            .as_mut()
            .expect("the session is back after every script run")
    }

    /// The session, read-only.
    pub fn session_ref(&self) -> &TmclSession {
        self.session
            .as_ref()
            .expect("the session is back after every script run")
    }

    /// Lends the session to `f` by value (scripts own the session while they run).
    pub fn lend<T>(&mut self, f: impl FnOnce(TmclSession) -> (TmclSession, T)) -> T {
        let session = self
            .session
            .take()
            .expect("the session is back after every script run");
        let (session, result) = f(session);
        self.session = Some(session);
        result
    }

    /// The prompt: the target's address character, and the wire mode when it is binary.
    pub fn prompt(&self) -> String {
        let session = self.session_ref();
        let target = session.target();
        let c = address_char(target).unwrap_or('?');
        match session.module_state(target) {
            Some((WireMode::Binary, _)) => format!("{c}[bin]> "),
            _ => format!("{c}> "),
        }
    }

    /// Runs a helper command line (starting with `:`), writing its output to `out`.
    pub fn helper(&mut self, line: &str, out: &mut dyn Write) -> Result<Flow, SessionError> {
        let body = line.trim().trim_start_matches(':');
        let (name, arg) = match body.split_once(char::is_whitespace) {
            Some((name, arg)) => (name, arg.trim()),
            None => (body, ""),
        };
        let helper = helpers::find(name).map_err(SessionError::Usage)?;
        if helper.arg == ArgKind::None && !arg.is_empty() {
            return Err(SessionError::Usage(format!(
                "{} takes no argument",
                helper.usage
            )));
        }
        let target = self.session().target();
        match helper.name {
            "help" => write_help(arg, self.session().profile(), out)?,
            "params" => {
                let profile = self.session().profile().clone();
                let rows: Vec<_> = profile.matching(arg).collect();
                if rows.is_empty() {
                    writeln!(out, "no parameter matches '{arg}'")?;
                } else {
                    write_table(&rows, out)?;
                }
            }
            "target" => {
                let module = parse_module(arg)?;
                self.session().set_target(module)?;
                writeln!(
                    out,
                    "target: module {} ({})",
                    module,
                    address_char(module).unwrap_or('?')
                )?;
            }
            "echo" => {
                let echo = Echo::parse(arg)
                    .ok_or_else(|| SessionError::Usage(format!("usage: {}", helper.usage)))?;
                let echo = self.session().set_echo(target, echo)?;
                writeln!(out, "echo: {}", echo.name())?;
            }
            "log" => self.set_log(arg, out)?,
            "raw" => {
                self.raw = !self.raw;
                writeln!(out, "raw output {}", if self.raw { "on" } else { "off" })?;
            }
            "run" => {
                let address = parse_address(arg)?;
                let exchange = self.session().run_program(target, address)?.checked()?;
                self.report_program(&exchange, "started", out)?;
            }
            "stop" => {
                let exchange = self.session().stop_program(target)?.checked()?;
                self.report_program(&exchange, "stopped", out)?;
            }
            "step" | "reset" | "status" => {
                let command = match helper.name {
                    "step" => 130,
                    "reset" => 131,
                    _ => 135,
                };
                let exchange =
                    program::control(self.session(), target, Instruction::new(command, 0, 0, 0))?;
                let mode = program::mode_text(self.session_ref(), target);
                let c = address_char(target).unwrap_or('?');
                match helper.name {
                    "status" => {
                        let value = exchange.value().unwrap_or(0);
                        writeln!(
                            out,
                            "program on module {c}: {} ({value}); the module is in {mode} mode",
                            program::status_name(value)
                        )?
                    }
                    name => writeln!(
                        out,
                        "program {name} done on module {c}; the module is in {mode} mode"
                    )?,
                }
            }
            "download" => {
                let (path, run) = match arg.strip_suffix("--run") {
                    Some(path) => (path.trim(), true),
                    None => (arg, false),
                };
                if path.is_empty() {
                    return Err(SessionError::Usage(format!("usage: {}", helper.usage)));
                }
                let profile = self.session_ref().profile().clone();
                let script_error = |f: crate::cli::Failure| SessionError::Script {
                    exit: f.exit,
                    message: f.message,
                };
                let instructions =
                    download::load(Path::new(path), &profile).map_err(script_error)?;
                let text = download::download_and_run(self.session(), &instructions, run)
                    .map_err(script_error)?;
                writeln!(out, "{text}")?;
            }
            "bin" => {
                self.session().leave_ascii(target)?;
                writeln!(
                    out,
                    "module {} is in binary direct mode: lines go out as binary frames (:ascii returns)",
                    address_char(target).unwrap_or('?')
                )?;
            }
            "ascii" => {
                self.session().enter_ascii(target)?;
                writeln!(
                    out,
                    "module {} is in ASCII mode",
                    address_char(target).unwrap_or('?')
                )?;
            }
            "source" => self.source(arg, out)?,
            "quit" => return Ok(Flow::Quit),
            other => unreachable!("helper table and dispatch disagree on :{other}"),
        }
        Ok(Flow::Continue)
    }

    fn report_program(
        &mut self,
        exchange: &Exchange,
        verb: &str,
        out: &mut dyn Write,
    ) -> io::Result<()> {
        let module = exchange.module;
        let mode = match self.session().module_state(module) {
            Some((WireMode::Binary, _)) => "binary",
            _ => "ASCII",
        };
        writeln!(
            out,
            "program {verb} on module {}; the module is in {mode} mode",
            address_char(module).unwrap_or('?')
        )
    }

    /// Runs a script over this shell's session; on failure the motors it moved are stopped.
    fn source(&mut self, arg: &str, out: &mut dyn Write) -> Result<(), SessionError> {
        let mut words = arg.split_whitespace();
        let path = words
            .next()
            .ok_or_else(|| SessionError::Usage("usage: :source SCRIPT.rhai [ARGS...]".into()))?;
        let args: Vec<String> = words.map(String::from).collect();
        let outcome = self
            .lend(|session| script::run_file(Path::new(path), &args, session, Limits::default()));
        let Err(report) = outcome else { return Ok(()) };
        interrupt::take();
        for message in self.session().stop_motion() {
            writeln!(out, "{message}")?;
        }
        Err(SessionError::Script {
            exit: report.exit,
            message: report.message,
        })
    }

    fn set_log(&mut self, arg: &str, out: &mut dyn Write) -> Result<(), SessionError> {
        if arg.is_empty() {
            match self.session().transcript() {
                Some(t) => writeln!(out, "logging to {}", t.path().display())?,
                None => writeln!(out, "not logging; :log FILE starts")?,
            }
        } else if arg == "off" {
            self.session().set_transcript(None);
            writeln!(out, "transcript stopped")?;
        } else {
            let transcript = Transcript::open(Path::new(arg))
                .map_err(|e| SessionError::Usage(format!("cannot open log file {arg}: {e}")))?;
            self.session().set_transcript(Some(transcript));
            writeln!(out, "logging to {arg}")?;
        }
        Ok(())
    }
}

impl From<io::Error> for SessionError {
    fn from(e: io::Error) -> Self {
        SessionError::Link(format!("output: {e}"))
    }
}

fn parse_module(arg: &str) -> Result<u8, SessionError> {
    let usage = || {
        SessionError::Usage(format!(
            "usage: :target N|CHAR (1..26 or A..Z), not '{arg}'"
        ))
    };
    if let Ok(n) = arg.parse::<u8>() {
        return (1..=26).contains(&n).then_some(n).ok_or_else(usage);
    }
    let mut chars = arg.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) => address_of(c).ok_or_else(usage),
        _ => Err(usage()),
    }
}

fn parse_address(arg: &str) -> Result<Option<i32>, SessionError> {
    if arg.is_empty() {
        return Ok(None);
    }
    arg.parse::<i32>()
        .ok()
        .filter(|a| *a >= 0)
        .map(Some)
        .ok_or_else(|| {
            SessionError::Usage(format!(
                "usage: :run [address], address a number, not '{arg}'"
            ))
        })
}

fn write_help(
    topic: &str,
    profile: &crate::profile::Profile,
    out: &mut dyn Write,
) -> io::Result<()> {
    let topic = topic.trim().trim_start_matches(':');
    if topic.is_empty() {
        writeln!(
            out,
            "Type TMCL commands as in the TMCL-IDE, e.g. GAP actual_position, 0 or MVP ABS, 0, 1000."
        )?;
        writeln!(
            out,
            "Parameter names work in place of numbers; Tab completes, hints show units and ranges."
        )?;
        writeln!(
            out,
            "A leading address character reaches another module: CGAP 4, 0.\n"
        )?;
        writeln!(out, "Helper commands:")?;
        for h in helpers::HELPERS {
            writeln!(out, "  {:<24} {}", h.usage, h.summary)?;
        }
        writeln!(
            out,
            "\nMore: :help COMMAND, :help params, :help exit, :help ascii"
        )?;
        return Ok(());
    }
    match topic.to_ascii_lowercase().as_str() {
        "params" => writeln!(
            out,
            "Parameters are listed by :params [filter]; use their names in SAP/GAP/SGP/GGP lines."
        )?,
        "exit" => writeln!(
            out,
            "Exit codes: 0 success, 1 device error status or failed assertion, 2 refused before sending, 3 connection/timeout/lost link, 130 Ctrl-C."
        )?,
        "ascii" => {
            writeln!(
                out,
                "ASCII mode (manual 6.6): lines are <address char><command>, replies <host char><module char> <status> <value>."
            )?;
            writeln!(
                out,
                "Only ROL ROR MST MVP SAP GAP STAP RSAP SGP GGP STGP RSGP RFS SIO GIO SAC SCO GCO CCO UF0-UF7, plus BIN RUN STOP."
            )?;
            writeln!(
                out,
                "Echo (GP 67 bits 4/5): char, line or none (:echo). :bin switches to binary frames for the rest."
            )?;
        }
        word => {
            if let Ok(h) = helpers::find(word) {
                writeln!(out, "{:<24} {}", h.usage, h.summary)?;
            } else if let Some(spec) = profile.commands.by_mnemonic(word).or_else(|| {
                word.parse()
                    .ok()
                    .and_then(|n| profile.commands.by_number(n))
            }) {
                writeln!(
                    out,
                    "{} — {} (command {})",
                    spec.usage(),
                    spec.name,
                    spec.number
                )?;
                for k in &spec.keywords {
                    writeln!(out, "  {:<8} {}", k.name, k.meaning)?;
                }
                let place = match (spec.ascii_allowed, spec.direct_mode) {
                    (true, _) => "ASCII and binary direct mode",
                    (false, true) => "binary direct mode only (:bin)",
                    (false, false) => "stand-alone programs only",
                };
                writeln!(out, "  usable in: {place}")?;
            } else {
                writeln!(out, "no help on '{topic}'; :help lists topics")?;
            }
        }
    }
    Ok(())
}
