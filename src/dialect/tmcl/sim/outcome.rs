//! What a command did: its reply, its effect on the serial interface, and where it came from —
//! shared by the direct-mode executor (`exec.rs`), the program runner (`vm.rs`) and the module's
//! serial interface, so that none of them needs another for its types.

use crate::dialect::tmcl::protocol::{Instruction, Status};

/// How the module answers a command.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Reply {
    /// The usual reply: status and value.
    Normal(Status, i32),
    /// 136 type 0: the special version-string frame.
    Version,
    /// 137: no reply at all.
    Silent,
}

/// What a command did beyond its reply, for the serial interface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Effect {
    /// Nothing.
    None,
    /// 139: switch to ASCII mode after replying.
    EnterAscii,
    /// 137: the module restarted.
    Rebooted,
}

/// A command's result.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Outcome {
    pub reply: Reply,
    pub effect: Effect,
}

impl Outcome {
    pub(super) fn ok(value: i32) -> Outcome {
        Outcome::status(Status::Ok, value)
    }

    pub(super) fn status(status: Status, value: i32) -> Outcome {
        Outcome {
            reply: Reply::Normal(status, value),
            effect: Effect::None,
        }
    }

    pub(super) fn error(status: Status, instruction: &Instruction) -> Outcome {
        Outcome::status(status, instruction.value)
    }
}

/// Where a command comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Source {
    /// The serial interface, binary or ASCII (direct mode).
    Direct,
    /// A running program.
    Program,
}
