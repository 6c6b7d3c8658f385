//! Looking for modules on the bus (`tmclsh scan`): a shorter timeout for the probes, binary frames
//! to addresses that have no ASCII address character, and what the session learnt about a module.

use std::time::{Duration, Instant};

use crate::dialect::tmcl::protocol::Instruction;

use super::{TmclExchange, TmclSession, WireMode};
use crate::session::SessionError;

impl TmclSession {
    /// Tells the user something found on the bus (with the next reply or error), and writes it
    /// to the transcript.
    pub fn notice(&mut self, text: String) {
        self.core.wire.note(&text);
        self.core.wire.notices.push(text);
    }
    /// The mode a module was in when the session first reached it.
    pub fn found_in(&self, module: u8) -> Option<WireMode> {
        self.modules.get(&module).map(|m| m.found_in)
    }

    /// Corrects the mode a module was found in, when the caller knows better than the guess from
    /// global parameter 67 bit 0 (a scan that saw it not answer binary frames); the session puts
    /// it back in that mode when it closes.
    pub fn set_found_in(&mut self, module: u8, mode: WireMode) {
        if let Some(state) = self.modules.get_mut(&module) {
            state.found_in = mode;
        }
    }

    /// Sends one binary frame to any bus address (1..255) and waits for its reply, without
    /// entering ASCII mode or remembering the module. ASCII-mode modules on the same bus take the
    /// frame as the start of a line: call [`TmclSession::end_partial_line`] after probing.
    pub fn probe_binary(
        &mut self,
        address: u8,
        instruction: Instruction,
    ) -> Result<TmclExchange, SessionError> {
        self.binary_request(address, instruction)
    }

    /// Leaves the line quiet for `duration` — binary-mode receivers drop a partial frame after
    /// their frame timeout — reading and discarding whatever arrives meanwhile.
    pub fn quiet(&mut self, duration: Duration) -> Result<(), SessionError> {
        let deadline = Instant::now() + duration;
        while Instant::now() < deadline {
            if self.core.wire.fill(deadline)? {
                let n = self.core.wire.rx.len();
                self.core
                    .wire
                    .discard_quietly(n, "while the line was kept quiet");
            }
        }
        let n = self.core.wire.rx.len();
        self.core
            .wire
            .discard_quietly(n, "while the line was kept quiet");
        Ok(())
    }

    /// Reaches `module` as one already in ASCII mode — its echo setting read with an ASCII line,
    /// no 139 sent — and makes it the target. A module in binary mode does not answer (a scan
    /// has found those with binary frames already); the line then holds ASCII bytes that binary
    /// receivers drop after their frame time-out.
    pub fn reach_in_ascii(&mut self, module: u8) -> Result<(), SessionError> {
        if self.modules.contains_key(&module) {
            return self.set_target(module);
        }
        self.assume_ascii(module)?;
        self.target = module;
        Ok(())
    }

    /// Keeps the line quiet until binary receivers are at a frame boundary again, if anything
    /// else was sent since the last complete binary exchange.
    pub fn align_frames(&mut self) -> Result<(), SessionError> {
        if std::mem::take(&mut self.frames_aligned) {
            return Ok(());
        }
        self.core.wire.idle_for(self.resync_gap())
    }

    /// Sends a lone CR, which ends whatever partial line ASCII-mode modules hold.
    pub fn end_partial_line(&mut self) -> Result<(), SessionError> {
        if self.frames_only {
            // CAN carries no text: no line is left partial.
            return Ok(());
        }
        self.ascii_sent = true;
        self.frames_aligned = false;
        self.core
            .wire
            .send(
                b"\r",
                "end of line, clears what the probes left in line buffers",
            )
            .map(|_| ())
    }
}
