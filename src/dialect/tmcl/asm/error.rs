//! What the assembler reports: every problem with the file, line and column it is at, so an editor
//! or a terminal can jump to it (`test2.tmc:12:9: error: unknown label 'Lop'; did you mean Loop?`).

use std::fmt;

use crate::dialect::tmcl::protocol::{InputError, Warning};
use crate::suggest::did_you_mean;

/// Why a source line cannot become an instruction.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Problem {
    /// The text does not follow the source grammar.
    #[error("{0}")]
    Syntax(String),
    /// No command has this mnemonic.
    #[error("unknown command '{word}'{}", did_you_mean(suggestion))]
    UnknownMnemonic {
        /// What was written.
        word: String,
        /// The nearest mnemonic.
        suggestion: Option<String>,
    },
    /// A command of other modules that this module's profile does not have.
    #[error(
        "the {module} has no command '{word}'; these profiles have it: {}; give --profile NAME, or download to the module and it is checked against the module identified",
        profiles.join(", ")
    )]
    NotInProfile {
        /// What was written.
        word: String,
        /// The module whose profile was used.
        module: String,
        /// The built-in profiles that have the command.
        profiles: Vec<String>,
    },
    /// A jump or call to a label that is not defined.
    #[error("unknown label '{name}'{}", did_you_mean(suggestion))]
    UnknownLabel {
        /// The label as written.
        name: String,
        /// The nearest defined label.
        suggestion: Option<String>,
    },
    /// A name in an expression that is neither a constant nor a label.
    #[error("unknown constant or label '{name}'{}", did_you_mean(suggestion))]
    UnknownSymbol {
        /// The name as written.
        name: String,
        /// The nearest defined symbol.
        suggestion: Option<String>,
    },
    /// A label or constant defined twice.
    #[error("'{name}' is already defined on line {first_line}")]
    Duplicate {
        /// The name.
        name: String,
        /// Where it was defined first.
        first_line: usize,
    },
    /// A constant defined in terms of itself.
    #[error("constant '{name}' is defined in terms of itself")]
    Cycle {
        /// The constant.
        name: String,
    },
    /// Overflow or division by zero while evaluating an expression.
    #[error("{0}")]
    Arithmetic(String),
    /// More instructions than the module's program memory holds.
    #[error(
        "the program has {count} instructions but the {module} holds {limit}; this is instruction {first_extra}"
    )]
    TooLong {
        /// Instructions in the source.
        count: usize,
        /// Program memory size.
        limit: u16,
        /// Module name.
        module: String,
        /// The first instruction that does not fit (1-based).
        first_extra: usize,
    },
    /// Refused by the command table or the validator (shared with the interactive line grammar).
    #[error(transparent)]
    Input(#[from] InputError),
}

/// A place in a source file (1-based line and character column).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Default)]
pub struct Position {
    /// Line number.
    pub line: usize,
    /// Column, in characters.
    pub column: usize,
}

/// One error, located.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AsmError {
    /// The source file's name as given to [`assemble`](super::assemble).
    pub file: String,
    /// Where.
    pub at: Position,
    /// What is wrong.
    pub problem: Problem,
}

impl fmt::Display for AsmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: error: {}",
            self.file, self.at.line, self.at.column, self.problem
        )
    }
}

/// A warning about a line that still assembles (for example a parameter number the profile does
/// not list).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AsmWarning {
    /// The source file's name.
    pub file: String,
    /// Where.
    pub at: Position,
    /// What is worth knowing.
    pub warning: Warning,
}

impl fmt::Display for AsmWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: warning: {}",
            self.file, self.at.line, self.at.column, self.warning
        )
    }
}

/// Everything wrong with a source file: all errors found, in line order, and the warnings.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub struct AsmErrors {
    /// The errors (never empty).
    pub errors: Vec<AsmError>,
    /// Warnings found along the way.
    pub warnings: Vec<AsmWarning>,
}

impl fmt::Display for AsmErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, error) in self.errors.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{error}")?;
        }
        Ok(())
    }
}

/// Collects located problems while the assembler keeps going.
#[derive(Debug, Default)]
pub(super) struct Diagnostics {
    file: String,
    errors: Vec<AsmError>,
    warnings: Vec<AsmWarning>,
}

impl Diagnostics {
    pub(super) fn new(file: &str) -> Self {
        Diagnostics {
            file: file.to_string(),
            ..Diagnostics::default()
        }
    }

    pub(super) fn error(&mut self, at: Position, problem: Problem) {
        self.errors.push(AsmError {
            file: self.file.clone(),
            at,
            problem,
        });
    }

    pub(super) fn warning(&mut self, at: Position, warning: Warning) {
        self.warnings.push(AsmWarning {
            file: self.file.clone(),
            at,
            warning,
        });
    }

    /// The warnings, or everything as an error if any error was found.
    pub(super) fn finish(mut self) -> Result<Vec<AsmWarning>, AsmErrors> {
        if self.errors.is_empty() {
            return Ok(self.warnings);
        }
        self.errors.sort_by_key(|e| e.at);
        Err(AsmErrors {
            errors: self.errors,
            warnings: self.warnings,
        })
    }
}
