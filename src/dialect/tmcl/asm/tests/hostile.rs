//! Hostile sources: whatever a file holds, the assembler answers with located errors — never a
//! panic, a stack overflow or a wait of minutes. Each source is assembled on a thread with a
//! small stack, so a recursion that is not bounded aborts this test binary rather than a user's
//! session with a motor turning.

use proptest::prelude::*;

use super::*;
use crate::dialect::tmcl::asm::parse::{MAX_DEPTH, MAX_NESTING};

/// A quarter of a Linux main thread's stack and the size of a Windows one; the deepest
/// expression allowed needs well under half of it even in an unoptimised build.
const STACK: usize = 1024 * 1024;

fn assemble_on_small_stack(source: String) -> Result<Program, AsmErrors> {
    std::thread::Builder::new()
        .stack_size(STACK)
        .spawn(move || assemble(&source, "t.tmc", &Profile::builtin()))
        .unwrap()
        .join()
        .expect("the assembler does not panic")
}

fn errors_of(source: String) -> Vec<String> {
    match assemble_on_small_stack(source) {
        Ok(program) => panic!("assembled: {:?}", program.instructions),
        Err(errors) => errors.errors.iter().map(ToString::to_string).collect(),
    }
}

/// The value of `ROL 0, <expr>` or of a constant used there.
fn value_of(source: String) -> i32 {
    match assemble_on_small_stack(source) {
        Ok(program) => program.instructions[0].value,
        Err(errors) => panic!("{errors}"),
    }
}

#[test]
fn deep_nesting_is_refused_at_the_level_that_is_too_deep() {
    let nested = format!("X = {}1{}", "(".repeat(100_000), ")".repeat(100_000));
    let minus = format!("X = {}1", "-".repeat(20_000));
    let plus = format!("ROL 0, {}1", "+".repeat(20_000));
    let mixed = format!("X = {}1{}", "-(".repeat(50_000), ")".repeat(50_000));
    let message = format!("parentheses and signs nest more than {MAX_NESTING} levels deep here");
    // Column of the first sign or parenthesis past the limit.
    let at = |start: usize, per_level: usize| {
        format!(
            "t.tmc:1:{}: error: {message}",
            start + MAX_NESTING * per_level
        )
    };
    assert_eq!(errors_of(nested), [at(5, 1)]);
    assert_eq!(errors_of(minus), [at(5, 1)]);
    assert_eq!(errors_of(plus), [at(8, 1)]);
    assert_eq!(errors_of(mixed), [at(5, 1)]);
}

#[test]
fn nesting_up_to_the_limit_is_evaluated() {
    let minus = format!("ROL 0, {}7", "-".repeat(MAX_NESTING));
    assert_eq!(value_of(minus), 7, "an even number of signs");
    let parens = format!(
        "ROL 0, {}7{}",
        "(".repeat(MAX_NESTING),
        ")".repeat(MAX_NESTING)
    );
    assert_eq!(value_of(parens), 7);
    let sums = format!(
        "ROL 0, {}0{}",
        "(1 + ".repeat(MAX_NESTING),
        ")".repeat(MAX_NESTING)
    );
    assert_eq!(value_of(sums), MAX_NESTING as i32);
    let one_more = format!("ROL 0, {}7", "-".repeat(MAX_NESTING + 1));
    assert_eq!(errors_of(one_more).len(), 1);
}

#[test]
fn long_chains_of_operators_are_refused_beyond_the_depth_limit() {
    let longest = format!("ROL 0, 1{}", " + 1".repeat(MAX_DEPTH - 1));
    assert_eq!(value_of(longest), MAX_DEPTH as i32);
    let million = format!("X = 1{}", "+1".repeat(1_000_000));
    let column = 5 + 1 + 2 * (MAX_DEPTH - 1);
    assert_eq!(
        errors_of(million),
        [format!(
            "t.tmc:1:{column}: error: the expression is more than {MAX_DEPTH} operations deep; split it with constants"
        )]
    );
    // Signs around a deep chain count too.
    let signed = format!("X = -({}1)", "1+".repeat(MAX_DEPTH - 1));
    assert_eq!(errors_of(signed).len(), 1);
}

