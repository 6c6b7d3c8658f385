//! The shape of a source line, before any table lookup:
//!
//! ```text
//! line       := { label ':' } [ statement ]
//! statement  := MNEMONIC [ operand { ',' operand } ]      ROL 0, 500000
//!             | NUMBER [ operand { ',' operand } ]        27 0, 0, 500   (raw: type, motor, value)
//!             | NAME '=' expr                             Speed = 500000
//!             | '#define' NAME expr                       #define Speed 500000
//! operand    := expr
//! expr       := term { ('+' | '-') term }
//! term       := unary { ('*' | '/' | '%') unary }
//! unary      := ('-' | '+') unary | NUMBER | NAME | '(' expr ')'
//! ```
//!
//! Unlike the interactive line grammar there is no address character, operands are separated by
//! commas only (an operand may contain spaces: `Speed * 2`), and lines may carry labels.
//! Parentheses and signs nest at most [`MAX_NESTING`] levels and an expression's tree is at most
//! [`MAX_DEPTH`] deep, so no file can exhaust the stack.

use super::error::Position;
use super::lex::{Tok, Token};

/// A numeric expression as written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Expr {
    /// A literal.
    Number { value: i64, hex: bool },
    /// A name: constant, label, keyword or parameter, depending on where it stands.
    Name { name: String, column: usize },
    /// `-x`.
    Negate { inner: Box<Expr>, column: usize },
    /// `a op b`.
    Binary {
        op: char,
        left: Box<Expr>,
        right: Box<Expr>,
        column: usize,
    },
}

impl Expr {
    /// The name, if the expression is a single name.
    pub(super) fn as_name(&self) -> Option<&str> {
        match self {
            Expr::Name { name, .. } => Some(name),
            _ => None,
        }
    }

    /// Whether the expression is a single hex literal (which may use the full unsigned range).
    pub(super) fn is_hex_literal(&self) -> bool {
        matches!(self, Expr::Number { hex: true, .. })
    }
}

/// An operand: the expression and the column it starts at.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Operand {
    pub expr: Expr,
    pub column: usize,
}

/// How an instruction names its command.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Head {
    /// By mnemonic (`MVP`).
    Mnemonic(String),
    /// By command number, operands then being type, motor and value as raw fields.
    Number(i64),
}

/// An instruction line before resolution.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Statement {
    pub head: Head,
    pub at: Position,
    pub operands: Vec<Operand>,
}

/// What a line defines or asks for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Body {
    /// Nothing but labels (or nothing at all).
    Empty,
    /// A constant, with the column of its name.
    Constant {
        name: String,
        column: usize,
        expr: Expr,
    },
    /// An instruction.
    Instruction(Statement),
}

/// A parsed line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct ParsedLine {
    /// Labels defined at the start of the line, with their columns.
    pub labels: Vec<(String, usize)>,
    pub body: Body,
}

/// Column and message of a syntax error.
pub(super) type SyntaxError = (usize, String);

/// Parses the tokens of line `line`.
pub(super) fn parse_line(line: usize, tokens: &[Token]) -> Result<ParsedLine, SyntaxError> {
    let mut labels = Vec::new();
    let mut rest = tokens;
    while let [first, colon, after @ ..] = rest {
        match &first.tok {
            Tok::Ident(name) if colon.is(':') => {
                labels.push((name.clone(), first.column));
                rest = after;
            }
            _ => break,
        }
    }
    let Some(first) = rest.first() else {
        return Ok(ParsedLine {
            labels,
            body: Body::Empty,
        });
    };
    let at = Position {
        line,
        column: first.column,
    };
    let body = match (&first.tok, rest.get(1)) {
        (Tok::Punct('#'), _) => define(rest)?,
        (Tok::Ident(name), Some(eq)) if eq.is('=') => Body::Constant {
            name: name.clone(),
            column: first.column,
            expr: whole_expr(&rest[2..], eq.column + 1)?,
        },
        (Tok::Ident(name), _) => Body::Instruction(Statement {
            head: Head::Mnemonic(name.clone()),
            at,
            operands: operands(&rest[1..])?,
        }),
        (Tok::Number { value, .. }, _) => Body::Instruction(Statement {
            head: Head::Number(*value),
            at,
            operands: operands(&rest[1..])?,
        }),
        (Tok::Punct(':'), _) => return Err((first.column, "label name missing before ':'".into())),
        (Tok::Punct(_) | Tok::Text(_), _) => {
            return Err((
                first.column,
                format!(
                    "expected a command, a label or a constant, found '{}'",
                    first.text()
                ),
            ));
        }
    };
    Ok(ParsedLine { labels, body })
}

/// `#define NAME expr`.
fn define(tokens: &[Token]) -> Result<Body, SyntaxError> {
    let hash = &tokens[0];
    match tokens.get(1).map(|t| &t.tok) {
        Some(Tok::Ident(word)) if word.eq_ignore_ascii_case("define") => {}
        Some(Tok::Ident(word)) => {
            return Err((
                tokens[1].column,
                format!("unknown directive '#{word}'; only #define is supported"),
            ));
        }
        _ => return Err((hash.column, "expected 'define' after '#'".into())),
    }
    let Some(Token {
        tok: Tok::Ident(name),
        column,
    }) = tokens.get(2)
    else {
        let column = tokens.get(2).map_or(tokens[1].column, |t| t.column);
        return Err((column, "#define needs a name and a value".into()));
    };
    if tokens.len() == 3 {
        return Err((*column, format!("#define {name} needs a value")));
    }
    Ok(Body::Constant {
        name: name.clone(),
        column: *column,
        expr: whole_expr(&tokens[3..], column + name.chars().count())?,
    })
}

