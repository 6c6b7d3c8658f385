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
//!
//! Counting is the program's business, not the library's: only a program chooses its global
//! allocator. The `tmclsh` binary installs a counting one (`src/main.rs`) and registers its
//! reading with [`count_allocations_with`] at start-up. A program that registers no counter runs
//! scripts without a memory bound — [`Limits::max_memory`](super::Limits::max_memory) is then not
//! enforced, while operations, call depth and time still are; one that runs scripts it does not
//! trust registers a counter first.

use std::sync::OnceLock;

use rhai::{Array, Blob, Dynamic, Engine, EvalAltResult, INT, ImmutableString};

/// Reads how many bytes the process has allocated now (a counting global allocator's total).
pub type AllocationCounter = fn() -> usize;

/// The counter registered at start-up, if any.
static COUNTER: OnceLock<AllocationCounter> = OnceLock::new();

/// Bounds the memory of every script run from now on with `counter`, which reads the bytes the
/// process has allocated. Call it once at start-up, before any script runs; a second call
/// changes nothing and returns false.
pub fn count_allocations_with(counter: AllocationCounter) -> bool {
    COUNTER.set(counter).is_ok()
}

/// How much a script may allocate beyond what the process held when it started.
#[derive(Debug, Clone, Copy)]
pub struct Budget {
    ceiling: usize,
    allocated: AllocationCounter,
}

impl Budget {
    /// A budget of `bytes` from now; none when the program counts no allocations (see
    /// [`count_allocations_with`]).
    pub fn from_now(bytes: usize) -> Option<Budget> {
        COUNTER
            .get()
            .map(|&allocated| Budget::counted_by(allocated, bytes))
    }

    /// A budget of `bytes` from what `allocated` reads now.
    fn counted_by(allocated: AllocationCounter, bytes: usize) -> Budget {
        Budget {
            ceiling: allocated().saturating_add(bytes),
            allocated,
        }
    }

    /// Whether the script holds more than its budget.
    pub fn exceeded(self) -> bool {
        (self.allocated)() > self.ceiling
    }

    /// Whether `more` bytes fit in what is left.
    fn fits(self, more: usize) -> bool {
        (self.allocated)().saturating_add(more) <= self.ceiling
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

#[cfg(test)]
mod tests {
    use std::sync::atomic::{AtomicUsize, Ordering};

    use super::*;

    /// What the fake counter of the first test reads.
    static HELD: AtomicUsize = AtomicUsize::new(0);

    fn held() -> usize {
        HELD.load(Ordering::SeqCst)
    }

    #[test]
    fn a_budget_counts_from_what_the_process_held_when_it_started() {
        HELD.store(10_000, Ordering::SeqCst);
        let budget = Budget::counted_by(held, 500);
        assert!(!budget.exceeded());
        assert!(budget.fits(500) && !budget.fits(501));
        HELD.store(10_500, Ordering::SeqCst);
        assert!(!budget.exceeded() && budget.fits(0) && !budget.fits(1));
        HELD.store(10_501, Ordering::SeqCst);
        assert!(budget.exceeded());
    }

    #[test]
    fn pad_and_blob_are_refused_before_they_allocate_past_the_budget() {
        // A counter that never moves: only the sizes asked for count.
        let mut engine = Engine::new();
        register_builders(&mut engine, Budget::counted_by(|| 1 << 20, 1 << 16));
        for fits in [
            "blob(60000).len()",
            "blob(60000, 7).len()",
            "let s = \"\"; s.pad(10000, 'x'); s.len()",
            "let a = []; a.pad(100, 0); a.len()",
        ] {
            assert!(engine.eval::<INT>(fits).is_ok(), "{fits} fits");
        }
        for too_big in [
            "blob(70000)",
            "blob(1000000, 7)",
            "let s = \"\"; s.pad(1000000, 'x'); s",
            "let s = \"\"; s.pad(1000000, \"ab\"); s",
            "let a = []; a.pad(1000000, 0); a",
            "let b = blob(); b.pad(70000, 1); b",
        ] {
            let error = engine.eval::<Dynamic>(too_big).expect_err(too_big);
            let EvalAltResult::ErrorRuntime(value, _) = *error else {
                panic!("{too_big}: {error}");
            };
            let failure = value.cast::<crate::exit::Failure>();
            assert_eq!(failure.message, MESSAGE, "{too_big}");
        }
    }

    #[test]
    fn without_a_counter_no_budget_is_set() {
        // The library's unit tests register no counter (only the binary does).
        assert!(Budget::from_now(1).is_none());
    }
}
