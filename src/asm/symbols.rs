//! Labels and constants, and the evaluation of expressions over them.
//!
//! Names are case-insensitive (like mnemonics and keywords), so `loop` and `Loop` cannot name two
//! different things. All definitions are collected in the first pass, so labels and constants may
//! be used before the line that defines them; constants are evaluated on first use, and a
//! constant defined in terms of itself is an error rather than a hang.

use std::collections::HashMap;

use crate::suggest;

use super::error::{Diagnostics, Position, Problem};
use super::parse::Expr;

/// Why an expression has no value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum EvalError {
    /// A new problem at this column of the line being evaluated.
    At(usize, Problem),
    /// It depends on a constant whose problem was already reported.
    Reported,
}

#[derive(Debug, Clone)]
enum Kind {
    Label(i64),
    Constant(Expr),
}

#[derive(Debug, Clone)]
struct Definition {
    name: String,
    at: Position,
    kind: Kind,
}

/// What kind of name an operand expects, for the message when it is unknown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Expect {
    /// A jump or call target.
    Label,
    /// Any constant or label.
    Value,
}

/// The labels and constants of one source file.
#[derive(Debug, Default)]
pub(super) struct Symbols {
    definitions: HashMap<String, Definition>,
    /// Evaluated constants; `None` for those whose problem was reported.
    values: HashMap<String, Option<i64>>,
}

impl Symbols {
    /// Defines a label at `address`.
    pub(super) fn label(
        &mut self,
        name: &str,
        at: Position,
        address: usize,
    ) -> Result<(), Problem> {
        self.define(name, at, Kind::Label(address as i64))
    }

    /// Defines a constant.
    pub(super) fn constant(&mut self, name: &str, at: Position, expr: Expr) -> Result<(), Problem> {
        self.define(name, at, Kind::Constant(expr))
    }

    fn define(&mut self, name: &str, at: Position, kind: Kind) -> Result<(), Problem> {
        let key = name.to_ascii_lowercase();
        if let Some(first) = self.definitions.get(&key) {
            return Err(Problem::Duplicate {
                name: name.to_string(),
                first_line: first.at.line,
            });
        }
        let name = name.to_string();
        self.definitions.insert(key, Definition { name, at, kind });
        Ok(())
    }

    /// Whether `name` is a label or constant.
    pub(super) fn contains(&self, name: &str) -> bool {
        self.definitions.contains_key(&name.to_ascii_lowercase())
    }

    /// Labels and their addresses, by address then name.
    pub(super) fn labels(&self) -> Vec<(String, usize)> {
        let mut labels: Vec<(String, usize)> = self
            .definitions
            .values()
            .filter_map(|d| match d.kind {
                Kind::Label(address) => Some((d.name.clone(), address as usize)),
                Kind::Constant(_) => None,
            })
            .collect();
        labels.sort_by(|a, b| (a.1, &a.0).cmp(&(b.1, &b.0)));
        labels
    }

    /// Evaluates every constant once, reporting problems at the constant's definition.
    pub(super) fn evaluate_constants(&mut self, diags: &mut Diagnostics) {
        let mut constants: Vec<(Position, String)> = self
            .definitions
            .iter()
            .filter(|(_, d)| matches!(d.kind, Kind::Constant(_)))
            .map(|(key, d)| (d.at, key.clone()))
            .collect();
        constants.sort();
        let mut problems = Vec::new();
        for (_, key) in constants {
            let mut resolver = Resolver {
                definitions: &self.definitions,
                values: &mut self.values,
                stack: Vec::new(),
                problems: &mut problems,
            };
            resolver.constant(&key);
        }
        problems.sort_by_key(|(at, _)| *at);
        for (at, problem) in problems {
            diags.error(at, problem);
        }
    }

    /// The value of `expr` (after [`evaluate_constants`](Self::evaluate_constants)).
    pub(super) fn eval(&self, expr: &Expr, expect: Expect) -> Result<i64, EvalError> {
        evaluate(expr, &mut |name, column| {
            let key = name.to_ascii_lowercase();
            match self.definitions.get(&key).map(|d| &d.kind) {
                Some(Kind::Label(address)) => Ok(*address),
                Some(Kind::Constant(_)) => self
                    .values
                    .get(&key)
                    .copied()
                    .flatten()
                    .ok_or(EvalError::Reported),
                None => Err(EvalError::At(column, self.unknown(name, expect))),
            }
        })
    }

