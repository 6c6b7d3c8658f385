//! Reading the stored program back (`tmclsh upload`, the shell's `:upload`): command 134 at each
//! address, as `download` verifies, until the program's end — the first STOP, JA, RSUB or RETI
//! past which no jump, call or vector of the program reaches, an empty word there, or the end of
//! the module's memory — or a bound, which is said. The instructions are turned into source with
//! labels by the disassembler.

use crate::dialect::tmcl::asm;
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::{Field, OperandKind};
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode, Status};
use crate::dialect::tmcl::session::TmclSession;
use crate::session::SessionError;

use super::{unreadable, with_fields};

/// Where the reading stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// At an instruction that ends the flow (STOP …) at this address, nothing reaching past it.
    Flow(usize),
    /// At an empty word (all fields zero) at this address, nothing reaching it.
    Empty(usize),
    /// At the end of the module's memory (134 refused this address as out of range).
    Memory(usize),
    /// At the bound: this many instructions read without finding the end.
    Bound(usize),
}

/// A program read back.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Upload {
    /// The instructions from address 0.
    pub instructions: Vec<Instruction>,
    /// Why the reading stopped.
    pub end: End,
}

impl Upload {
    /// The program as source text: a comment saying where it came from and how it ended, then
    /// the disassembler's lines with labels.
    pub fn source(&self, from: &str, profile: &Profile) -> String {
        let disassembly = asm::disassemble(&self.instructions, profile);
        format!(
            "// uploaded from {from}: {}, {}\n{}",
            crate::count::counted(self.instructions.len(), "instruction"),
            self.end_text(),
            disassembly.source
        )
    }

    /// How the reading ended, in words.
    pub fn end_text(&self) -> String {
        match self.end {
            End::Flow(at) => format!("ending at address {at}, past which nothing jumps"),
            End::Empty(at) => format!("ending before the empty word at address {at}"),
            End::Memory(at) => format!("ending with the program memory at address {at}"),
            End::Bound(n) => format!(
                "stopped at the bound of {n} without finding the end (more may follow: --max)"
            ),
        }
    }
}

/// Reads `module`'s program back, at most `bound` instructions; `progress(done, bound)` is
/// called as they come.
pub fn upload(
    session: &mut TmclSession,
    module: u8,
    bound: usize,
    mut progress: impl FnMut(usize, usize),
) -> Result<Upload, SessionError> {
    let profile = session.profile_of(module);
    session.in_binary(module, |s| {
        let mut instructions = Vec::new();
        // The furthest address a jump, call or vector read so far goes to.
        let mut reach = 0;
        for at in 0..bound {
            let Some(instruction) = read_at(s, module, at)? else {
                return Ok(Upload {
                    instructions,
                    end: End::Memory(at),
                });
            };
            if instruction == Instruction::default() && reach <= at {
                return Ok(Upload {
                    instructions,
                    end: End::Empty(at),
                });
            }
            instructions.push(instruction);
            progress(at + 1, bound);
            if let Some(target) = target(&instruction, &profile) {
                reach = reach.max(target);
            }
            if ends_flow(&instruction, &profile) && reach <= at {
                return Ok(Upload {
                    instructions,
                    end: End::Flow(at),
                });
            }
        }
        Ok(Upload {
            instructions,
            end: End::Bound(bound),
        })
    })
}

/// One instruction read with 134 (type 0 its value, type 1 command, type and motor: the
/// convention `download`'s verification reads); `None` past the end of memory.
fn read_at(
    s: &mut TmclSession,
    module: u8,
    at: usize,
) -> Result<Option<Instruction>, SessionError> {
    let address = i32::try_from(at).unwrap_or(i32::MAX);
    let value = s.request(module, Instruction::new(Opcode::ReadMemory, 0, 0, address))?;
    match value.status() {
        Some(Status::InvalidValue) if at > 0 => return Ok(None),
        status if unreadable(status) => {
            return Err(SessionError::Device {
                module: ModuleName(module).to_string(),
                sent: "134 (read program memory)".into(),
                reason: format!(
                    "status {}: the module does not read its program back (code protection, or \
                     no such command)",
                    value.status().unwrap_or(Status::Other(0))
                ),
            });
        }
        _ => {}
    }
    with_fields(s, module, address, value).map(Some)
}

/// The address a jump, call or vector goes to, as the command table says.
fn target(instruction: &Instruction, profile: &Profile) -> Option<usize> {
    let spec = profile.commands.by_number(instruction.command)?;
    let jumps = spec.field_is(Field::Value, OperandKind::Address);
    if !jumps {
        return None;
    }
    usize::try_from(instruction.value).ok()
}

/// Whether the program does not go on to the next address after it: STOP, JA, RSUB, RETI.
fn ends_flow(instruction: &Instruction, profile: &Profile) -> bool {
    profile
        .commands
        .by_number(instruction.command)
        .is_some_and(|spec| ["STOP", "JA", "RSUB", "RETI"].contains(&spec.mnemonic.as_str()))
}

/// Where an upload goes: printed as source, or written as source (`.tmc`) or as a program file
/// (`.bin`, what `tmclsh asm -o` writes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output<'p> {
    /// Source on the output.
    Print,
    /// Source to this file.
    Source(&'p std::path::Path),
    /// A program file to this file.
    Binary(&'p std::path::Path),
}

impl<'p> Output<'p> {
    /// The output a file name asks for by its extension; other names are refused.
    pub fn for_file(path: &'p std::path::Path) -> Result<Output<'p>, SessionError> {
        match path.extension().and_then(|e| e.to_str()) {
            Some(e) if e.eq_ignore_ascii_case("tmc") => Ok(Output::Source(path)),
            Some(e) if e.eq_ignore_ascii_case("bin") => Ok(Output::Binary(path)),
            _ => Err(SessionError::Usage(format!(
                "{}: name the file FILE.tmc (source) or FILE.bin (program file)",
                path.display()
            ))),
        }
    }
}

/// Reads the target's program back (at most `max` instructions, the module's program memory by
/// default) with a progress bar on a terminal, and prints or writes it; returns what to print.
pub fn upload_to(
    session: &mut TmclSession,
    output: Output<'_>,
    max: Option<usize>,
) -> Result<String, SessionError> {
    let module = session.target();
    let profile = session.profile_of(module);
    let bound = max.unwrap_or(usize::from(profile.program_memory));
    let progress = crate::progress::Progress::steps(bound, 64, "upload");
    let upload = upload(session, module, bound, |done, total| {
        progress.set(done, total)
    });
    drop(progress);
    let upload = upload?;
    let from = format!("{}, {}", ModuleName(module), profile.module);
    let written = |path: &std::path::Path, bytes: &[u8]| {
        crate::file::write(path, bytes).map_err(|e| {
            SessionError::Failed(crate::exit::Failure::refused(format!("cannot write {e}")))
        })
    };
    let summary = |path: &std::path::Path| {
        format!(
            "uploaded {} from {from}, {}; written to {}",
            crate::count::counted(upload.instructions.len(), "instruction"),
            upload.end_text(),
            path.display()
        )
    };
    match output {
        Output::Print => Ok(upload.source(&from, &profile)),
        Output::Source(path) => {
            written(path, upload.source(&from, &profile).as_bytes())?;
            Ok(summary(path) + "\n")
        }
        Output::Binary(path) => {
            let bytes = asm::write_binary(&upload.instructions)
                .map_err(|e| SessionError::Failed(e.into()))?;
            written(path, &bytes)?;
            Ok(summary(path) + "\n")
        }
    }
}
