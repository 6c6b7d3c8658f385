//! Functions every dialect's scripts have: assertions, `sleep`, `wait_until`, `log`.

use std::time::Duration;

use std::rc::Rc;

use rhai::{Dynamic, Engine, FnPtr, INT, NativeCallContext, Position};

use super::failure::{Fallible, refused, runtime};
use super::waiting;

/// Registers the shared functions. `log` lines go to `log_sink`; `source` is the script's text,
/// which names the condition of a `wait_until` in its messages.
pub(crate) fn register(engine: &mut Engine, source: Rc<str>, log_sink: impl Fn(&str) + 'static) {
    volatile!(engine, "sleep", |ms: INT| waiting::sleep(duration(ms)?));
    volatile!(
        engine,
        "wait_until",
        move |context: NativeCallContext, check: FnPtr, timeout_ms: INT| {
            let what = condition_text(&source, context.call_position())
                .map_or_else(|| "the condition".to_string(), |text| format!("`{text}`"));
            waiting::until_showing(&what, duration(timeout_ms)?, || {
                let value: Dynamic = check.call_within_context(&context, ())?;
                Ok((truthy(&value), show(&value)))
            })
        }
    );
    volatile!(engine, "assert", |cond: bool, message: &str| check(
        cond,
        || format!("assertion failed: {message}")
    ));
    volatile!(engine, "assert", |cond: bool| check(cond, || {
        "assertion failed".to_string()
    }));
    volatile!(engine, "assert_eq", |a: Dynamic, b: Dynamic| {
        check(equal(&a, &b), || {
            format!(
                "assert_eq failed: left = {}, right = {}",
                show(&a),
                show(&b)
            )
        })
    });
    volatile!(
        engine,
        "assert_eq",
        |a: Dynamic, b: Dynamic, message: &str| {
            check(equal(&a, &b), || {
                format!(
                    "assert_eq failed: {message}: left = {}, right = {}",
                    show(&a),
                    show(&b)
                )
            })
        }
    );
    volatile!(
        engine,
        "assert_near",
        |a: Dynamic, b: Dynamic, tolerance: Dynamic| {
            let (x, y, t) = (number(&a)?, number(&b)?, number(&tolerance)?);
            check((x - y).abs() <= t, || {
                format!(
                    "assert_near failed: left = {}, right = {}, tolerance = {} (difference {})",
                    show(&a),
                    show(&b),
                    show(&tolerance),
                    trim_float((x - y).abs())
                )
            })
        }
    );
    volatile!(engine, "log", move |message: &str| log_sink(message));
}

/// Longest condition text quoted in a message.
const CONDITION_CHARS: usize = 60;

/// The source text of the condition of the `wait_until` call at `position` (its first argument,
/// a closure's body without the `||`): how a timeout names what it waited for.
fn condition_text(source: &str, position: Position) -> Option<String> {
    let (line, column) = (position.line()?, position.position()?);
    let text = source.lines().nth(line - 1)?;
    let start = text.char_indices().nth(column - 1).map(|(i, _)| i)?;
    // The rest of the script from the call: a condition may span lines.
    let offset: usize = source.lines().take(line - 1).map(|l| l.len() + 1).sum();
    let call = source.get(offset + start..)?;
    let args = call
        .strip_prefix("wait_until")?
        .trim_start()
        .strip_prefix('(')?;
    let mut depth = 0usize;
    let mut quote: Option<char> = None;
    let mut end = None;
    for (i, c) in args.char_indices() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '"' | '`' | '\'') => quote = Some(c),
            (None, '(' | '[' | '{') => depth += 1,
            (None, ')' | ']' | '}') if depth > 0 => depth -= 1,
            (None, ',' | ')') if depth == 0 => {
                end = Some(i);
                break;
            }
            _ => {}
        }
    }
    let argument = args[..end?].trim();
    let body = match argument.strip_prefix('|') {
        Some(rest) => rest.split_once('|').map_or(rest, |(_, body)| body).trim(),
        None => argument,
    };
    let body: String = body.split_whitespace().collect::<Vec<_>>().join(" ");
    if body.is_empty() {
        return None;
    }
    Some(if body.chars().count() > CONDITION_CHARS {
        let cut: String = body.chars().take(CONDITION_CHARS).collect();
        format!("{cut}…")
    } else {
        body
    })
}

fn check(cond: bool, message: impl FnOnce() -> String) -> Fallible<()> {
    if cond {
        Ok(())
    } else {
        Err(runtime(message()))
    }
}

/// A non-negative millisecond count as a duration.
pub(crate) fn duration(ms: INT) -> Fallible<Duration> {
    u64::try_from(ms).map(Duration::from_millis).map_err(|_| {
        refused(format!(
            "a time in milliseconds must not be negative, got {ms}"
        ))
    })
}

fn truthy(value: &Dynamic) -> bool {
    if let Ok(b) = value.as_bool() {
        return b;
    }
    if let Ok(i) = value.as_int() {
        return i != 0;
    }
    !value.is_unit()
}

fn number(value: &Dynamic) -> Fallible<f64> {
    if let Ok(i) = value.as_int() {
        return Ok(i as f64);
    }
    if let Ok(f) = value.as_float() {
        return Ok(f);
    }
    Err(runtime(format!(
        "expected a number, got {} ({})",
        show(value),
        value.type_name()
    )))
}

fn equal(a: &Dynamic, b: &Dynamic) -> bool {
    match (number(a), number(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => a.type_name() == b.type_name() && a.to_string() == b.to_string(),
    }
}

fn show(value: &Dynamic) -> String {
    if value.is_string() {
        format!("{:?}", value.to_string())
    } else {
        value.to_string()
    }
}

fn trim_float(x: f64) -> String {
    if x.fract() == 0.0 {
        format!("{x:.0}")
    } else {
        x.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(source: &str, line: usize, column: usize) -> Option<String> {
        condition_text(source, Position::new(line as u16, column as u16))
    }

    #[test]
    fn the_condition_is_quoted_from_the_source() {
        let source = "let m = 0;\n  wait_until(|| gap(8, m) == 1, 5000);\n";
        assert_eq!(at(source, 2, 3).as_deref(), Some("gap(8, m) == 1"));
        let source = "wait_until(|| {\n    let v = gap(1, 0);\n    v > f(1, 2)\n}, 100)";
        assert_eq!(
            at(source, 1, 1).as_deref(),
            Some("{ let v = gap(1, 0); v > f(1, 2) }")
        );
        assert_eq!(at("wait_until(ready, 10)", 1, 1).as_deref(), Some("ready"));
        assert_eq!(
            at("wait_until(|| s == \"a,b\", 10)", 1, 1).as_deref(),
            Some("s == \"a,b\"")
        );
        let long = format!("wait_until(|| {} == 1, 10)", "x".repeat(80));
        assert!(at(&long, 1, 1).unwrap().ends_with('…'));
        // Nothing to quote where the position is not a call of wait_until.
        assert_eq!(at("sleep(10)", 1, 1), None);
        assert_eq!(at("wait_until(", 1, 1), None);
        assert_eq!(at("x", 5, 1), None);
    }
}
