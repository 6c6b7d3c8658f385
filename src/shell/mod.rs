//! What the REPL and non-interactive use share: a session of any dialect plus display settings,
//! and the helper commands (`:help`, `:target`, `:run` …).

pub mod batch;
pub mod commission;
mod help;
pub mod helpers;
mod line;
mod script;
pub mod terminal;
pub mod values;
pub mod words;

use std::io::Write;
use std::path::Path;

use crate::dialect::DialectSession;
use crate::script::Limits;
use crate::session::{SessionError, Transcript, interrupt};

pub use script::{run_file, run_file_with_blocks, run_source};

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
    session: Option<Box<dyn DialectSession>>,
    /// Show replies exactly as received (`:raw`).
    pub raw: bool,
    /// Put the time before each reply on screen (`:log time on`).
    pub timestamps: bool,
    /// What the commissioning helpers remember (the last recording).
    pub commission: commission::State,
}

impl Shell {
    /// A shell over an open session.
    pub fn new(session: Box<dyn DialectSession>) -> Self {
        Shell {
            session: Some(session),
            raw: false,
            timestamps: false,
            commission: Default::default(),
        }
    }

    /// The session.
    pub fn session(&mut self) -> &mut dyn DialectSession {
        self.session
            .as_deref_mut()
            .expect("the session is back after every script run")
    }

    /// The session, read-only.
    pub fn session_ref(&self) -> &dyn DialectSession {
        self.session
            .as_deref()
            .expect("the session is back after every script run")
    }

    /// Lends the session to `f` by value (scripts own the session while they run).
    pub fn lend<T>(
        &mut self,
        f: impl FnOnce(Box<dyn DialectSession>) -> (Box<dyn DialectSession>, T),
    ) -> T {
        let session = self
            .session
            .take()
            .expect("the session is back after every script run");
        let (session, result) = f(session);
        self.session = Some(session);
        result
    }

    /// The prompt: which module typed lines go to, and how (the dialect says).
    pub fn prompt(&self) -> String {
        self.session_ref().prompt()
    }

    /// Runs a helper command line (starting with `:`), writing its output to `out`.
    pub fn helper(&mut self, line: &str, out: &mut dyn Write) -> Result<Flow, SessionError> {
        let body = line.trim().trim_start_matches(':');
        let (name, arg) = match body.split_once(char::is_whitespace) {
            Some((name, arg)) => (name, arg.trim()),
            None => (body, ""),
        };
        let dialect = self.session_ref().dialect();
        let helper =
            helpers::find(name, dialect).map_err(|e| SessionError::Usage(e.to_string()))?;
        if helper.arg == crate::dialect::ArgKind::None && !arg.is_empty() {
            return Err(SessionError::Usage(format!(
                "{} takes no argument",
                helper.usage
            )));
        }
        match helper.name() {
            "help" => help::write_help(arg, dialect, self.session_ref(), out)?,
            "log" => self.set_log(arg, out)?,
            "raw" => {
                self.raw = !self.raw;
                writeln!(out, "raw output {}", if self.raw { "on" } else { "off" })?;
            }
            "source" => self.source(arg, out)?,
            "line" => line::write_line_state(self.session(), out)?,
            "snapshot" | "scan" | "watch" | "record" | "plot" => {
                let session = self.session.as_deref_mut().expect("the session is back");
                commission::helper(session, &mut self.commission, helper.name(), arg, out)?
            }
            "quit" => return Ok(Flow::Quit),
            "params" if values::values_filter(arg).is_some() => {
                let wanted = values::values_filter(arg).expect("checked")?;
                if values::write_values(self.session().param_device(), &wanted, out)? == 0 {
                    writeln!(
                        out,
                        "{}",
                        crate::escape::escape_control(&values::none_matched(&wanted))
                    )?;
                }
            }
            _ => self.session().run_helper(helper, arg, out)?,
        }
        Ok(Flow::Continue)
    }

    /// Runs a script over this shell's session; on failure the motors it moved are stopped.
    fn source(&mut self, arg: &str, out: &mut dyn Write) -> Result<(), SessionError> {
        let mut words = arg.split_whitespace();
        let path = words
            .next()
            .ok_or_else(|| SessionError::Usage("usage: :source SCRIPT.rhai [ARGS...]".into()))?;
        let args: Vec<String> = words.map(String::from).collect();
        let outcome =
            self.lend(|session| run_file(Path::new(path), &args, session, Limits::default()));
        let Err(failure) = outcome else { return Ok(()) };
        interrupt::take();
        for message in self.session().stop_motion() {
            writeln!(out, "{}", crate::escape::escape_control(&message))?;
        }
        Err(failure.into())
    }

    fn set_log(&mut self, arg: &str, out: &mut dyn Write) -> Result<(), SessionError> {
        if let Some(timestamps) = timestamps_arg(arg, self.timestamps)? {
            self.timestamps = timestamps;
            let state = if timestamps { "on" } else { "off" };
            writeln!(out, "timestamps on screen {state}")?;
            return Ok(());
        }
        let timestamps = self.timestamps;
        let session = self.session();
        if arg.is_empty() {
            let state = if timestamps { "on" } else { "off" };
            writeln!(out, "timestamps on screen {state} (:log time on|off)")?;
            match session.transcript() {
                Some(t) => match t.failure() {
                    Some(failure) => writeln!(out, "not logging: {failure}; :log FILE starts")?,
                    None => writeln!(out, "logging to {}", t.path().display())?,
                },
                None => writeln!(out, "not logging; :log FILE starts")?,
            }
        } else if arg == "off" {
            session.set_transcript(None);
            writeln!(out, "transcript stopped")?;
        } else {
            let header = session.header();
            let transcript = Transcript::open(Path::new(arg), &header)?;
            session.set_transcript(Some(transcript));
            writeln!(out, "logging to {arg}")?;
        }
        Ok(())
    }
}

/// `:log time [on|off]`: the new setting (a bare `time` toggles), or `None` for other arguments.
fn timestamps_arg(arg: &str, now: bool) -> Result<Option<bool>, SessionError> {
    let mut words = arg.split_whitespace();
    if words.next() != Some("time") {
        return Ok(None);
    }
    match (words.next(), words.next()) {
        (None, _) => Ok(Some(!now)),
        (Some("on"), None) => Ok(Some(true)),
        (Some("off"), None) => Ok(Some(false)),
        _ => Err(SessionError::Usage("usage: :log time [on|off]".into())),
    }
}

/// The time of day to put before a line on screen (`:log time on`): UTC with milliseconds, the
/// clock of the transcript's timestamps, so the two can be read side by side.
pub fn time_of_day() -> String {
    let now = humantime::format_rfc3339_millis(std::time::SystemTime::now()).to_string();
    now.split_once('T')
        .map_or(now.clone(), |(_, time)| time.to_string())
}
