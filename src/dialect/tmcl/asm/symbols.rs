//! Labels and constants, and the evaluation of expressions over them.
//!
//! Names are case-insensitive (like mnemonics and keywords), so `loop` and `Loop` cannot name two
//! different things. All definitions are collected in the first pass, so labels and constants may
//! be used before the line that defines them; constants are evaluated on first use, and a
//! constant defined in terms of itself is an error rather than a hang.

use std::cell::Cell;
use std::collections::{HashMap, HashSet};

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
    /// "Did you mean" suggestions still to be offered (see [`MAX_SUGGESTIONS`]).
    suggestions: Suggestions,
}

/// How many unknown names get a "did you mean" suggestion. Each compares the name with every
/// definition, so a file of tens of thousands of misspellings would otherwise take minutes; the
/// errors beyond the first ones are still reported, without suggestion.
const MAX_SUGGESTIONS: usize = 100;

/// The suggestions offered so far in one file.
#[derive(Debug, Default)]
struct Suggestions(Cell<usize>);

impl Suggestions {
    /// The definition nearest to `name` among `candidates`, while the budget lasts.
    fn nearest<'d>(
        &self,
        name: &str,
        candidates: impl Iterator<Item = &'d Definition>,
    ) -> Option<String> {
        let given = self.0.get();
        if given >= MAX_SUGGESTIONS {
            return None;
        }
        self.0.set(given + 1);
        suggest::nearest(name, candidates.map(|d| d.name.as_str()))
    }
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
                suggestions: &self.suggestions,
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
            known(&self.definitions, &self.values, name)
                .unwrap_or_else(|| Err(EvalError::At(column, self.unknown(name, expect))))
        })
    }

    fn unknown(&self, name: &str, expect: Expect) -> Problem {
        let candidates = self
            .definitions
            .values()
            .filter(|d| expect == Expect::Value || matches!(d.kind, Kind::Label(_)));
        let suggestion = self.suggestions.nearest(name, candidates);
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

/// Evaluates constants in dependency order with a work list of its own rather than by recursion,
/// so a chain of a hundred thousand constants, each defined by the next, needs no deeper stack
/// than one constant; constants on the way are remembered to catch cycles.
struct Resolver<'a> {
    definitions: &'a HashMap<String, Definition>,
    values: &'a mut HashMap<String, Option<i64>>,
    suggestions: &'a Suggestions,
    problems: &'a mut Vec<(Position, Problem)>,
}

impl<'a> Resolver<'a> {
    /// Evaluates the constant `root` and every constant it needs that has no value yet.
    fn constant(&mut self, root: &str) {
        let definitions = self.definitions;
        // Each constant on the way, with its names and how many of them are settled.
        let mut pending: Vec<(&str, Vec<&str>, usize)> = Vec::new();
        let mut on_the_way: HashSet<&str> = HashSet::new();
        let mut next = Some(root).filter(|key| !self.values.contains_key(*key));
        loop {
            if let Some(key) = next.take() {
                let (_, expr) = constant_definition(definitions, key);
                pending.push((key, names_in(expr), 0));
                on_the_way.insert(key);
            }
            let Some((key, names, settled)) = pending.last_mut() else {
                return;
            };
            while let Some(name) = names.get(*settled) {
                match self.unsettled(name) {
                    Some(dependency) if on_the_way.contains(dependency) => {
                        let (cycle, _) = constant_definition(definitions, dependency);
                        self.problems.push((
                            cycle.at,
                            Problem::Cycle {
                                name: cycle.name.clone(),
                            },
                        ));
                        self.values.insert(dependency.to_string(), None);
                    }
                    Some(dependency) => {
                        next = Some(dependency);
                        break;
                    }
                    None => {}
                }
                *settled += 1;
            }
            if next.is_some() {
                continue;
            }
            let key = *key;
            pending.pop();
            on_the_way.remove(key);
            let (definition, expr) = constant_definition(definitions, key);
            let value = match evaluate(expr, &mut |name, column| self.lookup(name, column)) {
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
            self.values.entry(key.to_string()).or_insert(value);
        }
    }

    /// The key of the constant `name` if it has no value yet.
    fn unsettled(&self, name: &str) -> Option<&'a str> {
        let (key, definition) = self.definitions.get_key_value(&name.to_ascii_lowercase())?;
        let constant = matches!(definition.kind, Kind::Constant(_));
        (constant && !self.values.contains_key(key)).then_some(key.as_str())
    }

    /// A name's value once every constant it needs has one.
    fn lookup(&self, name: &str, column: usize) -> Result<i64, EvalError> {
        match known(self.definitions, self.values, name) {
            Some(value) => value,
            None => {
                let suggestion = self.suggestions.nearest(name, self.definitions.values());
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

/// The value of a defined name: a label's address, or a constant's value (an error already
/// reported when it has none); `None` for a name nothing defines.
fn known(
    definitions: &HashMap<String, Definition>,
    values: &HashMap<String, Option<i64>>,
    name: &str,
) -> Option<Result<i64, EvalError>> {
    let key = name.to_ascii_lowercase();
    match &definitions.get(&key)?.kind {
        Kind::Label(address) => Some(Ok(*address)),
        Kind::Constant(_) => Some(
            values
                .get(&key)
                .copied()
                .flatten()
                .ok_or(EvalError::Reported),
        ),
    }
}

/// The definition and expression of constant `key`.
fn constant_definition<'d>(
    definitions: &'d HashMap<String, Definition>,
    key: &str,
) -> (&'d Definition, &'d Expr) {
    let definition = &definitions[key];
    match &definition.kind {
        Kind::Constant(expr) => (definition, expr),
        Kind::Label(_) => unreachable!("only constants are resolved"),
    }
}

/// The names in `expr`, in the order evaluation meets them.
fn names_in(expr: &Expr) -> Vec<&str> {
    let mut names = Vec::new();
    let mut stack = vec![expr];
    while let Some(expr) = stack.pop() {
        match expr {
            Expr::Number { .. } => {}
            Expr::Name { name, .. } => names.push(name.as_str()),
            Expr::Negate { inner, .. } => stack.push(inner),
            Expr::Binary { left, right, .. } => {
                stack.push(right);
                stack.push(left);
            }
        }
    }
    names
}

/// Evaluates `expr` in checked 64-bit arithmetic, looking names up with `lookup`. Recursion is
/// bounded by the parser's nesting limit.
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
                '/' => a.checked_div(b).ok_or_else(|| fail("overflow in '/'")),
                '%' if b == 0 => Err(fail("division by zero in '%'")),
                _ => a.checked_rem(b).ok_or_else(|| fail("overflow in '%'")),
            }
        }
    }
}
