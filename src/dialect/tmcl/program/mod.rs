//! Stand-alone TMCL programs on the module, from the host's side: download with read-back
//! verification, and program control (run, stop, step, reset, status) from ASCII mode, switching
//! to binary mode transparently for the control functions ASCII mode lacks.

pub mod download;
pub mod upload;

use crate::dialect::session::DialectSession;
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::dialect::tmcl::protocol::ModuleName;
use crate::dialect::tmcl::protocol::{Instruction, Opcode, Status};
use crate::dialect::tmcl::render::application_status;
use crate::dialect::tmcl::session::{TmclExchange, TmclSession, WireMode};
use crate::session::{SessionError, interrupt};

/// What a download did.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DownloadReport {
    /// Instructions stored.
    pub stored: usize,
    /// Whether every instruction was read back and matched (false when the module cannot read
    /// its memory back, e.g. code protection).
    pub verified: bool,
}

/// Downloads `program` to `module` from address 0: download mode (132), each instruction,
/// quit (133), then read-back through 134 where the module allows it. `progress(done, total)` is
/// called as instructions go out. The module is returned to the mode it was in.
pub fn download(
    session: &mut TmclSession,
    module: u8,
    program: &[Instruction],
    mut progress: impl FnMut(usize, usize),
) -> Result<DownloadReport, SessionError> {
    session.in_binary(module, |s| {
        let mut download_mode = DownloadMode::enter(s, module)?;
        let mut count = 0;
        let stored = store_all(
            download_mode.session,
            module,
            program,
            &mut count,
            &mut progress,
        );
        let quit = download_mode.leave();
        drop(download_mode);
        if stored.is_err() && count > 0 {
            // Whatever ended it (Ctrl-C, a lost link, a refusal), the module keeps what it got.
            s.notify(format!(
                "{}: program memory now holds a partial program ({} of {} stored from address \
                 0, the rest as it was); download it again before running it",
                ModuleName(module),
                count,
                crate::count::counted(program.len(), "instruction"),
            ));
        }
        stored?;
        quit?;
        let verified = verify(s, module, program, &mut progress)?;
        Ok(DownloadReport {
            stored: program.len(),
            verified,
        })
    })
}

/// A module in download mode (132), which stores every command instead of executing it — the MST
/// meant to stop a motor included. It is left (133) whatever ends the download: an error, Ctrl-C
/// (whose flag would cancel the request and is put back afterwards) or a panic unwinding
/// through it.
struct DownloadMode<'s> {
    session: &'s mut TmclSession,
    module: u8,
    open: bool,
}

impl<'s> DownloadMode<'s> {
    fn enter(session: &'s mut TmclSession, module: u8) -> Result<Self, SessionError> {
        session
            .request(module, Instruction::new(Opcode::StartDownload, 0, 0, 0))?
            .checked()?;
        Ok(DownloadMode {
            session,
            module,
            open: true,
        })
    }

    fn leave(&mut self) -> Result<(), SessionError> {
        self.open = false;
        let interrupted = interrupt::take();
        let quit = self
            .session
            .request(self.module, Instruction::new(Opcode::QuitDownload, 0, 0, 0))
            .and_then(TmclExchange::checked);
        if interrupted {
            interrupt::raise();
        }
        quit.map(|_| ())
    }
}

impl Drop for DownloadMode<'_> {
    fn drop(&mut self) {
        if self.open {
            let _ = catch_unwind(AssertUnwindSafe(|| self.leave()));
        }
    }
}

/// Stores each instruction in turn; `count` says how many the module stored, also on failure.
fn store_all(
    s: &mut TmclSession,
    module: u8,
    program: &[Instruction],
    count: &mut usize,
    progress: &mut impl FnMut(usize, usize),
) -> Result<(), SessionError> {
    for (address, instruction) in program.iter().enumerate() {
        let exchange = s.store_instruction(module, *instruction)?;
        if exchange.status() == Some(Status::Stored) {
            *count = address + 1;
        }
        if exchange.status() != Some(Status::Stored) {
            let status = exchange.status().unwrap_or(Status::Other(0));
            return Err(SessionError::Device {
                module: ModuleName(module).to_string(),
                sent: format!("instruction {address} ({})", exchange.sent),
                reason: format!("status {status}, expected 101 (stored)"),
            });
        }
        progress(address + 1, program.len() * 2);
        crate::crash::point("download", &address.to_string());
    }
    Ok(())
}

