//! The dialect seam: a session of either dialect, with what the faces (REPL, `-c`/stdin, scripts)
//! need from it regardless of dialect. Dialect-specific faces match on the variant.

use crate::dialect::Dialect;
use crate::dialect::session::{DialectSession, Reply};
use crate::dialect::smd4::session::Smd4Session;
use crate::dialect::tmcl::session::TmclSession;

use super::{SessionError, Transcript};

/// An open session.
pub enum Session {
    /// A TMCL module bus.
    Tmcl(TmclSession),
    /// SMD4 drives.
    Smd4(Smd4Session),
}

impl Session {
    /// The dialect spoken.
    pub fn dialect(&self) -> Dialect {
        match self {
            Session::Tmcl(_) => Dialect::Tmcl,
            Session::Smd4(_) => Dialect::Smd4,
        }
    }

    /// The session as the trait every dialect implements.
    pub fn as_dyn(&self) -> &dyn DialectSession {
        match self {
            Session::Tmcl(s) => s,
            Session::Smd4(s) => s,
        }
    }

    /// The session as the trait every dialect implements, to change.
    pub fn as_dyn_mut(&mut self) -> &mut dyn DialectSession {
        match self {
            Session::Tmcl(s) => s,
            Session::Smd4(s) => s,
        }
    }

    /// Parses, validates and sends one typed line.
    pub fn execute(&mut self, text: &str) -> Result<Reply, SessionError> {
        self.as_dyn_mut().execute(text)
    }

    /// What the link talks to.
    pub fn describe(&self) -> String {
        self.as_dyn().describe()
    }

    /// Messages gathered since the last call.
    pub fn take_notices(&mut self) -> Vec<String> {
        self.as_dyn_mut().take_notices()
    }

    /// Stops whatever this session set moving; returns what was done.
    pub fn stop_motion(&mut self) -> Vec<String> {
        self.as_dyn_mut().stop_motion()
    }

    /// Whether this session started motion that may still be going.
    pub fn may_be_moving(&self) -> bool {
        self.as_dyn().may_be_moving()
    }

    /// After Ctrl-C: stops the target's motors and everything the session set moving.
    pub fn stop_target(&mut self) -> Vec<String> {
        self.as_dyn_mut().stop_target()
    }

    /// Ends the session, restoring module modes; returns what was done.
    pub fn close(&mut self) -> Vec<String> {
        self.as_dyn_mut().close()
    }

    /// Reopens a lost link.
    pub fn reconnect(&mut self) -> Result<(), SessionError> {
        self.as_dyn_mut().reconnect()
    }

    /// Starts or stops writing the transcript.
    pub fn set_transcript(&mut self, transcript: Option<Transcript>) {
        self.as_dyn_mut().set_transcript(transcript)
    }

    /// The transcript being written.
    pub fn transcript(&self) -> Option<&Transcript> {
        self.as_dyn().transcript()
    }

    /// Writes a remark into the transcript; false when none is written.
    pub fn annotate(&mut self, text: &str) -> bool {
        self.as_dyn_mut().annotate(text)
    }
}
