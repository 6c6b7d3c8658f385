//! Barriers: after a request failed, its reply may still come, however late, and be taken for the
//! answer to a later request. Waiting for a quiet line does not rule that out (a module can be
//! slower than any window), so before the next request that could take such a reply the session
//! sends a *barrier*: a read-only request whose reply no earlier request can send, and discards
//! everything until that reply has come. A module answers in order, so once the barrier's reply
//! is in, every earlier reply has come or never will.
//!
//! - **Binary direct mode**: a reply frame names its module and command. The session keeps, per
//!   module, the commands whose replies may still come ([`LateFrames`]); a request whose command is
//!   not among them cannot take a late reply and goes out as it is. Otherwise the barrier is a
//!   read with a command none of them has (136 type 1, 135, 134), taken only from a frame of
//!   that command. All three are control functions, so a module in download mode executes
//!   them instead of storing them.
//! - **ASCII without echo**: a reply names only its module. The barrier is `GAP 1, 255`, which a
//!   module refuses with status 4 (there is no motor 255; 2 or 3 are taken too), a refusal no
//!   validated request gets from a module its profile describes; every other reply before it is
//!   discarded.
//!
//! A barrier that is not answered fails the request (unsent) with a clear error; the line stays
//! in doubt and the next request puts another barrier first. Barriers are never sent on a clean
//! line, nor before a stop that must go out at once.

use std::collections::BTreeMap;

use crate::dialect::tmcl::protocol::line::address_char;
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode, Status};
use crate::session::{SessionError, barrier_failed};

use super::TmclSession;

/// The reads a binary barrier is made of, in order of preference: each is answered by every
/// module (a module without one refuses it, naming the command, which is an answer too) and
/// changes nothing: the version number, the program's status, the program memory at 0.
const BINARY_BARRIERS: [(Opcode, u8, u8); 3] = [
    (Opcode::FirmwareVersion, 1, 0),
    (Opcode::ApplicationStatus, 0, 0),
    (Opcode::ReadMemory, 0, 0),
];

/// Barriers one request may need at most: each answered one resolves at least the oldest
/// command in doubt, and with three kinds of barrier one suffices unless a stop went out between.
const MAX_BARRIERS: usize = 3;

/// The most commands remembered per module: 64 failures in a row without an answer.
const KEPT: usize = 64;

/// The ASCII barrier after the address character: actual position of a motor no module has.
pub(super) const ASCII_BARRIER: &str = "GAP 1, 255";

/// Whether a status is how a module refuses the ASCII barrier: 4 (invalid value: the motor
/// number), or 2 or 3 from a firmware that finds fault with the line otherwise. No request
/// validated against the module's profile gets any of them.
pub(super) fn refuses_barrier(status: Status) -> bool {
    matches!(
        status,
        Status::InvalidValue | Status::WrongType | Status::InvalidCommand
    )
}

/// Binary requests whose reply frame may still come, per module: their commands, oldest first.
#[derive(Debug, Default)]
pub(super) struct LateFrames {
    modules: BTreeMap<u8, Vec<Opcode>>,
}

impl LateFrames {
    /// A request to `module` with `command` failed: its reply may still come.
    pub(super) fn failed(&mut self, module: u8, command: Opcode) {
        let list = self.modules.entry(module).or_default();
        // Two in a row resolve alike: through the first.
        if list.last() != Some(&command) {
            list.push(command);
        }
        if list.len() > KEPT {
            list.remove(0);
        }
    }

    /// A reply frame of `command` from `module` was taken. It answers the request just sent or
    /// an earlier one with the same command; either way every request sent before that one has
    /// been answered or never will be. What stays in doubt: the commands after the first with
    /// `command`, and `command` itself when it was in doubt (the reply taken may be the older).
    pub(super) fn answered(&mut self, module: u8, command: Opcode) {
        let Some(list) = self.modules.get_mut(&module) else {
            return;
        };
        match list.iter().position(|&c| c == command) {
            None => {
                self.modules.remove(&module);
            }
            Some(i) => {
                list.drain(..=i);
                if !list.contains(&command) {
                    list.push(command);
                }
            }
        }
    }

    /// Whether the answer to `instruction` could be a late reply: its command is in doubt, or
    /// anything is and it asks for the version string (whose frame names no command).
    pub(super) fn in_doubt(&self, module: u8, instruction: &Instruction) -> bool {
        self.modules
            .get(&module)
            .is_some_and(|list| version_string(instruction) || list.contains(&instruction.command))
    }

    /// The barrier for `module`: a read whose command is not in doubt, or else the one whose
    /// reply resolves the most (its command's first place in doubt is the latest).
    pub(super) fn barrier(&self, module: u8) -> Instruction {
        let list = self.modules.get(&module).map_or(&[][..], Vec::as_slice);
        let first_place = |command: Opcode| list.iter().position(|&c| c == command);
        // Reversed: of equals, `max_by_key` keeps the last, and the first is preferred.
        let (command, type_, motor) = BINARY_BARRIERS
            .into_iter()
            .rev()
            .max_by_key(|&(command, ..)| first_place(command).map_or(usize::MAX, |i| i))
            .unwrap_or(BINARY_BARRIERS[0]);
        Instruction::new(command, type_, motor, 0)
    }
}

/// 136 type 0: answered with the version string, a frame without a command byte.
fn version_string(instruction: &Instruction) -> bool {
    instruction.command == Opcode::FirmwareVersion && instruction.type_ == 0
}

