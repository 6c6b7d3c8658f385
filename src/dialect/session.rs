//! An open session of any dialect, as the faces (the REPL, `-c`/stdin lines, scripts, the
//! commissioning helpers, the CLI) use it: one object-safe trait for the wire, its presentation
//! in [`Faces`]. What every dialect does alike
//! is written here once, over the [`SessionCore`] each session holds; a dialect implements only
//! what differs. Code that needs a dialect's own session type downcasts inside that dialect's
//! folder ([`AsAny`]).

use std::any::Any;
use std::fmt;
use std::sync::Arc;
use std::time::Duration;

use crate::commission::ParamDevice;
use crate::exit::Failure;
use crate::script::{Registrar, Script};
use crate::session::core::SessionCore;
use crate::session::transcript::{Header, Transcript};
use crate::session::{SessionError, SessionOptions};

use super::{Dialect, Faces};

/// A typed line's outcome, in the forms the faces show it.
#[derive(Debug, Clone)]
pub struct Reply {
    /// The answer as the module sent it, for stdout in non-interactive use: the reply line
    /// without echo and line ending, the version string of TMCL command 136, the lines of an
    /// SMD4 reply.
    pub shown: String,
    /// The answer decoded for people (the REPL): `actual_position = -5000 usteps`.
    pub decoded: String,
    /// The error status or code the module answered with, if any.
    pub refusal: Option<Refusal>,
    /// The forms of the output modes (`--value`, `--json`), made when asked for.
    pub forms: Arc<dyn ReplyForms>,
}

/// A reply in the output modes of non-interactive use, made from the dialect's own exchange only
/// when a mode asks for it.
pub trait ReplyForms: fmt::Debug + Send + Sync {
    /// Only the value (`--value`): TMCL the number (or the version string of 136), SMD4 the data
    /// items as received; empty when the module sends no reply.
    fn value(&self) -> String;

    /// The dialect's fields of the line's JSON object (`--json`): where it went, whether it
    /// succeeded, status or flags and error, value or items, the reply as received.
    fn json_fields(&self) -> Vec<(&'static str, serde_json::Value)>;
}

/// How a reply reads to a person, and whether it is good news.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Decoded {
    /// The text (`actual_position = -5000 usteps`).
    pub text: String,
    /// Whether the module reported success.
    pub ok: bool,
}

/// A module's answer that it could not do what was asked: an error status or error code.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    /// The module as messages name it (`module 1 (A)`, `drive @3`).
    pub module: String,
    /// The line sent.
    pub sent: String,
    /// The status or error it answered.
    pub reason: String,
}

impl From<Refusal> for SessionError {
    fn from(refusal: Refusal) -> Self {
        SessionError::Device {
            module: refusal.module,
            sent: refusal.sent,
            reason: refusal.reason,
        }
    }
}

impl Reply {
    /// Whether the module reported success.
    pub fn ok(&self) -> bool {
        self.refusal.is_none()
    }

    /// The reply, or the device error it carries (exit 1).
    pub fn checked(self) -> Result<Reply, SessionError> {
        match self.refusal {
            Some(refusal) => Err(refusal.into()),
            None => Ok(self),
        }
    }
}

/// What a bus scan found, ready to print.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BusScan {
    /// How many modules answered.
    pub found: usize,
    /// One line: how many answered where (`3 modules answered at 1-26 …`).
    pub summary: String,
    /// The table of modules found, the summary line and any notes, line by line.
    pub report: String,
    /// Each module found as a JSON object (`scan --json`; fields in docs/machine-output.md).
    pub modules: Vec<crate::json::Value>,
}

/// Any value as [`Any`], so a dialect can get its own session type back from a trait object.
pub trait AsAny: Any {
    /// As a reference to [`Any`].
    fn as_any(&self) -> &dyn Any;
    /// As a mutable reference to [`Any`].
    fn as_any_mut(&mut self) -> &mut dyn Any;
    /// As a box of [`Any`].
    fn into_any(self: Box<Self>) -> Box<dyn Any>;
}

impl<T: Any> AsAny for T {
    fn as_any(&self) -> &dyn Any {
        self
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }

    fn into_any(self: Box<Self>) -> Box<dyn Any> {
        self
    }
}

/// An open session of one dialect: the wire. What the faces show of it is its [`Faces`].
pub trait DialectSession: Faces + AsAny {
    /// The dialect spoken.
    fn dialect(&self) -> &'static Dialect;

    /// The state every session shares.
    fn core(&self) -> &SessionCore;

    /// The state every session shares, to change.
    fn core_mut(&mut self) -> &mut SessionCore;

    /// Parses, validates and sends one typed line. An error status or code from the module is an
    /// `Ok` reply whose [`Reply::ok`] is false.
    fn execute(&mut self, line: &str) -> Result<Reply, SessionError>;

