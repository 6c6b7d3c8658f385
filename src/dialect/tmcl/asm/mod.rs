//! The TMCL assembler and disassembler: stand-alone program source (`.tmc`, as the TMCL-IDE
//! writes it) to the 7-byte instructions a module stores, and back.
//!
//! Source, one statement per line:
//!
//! ```text
//! // comment to the end of the line; /* block comments */ too
//! #define Speed 500000          // constant (also: Speed = 500000)
//! Far = Speed * 2               // + - * / % and ( ) over numbers and constants
//!         SAP max_positioning_speed, 0, Speed   // parameter names or numbers
//! Loop:   MVP ABS, 0, 0x1000    // label before an instruction; decimal, 0x or $ hex
//!         WAIT POS, 0, 0
//!         JA Loop               // labels as jump and call addresses, forward or backward
//! ```
//!
//! Mnemonics, keywords (`ABS`, `TICKS`, `EQ`, `ADD` …), operand layouts and ranges all come from
//! the profile's command table; a mnemonic's operands go through the operand grammar of typed
//! lines (`protocol::operands`), with constants, labels and expressions evaluated to numbers; and
//! each instruction passes the same validator as a typed command (in `Mode::Program`), so the
//! assembler knows no command by itself. Unlike the interactive line
//! grammar there is no address character, operands are separated by commas only, and `STOP` is
//! command 28 (end of program). A command may also be given by number with raw fields
//! (`27 0, 0, 500`), which is how the disassembler writes instructions that have no mnemonic form.
//!
//! Names are case-insensitive. Two passes: labels and constants may be used before they are
//! defined. All errors of a file are reported, each with file, line and column.

mod binary;
mod disasm;
mod encode;
mod error;
mod lex;
mod parse;
mod program;
mod symbols;

pub use binary::{BinaryError, HEADER_LEN, MAGIC, VERSION, is_program_file};
pub use disasm::{Disassembly, disassemble};
pub use error::{AsmError, AsmErrors, AsmWarning, Position, Problem};
pub use program::{Label, Program};

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::validate::{Mode, validate_instruction};
use crate::dialect::tmcl::protocol::{InputError, Instruction};

use encode::{Refusal, encode};
use error::Diagnostics;
use parse::{Body, Statement, parse_line};
use symbols::Symbols;

/// The `.bin` program file contents for `instructions` (format in docs/programs.md and [`MAGIC`]).
pub fn write_binary(instructions: &[Instruction]) -> Result<Vec<u8>, BinaryError> {
    binary::write(instructions)
}

/// The instructions of a `.bin` program file.
pub fn read_binary(bytes: &[u8]) -> Result<Vec<Instruction>, BinaryError> {
    binary::read(bytes)
}

/// Assembles `source`; `file` names it in messages. Checks every instruction for a stand-alone
/// program of `profile`, and the program against `profile.program_memory`.
pub fn assemble(source: &str, file: &str, profile: &Profile) -> Result<Program, AsmErrors> {
    crate::crash::point("assemble", file);
    let mut diags = Diagnostics::new(file);
    let mut symbols = Symbols::default();
    let mut statements: Vec<Statement> = Vec::new();
    for (line, tokens) in lex::tokenize(source, &mut diags) {
        let parsed = match parse_line(line, &tokens) {
            Ok(parsed) => parsed,
            Err((column, message)) => {
                diags.error(Position { line, column }, Problem::Syntax(message));
                continue;
            }
        };
        for (name, column) in parsed.labels {
            let at = Position { line, column };
            if let Err(problem) = symbols.label(&name, at, statements.len()) {
                diags.error(at, problem);
            }
        }
        match parsed.body {
            Body::Empty => {}
            Body::Constant { name, column, expr } => {
                let at = Position { line, column };
                if let Err(problem) = symbols.constant(&name, at, expr) {
                    diags.error(at, problem);
                }
            }
            Body::Instruction(statement) => statements.push(statement),
        }
    }
    let limit = usize::from(profile.program_memory);
    if let Some(first_extra) = statements.get(limit) {
        diags.error(
            first_extra.at,
            Problem::TooLong {
                count: statements.len(),
                limit: profile.program_memory,
                module: profile.module.clone(),
                first_extra: limit + 1,
            },
        );
    }
    symbols.evaluate_constants(&mut diags);
    let mut instructions = Vec::with_capacity(statements.len());
    for statement in &statements {
        match encode(statement, &symbols, profile) {
            Ok(encoded) => {
                instructions.push(encoded.instruction);
                for (at, warning) in encoded.warnings {
                    diags.warning(at, warning);
                }
            }
            Err(Refusal::At(at, problem)) => diags.error(at, problem),
            Err(Refusal::Reported) => {}
        }
    }
    let warnings = diags.finish()?;
    Ok(Program {
        instructions,
        lines: statements.iter().map(|s| s.at.line).collect(),
        labels: symbols
            .labels()
            .into_iter()
            .map(|(name, address)| Label { name, address })
            .collect(),
        warnings,
    })
}

/// Why a file given to `download` cannot be loaded.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum LoadError {
    /// Source that does not assemble.
    #[error("{0}")]
    Source(AsmErrors),
    /// A damaged or foreign program file.
    #[error("{name}: {error}")]
    Binary {
        /// The file name.
        name: String,
        /// What is wrong.
        error: BinaryError,
    },
    /// A program file holding an instruction that is not valid in a program.
    #[error("{name}: instruction {address}: {error}")]
    Invalid {
        /// The file name.
        name: String,
        /// Its address.
        address: usize,
        /// Why.
        error: InputError,
    },
    /// A program file longer than the module's program memory.
    #[error("{name}: {count} instructions do not fit in the {module}'s program memory of {limit}")]
    TooLong {
        /// The file name.
        name: String,
        /// Instructions in the file.
        count: usize,
        /// Module name.
        module: String,
        /// Program memory size.
        limit: u16,
    },
}

/// A file that does not load is refused before anything is sent.
impl crate::exit::ExitStatus for LoadError {
    fn exit(&self) -> crate::exit::Exit {
        crate::exit::Exit::Refused
    }
}

/// A source file's bytes as text: not UTF-8 only in comments (old Windows files), so invalid
/// bytes are replaced; a byte order mark skipped; CR LF and CR-only line ends (old Mac
/// editors, TMCL-IDE exports) made LF, so every line is its own.
pub fn source_text(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    text.replace("\r\n", "\n").replace('\r', "\n")
}

/// The instructions of a program file or of source text, told apart by the file's first bytes
/// (not its name): assembled if source, checked as the assembler would if binary.
pub fn load_program(
    bytes: &[u8],
    name: &str,
    profile: &Profile,
) -> Result<Vec<Instruction>, LoadError> {
    if !is_program_file(bytes) {
        let source = source_text(bytes);
        return assemble(&source, name, profile)
            .map(|p| p.instructions)
            .map_err(LoadError::Source);
    }
    let binary_error = |error| LoadError::Binary {
        name: name.to_string(),
        error,
    };
    let instructions = read_binary(bytes).map_err(binary_error)?;
    if instructions.len() > usize::from(profile.program_memory) {
        return Err(LoadError::TooLong {
            name: name.to_string(),
            count: instructions.len(),
            module: profile.module.clone(),
            limit: profile.program_memory,
        });
    }
    for (address, instruction) in instructions.iter().enumerate() {
        validate_instruction(instruction, profile, Mode::Program).map_err(|error| {
            LoadError::Invalid {
                name: name.to_string(),
                address,
                error,
            }
        })?;
    }
    Ok(instructions)
}

#[cfg(test)]
mod tests;