/// Comma-separated operands.
fn operands(tokens: &[Token]) -> Result<Vec<Operand>, SyntaxError> {
    let mut out = Vec::new();
    if tokens.is_empty() {
        return Ok(out);
    }
    let mut rest = tokens;
    loop {
        let Some(first) = rest.first() else {
            let column = tokens.last().map_or(0, |t| t.column);
            return Err((column, "operand missing after ','".into()));
        };
        if first.is(',') {
            return Err((first.column, "operand missing before ','".into()));
        }
        let (expr, _, after) = expr(rest, 0)?;
        out.push(Operand {
            expr,
            column: first.column,
        });
        match after.first() {
            None => return Ok(out),
            Some(comma) if comma.is(',') => rest = &after[1..],
            Some(other) => {
                return Err((
                    other.column,
                    format!("expected ',' between operands, found '{}'", other.text()),
                ));
            }
        }
    }
}

/// How deeply parentheses and signs may nest (C asks compilers for 63 levels). The parser
/// recurses once per level, so the bound keeps a hostile file (20,000 minus signs, 100,000
/// parentheses) from overflowing the stack.
pub(super) const MAX_NESTING: usize = 64;

/// How deep an expression's tree may grow (a chain `a + b + c …` grows one level per operator).
/// Evaluating and dropping the tree recurse once per level.
pub(super) const MAX_DEPTH: usize = 256;

/// An expression that must use all of `tokens`; `end_column` locates a missing one.
fn whole_expr(tokens: &[Token], end_column: usize) -> Result<Expr, SyntaxError> {
    if tokens.is_empty() {
        return Err((end_column, "value missing".into()));
    }
    let (expr, _, rest) = expr(tokens, 0)?;
    match rest.first() {
        None => Ok(expr),
        Some(t) => Err((
            t.column,
            format!("unexpected '{}' after the value", t.text()),
        )),
    }
}

/// A parsed expression, the number of levels it spans, and the tokens after it.
type Parsed<'a> = Result<(Expr, usize, &'a [Token]), SyntaxError>;

/// Each rule gets `nesting`, the parentheses and signs around the expression it parses, and
/// returns the depth of the tree it built.
type Rule<'a> = fn(&'a [Token], usize) -> Parsed<'a>;

fn expr(tokens: &[Token], nesting: usize) -> Parsed<'_> {
    binary(tokens, nesting, &['+', '-'], term)
}

fn term(tokens: &[Token], nesting: usize) -> Parsed<'_> {
    binary(tokens, nesting, &['*', '/', '%'], unary)
}

fn binary<'a>(tokens: &'a [Token], nesting: usize, ops: &[char], next: Rule<'a>) -> Parsed<'a> {
    let (mut left, mut depth, mut rest) = next(tokens, nesting)?;
    while let Some(op_token) = rest.first() {
        let Tok::Punct(op) = op_token.tok else { break };
        if !ops.contains(&op) {
            break;
        }
        let (right, right_depth, after) =
            next(&rest[1..], nesting).map_err(|e| missing_after(e, op_token))?;
        depth = depth.max(right_depth) + 1;
        if depth > MAX_DEPTH {
            return Err(too_deep(op_token));
        }
        left = Expr::Binary {
            op,
            left: Box::new(left),
            right: Box::new(right),
            column: op_token.column,
        };
        rest = after;
    }
    Ok((left, depth, rest))
}

fn unary<'a>(tokens: &'a [Token], nesting: usize) -> Parsed<'a> {
    let Some(first) = tokens.first() else {
        return Err((0, "value missing".into()));
    };
    let inner = |rest: &'a [Token], rule: Rule<'a>| -> Parsed<'a> {
        if nesting >= MAX_NESTING {
            return Err(too_nested(first));
        }
        rule(rest, nesting + 1).map_err(|e| missing_after(e, first))
    };
    match &first.tok {
        Tok::Punct('-') => {
            let (inner, depth, rest) = inner(&tokens[1..], unary)?;
            if depth >= MAX_DEPTH {
                return Err(too_deep(first));
            }
            let negated = Expr::Negate {
                inner: Box::new(inner),
                column: first.column,
            };
            Ok((negated, depth + 1, rest))
        }
        Tok::Punct('+') => inner(&tokens[1..], unary),
        Tok::Punct('(') => {
            let (inner, depth, rest) = inner(&tokens[1..], expr)?;
            match rest.first() {
                Some(close) if close.is(')') => Ok((inner, depth, &rest[1..])),
                Some(other) => Err((
                    other.column,
                    format!("expected ')', found '{}'", other.text()),
                )),
                None => Err((first.column, "'(' is never closed".into())),
            }
        }
        Tok::Number { value, hex } => Ok((
            Expr::Number {
                value: *value,
                hex: *hex,
            },
            1,
            &tokens[1..],
        )),
        Tok::Ident(name) => Ok((
            Expr::Name {
                name: name.clone(),
                column: first.column,
            },
            1,
            &tokens[1..],
        )),
        Tok::Punct(_) | Tok::Text(_) => Err((
            first.column,
            format!("expected a number or a name, found '{}'", first.text()),
        )),
    }
}

fn too_nested(at: &Token) -> SyntaxError {
    (
        at.column,
        format!("parentheses and signs nest more than {MAX_NESTING} levels deep here"),
    )
}

fn too_deep(at: &Token) -> SyntaxError {
    (
        at.column,
        format!("the expression is more than {MAX_DEPTH} operations deep; split it with constants"),
    )
}

/// A "value missing" at the end of the line points just after the operator.
fn missing_after(error: SyntaxError, operator: &Token) -> SyntaxError {
    match error {
        (0, _) => (
            operator.column + 1,
            format!("value missing after '{}'", operator.text()),
        ),
        other => other,
    }
}

#[cfg(test)]
mod tests;
