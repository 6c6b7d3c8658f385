//! A link lost under a TMCL session: a request cut short, the wait `--reconnect` asks for, and
//! what is done once the link is back — each module put back in the mode it was in, asked again
//! what it is (136), and a read that was cut short sent again. A motion or a write is never sent
//! again: whether the module got it before the link went is unknown.

use crate::dialect::DialectSession;
use crate::dialect::tmcl::protocol::line::{Line, Op, format_line};
use crate::dialect::tmcl::protocol::{ModuleName, Opcode};
use crate::session::SessionError;

use super::identify::Identity;
use super::{TmclExchange, TmclSession, WireMode};

/// Whether a request only reads: sending it twice changes nothing on the module.
fn is_read(op: Op) -> bool {
    matches!(
        op,
        Op::Command(i) if matches!(
            i.command,
            Opcode::Gap
                | Opcode::Ggp
                | Opcode::Gio
                | Opcode::Gco
                | Opcode::ReadMemory
                | Opcode::ApplicationStatus
                | Opcode::FirmwareVersion
        )
    )
}

impl TmclSession {
    /// `op` to `module` was cut short by the lost link (`why`): the port is closed and the loss
    /// recorded; without `--reconnect` (or while already reconnecting) the loss is the answer.
    /// Otherwise the link is waited for; once back, a read is sent again and anything else
    /// fails with an error that says it was not.
    pub(super) fn after_loss(
        &mut self,
        module: u8,
        op: Op,
        why: String,
    ) -> Result<TmclExchange, SessionError> {
        let what = self.request_text(module, op);
        let c = ModuleName(module);
        // The module may have got it: what it may have set going is stopped on a failure.
        if let Op::Command(i) = op {
            let spec = self
                .profile_of(module)
                .commands
                .by_number(i.command)
                .cloned();
            if spec.is_some_and(|s| s.starts_motion) {
                self.core.moved.insert(Some(module.into()));
            }
            if i.command == Opcode::RunApplication {
                self.core.running.insert(Some(module.into()));
            }
        }
        self.after_cut_short(&what, &c.to_string(), is_read(op), why)?;
        self.perform_once(module, op)
    }

    /// The request as a line, for messages.
    fn request_text(&self, module: u8, op: Op) -> String {
        let address = (module != self.target).then_some(module);
        let line = Line { address, op };
        format_line(&line, self.target, &self.profile_of(module))
    }

    /// After the link was reopened: every module asked again what it is (136, in binary mode,
    /// so a module in ASCII mode is taken out of it first), a changed firmware said, and the
    /// modules that were in ASCII mode put back into it with their echo learnt again.
    pub(super) fn reenter_modules(&mut self) -> Result<(), SessionError> {
        // A reopened line may hold anything: the first frame waits for it to fall quiet.
        self.ascii_sent = !self.core.wire.link.private();
        self.frames_aligned = false;
        let mut modules: Vec<(u8, Option<WireMode>)> = self
            .modules
            .iter()
            .map(|(&a, m)| (a, Some(m.mode)))
            .collect();
        for &address in self.known.keys() {
            if !self.modules.contains_key(&address) {
                modules.push((address, None));
            }
        }
        for (module, mode) in modules {
            let ascii = mode == Some(WireMode::Ascii);
            if ascii {
                self.leave_ascii(module)?;
            }
            self.reidentify(module)?;
            if ascii {
                self.enter_ascii(module)?;
                self.echo_again(module)?;
            }
        }
        Ok(())
    }

    /// Sets the echo this session had set on `module` again, where the module no longer has it
    /// (it lost its RAM settings while the link was away).
    fn echo_again(&mut self, module: u8) -> Result<(), SessionError> {
        let Some(&echo) = self.echo_set.get(&module) else {
            return Ok(());
        };
        if self.modules.get(&module).is_some_and(|m| m.echo == echo) {
            return Ok(());
        }
        self.set_echo(module, echo)?;
        self.core.wire.notices.push(format!(
            "{} had lost the echo set before the link was lost; set to {} again",
            ModuleName(module),
            echo.name()
        ));
        Ok(())
    }

    /// Asks `module` again what it is, where it was identified before; a different firmware is
    /// said (a module swapped or updated while the link was away) and its profile chosen again.
    fn reidentify(&mut self, module: u8) -> Result<(), SessionError> {
        let Some(before) = self.known.get(&module).cloned() else {
            return Ok(());
        };
        let Identity::Answered { firmware: was, .. } = &before.identity else {
            return Ok(());
        };
        self.known.remove(&module);
        self.settle_identity(module, false)?;
        let c = ModuleName(module);
        let now = self.known.get(&module).map(|k| k.identity.clone());
        match now {
            Some(Identity::Answered { firmware, .. }) if firmware == *was => {
                self.core.wire.note(&format!(
                    "re-identified {c}: firmware {firmware}, as before"
                ));
            }
            Some(Identity::Answered {
                firmware,
                module: kind,
            }) => {
                self.core.wire.notices.push(format!(
                    "{c} now answers as {kind}, firmware {firmware} (it was {was} before the link \
                     was lost): another module or a new firmware; its profile is chosen again"
                ));
            }
            _ => {
                // No answer now: keep what was known, and say so.
                self.known.insert(module, before.clone());
                self.core.wire.notices.push(format!(
                    "{c} did not say what it is after the reconnect; taken to be {was} as before"
                ));
            }
        }
        if module == self.target {
            self.show_target();
        }
        Ok(())
    }
}