    /// Stops whatever this session set moving (motors, programs), at once even on a line that
    /// has not settled since a failure; returns what was done.
    fn stop_motion(&mut self) -> Vec<String>;

    /// The address of the module or drive typed lines go to, which Ctrl-C stops even when this
    /// session did not start it.
    fn target_address(&self) -> Option<u32>;

    /// Ends the session, putting modules back in the mode they were found in; returns what was
    /// done.
    fn close(&mut self) -> Vec<String>;

    /// The header of this session's transcripts (`:log FILE`).
    fn header(&self) -> Header;

    /// The module talked to, as the commissioning tools see it (snapshots, watches,
    /// recordings).
    fn param_device(&mut self) -> &mut dyn ParamDevice;

    /// Finds the modules at `addresses`, awaiting each reply at most `per_reply`.
    fn scan_bus(&mut self, addresses: &[u8], per_reply: Duration) -> Result<BusScan, SessionError>;

    /// Runs `script` over this session, with the dialect's device functions and the
    /// commissioning functions; gives the session back with the outcome.
    fn run_script(
        self: Box<Self>,
        script: &Script,
    ) -> (Box<dyn DialectSession>, Result<(), Failure>);

    /// After the link was reopened: puts the modules back in the mode the session had them in.
    fn reenter(&mut self) -> Result<(), SessionError> {
        Ok(())
    }

    /// What the link talks to.
    fn describe(&self) -> String {
        self.core().describe()
    }

    /// The session's settings.
    fn options(&self) -> &SessionOptions {
        &self.core().options
    }

    /// Messages gathered since the last call: validator warnings, line noise, ignored replies.
    fn take_notices(&mut self) -> Vec<String> {
        crate::session::notices::summarise(std::mem::take(&mut self.core_mut().wire.notices))
    }

    /// Adds a message for the user, shown with the session's own notices (on stderr in
    /// non-interactive use) at the next [`take_notices`](Self::take_notices).
    fn notify(&mut self, text: String) {
        self.core_mut().wire.notices.push(text);
    }

    /// The transcript being written, if any.
    fn transcript(&self) -> Option<&Transcript> {
        self.core().wire.transcript.as_ref()
    }

    /// Starts or stops writing the transcript.
    fn set_transcript(&mut self, transcript: Option<Transcript>) {
        self.core_mut().wire.transcript = transcript;
    }

    /// Writes a remark into the transcript; false when no transcript is being written.
    fn annotate(&mut self, text: &str) -> bool {
        let core = self.core_mut();
        core.wire.note(text);
        core.wire.transcript.is_some()
    }

    /// Before a run ends on a time-out: whether the silence is a device of another dialect, as
    /// the failure naming the `--protocol` to give (exit 2). Asked only as the run ends, since
    /// the probe may leave bytes the device keeps; `None` when the session heard anything at all.
    fn wrong_dialect(&mut self) -> Option<crate::exit::Failure> {
        None
    }

    /// Warnings for a user leaving the interactive shell while motors this session set moving
    /// (itself or by a program) still turn, each saying how to stop one; leaving stops nothing.
    /// None where the dialect cannot tell.
    fn turning_at_exit(&mut self) -> Vec<String> {
        Vec::new()
    }

    /// Whether this session started motion or a program that may still be going.
    fn may_be_moving(&self) -> bool {
        let core = self.core();
        !core.moved.is_empty() || !core.running.is_empty()
    }

    /// Sets how long replies are awaited; returns the previous time.
    fn set_timeout(&mut self, timeout: Duration) -> Duration {
        std::mem::replace(&mut self.core_mut().options.timeout, timeout)
    }

    /// Runs `f` with replies awaited at most `timeout` (a bus scan's time per address, a stop's
    /// confirmation), then restores the session's timeout.
    fn with_timeout<T>(&mut self, timeout: Duration, f: impl FnOnce(&mut Self) -> T) -> T
    where
        Self: Sized,
    {
        let saved = self.set_timeout(timeout);
        let result = f(self);
        self.set_timeout(saved);
        result
    }

    /// Runs `f` with requests sent at once, without resynchronising a suspect line first (stops,
    /// mode restores).
    fn urgently<T>(&mut self, f: impl FnOnce(&mut Self) -> T) -> T
    where
        Self: Sized,
    {
        let was = std::mem::replace(&mut self.core_mut().urgent, true);
        let result = f(self);
        self.core_mut().urgent = was;
        result
    }

    /// Reopens a lost link (the port found again by the name given), and puts the modules back
    /// in the mode the session had them in.
    fn reconnect(&mut self) -> Result<(), SessionError> {
        let wire = &mut self.core_mut().wire;
        wire.link.reopen()?;
        wire.reset();
        let reopened = format!("link reopened: {}", wire.link.describe());
        wire.note(&reopened);
        let core = self.core_mut();
        let was = std::mem::replace(&mut core.relinking, true);
        let result = self.reenter();
        self.core_mut().relinking = was;
        if result.is_ok() {
            self.core_mut().wire.note("reconnected");
        }
        result
    }