impl TmclSession {
    /// Puts barriers on the line until no late reply can pass for the answer to `instruction`
    /// (binary direct mode). Stops that must go out at once do not wait for one.
    pub(super) fn binary_barriers(
        &mut self,
        module: u8,
        instruction: &Instruction,
    ) -> Result<(), SessionError> {
        if self.core.urgent {
            return Ok(());
        }
        for _ in 0..MAX_BARRIERS {
            if !self.late_frames.in_doubt(module, instruction) {
                return Ok(());
            }
            let barrier = self.late_frames.barrier(module);
            let shown = self.describe_instruction(&barrier);
            self.note_barrier(module, &shown);
            let result = self.exchange(module, false, |s| s.binary_exchange(module, barrier));
            match result {
                Ok(_) => self.late_frames.answered(module, barrier.command),
                Err(error) => {
                    self.late_frames.failed(module, barrier.command);
                    return Err(barrier_failed(&shown, error));
                }
            }
        }
        if self.late_frames.in_doubt(module, instruction) {
            return Err(SessionError::Link(format!(
                "{} may still send late replies to requests given up earlier, after {MAX_BARRIERS} \
                 barriers; the request was not sent (the next one tries again)",
                ModuleName(module)
            )));
        }
        Ok(())
    }

    /// Puts a barrier on the line when a request to `module` failed in ASCII mode without echo
    /// and its reply may still come. Stops that must go out at once do not wait for one.
    pub(super) fn ascii_barrier(&mut self, module: u8) -> Result<(), SessionError> {
        let Some(c) = address_char(module) else {
            return Ok(());
        };
        let no_echo = self
            .modules
            .get(&module)
            .is_some_and(|m| m.echo_known && m.echo == super::Echo::None);
        if self.core.urgent || !no_echo || !self.unanswered.pending(c) {
            return Ok(());
        }
        let text = format!("{c}{ASCII_BARRIER}");
        self.note_barrier(module, &text);
        match self.ascii_barrier_request(module, text.clone()) {
            Ok(_) => {
                self.unanswered.forget(c);
                Ok(())
            }
            Err(error) => {
                self.unanswered.barrier_lost(c);
                Err(barrier_failed(&text, error))
            }
        }
    }

    fn note_barrier(&mut self, module: u8, shown: &str) {
        self.core.wire.note(&format!(
            "barrier: {shown} to {}, whose reply no request given up earlier can send; \
             everything before it is discarded",
            ModuleName(module)
        ));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const GGP: Opcode = Opcode::Ggp;

    fn ggp() -> Instruction {
        Instruction::new(GGP, 3, 2, 0)
    }

    #[test]
    fn a_clean_line_needs_no_barrier() {
        let late = LateFrames::default();
        assert!(!late.in_doubt(1, &ggp()));
    }

    #[test]
    fn only_a_command_in_doubt_needs_a_barrier() {
        let mut late = LateFrames::default();
        late.failed(1, GGP);
        assert!(late.in_doubt(1, &ggp()));
        assert!(
            !late.in_doubt(2, &ggp()),
            "another module's replies name it"
        );
        let sap = Instruction::new(Opcode::Sap, 4, 0, 100);
        assert!(!late.in_doubt(1, &sap), "a SAP reply cannot be a GGP's");
        let version = Instruction::new(Opcode::FirmwareVersion, 0, 0, 0);
        assert!(
            late.in_doubt(1, &version),
            "the version string names no command"
        );
    }

    #[test]
    fn a_barrier_has_a_command_not_in_doubt_and_its_reply_clears_the_line() {
        let mut late = LateFrames::default();
        late.failed(1, GGP);
        let barrier = late.barrier(1);
        assert_eq!(barrier.command, Opcode::FirmwareVersion);
        late.answered(1, barrier.command);
        assert!(!late.in_doubt(1, &ggp()));
        assert!(late.modules.is_empty());
    }

    #[test]
    fn a_lost_barrier_is_in_doubt_too_and_the_next_differs() {
        let mut late = LateFrames::default();
        late.failed(1, GGP);
        late.failed(1, Opcode::FirmwareVersion);
        assert_eq!(late.barrier(1).command, Opcode::ApplicationStatus);
        late.failed(1, Opcode::ApplicationStatus);
        assert_eq!(late.barrier(1).command, Opcode::ReadMemory);
        late.failed(1, Opcode::ReadMemory);
        // Every kind in doubt: the one whose first place is latest resolves the most.
        assert_eq!(late.barrier(1).command, Opcode::ReadMemory);
        late.answered(1, Opcode::ReadMemory);
        assert!(!late.in_doubt(1, &ggp()), "GGP came before the first 134");
        assert!(late.in_doubt(1, &Instruction::new(Opcode::ReadMemory, 0, 0, 0)));
    }

    #[test]
    fn a_reply_to_a_command_in_doubt_resolves_only_up_to_its_first_place() {
        let mut late = LateFrames::default();
        late.failed(1, Opcode::Mst);
        late.failed(1, GGP);
        // A stop goes out without a barrier; its reply may be the older stop's.
        late.answered(1, Opcode::Mst);
        assert!(late.in_doubt(1, &ggp()));
        assert!(late.in_doubt(1, &Instruction::new(Opcode::Mst, 0, 0, 0)));
        late.answered(1, Opcode::FirmwareVersion);
        assert!(late.modules.is_empty());
    }

    #[test]
    fn failures_in_a_row_are_bounded() {
        let mut late = LateFrames::default();
        for _ in 0..10 {
            late.failed(1, GGP);
        }
        assert_eq!(late.modules[&1].len(), 1);
        for i in 0..200u8 {
            late.failed(1, Opcode::from(i));
        }
        assert_eq!(late.modules[&1].len(), KEPT);
    }
}
