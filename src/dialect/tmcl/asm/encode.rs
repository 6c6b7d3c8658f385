//! One instruction line to its 7-byte instruction. A mnemonic's operands go through the operand
//! grammar of typed lines ([`operands::encode`]), which knows the command table's keywords and
//! parameter names; what a program has beyond a typed line — constants, labels and expressions —
//! is evaluated to a number here. A command given by number takes raw fields. The validator of
//! the interactive commands then checks the result for a stand-alone program (`Mode::Program`),
//! so a program is held to exactly the rules a typed command is.

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::catalogue;
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::protocol::operands::{self, Number, OperandText, Refused, byte};
use crate::dialect::tmcl::protocol::validate::{Mode, validate, validate_instruction};
use crate::dialect::tmcl::protocol::{InputError, Instruction, Line, Op, Warning};
use crate::suggest;

use super::error::{Position, Problem};
use super::parse::{Head, Operand, Statement};
use super::symbols::{EvalError, Expect, Symbols};

/// Why a line produced no instruction.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Refusal {
    /// A problem to report here.
    At(Position, Problem),
    /// Caused by a problem already reported elsewhere (a broken constant).
    Reported,
}

/// An encoded line and its warnings.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Encoded {
    pub instruction: Instruction,
    pub warnings: Vec<(Position, Warning)>,
}

/// Where the operand of each field was written, to point errors at it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Columns {
    head: usize,
    type_: Option<usize>,
    motor: Option<usize>,
    value: Option<usize>,
    coordinate_in_type: bool,
}

impl Columns {
    /// The columns of `statement`'s operands, which fill `fields` in order.
    fn new(statement: &Statement, fields: impl Iterator<Item = Field>) -> Columns {
        let mut columns = Columns {
            head: statement.at.column,
            type_: None,
            motor: None,
            value: None,
            coordinate_in_type: false,
        };
        for (field, operand) in fields.zip(&statement.operands) {
            let column = Some(operand.column);
            match field {
                Field::Type => columns.type_ = column,
                Field::Motor => columns.motor = column,
                Field::Value => columns.value = column,
            }
        }
        columns
    }

    fn of(&self, field: Field) -> usize {
        let column = match field {
            Field::Type => self.type_,
            Field::Motor => self.motor,
            Field::Value => self.value,
        };
        column.unwrap_or(self.head)
    }

    /// The operand a validation error is about.
    fn for_error(&self, error: &InputError) -> usize {
        match error {
            InputError::BadKeyword { .. }
            | InputError::NotReadable { .. }
            | InputError::ReadOnly { .. }
            | InputError::NotStorable { .. } => self.of(Field::Type),
            InputError::BadMotor { .. } => self.of(Field::Motor),
            InputError::OutOfRange { what, .. }
                if self.coordinate_in_type && what == "the coordinate number" =>
            {
                self.of(Field::Type)
            }
            InputError::OutOfRange { .. } => self.of(Field::Value),
            _ => self.head,
        }
    }
}

/// Encodes and validates one instruction line.
pub(super) fn encode(
    statement: &Statement,
    symbols: &Symbols,
    profile: &Profile,
) -> Result<Encoded, Refusal> {
    let at = |column| Position {
        line: statement.at.line,
        column,
    };
    let (instruction, columns) = instruction(statement, symbols, profile)?;
    let warnings = validate_instruction(&instruction, profile, Mode::Program)
        .map_err(|e| Refusal::At(at(columns.for_error(&e)), e.into()))?;
    Ok(Encoded {
        instruction,
        warnings: warnings
            .into_iter()
            .map(|w| (at(columns.of(Field::Type)), w))
            .collect(),
    })
}

/// The instruction a line makes, before validation, and where each field was written.
pub(super) fn instruction(
    statement: &Statement,
    symbols: &Symbols,
    profile: &Profile,
) -> Result<(Instruction, Columns), Refusal> {
    match &statement.head {
        Head::Number(number) => raw(*number, statement, symbols),
        Head::Mnemonic(word) => {
            let spec = command(word, profile).map_err(|p| Refusal::At(statement.at, p))?;
            mnemonic(spec, statement, symbols, profile)
        }
    }
}

