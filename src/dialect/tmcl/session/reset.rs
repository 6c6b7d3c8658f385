//! A module power-cycled under an ASCII session starts again in the mode GP 67 bit 0 says —
//! binary by default — and would leave the session with "no reply" for ever. When an ASCII
//! request goes unanswered, the session asks once in binary (a read, 136 type 1, after the line
//! was quiet for longer than the module's frame time-out, as every binary frame after ASCII
//! lines; awaited as briefly as an optional reply, so a module that is simply gone costs little
//! more than the timeout); a module that answers there was reset: the session says so, enters ASCII mode again,
//! sets the echo it had set, and carries on. The request that failed stays failed and is not sent
//! again: the module's RAM settings are back to their stored values, so even a read could now
//! mean something else than when it was typed.

use crate::dialect::session::DialectSession;
use crate::dialect::tmcl::protocol::frame::FRAME_LEN;
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode, address_char};
use crate::session::SessionError;

use super::mode::WireMode;
use super::{Echo, TmclSession};

impl TmclSession {
    /// After `error`, the timeout of an ASCII request to `module`: the same error, its hint
    /// saying what the binary probe found when the module had restarted.
    pub(super) fn after_ascii_silence(&mut self, module: u8, error: SessionError) -> SessionError {
        let SessionError::Timeout {
            module: name,
            timeout,
            hint,
        } = error
        else {
            return error;
        };
        let ascii = self
            .modules
            .get(&module)
            .is_some_and(|m| m.mode == WireMode::Ascii);
        if !ascii || self.probing_reset || !self.has_ascii(module) {
            return SessionError::Timeout {
                module: name,
                timeout,
                hint,
            };
        }
        self.probing_reset = true;
        let found = self.probe_reset(module);
        self.probing_reset = false;
        let hint = match found {
            Ok(false) => hint,
            Ok(true) => format!(
                "{hint}; {} had restarted: it is in ASCII mode again and the request was not \
                 repeated",
                ModuleName(module)
            ),
            Err(e) => format!(
                "{hint}; {} restarted in binary mode and could not be put back into ASCII \
                 mode ({e})",
                ModuleName(module)
            ),
        };
        SessionError::Timeout {
            module: name,
            timeout,
            hint,
        }
    }

    /// Asks `module` in binary whether it is there: true when it answered and is back in ASCII
    /// mode, false when it is silent in binary too.
    fn probe_reset(&mut self, module: u8) -> Result<bool, SessionError> {
        let probe = Instruction::new(Opcode::FirmwareVersion, 1, 0, 0);
        self.ascii_sent = true; // the quiet gap before the frame, whatever came before
        // A restarted module answers with its stored host address, which a host address set in
        // RAM before the restart is not: the probe's reply names the one to expect.
        self.host = None;
        // A restarted module answers at once: the probe waits no longer than an optional reply.
        let wait = self.optional_wait(2 * FRAME_LEN as u32);
        if self
            .with_timeout(wait, |s| s.binary_request(module, probe))
            .is_err()
        {
            return Ok(false);
        }
        let name = ModuleName(module);
        let message = format!(
            "{name} restarted in binary mode; re-entering ASCII mode; RAM settings are back to \
             their stored values"
        );
        self.core.wire.note(&message);
        self.core.wire.notices.push(message);
        // What it was doing ended with the power: motion, a program, unanswered lines.
        self.core.moved.remove(&Some(module.into()));
        self.core.running.remove(&Some(module.into()));
        // Nothing sent before the restart can be answered any more, a barrier's refusal neither:
        // no barrier is owed to it (see `barrier.rs`).
        if let Some(c) = address_char(module) {
            self.unanswered.forget(c);
            self.unanswered.replied(c);
        }
        let found_in = self.modules.remove(&module).map(|m| m.found_in);
        self.enter_ascii(module)?;
        if let (Some(state), Some(found_in)) = (self.modules.get_mut(&module), found_in) {
            state.found_in = found_in;
        }
        if let Some(&echo) = self.echo_set.get(&module) {
            let now = self.modules.get(&module).map(|m| m.echo);
            if now != Some(echo) {
                self.set_echo(module, echo)?;
                self.core.wire.notices.push(format!(
                    "echo {} set again on {name}, as before the restart",
                    echo.name()
                ));
            }
        }
        Ok(true)
    }

    /// Remembers the echo the user chose for `module`, to set again after a restart.
    pub(super) fn chose_echo(&mut self, module: u8, echo: Echo) {
        self.echo_set.insert(module, echo);
    }
}