#[test]
fn a_long_chain_of_constants_is_resolved_without_deep_recursion() {
    let mut source = String::from("ROL 0, C0\n");
    for i in 0..100_000 {
        source.push_str(&format!("C{i} = C{} + 1\n", i + 1));
    }
    source.push_str("C100000 = 0\n");
    assert_eq!(value_of(source), 100_000);
}

#[test]
fn a_long_cycle_of_constants_is_one_error() {
    let mut source = String::from("ROL 0, C0\n");
    for i in 0..10_000 {
        source.push_str(&format!("C{i} = C{} + 1\n", (i + 1) % 10_000));
    }
    assert_eq!(
        errors_of(source),
        ["t.tmc:2:1: error: constant 'C0' is defined in terms of itself"]
    );
}

#[test]
fn every_overflow_in_constant_arithmetic_is_an_error() {
    // i64::MIN, built from 32-bit literals.
    let min = "Min = -(0xFFFFFFFF + 1) * 0x80000000\n";
    for (expr, op) in [
        ("Min / -1", "/"),
        ("Min % -1", "%"),
        ("-Min", "-"),
        ("Min - 1", "-"),
        ("-(Min + 1) + 2", "+"),
        ("Min * 2", "*"),
    ] {
        let errors = errors_of(format!("{min}X = {expr}\nROL 0, 1"));
        assert_eq!(errors.len(), 1, "{expr}: {errors:?}");
        assert!(
            errors[0].ends_with(&format!("error: overflow in '{op}'")),
            "{expr}: {errors:?}"
        );
    }
    // Fine in 64 bits, then refused as a 32-bit value, not wrapped.
    let errors = errors_of(format!("{min}ROL 0, Min / 0x100000000 * 0x100000000"));
    assert_eq!(errors.len(), 1, "{errors:?}");
}

#[test]
fn only_the_first_unknown_names_get_a_suggestion() {
    let mut source = String::new();
    for i in 0..2_000 {
        source.push_str(&format!("Speed{i} = {i}\n"));
    }
    for i in 0..2_000 {
        source.push_str(&format!("ROL 0, Sped{i}\n"));
    }
    let errors = errors_of(source);
    assert_eq!(errors.len(), 2_000);
    let suggested = errors.iter().filter(|e| e.contains("did you mean")).count();
    assert!((1..=100).contains(&suggested), "{suggested} suggestions");
    assert!(errors[0].contains("did you mean Speed0?"), "{}", errors[0]);
}

#[test]
fn a_file_of_several_megabytes_is_answered() {
    let line = format!(
        "Loop: MVP ABS, 0, ({}) // {}\n",
        "1 + ".repeat(100) + "1",
        "x".repeat(100)
    );
    let source = line.repeat(20_000);
    assert!(source.len() > 4_000_000);
    let errors = errors_of(source);
    assert!(errors[0].contains("already defined"), "{}", errors[0]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Lines made of the source's own characters, in any order: an answer, never a panic.
    #[test]
    fn any_arrangement_of_source_characters_is_answered(
        source in "[-+*/%(),:=#$ A-Z0-9xX\n]{0,400}"
    ) {
        let _ = assemble_on_small_stack(source);
    }

    /// Expressions of any shape over large numbers: a value or an arithmetic error.
    #[test]
    fn any_expression_over_extreme_numbers_is_answered(
        parts in proptest::collection::vec(
            ("[-+*/%]", prop_oneof![Just("0"), Just("1"), Just("0xFFFFFFFF"), Just("X"), Just("(X)")]),
            1..40,
        )
    ) {
        let mut expr = String::from("X = -(0xFFFFFFFF + 1) * 0x80000000\nY = 1");
        for (op, operand) in &parts {
            expr.push_str(&format!(" {op} {operand}"));
        }
        let _ = assemble_on_small_stack(expr + "\nROL 0, 0");
    }
}