/// The operands of a mnemonic, through the operand grammar.
fn mnemonic(
    spec: &CommandSpec,
    statement: &Statement,
    symbols: &Symbols,
    profile: &Profile,
) -> Result<(Instruction, Columns), Refusal> {
    let line = statement.at.line;
    let texts: Vec<ProgramOperand> = statement
        .operands
        .iter()
        .map(|operand| ProgramOperand {
            operand,
            symbols,
            line,
        })
        .collect();
    let instruction = operands::encode(spec, &texts, profile).map_err(|refused| match refused {
        Refused::Table { operand, error } => {
            let column = operand.map_or(statement.at.column, |i| statement.operands[i].column);
            Refusal::At(Position { line, column }, error.into())
        }
        Refused::Operand(refusal) => refusal,
    })?;
    let mut columns = Columns::new(statement, spec.operands.iter().map(|o| o.kind.field()));
    columns.coordinate_in_type = spec.field_is(Field::Type, OperandKind::Coord);
    Ok((instruction, columns))
}

/// An operand of a program line: the names the program defines are its constants and labels,
/// evaluated to numbers; every other name is for the command table.
struct ProgramOperand<'a> {
    operand: &'a Operand,
    symbols: &'a Symbols,
    line: usize,
}

impl ProgramOperand<'_> {
    fn evaluate(&self, expect: Expect) -> Result<Number, Refusal> {
        let value = self
            .symbols
            .eval(&self.operand.expr, expect)
            .map_err(|e| match e {
                EvalError::At(column, problem) => Refusal::At(
                    Position {
                        line: self.line,
                        column,
                    },
                    problem,
                ),
                EvalError::Reported => Refusal::Reported,
            })?;
        Ok(Number {
            value,
            hex: self.operand.expr.is_hex_literal(),
        })
    }
}

impl OperandText for ProgramOperand<'_> {
    type Error = Refusal;

    fn name(&self) -> Option<&str> {
        self.operand.expr.as_name()
    }

    fn table_name(&self) -> Option<&str> {
        self.name().filter(|name| !self.symbols.contains(name))
    }

    fn number(&self, kind: OperandKind) -> Result<Option<Number>, Refusal> {
        let expect = match kind {
            OperandKind::Address => Expect::Label,
            _ => Expect::Value,
        };
        self.evaluate(expect).map(Some)
    }
}

/// The command a mnemonic names.
fn command<'p>(word: &str, profile: &'p Profile) -> Result<&'p CommandSpec, Problem> {
    if let Some(spec) = profile.commands.by_mnemonic(word) {
        return Ok(spec);
    }
    if let Some(ascii) = profile.commands.ascii_word(word) {
        let line = Line {
            address: None,
            op: Op::Ascii(ascii),
        };
        if let Err(e) = validate(&line, profile, Mode::Program) {
            return Err(e.into());
        }
    }
    // A command other modules have (EI, VECT … on the TMCM-1140) names them, not a near miss.
    let elsewhere: Vec<String> = catalogue::all()
        .iter()
        .filter(|other| other.name != profile.name && other.commands.by_mnemonic(word).is_some())
        .map(|other| other.name.clone())
        .collect();
    if !elsewhere.is_empty() {
        return Err(Problem::NotInProfile {
            word: word.to_string(),
            module: profile.module.clone(),
            profiles: elsewhere,
        });
    }
    let mnemonics = profile
        .commands
        .iter()
        .map(|c| c.mnemonic.as_str())
        .filter(|m| !m.is_empty());
    Err(Problem::UnknownMnemonic {
        word: word.to_string(),
        suggestion: suggest::nearest(word, mnemonics),
    })
}

/// `NUMBER [type], [motor], [value]`: the fields as given, for any command number.
fn raw(
    number: i64,
    statement: &Statement,
    symbols: &Symbols,
) -> Result<(Instruction, Columns), Refusal> {
    let at = statement.at;
    let command = byte("the command number", number).map_err(|e| Refusal::At(at, e.into()))?;
    if statement.operands.len() > 3 {
        return Err(Refusal::At(
            at,
            InputError::ArgumentCount {
                mnemonic: number.to_string(),
                expected: "0 to 3 arguments".into(),
                got: statement.operands.len(),
                usage: format!("{number} [<type>], [<motor>], [<value>]"),
            }
            .into(),
        ));
    }
    let mut out = Instruction::new(command, 0, 0, 0);
    let fields = [
        (Field::Type, "the type"),
        (Field::Motor, "the motor"),
        (Field::Value, "the value"),
    ];
    for ((field, what), operand) in fields.into_iter().zip(&statement.operands) {
        let text = ProgramOperand {
            operand,
            symbols,
            line: at.line,
        };
        let number = text.evaluate(Expect::Value)?;
        operands::store(&mut out, field, what, number).map_err(|e| {
            let column = operand.column;
            Refusal::At(
                Position {
                    line: at.line,
                    column,
                },
                e.into(),
            )
        })?;
    }
    let columns = Columns::new(statement, fields.into_iter().map(|(field, _)| field));
    Ok((out, columns))
}
