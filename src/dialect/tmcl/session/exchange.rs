//! What a TMCL request got back: the module's reply, and the exchange as the session reports it
//! (the line sent, what it resolved to, the reply as received).

use crate::dialect::session::Refusal;
use crate::dialect::tmcl::protocol::ModuleName;
use crate::dialect::tmcl::protocol::line::Op;
use crate::dialect::tmcl::protocol::{InputError, Status};
use crate::session::SessionError;

/// What a module replied, from either form (an ASCII reply line or a binary reply frame).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TmclReply {
    /// A status and value.
    Status {
        /// Outcome.
        status: Status,
        /// Returned value.
        value: i32,
    },
    /// The version string of command 136 type 0.
    Version(String),
    /// No reply is expected (137 factory reset, BIN without reply).
    Nothing,
}

/// One request and its reply.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TmclExchange {
    /// The module addressed.
    pub module: u8,
    /// The line sent, in canonical form (`AGAP 1, 0`; binary: `GAP 1, 0`).
    pub sent: String,
    /// What was sent, when the line resolved.
    pub op: Option<Op>,
    /// What the module replied.
    pub reply: TmclReply,
    /// The reply as the module sent it, without echo and line ending (`BA 100 -5000`).
    pub raw: String,
}

impl TmclExchange {
    /// Whether the module reported success (or nothing was expected).
    pub fn ok(&self) -> bool {
        match self.reply {
            TmclReply::Status { status, .. } => status.is_success(),
            _ => true,
        }
    }

    /// The returned value of a status reply.
    pub fn value(&self) -> Option<i32> {
        match self.reply {
            TmclReply::Status { value, .. } => Some(value),
            _ => None,
        }
    }

    /// The status of a status reply.
    pub fn status(&self) -> Option<Status> {
        match self.reply {
            TmclReply::Status { status, .. } => Some(status),
            _ => None,
        }
    }

    /// The exchange, or a device error when the module answered with an error status.
    pub fn checked(self) -> Result<TmclExchange, SessionError> {
        match self.refusal() {
            Some(refusal) => Err(refusal.into()),
            None => Ok(self),
        }
    }

    /// The error status the module answered with, if any.
    pub fn refusal(&self) -> Option<Refusal> {
        match self.reply {
            TmclReply::Status { status, .. } if !status.is_success() => Some(Refusal {
                module: ModuleName(self.module).to_string(),
                sent: self.sent.clone(),
                reason: format!("status {status}"),
            }),
            _ => None,
        }
    }

    /// The answer as the module sent it: the reply line without echo and line ending, or the
    /// version string of 136.
    pub fn shown(&self) -> String {
        match &self.reply {
            TmclReply::Version(version) => version.clone(),
            _ => self.raw.clone(),
        }
    }
}

/// A line the parser or validator refuses is refused before sending (exit 2).
impl From<InputError> for SessionError {
    fn from(error: InputError) -> Self {
        SessionError::Refused(error.to_string())
    }
}
