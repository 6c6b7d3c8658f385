//! The exit-code convention every face of tmclsh follows (documented in the README).

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
