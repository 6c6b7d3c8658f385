//! The exit-code convention every face of tmclsh follows (documented in docs/exit-codes.md).

/// What a run of tmclsh ended with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Exit {
    /// 0: everything succeeded.
    Success,
    /// 1: the device reported an error status, or a script assertion failed.
    DeviceError,
    /// 2: input refused before anything was sent (validation, usage, script compile error).
    Refused,
    /// 3: connection failure, timeout or lost link.
    Link,
    /// 130: interrupted by Ctrl-C.
    Interrupted,
    /// 128 + N: ended by signal N (SIGTERM 143, SIGHUP 129), after stopping the motors; 141 when
    /// stdout was closed, as for SIGPIPE (`crate::stdout`).
    Terminated(u8),
}

impl Exit {
    /// The process exit code.
    pub fn code(self) -> u8 {
        match self {
            Exit::Success => 0,
            Exit::DeviceError => 1,
            Exit::Refused => 2,
            Exit::Link => 3,
            Exit::Interrupted => 130,
            Exit::Terminated(signal) => 128u8.saturating_add(signal),
        }
    }

    /// The worse of two outcomes, by what the failure says about the run: SIGTERM or SIGHUP
    /// (143, 129) and Ctrl-C (130) ended it; a link failure (3) leaves unknown what the module
    /// did; a device error (1) means the module is not in the state the input assumed; a refused
    /// line (2) was not sent at all. On a tie, `self`.
    pub fn worse(self, other: Exit) -> Exit {
        fn rank(exit: Exit) -> u8 {
            match exit {
                Exit::Success => 0,
                Exit::Refused => 1,
                Exit::DeviceError => 2,
                Exit::Link => 3,
                Exit::Interrupted => 4,
                Exit::Terminated(_) => 5,
            }
        }
        if rank(other) > rank(self) {
            other
        } else {
            self
        }
    }
}

impl From<Exit> for std::process::ExitCode {
    fn from(exit: Exit) -> Self {
        std::process::ExitCode::from(exit.code())
    }
}

/// An error that knows which exit code it means.
pub trait ExitStatus {
    /// The exit code for this error.
    fn exit(&self) -> Exit;
}

/// Output or a file that cannot be written or read where the command line meets the system
/// (stdout, an installed file, a listening socket): the user sees nothing more of the command,
/// which ends as a link failure does.
impl ExitStatus for std::io::Error {
    fn exit(&self) -> Exit {
        Exit::Link
    }
}

/// A failure on its way out: what to print and the exit code it means. Every face ends in one —
/// the command line, a script (thrown as the Rhai error value, so a script can `catch` it and a
/// runner can tell an assertion from a lost link), a `:source` in the shell — and every layer's
/// typed error that knows its exit code becomes one with `?`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct Failure {
    /// The exit code.
    pub exit: Exit,
    /// What happened.
    pub message: String,
}

impl Failure {
    /// A failure with its exit code.
    pub fn new(exit: Exit, message: impl Into<String>) -> Self {
        Failure {
            message: message.into(),
            exit,
        }
    }

    /// Input refused before anything was sent (exit 2).
    pub fn refused(message: impl Into<String>) -> Self {
        Failure::new(Exit::Refused, message)
    }
}

impl<E: ExitStatus + std::fmt::Display> From<E> for Failure {
    fn from(error: E) -> Self {
        Failure::new(error.exit(), error.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Lost;

    impl ExitStatus for Lost {
        fn exit(&self) -> Exit {
            Exit::Link
        }
    }

    impl std::fmt::Display for Lost {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str("link lost")
        }
    }

    #[test]
    fn a_typed_error_becomes_a_failure_with_its_exit_code_and_text() {
        let failure = Failure::from(Lost);
        assert_eq!(failure, Failure::new(Exit::Link, "link lost"));
        assert_eq!(failure.to_string(), "link lost");
        assert_eq!(Failure::refused("no").exit.code(), 2);
    }
}
