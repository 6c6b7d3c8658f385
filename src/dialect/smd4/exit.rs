//! What the SMD4 protocol's errors mean as exit codes: the protocol is pure and knows nothing of
//! processes; the faces that end a run with an error ask here.

use crate::exit::{Exit, ExitStatus};

use super::protocol::{DeviceError, ReplyError, RequestError, ValidationError};

impl ExitStatus for DeviceError {
    /// A device error code means exit 1.
    fn exit(&self) -> Exit {
        Exit::DeviceError
    }
}

impl ExitStatus for RequestError {
    /// Refused before sending: exit 2.
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}

impl ExitStatus for ReplyError {
    /// Garbage from the link is a link failure: exit 3.
    fn exit(&self) -> Exit {
        Exit::Link
    }
}

impl ExitStatus for ValidationError {
    /// Refused before sending: exit 2.
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}
