//! A script's memory, bounded at constant cost per operation.
//!
//! Rhai's own data-size limits (`set_max_array_size`, `set_max_string_size`, `set_max_map_size`)
//! walk the whole value after every call that may change it — every `a.push(x)` counts all of
//! `a` again — which makes building an array quadratic: 100,000 pushes took seconds and two
//! million took minutes, all within the operation cap. They are not used. Instead the process
//! counts the bytes it has allocated (one atomic add per allocation), the engine's progress
//! callback compares that with the script's budget at every operation, and the few functions
//! that can allocate a size given as an argument in one call (`pad`, `blob`) check the size
//! first.

use std::alloc::System;

use cap::Cap;
use rhai::{Array, Blob, Dynamic, Engine, EvalAltResult, INT, ImmutableString};

/// The process's allocator, counting what is allocated (no limit is set on it: a failed
/// allocation would abort; the budget is enforced by the script engine instead).
#[global_allocator]
static ALLOCATOR: Cap<System> = Cap::new(System, usize::MAX);

/// Bytes allocated by the process now.
pub fn allocated() -> usize {
    ALLOCATOR.allocated()
}

/// How much a script may allocate beyond what the process held when it started.
#[derive(Debug, Clone, Copy)]
pub struct Budget {
    ceiling: usize,
}

impl Budget {
    /// A budget of `bytes` from now.
    pub fn from_now(bytes: usize) -> Budget {
        Budget {
            ceiling: allocated().saturating_add(bytes),
        }
    }

    /// Whether the script holds more than its budget.
    pub fn exceeded(self) -> bool {
        allocated() > self.ceiling
    }

    /// Whether `more` bytes fit in what is left.
    fn fits(self, more: usize) -> bool {
        allocated().saturating_add(more) <= self.ceiling
    }
}

/// The error of a script that holds too much.
pub fn too_much() -> Box<EvalAltResult> {
    super::failure::runtime(MESSAGE)
}

/// What a script that holds too much is told.
pub const MESSAGE: &str =
    "runaway script: it holds more memory than allowed (raise the cap with --max-memory)";

/// Registers `pad` and `blob` in place of Rhai's own, checking the size they would allocate
/// against `budget` first.
pub fn register_builders(engine: &mut Engine, budget: Budget) {
    let check = move |bytes: usize| {
        if budget.fits(bytes) {
            Ok(())
        } else {
            Err(too_much())
        }
    };
    engine.register_fn(
        "pad",
        move |s: &mut ImmutableString, len: INT, ch: char| -> Result<(), Box<EvalAltResult>> {
            let missing = missing(s.chars().count(), len);
            check(missing.saturating_mul(ch.len_utf8()))?;
            s.make_mut().extend(std::iter::repeat_n(ch, missing));
            Ok(())
        },
    );
    engine.register_fn(
        "pad",
        move |s: &mut ImmutableString, len: INT, padding: &str| -> Result<(), Box<EvalAltResult>> {
            let missing = missing(s.chars().count(), len);
            if padding.is_empty() {
                return Ok(());
            }
            check(missing.saturating_mul(4))?;
            s.make_mut().extend(padding.chars().cycle().take(missing));
            Ok(())
        },
    );
    engine.register_fn(
        "pad",
        move |array: &mut Array, len: INT, item: Dynamic| -> Result<(), Box<EvalAltResult>> {
            let missing = missing(array.len(), len);
            let each = std::mem::size_of::<Dynamic>().saturating_add(weight(&item));
            check(missing.saturating_mul(each))?;
            array.resize(array.len() + missing, item);
            Ok(())
        },
    );
    engine.register_fn(
        "pad",
        move |blob: &mut Blob, len: INT, value: INT| -> Result<(), Box<EvalAltResult>> {
            let missing = missing(blob.len(), len);
            check(missing)?;
            blob.resize(blob.len() + missing, value as u8);
            Ok(())
        },
    );
    engine.register_fn(
        "blob",
        move |len: INT| -> Result<Blob, Box<EvalAltResult>> {
            let len = usize::try_from(len).unwrap_or(0);
            check(len)?;
            Ok(vec![0; len])
        },
    );
    engine.register_fn(
        "blob",
        move |len: INT, value: INT| -> Result<Blob, Box<EvalAltResult>> {
            let len = usize::try_from(len).unwrap_or(0);
            check(len)?;
            Ok(vec![value as u8; len])
        },
    );
}

/// How many elements a pad to `len` adds to `current`.
fn missing(current: usize, len: INT) -> usize {
    usize::try_from(len).unwrap_or(0).saturating_sub(current)
}

/// About how many bytes a value holds besides its own slot.
fn weight(value: &Dynamic) -> usize {
    let slot = std::mem::size_of::<Dynamic>();
    if let Ok(s) = value.as_immutable_string_ref() {
        return s.len();
    }
    if let Ok(a) = value.as_array_ref() {
        return a.iter().map(|v| slot + weight(v)).sum();
    }
    if let Ok(b) = value.as_blob_ref() {
        return b.len();
    }
    if let Ok(m) = value.as_map_ref() {
        return m
            .iter()
            .map(|(k, v)| k.len() + slot + weight(v))
            .sum::<usize>();
    }
    0
}
