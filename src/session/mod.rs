//! Sessions: the only place where a protocol meets I/O. A session owns a link and speaks one
//! dialect over it — entering the module's ASCII mode, stripping echoes, matching replies to the
//! addressed module, timing out with a clear error, resynchronising, logging the transcript, and
//! stopping motors it set moving when a run is aborted. The REPL, `-c` lines, piped stdin and
//! Rhai scripts all go through the same session.

pub mod core;
pub mod interrupt;
pub mod notices;
pub mod relink;
pub(crate) mod rx;
pub mod transcript;
pub(crate) mod wire;

use std::time::Duration;

use crate::exit::{Exit, ExitStatus, Failure};

pub use transcript::Transcript;

/// How long a stop (MST, MOTOR:STOP) waits for its answer besides the exchange's wire time. Stops
/// go out at once; a module answers them at once; and after Ctrl-C the user hears within this that
/// the stop went out, however long the interrupted reply would have taken.
pub(crate) const STOP_CONFIRMATION: Duration = Duration::from_millis(50);

/// Settings shared by every dialect's session.
#[derive(Debug, Clone)]
pub struct SessionOptions {
    /// The module addressed by lines without an address character (`--module`).
    pub module: u8,
    /// How long to wait for a reply (`--timeout`).
    pub timeout: Duration,
    /// Refuse invalid lines before sending (off with `--no-validate`).
    pub validate: bool,
    /// How long a run that is not interactive waits for a lost link to come back
    /// (`--reconnect`); `None`: it fails at once (exit 3).
    pub reconnect: Option<Duration>,
    /// Whether the adapter hands back what is sent (`--local-echo`).
    pub local_echo: LocalEcho,
}

/// Whether the adapter echoes what the host sends (a 2-wire RS-485 converter without echo
/// suppression), so the session strips it (`--local-echo`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LocalEcho {
    /// Found out at open, from the first request that can tell.
    #[default]
    Auto,
    /// It does: strip it.
    On,
    /// It does not.
    Off,
}

impl Default for SessionOptions {
    fn default() -> Self {
        SessionOptions {
            module: 1,
            timeout: Duration::from_millis(1000),
            validate: true,
            reconnect: None,
            local_echo: LocalEcho::Auto,
        }
    }
}

/// Why a request failed.
#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    /// The line was refused before sending (TMCL's parser or validator says why).
    #[error("{0}")]
    Refused(String),
    /// A helper command or argument was wrong.
    #[error("{0}")]
    Usage(String),
    /// The line was refused before sending by a dialect's validator (SMD4).
    #[error("{0}")]
    Rejected(String),
    /// The module answered with an error status or error code.
    #[error("{module} refused '{sent}': {reason}")]
    Device {
        /// The module as messages name it (`module 1 (A)`, `drive @3`).
        module: String,
        /// The line sent.
        sent: String,
        /// The status or error it answered.
        reason: String,
    },
    /// Nothing (usable) came back in time.
    #[error("no reply from {module} within {} ms{hint}", timeout.as_millis())]
    Timeout {
        /// The module as messages name it (`module 1 (A)`, `drive @3`).
        module: String,
        /// How long we waited.
        timeout: Duration,
        /// What may be wrong.
        hint: String,
    },
    /// The link could not be opened, or what came back was not a usable reply.
    #[error("{0}")]
    Link(String),
    /// The link is gone (USB unplugged, TCP peer closed).
    #[error("link lost: {0}")]
    Lost(String),
    /// Ctrl-C.
    #[error("interrupted")]
    Interrupted,
    /// A failure with its own exit code: a script (`:source`, its message naming file, line and
    /// column), a download as a whole, a snapshot's differences.
    #[error(transparent)]
    Failed(#[from] Failure),
}

/// A barrier that failed fails the request it was for (see `dialect/tmcl/session/barrier.rs`):
/// the error says so, and keeps what it said about the line.
pub(crate) fn barrier_failed(barrier: &str, error: SessionError) -> SessionError {
    const AFTER: &str = "sent because an earlier request failed and its reply may still come; \
                         the request was not sent, and the next one puts another barrier first";
    match error {
        SessionError::Timeout {
            module,
            timeout,
            hint,
        } => SessionError::Timeout {
            module,
            timeout,
            hint: format!(" to the barrier '{barrier}', {AFTER}{hint}"),
        },
        SessionError::Link(message) => {
            SessionError::Link(format!("{message} (the barrier '{barrier}', {AFTER})"))
        }
        other => other,
    }
}

impl SessionError {
    /// An adapter's echo that differs from what was sent (`--local-echo`): the line is not
    /// usable as it is, which a scan must not take for an empty address.
    pub(crate) fn is_echo_mismatch(&self) -> bool {
        matches!(self, SessionError::Link(message) if message.starts_with(wire::ECHO_MISMATCH))
    }
}

impl ExitStatus for SessionError {
    fn exit(&self) -> Exit {
        match self {
            SessionError::Refused(_) | SessionError::Rejected(_) | SessionError::Usage(_) => {
                Exit::Refused
            }
            SessionError::Device { .. } => Exit::DeviceError,
            SessionError::Timeout { .. } | SessionError::Link(_) | SessionError::Lost(_) => {
                Exit::Link
            }
            SessionError::Interrupted => Exit::Interrupted,
            SessionError::Failed(failure) => failure.exit,
        }
    }
}

impl From<crate::link::LinkError> for SessionError {
    fn from(error: crate::link::LinkError) -> Self {
        use crate::link::LinkError;
        match error {
            LinkError::Lost(message) => SessionError::Lost(message),
            LinkError::Open(message) | LinkError::Adapter(message) => SessionError::Link(message),
            LinkError::Timeout => SessionError::Link("timed out".into()),
        }
    }
}

/// Output that cannot be written (a helper's table, a report) ends the command as a link
/// failure: the user can see nothing more of it.
impl From<std::io::Error> for SessionError {
    fn from(e: std::io::Error) -> Self {
        SessionError::Link(format!("output: {e}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_barrier_says_so_and_keeps_what_the_error_said() {
        let timeout = SessionError::Timeout {
            module: "the drive".into(),
            timeout: Duration::from_millis(100),
            hint: " (check the port)".into(),
        };
        let text = barrier_failed("TMCLSH:BARRIER", timeout).to_string();
        assert!(
            text.starts_with(
                "no reply from the drive within 100 ms to the barrier 'TMCLSH:BARRIER'"
            ) && text.contains("the request was not sent")
                && text.ends_with(" (check the port)"),
            "{text}"
        );
        let noise = barrier_failed("136 1", SessionError::Link("line noise: x".into()));
        assert!(
            noise
                .to_string()
                .starts_with("line noise: x (the barrier '136 1'")
        );
        assert!(matches!(
            barrier_failed("136 1", SessionError::Interrupted),
            SessionError::Interrupted
        ));
    }
}
