//! Typed lines and program lines share one operand grammar: the same text makes the same
//! instruction, or is refused for the same reason, in both. The one difference is by design: a
//! name where only a number can stand is refused by a typed line as not a number, and read by a
//! program as a constant or label (here: unknown). (A literal beyond 32 bits, refused by both,
//! is refused by the program's lexer, before its grammar.)

use proptest::prelude::*;

use super::*;
use crate::dialect::tmcl::asm::encode::{self, Refusal};
use crate::dialect::tmcl::asm::lex;
use crate::dialect::tmcl::asm::parse::{Body, ParsedLine};
use crate::dialect::tmcl::profile::commands::{CommandSpec, Field, OperandKind};
use crate::dialect::tmcl::protocol::{Line, Op, format_instruction, parse};

/// What a program line makes of `text`, before validation (which holds programs to
/// `Mode::Program` and typed lines to their session's mode); `None` for a lexical error.
fn program_line(text: &str, profile: &Profile) -> Option<Result<Instruction, Refusal>> {
    let mut diags = Diagnostics::new("t.tmc");
    let lines = lex::tokenize(text, &mut diags);
    if diags.finish().is_err() {
        return None;
    }
    let [(line, tokens)] = lines.as_slice() else {
        panic!("{text}: not one line");
    };
    let statement = match parse_line(*line, tokens) {
        Ok(ParsedLine {
            body: Body::Instruction(statement),
            ..
        }) => statement,
        other => panic!("{text}: not an instruction: {other:?}"),
    };
    let instruction = encode::instruction(&statement, &Symbols::default(), profile);
    Some(instruction.map(|(instruction, _)| instruction))
}

/// What a typed line makes of `text`, before validation.
fn typed_line(text: &str, profile: &Profile) -> Result<Instruction, InputError> {
    match parse(text, profile)? {
        Line {
            address: None,
            op: Op::Command(instruction),
        } => Ok(instruction),
        other => panic!("{text}: not a command without address: {other:?}"),
    }
}

/// The commands a typed line can send, with the word that names them. STOP names the ASCII
/// word in a typed line and command 28 in a program, so it is left out.
fn direct_commands(profile: &Profile) -> Vec<(&CommandSpec, String)> {
    profile
        .commands
        .iter()
        .filter(|c| c.direct_mode && profile.commands.ascii_word(&c.mnemonic).is_none())
        .map(|c| (c, c.display_name()))
        .collect()
}

/// Asserts that both faces agree on `text`; returns whether it made an instruction.
fn agree(text: &str, profile: &Profile) -> bool {
    let Some(program) = program_line(text, profile) else {
        let typed = typed_line(text, profile);
        let too_long = |value: i64| !(-i64::from(u32::MAX)..=i64::from(u32::MAX)).contains(&value);
        match typed {
            Err(InputError::FieldOverflow { value, .. }) if too_long(value) => return false,
            other => panic!("{text}: typed {other:?}, program: lexical error"),
        }
    };
    match (typed_line(text, profile), program) {
        (Ok(typed), Ok(program)) => {
            assert_eq!(typed, program, "{text}");
            true
        }
        (Err(InputError::ExpectedNumber { found, .. }), Err(Refusal::At(_, problem))) => {
            match problem {
                Problem::UnknownSymbol { name, .. } | Problem::UnknownLabel { name, .. } => {
                    assert_eq!(found, name, "{text}")
                }
                other => panic!("{text}: typed: not a number; program: {other}"),
            }
            false
        }
        (Err(typed), Err(Refusal::At(_, Problem::Input(program)))) => {
            assert_eq!(typed, program, "{text}");
            false
        }
        (typed, program) => panic!("{text}: typed {typed:?}, program {program:?}"),
    }
}

/// Operand texts a typed line may give for `kind`, each of which it accepts.
fn valid_texts(kind: OperandKind, spec: &CommandSpec, profile: &Profile) -> Vec<String> {
    let mut texts: Vec<String> = ["0", "1", "0x1F", "$a"].map(String::from).into();
    match kind {
        OperandKind::Keyword => {
            texts.extend(spec.keywords.iter().map(|k| k.name.clone()));
            texts.extend(spec.keywords.iter().map(|k| k.name.to_ascii_lowercase()));
        }
        OperandKind::AxisParam => texts.extend(profile.axis.iter().map(|p| p.ident.clone())),
        OperandKind::Value | OperandKind::Address => texts
            .extend(["-1", "2147483647", "-2147483648", "0xFFFFFFFF", "-0x10"].map(String::from)),
        _ => texts.push("255".into()),
    }
    texts
}

/// Operand texts that some fields refuse: too large for a byte or for 32 bits (`0x100000000`
/// already for a program's lexer), negative, or names of nothing.
const INVALID_TEXTS: [&str; 7] = [
    "256",
    "-1",
    "2147483648",
    "0x100000000",
    "-0x80000001",
    "nope",
    "max_curent",
];