/// Reads the program back with 134 (type 0 value, type 1 command/type/motor — the simulator's
/// documented convention). Returns false when the module does not support reading back.
fn verify(
    s: &mut TmclSession,
    module: u8,
    program: &[Instruction],
    progress: &mut impl FnMut(usize, usize),
) -> Result<bool, SessionError> {
    for (address, expected) in program.iter().enumerate() {
        let at = address as i32;
        let value = s.request(module, Instruction::new(Opcode::ReadMemory, 0, 0, at))?;
        if unreadable(value.status()) {
            s.annotate("the module does not read its program memory back; download not verified");
            return Ok(false);
        }
        let got = with_fields(s, module, at, value)?;
        if got != *expected {
            return Err(SessionError::Link(format!(
                "verification failed at address {address}: stored {got:?}, expected {expected:?}"
            )));
        }
        progress(program.len() + address + 1, program.len() * 2);
    }
    Ok(true)
}

/// Whether a 134 answer's status says the module does not read its program memory back.
fn unreadable(status: Option<Status>) -> bool {
    matches!(
        status,
        Some(Status::NotAvailable | Status::InvalidCommand | Status::WrongType)
    )
}

/// The instruction at `address` whose value `value` (134 type 0) answered, completed by its
/// command, type and motor read with 134 type 1.
fn with_fields(
    s: &mut TmclSession,
    module: u8,
    address: i32,
    value: TmclExchange,
) -> Result<Instruction, SessionError> {
    let value = value.checked()?.value().unwrap_or(0);
    let fields = s
        .request(module, Instruction::new(Opcode::ReadMemory, 1, 0, address))?
        .checked()?
        .value()
        .unwrap_or(0);
    Ok(Instruction::new(
        (fields >> 16) as u8,
        (fields >> 8) as u8,
        fields as u8,
        value,
    ))
}

/// A control function (130 step, 131 reset, 135 status) sent in binary mode, switching there and
/// back when the module is in ASCII mode.
pub fn control(
    session: &mut TmclSession,
    module: u8,
    instruction: Instruction,
) -> Result<TmclExchange, SessionError> {
    session.in_binary(module, |s| s.request(module, instruction)?.checked())
}

/// The application status (135): 0 stopped, 1 running, 2 stepping, 3 reset.
pub fn status(session: &mut TmclSession, module: u8) -> Result<i32, SessionError> {
    Ok(control(
        session,
        module,
        Instruction::new(Opcode::ApplicationStatus, 0, 0, 0),
    )?
    .value()
    .unwrap_or(0))
}

/// Warnings about the motors of `module` that still turn, with their speed: stopping a program
/// does not stop the motion it started. A check that cannot be made says why.
pub fn still_turning(session: &mut TmclSession, module: u8) -> Vec<String> {
    warn_turning(session, module, |motor| {
        format!("the program stopped, its motion did not; MST {motor} or Ctrl-C stops it")
    })
}

/// Warnings about the motors of `module` still turning as the interactive shell ends: leaving
/// does not stop them (as `:stop` does not stop a program's motion); each says how to.
pub fn turning_at_exit(session: &mut TmclSession, module: u8) -> Vec<String> {
    let option = if module == 1 {
        String::new()
    } else {
        format!("-m {module} ")
    };
    warn_turning(session, module, |motor| {
        format!(
            "leaving the shell does not stop it; MST {motor} does (tmclsh {option}-c 'MST {motor}' \
             with the same link)"
        )
    })
}

/// A warning for each motor of `module` whose actual speed is not 0, ending with `how(motor)`.
fn warn_turning(session: &mut TmclSession, module: u8, how: impl Fn(u8) -> String) -> Vec<String> {
    let name = ModuleName(module);
    let profile = session.profile_of(module);
    let Ok(speed) = profile.find_axis("actual_speed") else {
        return Vec::new();
    };
    let (number, ident) = (speed.number, speed.ident.clone());
    let mut warnings = Vec::new();
    for motor in 0..profile.axes {
        let read = session
            .request(module, Instruction::new(Opcode::Gap, number, motor, 0))
            .and_then(TmclExchange::checked);
        match read.map(|x| x.value().unwrap_or(0)) {
            Ok(0) => {}
            Ok(value) => warnings.push(format!(
                "motor {motor} of {name} is still turning ({ident} = {value}): {}",
                how(motor)
            )),
            Err(e) => warnings.push(format!(
                "could not check whether motor {motor} of {name} still turns: {e}"
            )),
        }
    }
    warnings
}

/// "stopped", "running" … for a status value.
pub fn status_name(value: i32) -> &'static str {
    application_status(value)
}

/// The mode the module is left in, for messages.
pub fn mode_text(session: &TmclSession, module: u8) -> &'static str {
    match session.module_state(module) {
        Some((WireMode::Binary, _)) => "binary",
        _ => "ASCII",
    }
}
