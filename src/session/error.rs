//! Why a request failed: the session layer's error, with what each kind means as an exit code.

use std::time::Duration;

use crate::exit::{Exit, ExitStatus, Failure};

use super::transcript::TranscriptError;

/// Why a request failed.
#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    /// The line was refused before sending by a dialect's parser or validator, which says why.
    #[error("{0}")]
    Refused(String),
    /// A helper command or argument was wrong.
    #[error("{0}")]
    Usage(String),
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
    /// The link could not be opened or used, or what came back could not be taken.
    #[error("{0}")]
    Link(String),
    /// What came back was no usable reply: garbled, glued to more data, an echo that differs
    /// from what was sent. The message says what (`line noise: …`).
    #[error("{said}")]
    Noise {
        /// What was heard, and why it was not taken.
        said: String,
        /// What kind of noise, for the callers that act on it.
        kind: NoiseKind,
    },
    /// The link is gone (USB unplugged, TCP peer closed).
    #[error("link lost: {0}")]
    Lost(String),
    /// Output that cannot be written (a helper's table, a report): the user can see nothing
    /// more of the command, which ends as a link failure does.
    #[error("output: {0}")]
    Output(#[from] std::io::Error),
    /// A transcript (`:log FILE`) that could not be started.
    #[error(transparent)]
    Transcript(#[from] TranscriptError),
    /// The transcript the run asked for can no longer be written (the notice before says why).
    #[error("the run stops: it asked for a transcript that cannot be written")]
    TranscriptLost,
    /// Ctrl-C.
    #[error("interrupted")]
    Interrupted,
    /// A failure with its own exit code: a script (`:source`, its message naming file, line and
    /// column), a download as a whole, a snapshot's differences.
    #[error(transparent)]
    Failed(#[from] Failure),
}

/// Kinds of line noise that callers tell apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NoiseKind {
    /// A reply garbled, cut short or followed by more data.
    Garbled,
    /// An adapter's echo that differs from what was sent (`--local-echo`): the line is not
    /// usable as it is, which a scan must not take for an empty address.
    Echo,
    /// A reply followed by one from a module at the host address, which answers the replies of
    /// others as if they were requests.
    HostClash,
}

impl SessionError {
    /// Line noise of the common kind: `said` says what came back and why it was not taken.
    pub(crate) fn noise(said: String) -> Self {
        SessionError::Noise {
            said,
            kind: NoiseKind::Garbled,
        }
    }

    /// An adapter's echo that differs from what was sent.
    pub(crate) fn is_echo_mismatch(&self) -> bool {
        matches!(
            self,
            SessionError::Noise {
                kind: NoiseKind::Echo,
                ..
            }
        )
    }
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
        SessionError::Noise { said, kind } => SessionError::Noise {
            said: format!("{said} (the barrier '{barrier}', {AFTER})"),
            kind,
        },
        other => other,
    }
}

/// The one place a session's failure becomes an exit code.
impl ExitStatus for SessionError {
    fn exit(&self) -> Exit {
        match self {
            SessionError::Refused(_) | SessionError::Usage(_) => Exit::Refused,
            SessionError::Device { .. } => Exit::DeviceError,
            SessionError::Timeout { .. }
            | SessionError::Link(_)
            | SessionError::Noise { .. }
            | SessionError::Lost(_)
            | SessionError::Output(_)
            | SessionError::TranscriptLost => Exit::Link,
            SessionError::Interrupted => Exit::Interrupted,
            SessionError::Transcript(e) => e.exit(),
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
        let noise = barrier_failed("136 1", SessionError::noise("line noise: x".into()));
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
