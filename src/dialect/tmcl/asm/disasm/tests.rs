use proptest::prelude::*;

use crate::dialect::tmcl::asm::assemble;
use crate::dialect::tmcl::profile::Profile;

use super::*;

fn i(command: u8, type_: u8, motor: u8, value: i32) -> Instruction {
    Instruction::new(command, type_, motor, value)
}

fn reassemble(source: &str) -> Vec<Instruction> {
    match assemble(source, "disassembly", &Profile::builtin()) {
        Ok(program) => program.instructions,
        Err(errors) => panic!("{source}\n{errors}"),
    }
}

#[test]
fn test2_disassembles_to_readable_source() {
    let program = [
        i(2, 0, 0, 500_000),
        i(27, 0, 0, 500),
        i(3, 0, 0, 0),
        i(5, 4, 0, 500_000),
        i(4, 0, 0, 1_000_000),
        i(27, 1, 0, 0),
        i(22, 0, 0, 4),
    ];
    let disassembly = disassemble(&program, &Profile::builtin());
    assert!(disassembly.problems.is_empty());
    assert_eq!(
        disassembly.source,
        "    ROL 0, 500000\n\
         \x20   WAIT TICKS, 0, 500\n\
         \x20   MST 0\n\
         \x20   SAP 4, 0, 500000            // max_positioning_speed\n\
         L4:\n\
         \x20   MVP ABS, 0, 1000000\n\
         \x20   WAIT POS, 0, 0\n\
         \x20   JA L4\n"
    );
    assert_eq!(reassemble(&disassembly.source), program);
}

#[test]
fn labels_cover_calls_conditions_and_the_end_of_the_program() {
    let program = [
        i(23, 0, 0, 3),  // CSUB L3
        i(21, 2, 0, 4),  // JC EQ, L4 (one past the last instruction)
        i(22, 0, 0, 99), // JA 99: beyond the program, stays a number
        i(24, 0, 0, 0),  // RSUB
    ];
    let source = disassemble(&program, &Profile::builtin()).source;
    assert_eq!(
        source,
        "    CSUB L3\n    JC EQ, L4\n    JA 99\nL3:\n    RSUB\nL4:\n"
    );
    assert_eq!(reassemble(&source), program);
}

#[test]
fn global_parameters_keep_their_bank_and_name() {
    let program = [i(9, 77, 0, 1), i(10, 5, 2, 0), i(35, 7, 2, 0)];
    let source = disassemble(&program, &Profile::builtin()).source;
    assert_eq!(
        source,
        "    SGP 77, 0, 1                // auto_start_mode\n\
         \x20   GGP 5, 2                    // user_variable_5\n\
         \x20   AGP 7, 2                    // user_variable_7\n"
    );
    assert_eq!(reassemble(&source), program);
}

#[test]
fn unused_fields_that_are_not_zero_are_written_raw() {
    let program = [i(3, 0, 0, 5), i(24, 1, 2, 3), i(19, 8, 0, 0)];
    let source = disassemble(&program, &Profile::builtin()).source;
    assert_eq!(
        source,
        "    3 0, 0, 5                   // MST with non-zero unused fields\n\
         \x20   24 1, 2, 3                  // RSUB with non-zero unused fields\n\
         \x20   CALC NOT\n"
    );
    assert_eq!(reassemble(&source), program);
}

#[test]
fn invalid_instructions_are_written_and_reported() {
    let program = [
        i(3, 0, 0, 0),
        i(129, 1, 0, 0),
        i(4, 7, 0, 0),
        i(17, 0, 0, 0),
    ];
    let disassembly = disassemble(&program, &Profile::builtin());
    let addresses: Vec<usize> = disassembly.problems.iter().map(|p| p.0).collect();
    assert_eq!(addresses, [1, 2, 3]);
    let lines: Vec<&str> = disassembly.source.lines().collect();
    assert!(
        lines[1].starts_with("    129 1, 0, 0                 // invalid in a program: 129 — run application — is a direct-mode control function"),
        "{}",
        lines[1]
    );
    assert!(lines[2].starts_with("    MVP 7, 0, 0 "), "{}", lines[2]);
    assert!(
        lines[3].ends_with("command 17 is not supported by the TMCM-142"),
        "{}",
        lines[3]
    );
    assert!(assemble(&disassembly.source, "d", &Profile::builtin()).is_err());
}

