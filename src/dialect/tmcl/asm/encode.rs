//! One instruction line to its 7-byte instruction: the command table says which field each operand
//! fills and which words are keywords; names resolve to keywords, parameters, labels or constants;
//! the validator of the interactive commands then checks the result for a stand-alone program
//! (`Mode::Program`), so a program is held to exactly the rules a typed command is.

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::protocol::line::{byte, count_text, word32};
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
struct Columns {
    head: usize,
    type_: Option<usize>,
    motor: Option<usize>,
    value: Option<usize>,
    coordinate_in_type: bool,
}

impl Columns {
    fn of(&self, field: Field) -> usize {
        let column = match field {
            Field::Type => self.type_,
            Field::Motor => self.motor,
            Field::Value => self.value,
        };
        column.unwrap_or(self.head)
    }

    fn set(&mut self, field: Field, column: usize) {
        match field {
            Field::Type => self.type_ = Some(column),
            Field::Motor => self.motor = Some(column),
            Field::Value => self.value = Some(column),
        }
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
    let mut columns = Columns {
        head: statement.at.column,
        type_: None,
        motor: None,
        value: None,
        coordinate_in_type: false,
    };
    let fields = |columns: &mut Columns| -> Result<Instruction, Refusal> {
        match &statement.head {
            Head::Number(number) => raw(*number, statement, symbols, columns),
            Head::Mnemonic(word) => {
                let spec = command(word, profile).map_err(|p| Refusal::At(statement.at, p))?;
                columns.coordinate_in_type = spec
                    .operand_for(Field::Type)
                    .is_some_and(|o| o.kind == OperandKind::Coord);
                operands(spec, statement, symbols, profile, columns)
            }
        }
    };
    let instruction = fields(&mut columns)?;
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
    columns: &mut Columns,
) -> Result<Instruction, Refusal> {
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
    let mut out = Instruction {
        command,
        ..Instruction::default()
    };
    let fields = [
        (Field::Type, "<type>"),
        (Field::Motor, "<motor>"),
        (Field::Value, "<value>"),
    ];
    for ((field, what), operand) in fields.into_iter().zip(&statement.operands) {
        let value = evaluate(operand, symbols, Expect::Value, at.line)?;
        store(&mut out, field, what, value, operand, at.line)?;
        columns.set(field, operand.column);
    }
    Ok(out)
}

/// The operands of a mnemonic, placed as the command table says.
fn operands(
    spec: &CommandSpec,
    statement: &Statement,
    symbols: &Symbols,
    profile: &Profile,
    columns: &mut Columns,
) -> Result<Instruction, Refusal> {
    let line = statement.at.line;
    let given = statement.operands.len();
    let is_profile_name = |operand: &Operand| {
        operand
            .expr
            .as_name()
            .is_some_and(|name| !symbols.contains(name))
    };
    // A global parameter given by name implies its bank, which may then be left out (as in the
    // interactive grammar).
    let bank_implied = spec
        .operands
        .first()
        .is_some_and(|o| o.kind == OperandKind::GlobalParam)
        && statement.operands.first().is_some_and(is_profile_name);
    let required = spec
        .required_operands()
        .saturating_sub(usize::from(bank_implied && given == 1));
    if given < required || given > spec.operands.len() {
        let expected = if required == spec.operands.len() {
            count_text(required)
        } else {
            format!("{} to {}", required, count_text(spec.operands.len()))
        };
        let error = InputError::ArgumentCount {
            mnemonic: spec.display_name(),
            expected,
            got: given,
            usage: spec.usage(),
        };
        return Err(Refusal::At(statement.at, error.into()));
    }
    let mut out = Instruction {
        command: spec.number,
        ..Instruction::default()
    };
    let mut named_bank: Option<(String, u8)> = None;
    for (kind, operand) in spec
        .operands
        .iter()
        .map(|o| o.kind)
        .zip(&statement.operands)
    {
        let at = Position {
            line,
            column: operand.column,
        };
        let refuse = |e: InputError| Refusal::At(at, e.into());
        let field = kind.field();
        columns.set(field, operand.column);
        let name = operand.expr.as_name().filter(|_| is_profile_name(operand));
        match (kind, name) {
            (OperandKind::Keyword, _) if !spec.keywords.is_empty() => {
                let keyword = operand.expr.as_name().and_then(|n| spec.keyword(n));
                match (keyword, name) {
                    (Some(keyword), _) => out.type_ = keyword.value,
                    (None, Some(word)) => {
                        return Err(refuse(InputError::BadKeyword {
                            mnemonic: spec.display_name(),
                            word: word.to_string(),
                            allowed: spec.keywords.iter().map(|k| k.name.clone()).collect(),
                        }));
                    }
                    (None, None) => {
                        let value = evaluate(operand, symbols, Expect::Value, line)?;
                        store(&mut out, field, kind.placeholder(), value, operand, line)?;
                    }
                }
            }
            (OperandKind::AxisParam, Some(name)) => {
                out.type_ = profile
                    .find_axis(name)
                    .map_err(|e| refuse(e.into()))?
                    .number;
            }
            (OperandKind::GlobalParam, Some(name)) => {
                let param = profile.find_global(name).map_err(|e| refuse(e.into()))?;
                named_bank = Some((param.ident.clone(), param.bank()));
                out.type_ = param.number;
            }
            _ => {
                let expect = match kind {
                    OperandKind::Address => Expect::Label,
                    _ => Expect::Value,
                };
                let value = evaluate(operand, symbols, expect, line)?;
                store(&mut out, field, kind.placeholder(), value, operand, line)?;
            }
        }
    }
    if let Some((ident, bank)) = named_bank {
        if given > 1 && out.motor != bank {
            let at = Position {
                line,
                column: columns.of(Field::Motor),
            };
            let error = InputError::BankMismatch {
                ident,
                bank,
                given: out.motor,
            };
            return Err(Refusal::At(at, error.into()));
        }
        out.motor = bank;
    }
    Ok(out)
}

fn evaluate(
    operand: &Operand,
    symbols: &Symbols,
    expect: Expect,
    line: usize,
) -> Result<i64, Refusal> {
    symbols.eval(&operand.expr, expect).map_err(|e| match e {
        EvalError::At(column, problem) => Refusal::At(Position { line, column }, problem),
        EvalError::Reported => Refusal::Reported,
    })
}

/// Puts `value` into `field`, refusing what does not fit.
fn store(
    out: &mut Instruction,
    field: Field,
    what: &str,
    value: i64,
    operand: &Operand,
    line: usize,
) -> Result<(), Refusal> {
    let result = match field {
        Field::Type => byte(what, value).map(|b| out.type_ = b),
        Field::Motor => byte(what, value).map(|b| out.motor = b),
        Field::Value => word32(what, value, operand.expr.is_hex_literal()).map(|w| out.value = w),
    };
    result.map_err(|e| {
        let at = Position {
            line,
            column: operand.column,
        };
        Refusal::At(at, e.into())
    })
}