    fn unknown(&self, name: &str, expect: Expect) -> Problem {
        let candidates = self
            .definitions
            .values()
            .filter(|d| expect == Expect::Value || matches!(d.kind, Kind::Label(_)));
        let suggestion = suggest::nearest(name, candidates.map(|d| d.name.as_str()));
        match expect {
            Expect::Label => Problem::UnknownLabel {
                name: name.to_string(),
                suggestion,
            },
            Expect::Value => Problem::UnknownSymbol {
                name: name.to_string(),
                suggestion,
            },
        }
    }
}

/// Evaluates constants depth-first, remembering which are on the way to catch cycles.
struct Resolver<'a> {
    definitions: &'a HashMap<String, Definition>,
    values: &'a mut HashMap<String, Option<i64>>,
    stack: Vec<String>,
    problems: &'a mut Vec<(Position, Problem)>,
}

impl Resolver<'_> {
    fn constant(&mut self, key: &str) -> Option<i64> {
        if let Some(value) = self.values.get(key) {
            return *value;
        }
        let definitions = self.definitions;
        let definition = &definitions[key];
        let Kind::Constant(expr) = &definition.kind else {
            unreachable!("only constants are resolved")
        };
        if self.stack.iter().any(|k| k == key) {
            self.problems.push((
                definition.at,
                Problem::Cycle {
                    name: definition.name.clone(),
                },
            ));
            self.values.insert(key.to_string(), None);
            return None;
        }
        self.stack.push(key.to_string());
        let result = evaluate(expr, &mut |name, column| self.lookup(name, column));
        self.stack.pop();
        let value = match result {
            Ok(value) => Some(value),
            Err(EvalError::At(column, problem)) => {
                let at = Position {
                    line: definition.at.line,
                    column,
                };
                self.problems.push((at, problem));
                None
            }
            Err(EvalError::Reported) => None,
        };
        // A cycle may already have marked this constant; keep the first verdict.
        *self.values.entry(key.to_string()).or_insert(value)
    }

    fn lookup(&mut self, name: &str, column: usize) -> Result<i64, EvalError> {
        let key = name.to_ascii_lowercase();
        match self.definitions.get(&key).map(|d| &d.kind) {
            Some(Kind::Label(address)) => Ok(*address),
            Some(Kind::Constant(_)) => self.constant(&key).ok_or(EvalError::Reported),
            None => {
                let suggestion =
                    suggest::nearest(name, self.definitions.values().map(|d| d.name.as_str()));
                Err(EvalError::At(
                    column,
                    Problem::UnknownSymbol {
                        name: name.to_string(),
                        suggestion,
                    },
                ))
            }
        }
    }
}

/// Evaluates `expr` in 64-bit arithmetic, looking names up with `lookup`.
fn evaluate(
    expr: &Expr,
    lookup: &mut dyn FnMut(&str, usize) -> Result<i64, EvalError>,
) -> Result<i64, EvalError> {
    match expr {
        Expr::Number { value, .. } => Ok(*value),
        Expr::Name { name, column } => lookup(name, *column),
        Expr::Negate { inner, column } => evaluate(inner, lookup)?
            .checked_neg()
            .ok_or_else(|| EvalError::At(*column, Problem::Arithmetic("overflow in '-'".into()))),
        Expr::Binary {
            op,
            left,
            right,
            column,
        } => {
            let (a, b) = (evaluate(left, lookup)?, evaluate(right, lookup)?);
            let fail = |what: &str| EvalError::At(*column, Problem::Arithmetic(what.into()));
            match op {
                '+' => a.checked_add(b).ok_or_else(|| fail("overflow in '+'")),
                '-' => a.checked_sub(b).ok_or_else(|| fail("overflow in '-'")),
                '*' => a.checked_mul(b).ok_or_else(|| fail("overflow in '*'")),
                '/' if b == 0 => Err(fail("division by zero")),
                '/' => Ok(a / b),
                '%' if b == 0 => Err(fail("division by zero in '%'")),
                _ => Ok(a % b),
            }
        }
    }
}