/// A valid program instruction built from random choices: the command among those a program may
/// hold, keywords, parameters and values drawn from the table's own lists and ranges, and, when
/// `junk` is set, noise in the fields the command does not use.
fn shaped(choice: (u8, u8, u8, i32, bool), profile: &Profile) -> Instruction {
    let (pick, type_seed, motor_seed, value_seed, junk) = choice;
    let commands: Vec<&CommandSpec> = profile
        .commands
        .iter()
        .filter(|c| c.standalone && !c.mnemonic.is_empty())
        .collect();
    let spec = commands[usize::from(pick) % commands.len()];
    let mut out = Instruction::new(spec.number, 0, 0, 0);
    let mut range = spec.value_range;
    let mut bank = None;
    let pick_from = |len: usize| usize::from(type_seed) % len;
    for operand in &spec.operands {
        match operand.kind {
            OperandKind::Keyword => out.type_ = spec.keywords[pick_from(spec.keywords.len())].value,
            OperandKind::AxisParam => {
                let param = &profile.axis[pick_from(profile.axis.len())];
                out.type_ = param.number;
                range = range.or(param.range);
            }
            OperandKind::GlobalParam => {
                let param = &profile.global[pick_from(profile.global.len())];
                out.type_ = param.number;
                bank = Some(param.bank());
                range = range.or(param.range);
            }
            OperandKind::Coord => out.type_ = type_seed % profile.coordinates,
            OperandKind::Port | OperandKind::Type => out.type_ = type_seed,
            OperandKind::Motor => out.motor = motor_seed % profile.axes,
            OperandKind::Bank => out.motor = bank.unwrap_or(motor_seed),
            OperandKind::IoBank => out.motor = motor_seed % 3,
            OperandKind::Value | OperandKind::Address => {
                out.value = match range {
                    Some((lo, hi)) => (lo + i64::from(value_seed).rem_euclid(hi - lo + 1)) as i32,
                    None => value_seed,
                }
            }
        }
    }
    if spec
        .keyword_for(out.type_)
        .is_some_and(|k| k.name == "COORD")
    {
        out.value = value_seed.rem_euclid(i32::from(profile.coordinates));
    }
    if junk {
        for (field, noise) in [
            (Field::Type, &mut out.type_),
            (Field::Motor, &mut out.motor),
        ] {
            if spec.operand_for(field).is_none() {
                *noise = type_seed | 1;
            }
        }
        if spec.operand_for(Field::Value).is_none() {
            out.value = value_seed | 1;
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn disassembly_reassembles_to_the_same_instructions(
        choices in proptest::collection::vec(any::<(u8, u8, u8, i32, bool)>(), 1..40),
        jump_seeds in proptest::collection::vec(any::<u16>(), 40),
    ) {
        let profile = Profile::builtin();
        let mut program: Vec<Instruction> =
            choices.iter().map(|&c| shaped(c, &profile)).collect();
        // Send most jumps and calls into the program (or just past it), so labels are exercised.
        let len = program.len();
        for (instruction, seed) in program.iter_mut().zip(&jump_seeds) {
            let jumps = profile.commands.by_number(instruction.command)
                .and_then(|spec| spec.operand_for(Field::Value))
                .is_some_and(|o| o.kind == OperandKind::Address);
            if jumps && seed % 4 != 0 {
                instruction.value = i32::from(*seed) % (len as i32 + 1);
            }
        }
        program.retain(|i| validate_instruction(i, &profile, Mode::Program).is_ok());
        prop_assume!(!program.is_empty());
        let disassembly = disassemble(&program, &profile);
        prop_assert!(disassembly.problems.is_empty(), "{:?}", disassembly.problems);
        let again = assemble(&disassembly.source, "disassembly", &profile)
            .map(|p| p.instructions)
            .map_err(|e| format!("{}\n{e}", disassembly.source));
        prop_assert_eq!(again, Ok(program));
    }

    #[test]
    fn any_bytes_disassemble_and_only_invalid_instructions_are_reported(
        raw in proptest::collection::vec(any::<(u8, u8, u8, i32)>(), 0..30),
    ) {
        let profile = Profile::builtin();
        let program: Vec<Instruction> =
            raw.iter().map(|&(c, t, m, v)| Instruction::new(c, t, m, v)).collect();
        let disassembly = disassemble(&program, &profile);
        let invalid: Vec<usize> = program
            .iter()
            .enumerate()
            .filter(|(_, i)| validate_instruction(i, &profile, Mode::Program).is_err())
            .map(|(address, _)| address)
            .collect();
        let reported: Vec<usize> = disassembly.problems.iter().map(|p| p.0).collect();
        prop_assert_eq!(&reported, &invalid);
        prop_assert_eq!(disassembly.source.lines().filter(|l| l.starts_with("    ")).count(), program.len());
        if invalid.is_empty() {
            prop_assert_eq!(reassemble(&disassembly.source), program);
        }
    }
}
