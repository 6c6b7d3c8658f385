//! The dialect seam: a session of either dialect, with what the faces (REPL, `-c`/stdin, scripts)
//! need from it regardless of dialect. Dialect-specific faces match on the variant.

use crate::dialect::Dialect;

use super::{SessionError, Transcript};
use crate::dialect::smd4::session::{Smd4Exchange, Smd4Session};
use crate::dialect::tmcl::session::{Answer, Exchange, TmclSession};

/// An open session.
pub enum Session {
    /// A TMCL module bus.
    Tmcl(TmclSession),
    /// SMD4 drives.
    Smd4(Smd4Session),
}

/// A request and its answer, in either dialect.
#[derive(Debug, Clone, PartialEq)]
pub enum Reply {
    /// TMCL.
    Tmcl(Exchange),
    /// SMD4.
    Smd4(Smd4Exchange),
}

impl Reply {
    /// The answer as the module sent it (for stdout in non-interactive use): the reply line
    /// without echo and line ending; the version string of 136; the lines of an SMD4 reply.
    pub fn shown(&self) -> String {
        match self {
            Reply::Tmcl(x) => match &x.answer {
                Answer::Version(version) => version.clone(),
                _ => x.raw.clone(),
            },
            Reply::Smd4(x) => x.raw(),
        }
    }

    /// Whether the module reported success.
    pub fn ok(&self) -> bool {
        match self {
            Reply::Tmcl(x) => x.ok(),
            Reply::Smd4(x) => x.ok(),
        }
    }

    /// The reply, or the device error it carries (exit 1).
    pub fn checked(self) -> Result<Reply, SessionError> {
        match self {
            Reply::Tmcl(x) => x.checked().map(Reply::Tmcl),
            Reply::Smd4(x) => x.checked().map(Reply::Smd4),
        }
    }
}

impl Session {
    /// The dialect spoken.
    pub fn dialect(&self) -> Dialect {
        match self {
            Session::Tmcl(_) => Dialect::Tmcl,
            Session::Smd4(_) => Dialect::Smd4,
        }
    }

    /// The TMCL session, or a usage error naming `what` for other dialects.
    pub fn tmcl(&mut self, what: &str) -> Result<&mut TmclSession, SessionError> {
        match self {
            Session::Tmcl(s) => Ok(s),
            Session::Smd4(_) => Err(SessionError::Usage(format!(
                "{what} works with TMCL modules only"
            ))),
        }
    }

    /// The SMD4 session, or a usage error naming `what` for other dialects.
    pub fn smd4(&mut self, what: &str) -> Result<&mut Smd4Session, SessionError> {
        match self {
            Session::Smd4(s) => Ok(s),
            Session::Tmcl(_) => Err(SessionError::Usage(format!(
                "{what} works with SMD4 drives only"
            ))),
        }
    }

    /// Parses, validates and sends one typed line.
    pub fn execute(&mut self, text: &str) -> Result<Reply, SessionError> {
        match self {
            Session::Tmcl(s) => s.execute(text).map(Reply::Tmcl),
            Session::Smd4(s) => s.execute(text).map(Reply::Smd4),
        }
    }

    /// What the link talks to.
    pub fn describe(&self) -> String {
        match self {
            Session::Tmcl(s) => s.describe(),
            Session::Smd4(s) => s.describe(),
        }
    }

    /// Messages gathered since the last call.
    pub fn take_notices(&mut self) -> Vec<String> {
        match self {
            Session::Tmcl(s) => s.take_notices(),
            Session::Smd4(s) => s.take_notices(),
        }
    }

    /// Stops whatever this session set moving; returns what was done.
    pub fn stop_motion(&mut self) -> Vec<String> {
        match self {
            Session::Tmcl(s) => s.stop_motion(),
            Session::Smd4(s) => s.stop_motion(),
        }
    }

    /// Whether this session started motion that may still be going.
    pub fn may_be_moving(&self) -> bool {
        match self {
            Session::Tmcl(s) => s.may_be_moving(),
            Session::Smd4(s) => s.may_be_moving(),
        }
    }

    /// After Ctrl-C: stops the target's motors even if this session did not start them, and
    /// everything the session set moving — each once, sent at once even while an interrupted
    /// reply may still be arriving. Returns one line per stop, then whatever else the session has
    /// to report, so nothing is left over for the next command.
    pub fn stop_target(&mut self) -> Vec<String> {
        let report = match self {
            Session::Tmcl(s) => {
                let target = s.target();
                s.stop_motion_and(target)
            }
            Session::Smd4(s) => s.stop_motion_and_target(),
        };
        let mut report: Vec<String> = report
            .into_iter()
            .map(|line| format!("interrupted: {line}"))
            .collect();
        report.extend(self.take_notices());
        report
    }

    /// Ends the session, restoring module modes; returns what was done.
    pub fn close(&mut self) -> Vec<String> {
        match self {
            Session::Tmcl(s) => s.close(),
            Session::Smd4(s) => s.close(),
        }
    }

    /// Reopens a lost link.
    pub fn reconnect(&mut self) -> Result<(), SessionError> {
        match self {
            Session::Tmcl(s) => s.reconnect(),
            Session::Smd4(s) => s.reconnect(),
        }
    }

    /// Starts or stops writing the transcript.
    pub fn set_transcript(&mut self, transcript: Option<Transcript>) {
        match self {
            Session::Tmcl(s) => s.set_transcript(transcript),
            Session::Smd4(s) => s.set_transcript(transcript),
        }
    }

    /// The transcript being written.
    pub fn transcript(&self) -> Option<&Transcript> {
        match self {
            Session::Tmcl(s) => s.transcript(),
            Session::Smd4(s) => s.transcript(),
        }
    }

    /// Writes a remark into the transcript; false when none is written.
    pub fn annotate(&mut self, text: &str) -> bool {
        match self {
            Session::Tmcl(s) => s.annotate(text),
            Session::Smd4(s) => s.annotate(text),
        }
    }
}
