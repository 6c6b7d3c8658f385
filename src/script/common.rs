//! Functions every dialect's scripts have: assertions, `sleep`, `wait_until`, `log`.

use std::time::Duration;

use rhai::{Dynamic, Engine, FnPtr, INT, NativeCallContext};

use super::failure::{Fallible, refused, runtime};
use super::waiting;

/// Registers the shared functions. `log` lines go to `log_sink`.
pub fn register(engine: &mut Engine, log_sink: impl Fn(&str) + 'static) {
    volatile!(engine, "sleep", |ms: INT| waiting::sleep(duration(ms)?));
    volatile!(
        engine,
        "wait_until",
        |context: NativeCallContext, check: FnPtr, timeout_ms: INT| {
            let what = format!("the condition {}", check.fn_name());
            waiting::until(&what, duration(timeout_ms)?, || {
                let value: Dynamic = check.call_within_context(&context, ())?;
                Ok(truthy(&value))
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

fn check(cond: bool, message: impl FnOnce() -> String) -> Fallible<()> {
    if cond {
        Ok(())
    } else {
        Err(runtime(message()))
    }
}

/// A non-negative millisecond count as a duration.
pub fn duration(ms: INT) -> Fallible<Duration> {
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