#[test]
fn every_direct_mode_line_form_makes_the_same_instruction_typed_and_in_a_program() {
    let profile = Profile::builtin();
    for (spec, head) in direct_commands(&profile) {
        // Each operand in turn takes every form, the others their first; then fewer operands,
        // down to none, and one too many.
        let forms: Vec<Vec<String>> = spec
            .operands
            .iter()
            .map(|o| valid_texts(o.kind, spec, &profile))
            .collect();
        let line = |operands: &[String]| {
            if operands.is_empty() {
                head.clone()
            } else {
                format!("{head} {}", operands.join(", "))
            }
        };
        let first: Vec<String> = forms.iter().map(|f| f[0].clone()).collect();
        for (position, texts) in forms.iter().enumerate() {
            let with = |text: &str| {
                let mut operands = first.clone();
                operands[position] = text.to_string();
                line(&operands)
            };
            for text in texts {
                // Not only equal refusals: each of these makes an instruction.
                assert!(agree(&with(text), &profile), "{}", with(text));
            }
            for text in INVALID_TEXTS {
                agree(&with(text), &profile);
            }
        }
        for given in 0..first.len() {
            agree(&line(&first[..given]), &profile);
        }
        agree(&line(&[first.clone(), vec!["1".into()]].concat()), &profile);
        agree(&head.to_ascii_lowercase(), &profile);
    }
}

#[test]
fn a_global_parameter_by_name_implies_its_bank_in_both() {
    let profile = Profile::builtin();
    for param in &profile.global {
        let bank = param.bank();
        for command in ["GGP", "STGP", "RSGP", "AGP"] {
            let text = format!("{command} {}", param.ident);
            let made = agree(&text, &profile);
            // STGP/RSGP need no EEPROM here: that is the validator's business, not the grammar's.
            assert!(made, "{text}");
            agree(&format!("{text}, {bank}"), &profile);
            agree(&format!("{text}, {}", bank.wrapping_add(1)), &profile);
        }
        agree(&format!("SGP {}, {bank}, 7", param.ident), &profile);
        agree(&format!("SGP {}, 7", param.ident), &profile);
    }
}

/// A name where only a number can stand: not a number to a typed line, an unknown constant to a
/// program — and a program's constant of that name is its value.
#[test]
fn a_name_for_a_number_is_the_one_difference() {
    let profile = Profile::builtin();
    assert!(!agree("MVP ABS, motor, 100", &profile));
    assert!(!agree("SAP 4, 0, Speed", &profile));
    assert!(!agree("ROR 0, ABS", &profile));
    assert_eq!(
        one("Speed = 500\nMotor = 0\nSAP 4, Motor, Speed"),
        i(5, 4, 0, 500)
    );
}

/// A keyword wins over a program's constant of the same name; a parameter name does not.
#[test]
fn keywords_are_read_before_a_programs_names() {
    assert_eq!(one("ABS = 7\nMVP ABS, 0, ABS"), i(4, 0, 0, 7));
    assert_eq!(one("max_current = 4\nSAP max_current, 0, 1"), i(5, 4, 0, 1));
}

/// The largest literal a program's lexer reads (beyond it, both refuse: see
/// `every_direct_mode_line_form…`).
const LITERAL: i64 = u32::MAX as i64;

/// Text for one operand: numbers in every spelling, near and far beyond each field's range, and
/// names — keywords of every command, parameter identifiers, and names of nothing.
fn operand_text(names: Vec<String>) -> impl Strategy<Value = String> {
    prop_oneof![
        (-300i64..300).prop_map(|v| v.to_string()),
        any::<i32>().prop_map(|v| v.to_string()),
        (-LITERAL..=LITERAL).prop_map(|v| v.to_string()),
        (0..=LITERAL).prop_map(|v| format!("0x{v:X}")),
        any::<u32>().prop_map(|v| format!("${v:x}")),
        (0..=LITERAL).prop_map(|v| format!("-0x{v:x}")),
        proptest::sample::select(names),
    ]
}

fn names(profile: &Profile) -> Vec<String> {
    let keywords = profile
        .commands
        .iter()
        .flat_map(|c| c.keywords.iter().map(|k| k.name.clone()));
    let params = profile.axis.iter().chain(&profile.global);
    keywords
        .chain(params.map(|p| p.ident.clone()))
        .chain(["nope", "Loop", "max", "user_variable"].map(String::from))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Any operands, right or wrong, for any command a typed line can send.
    #[test]
    fn any_operands_make_the_same_instruction_or_the_same_refusal(
        pick in any::<prop::sample::Index>(),
        lower in any::<bool>(),
        operands in proptest::collection::vec(operand_text(names(&Profile::builtin())), 0..5),
    ) {
        let profile = Profile::builtin();
        let commands = direct_commands(&profile);
        let (_, head) = &commands[pick.index(commands.len())];
        let head = if lower { head.to_ascii_lowercase() } else { head.clone() };
        let text = if operands.is_empty() {
            head
        } else {
            format!("{head} {}", operands.join(", "))
        };
        agree(&text, &profile);
    }

    /// An instruction written in its canonical form reads back as itself, typed and in a program.
    #[test]
    fn the_canonical_form_reads_back_the_same_in_both(
        pick in any::<prop::sample::Index>(),
        type_ in any::<u8>(),
        motor in any::<u8>(),
        value in any::<i32>(),
    ) {
        let profile = Profile::builtin();
        let commands = direct_commands(&profile);
        let (spec, _) = commands[pick.index(commands.len())];
        let has = |field| spec.operand_for(field).is_some();
        let instruction = Instruction::new(
            spec.number,
            if has(Field::Type) { type_ } else { 0 },
            if has(Field::Motor) { motor } else { 0 },
            if has(Field::Value) { value } else { 0 },
        );
        let text = format_instruction(&instruction, &profile);
        prop_assert_eq!(typed_line(&text, &profile), Ok(instruction), "{}", text);
        prop_assert_eq!(program_line(&text, &profile), Some(Ok(instruction)), "{}", text);
    }
}