    /// The link was found lost: closes it at once, so a port that went away is not held open
    /// (the loss itself is in the transcript already, noted where it was seen).
    fn lose_link(&mut self, why: &str) {
        let wire = &mut self.core_mut().wire;
        wire.link.close();
        let describe = wire.link.describe();
        wire.note(&format!("closed {describe} after losing it ({why})"));
    }

    /// Waits up to `wait` for the lost link to come back, trying to [`reconnect`] with growing
    /// pauses; `Err(Lost)` when it did not come back in time, `Err(Interrupted)` on Ctrl-C.
    ///
    /// [`reconnect`]: Self::reconnect
    fn await_link(&mut self, wait: Duration) -> Result<(), SessionError> {
        let until = std::time::Instant::now() + wait;
        let describe = self.describe();
        self.core_mut().wire.note(&format!(
            "waiting up to {} for the link to come back",
            crate::session::relink::say(wait)
        ));
        let mut backoff = crate::session::relink::Backoff::default();
        loop {
            let tried = self.reconnect();
            if tried.is_ok() {
                return Ok(());
            }
            if std::time::Instant::now() >= until {
                let why = format!(
                    "{describe} did not come back within {} (--reconnect)",
                    crate::session::relink::say(wait)
                );
                self.lose_link(&why);
                return Err(SessionError::Lost(why));
            }
            if let Err(e) = backoff.pause(Some(until)) {
                self.core_mut()
                    .wire
                    .note("stopped waiting for the link (Ctrl-C)");
                return Err(e);
            }
        }
    }

    /// A request (`what` to `whom`) was cut short by the lost link (`why`): the port is closed
    /// and the request recorded. Without `--reconnect` (or while already reconnecting) the loss
    /// is the answer; otherwise the link is waited for, and once it is back `Ok` lets a `read`
    /// go out again, while anything else fails saying it was not sent again (whether the module
    /// got it before the link went is unknown).
    fn after_cut_short(
        &mut self,
        what: &str,
        whom: &str,
        read: bool,
        why: String,
    ) -> Result<(), SessionError> {
        self.lose_link(&why);
        let core = self.core_mut();
        core.wire.note(&format!(
            "request cut short by the lost link: {what} to {whom}"
        ));
        let wait = match core.options.reconnect {
            Some(wait) if !core.relinking => wait,
            _ => return Err(SessionError::Lost(why)),
        };
        core.wire.notices.push(format!(
            "link lost ({why}) while `{what}` to {whom} was under way; waiting up to {} for it \
             to come back",
            crate::session::relink::say(wait)
        ));
        self.await_link(wait)?;
        let describe = self.describe();
        let core = self.core_mut();
        core.wire.notices.push(format!("reconnected: {describe}"));
        if read {
            core.wire
                .note(&format!("sent again after the reconnect: {what} (a read)"));
            return Ok(());
        }
        Err(Failure::new(
            crate::exit::Exit::Link,
            format!(
                "the link was lost while `{what}` to {whom} was under way; it is back, but a \
                 motion or write is never sent again (the module may or may not have done it): \
                 read the module's state and send it again if it is still wanted"
            ),
        )
        .into())
    }

    /// A descriptor of the open link to watch for its loss while nobody talks on it (see
    /// [`crate::link::Link::watch`]).
    #[cfg(unix)]
    fn watch_link(&self) -> Option<std::os::fd::OwnedFd> {
        self.core().wire.link.watch()
    }

    /// After Ctrl-C: stops the target's motors even if this session did not start them, and
    /// everything the session set moving — each once, sent at once even while an interrupted
    /// reply may still be arriving. Returns one line per stop, then whatever else the session has
    /// to report, so nothing is left over for the next command.
    fn stop_target(&mut self) -> Vec<String> {
        let target = self.target_address();
        self.core_mut().moved.insert(target);
        let mut report: Vec<String> = self
            .stop_motion()
            .into_iter()
            .map(|line| format!("interrupted: {line}"))
            .collect();
        report.extend(self.take_notices());
        report
    }
}

/// Every dialect's [`DialectSession::run_script`]: `script` run over `session` with the dialect's
/// own functions (`register`), its `log` lines in the session's transcript, its notices before
/// each `print`, and what the session set moving stopped after a failed `test` block.
pub fn run_script<S: DialectSession + ParamDevice + 'static>(
    session: S,
    script: &Script,
    register: Registrar<S>,
) -> (Box<dyn DialectSession>, Result<(), Failure>) {
    let (session, result) = script.run(
        session,
        |s, text| s.annotate(text),
        |s| s.take_notices(),
        |s| s.transcript().is_some_and(|t| t.failure().is_some()),
        |s| s.stop_motion(),
        register,
    );
    (Box::new(session), result)
}
