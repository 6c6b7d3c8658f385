use crate::dialect::tmcl::profile::Profile;

use super::*;

const TEST2: &str = include_str!("../../../../scripts/test2.tmc");

fn i(command: u8, type_: u8, motor: u8, value: i32) -> Instruction {
    Instruction::new(command, type_, motor, value)
}

fn program(source: &str) -> Vec<Instruction> {
    match assemble(source, "t.tmc", &Profile::builtin()) {
        Ok(program) => program.instructions,
        Err(errors) => panic!("{source}\n{errors}"),
    }
}

fn one(source: &str) -> Instruction {
    let instructions = program(source);
    assert_eq!(instructions.len(), 1, "{source}");
    instructions[0]
}

/// The error lines of a source that must not assemble.
fn errors(source: &str) -> Vec<String> {
    match assemble(source, "t.tmc", &Profile::builtin()) {
        Ok(program) => panic!("assembled: {source}\n{:?}", program.instructions),
        Err(errors) => errors.errors.iter().map(ToString::to_string).collect(),
    }
}

fn error(source: &str) -> String {
    let all = errors(source);
    assert_eq!(all.len(), 1, "{all:?}");
    all[0].clone()
}

#[test]
fn test2_from_the_manual_assembles_to_the_expected_instructions() {
    // Written from the manual's listing and the command numbers of its tables 6.4/6.5:
    // ROL 2, ROR 1, MST 3, MVP 4 (ABS 0), SAP 5, WAIT 27 (TICKS 0, POS 1), JA 22.
    let expected = [
        i(2, 0, 0, 500_000),    // 0  ROL 0, 500000
        i(27, 0, 0, 500),       // 1  WAIT TICKS, 0, 500
        i(3, 0, 0, 0),          // 2  MST 0
        i(1, 0, 0, 250_000),    // 3  ROR 0, 250000
        i(27, 0, 0, 500),       // 4  WAIT TICKS, 0, 500
        i(3, 0, 0, 0),          // 5  MST 0
        i(5, 4, 0, 500_000),    // 6  SAP 4, 0, 500000
        i(5, 5, 0, 50_000),     // 7  SAP 5, 0, 50000
        i(4, 0, 0, 1_000_000),  // 8  Loop: MVP ABS, 0, 1000000
        i(27, 1, 0, 0),         // 9  WAIT POS, 0, 0
        i(4, 0, 0, -1_000_000), // 10 MVP ABS, 0, -1000000
        i(27, 1, 0, 0),         // 11 WAIT POS, 0, 0
        i(22, 0, 0, 8),         // 12 JA Loop
    ];
    let program = assemble(TEST2, "test2.tmc", &Profile::builtin()).unwrap();
    assert_eq!(program.instructions, expected);
    assert!(program.warnings.is_empty(), "{:?}", program.warnings);
    assert_eq!(
        program.labels,
        [Label {
            name: "Loop".into(),
            address: 8
        }]
    );
    let loop_line = TEST2.lines().position(|l| l.starts_with("Loop:")).unwrap() + 1;
    assert_eq!(program.lines[8], loop_line);
}

#[test]
fn every_keyword_family_encodes_its_type_byte() {
    let cases = [
        ("MVP ABS, 0, 5", i(4, 0, 0, 5)),
        ("MVP REL, 0, -5", i(4, 1, 0, -5)),
        ("MVP COORD, 0, 3", i(4, 2, 0, 3)),
        ("WAIT TICKS, 0, 100", i(27, 0, 0, 100)),
        ("WAIT POS, 0, 0", i(27, 1, 0, 0)),
        ("WAIT REFSW, 0, 50", i(27, 2, 0, 50)),
        ("WAIT LIMSW, 0, 50", i(27, 3, 0, 50)),
        ("WAIT RFS, 0, 0", i(27, 4, 0, 0)),
        ("RFS START, 0", i(13, 0, 0, 0)),
        ("RFS STOP, 0", i(13, 1, 0, 0)),
        ("RFS STATUS, 0", i(13, 2, 0, 0)),
        ("CALC ADD, 7", i(19, 0, 0, 7)),
        ("CALC SUB, 7", i(19, 1, 0, 7)),
        ("CALC MUL, 7", i(19, 2, 0, 7)),
        ("CALC DIV, 7", i(19, 3, 0, 7)),
        ("CALC MOD, 7", i(19, 4, 0, 7)),
        ("CALC AND, 7", i(19, 5, 0, 7)),
        ("CALC OR, 7", i(19, 6, 0, 7)),
        ("CALC XOR, 7", i(19, 7, 0, 7)),
        ("CALC NOT", i(19, 8, 0, 0)),
        ("CALC LOAD, -3", i(19, 9, 0, -3)),
        ("CALCX ADD", i(33, 0, 0, 0)),
        ("CALCX XOR", i(33, 7, 0, 0)),
        ("CALCX NOT", i(33, 8, 0, 0)),
        ("CALCX LOAD", i(33, 9, 0, 0)),
        ("CALCX SWAP", i(33, 10, 0, 0)),
        ("CLE ALL", i(36, 0, 0, 0)),
        ("CLE ETO", i(36, 1, 0, 0)),
        ("CLE EAL", i(36, 2, 0, 0)),
        ("CLE EDV", i(36, 3, 0, 0)),
        ("CLE EPO", i(36, 4, 0, 0)),
    ];
    for (source, expected) in cases {
        assert_eq!(one(source), expected, "{source}");
    }
    let conditions = [
        "ZE", "NZ", "EQ", "NE", "GT", "GE", "LT", "LE", "ETO", "EAL", "EDV", "EPO",
    ];
    for (number, condition) in conditions.iter().enumerate() {
        let source = format!("JC {condition}, 0");
        assert_eq!(one(&source), i(21, number as u8, 0, 0), "{source}");
    }
    // Keywords are case-insensitive, and a number may stand for one.
    assert_eq!(one("mvp rel, 0, 1"), i(4, 1, 0, 1));
    assert_eq!(one("WAIT 1, 0, 0"), i(27, 1, 0, 0));
}

#[test]
fn every_program_only_command_assembles() {
    let source = "
        Start:  CALC LOAD, 10
                COMP 10
                JC EQ, Sub
                JA Start
        Sub:    CSUB Done
                RSUB
                WAIT TICKS, 0, 1
                CALCX SWAP
                AAP 4, 0
                AGP 5, 2
                ACO 3, 0
                CLE ETO
        Done:   STOP
    ";
    assert_eq!(
        program(source),
        [
            i(19, 9, 0, 10),
            i(20, 0, 0, 10),
            i(21, 2, 0, 4),
            i(22, 0, 0, 0),
            i(23, 0, 0, 12),
            i(24, 0, 0, 0),
            i(27, 0, 0, 1),
            i(33, 10, 0, 0),
            i(34, 4, 0, 0),
            i(35, 5, 2, 0),
            i(39, 3, 0, 0),
            i(36, 1, 0, 0),
            i(28, 0, 0, 0),
        ]
    );
}

#[test]
fn labels_resolve_forward_backward_and_at_the_end() {
    let source = "
        JA Forward          // 0
    Back:                   // label alone on its line
        MST 0               // 1
    Forward: Again: JC NZ, back   // 2, two labels, used case-insensitively
        CSUB End            // 3
        JA Again            // 4
    End:
    ";
    let program = assemble(source, "t.tmc", &Profile::builtin()).unwrap();
    assert_eq!(
        program.instructions,
        [
            i(22, 0, 0, 2),
            i(3, 0, 0, 0),
            i(21, 1, 0, 1),
            i(23, 0, 0, 5),
            i(22, 0, 0, 2)
        ]
    );
    let labels: Vec<(&str, usize)> = program
        .labels
        .iter()
        .map(|l| (l.name.as_str(), l.address))
        .collect();
    assert_eq!(
        labels,
        [("Back", 1), ("Again", 2), ("Forward", 2), ("End", 5)]
    );
}

#[test]
fn constants_and_expressions() {
    let source = "
        #define Speed 1000
        Accel = Speed / 4 + 6       // 256, defined from another constant
        Far = -(Speed * 2) % 1500   // -500: precedence, parentheses, unary minus
        SAP 4, 0, Speed
        SAP 5, 0, Accel
        MVP REL, 0, Far
        MVP ABS, 0, Later           // used before its definition
        CALC LOAD, $FF + 0x10 - 1
        CALC LOAD, 0xFFFFFFFF       // a hex literal may be written unsigned
        JA Target + 1
        Target: MST 0
        Later = Accel * 2
    ";
    assert_eq!(
        program(source),
        [
            i(5, 4, 0, 1000),
            i(5, 5, 0, 256),
            i(4, 1, 0, -500),
            i(4, 0, 0, 512),
            i(19, 9, 0, 270),
            i(19, 9, 0, -1),
            i(22, 0, 0, 8),
            i(3, 0, 0, 0),
        ]
    );
}

#[test]
fn parameter_names_stand_for_numbers_and_imply_the_bank() {
    let cases = [
        ("SAP max_positioning_speed, 0, 100", i(5, 4, 0, 100)),
        ("GAP actual_position, 0", i(6, 1, 0, 0)),
        ("SAP max_acc, 0, 100", i(5, 5, 0, 100)), // unique prefix
        ("GGP user_variable_5", i(10, 5, 2, 0)),
        ("GGP user_variable_5, 2", i(10, 5, 2, 0)),
        ("SGP auto_start_mode, 0, 1", i(9, 77, 0, 1)),
        ("AGP user_variable_7", i(35, 7, 2, 0)),
        ("AAP target_position, 0", i(34, 0, 0, 0)),
    ];
    for (source, expected) in cases {
        assert_eq!(one(source), expected, "{source}");
    }
    // A user's constant wins over a parameter name, as in TMCL-IDE sources.
    assert_eq!(
        program("actual_position = 4\nGAP actual_position, 0"),
        [i(6, 4, 0, 0)]
    );
}

#[test]
fn commands_by_number_take_raw_fields() {
    assert_eq!(one("27 0, 0, 500"), i(27, 0, 0, 500));
    assert_eq!(one("28"), i(28, 0, 0, 0));
    assert_eq!(one("3 0, 0, 5"), i(3, 0, 0, 5));
}

#[test]
fn unknown_parameter_numbers_assemble_with_a_warning() {
    let program = assemble("MST 0\n  GAP 200, 0", "t.tmc", &Profile::builtin()).unwrap();
    assert_eq!(program.instructions[1], i(6, 200, 0, 0));
    let warnings: Vec<String> = program.warnings.iter().map(ToString::to_string).collect();
    assert_eq!(
        warnings,
        [
            "t.tmc:2:7: warning: axis parameter 200 is not in the TMCM-142 profile; sending it anyway"
        ]
    );
}

#[test]
fn each_error_names_file_line_column_and_what_is_wrong() {
    let cases = [
        (
            "  MVPP ABS, 0, 10",
            "t.tmc:1:3: error: unknown command 'MVPP'; did you mean MVP?",
        ),
        (
            "Loop: MST 0\n  JA Lopo",
            "t.tmc:2:6: error: unknown label 'Lopo'; did you mean Loop?",
        ),
        (
            "MVP ABSS, 0, 10",
            "t.tmc:1:5: error: 'ABSS' is not a keyword of MVP; use ABS, REL, COORD",
        ),
        (
            "ROL 0",
            "t.tmc:1:1: error: ROL takes 2 arguments, got 1; usage: ROL <motor>, <value>",
        ),
        (
            "MST 0, 1",
            "t.tmc:1:1: error: MST takes 1 argument, got 2; usage: MST <motor>",
        ),
        (
            "ROL 0, -5",
            "t.tmc:1:8: error: -5 is out of range for the value of ROL: allowed 0..2147483647",
        ),
        (
            "SAP max_current, 0, 16",
            "t.tmc:1:21: error: 16 is out of range for max_current (axis parameter 6): allowed 0..15 (1/15 of full scale (0 = 0 %, 15 = 100 %))",
        ),
        (
            "JA 2048",
            "t.tmc:1:4: error: 2048 is out of range for the value of JA: allowed 0..2047",
        ),
        (
            "ROL 1, 100",
            "t.tmc:1:5: error: motor 1 does not exist: the TMCM-142 has one motor (0..0)",
        ),
        (
            "SAP 4, 300, 1",
            "t.tmc:1:8: error: the motor 300 does not fit: it must lie in 0..255",
        ),
        (
            "129 1, 0, 0",
            "t.tmc:1:1: error: 129 — run application — is a direct-mode control function and cannot be stored in a program",
        ),
        (
            "RUN",
            "t.tmc:1:1: error: RUN is an ASCII-mode word, not a program instruction",
        ),
        (
            "17 0, 0, 0",
            "t.tmc:1:1: error: command 17 is not supported by the TMCM-142",
        ),
        (
            "SAP 8, 0, 1",
            "t.tmc:1:5: error: axis parameter 8 (target_position_reached) is read-only; use GAP 8, 0 to read it",
        ),
        (
            "SAP max_positoning_speed, 0, 1",
            "t.tmc:1:5: error: unknown axis parameter 'max_positoning_speed'; did you mean max_positioning_speed?; list them with :params or `tmclsh params`",
        ),
        (
            "GGP user_variable_5, 0",
            "t.tmc:1:22: error: global parameter 'user_variable_5' is in bank 2, not bank 0",
        ),
        (
            "SAP 4, 0, Speed",
            "t.tmc:1:11: error: unknown constant or label 'Speed'",
        ),
        (
            "Loop: MST 0\nLoop: MST 0",
            "t.tmc:2:1: error: 'Loop' is already defined on line 1",
        ),
        (
            "A = B + 1\nB = A",
            "t.tmc:1:1: error: constant 'A' is defined in terms of itself",
        ),
        (
            "CALC DIV, 10 / (3 - 3)",
            "t.tmc:1:14: error: division by zero",
        ),
        (
            "ROL 0 500",
            "t.tmc:1:7: error: expected ',' between operands, found '500'",
        ),
        ("ROL 0,", "t.tmc:1:6: error: operand missing after ','"),
        (
            "#include \"x.tmc\"",
            "t.tmc:1:2: error: unknown directive '#include'; only #define is supported",
        ),
        (
            "MVP COORD, 0, 21",
            "t.tmc:1:15: error: 21 is out of range for the coordinate number: allowed 0..20",
        ),
    ];
    for (source, expected) in cases {
        assert_eq!(error(source), expected, "{source}");
    }
}

#[test]
fn all_errors_of_a_file_are_reported_in_line_order() {
    let source = "ROL 0, 1\nFOO 1\nJA Nowhere\nMST 0\nMVP XYZ, 0, 1\nLoop:\nLoop:";
    let lines: Vec<usize> = assemble(source, "t.tmc", &Profile::builtin())
        .unwrap_err()
        .errors
        .iter()
        .map(|e| e.at.line)
        .collect();
    assert_eq!(lines, [2, 3, 5, 7]);
}

#[test]
fn a_program_longer_than_program_memory_is_refused() {
    let profile = Profile::builtin();
    let limit = usize::from(profile.program_memory);
    assert_eq!(limit, 2048);
    let fits = "MST 0\n".repeat(limit);
    assert_eq!(program(&fits).len(), limit);
    let too_long = format!("{fits}MST 0\nMST 0\n");
    assert_eq!(
        error(&too_long),
        "t.tmc:2049:1: error: the program has 2050 instructions but the TMCM-142 holds 2048; this is instruction 2049"
    );
}

#[test]
fn the_listing_shows_address_bytes_and_source_line() {
    let source = "// demo\nLoop: MVP ABS, 0, 1000000 // go\n  JA Loop\n";
    let program = assemble(source, "t.tmc", &Profile::builtin()).unwrap();
    assert_eq!(program.byte_len(), 14);
    assert_eq!(
        program.listing(source),
        format!(
            "addr  bytes                 line  source\n{:31}1  // demo\n\
         0000  04 00 00 00 0F 42 40     2  Loop: MVP ABS, 0, 1000000 // go\n\
         0001  16 00 00 00 00 00 00     3    JA Loop\n",
            ""
        )
    );
}

#[test]
fn load_program_takes_source_or_a_checked_program_file() {
    let profile = Profile::builtin();
    let from_source = load_program(TEST2.as_bytes(), "test2.tmc", &profile).unwrap();
    assert_eq!(from_source.len(), 13);
    let bytes = write_binary(&from_source).unwrap();
    assert_eq!(
        load_program(&bytes, "test2.bin", &profile).unwrap(),
        from_source
    );
    let invalid = write_binary(&[i(3, 0, 0, 0), i(129, 0, 0, 0)]).unwrap();
    assert_eq!(
        load_program(&invalid, "x.bin", &profile)
            .unwrap_err()
            .to_string(),
        "x.bin: instruction 1: 129 — run application — is a direct-mode control function and cannot be stored in a program"
    );
    let too_long = write_binary(&vec![i(3, 0, 0, 0); 2049]).unwrap();
    assert!(matches!(
        load_program(&too_long, "x.bin", &profile),
        Err(LoadError::TooLong { count: 2049, .. })
    ));
    let broken = load_program(b"MST 0\nFOO", "x.tmc", &profile).unwrap_err();
    assert_eq!(
        broken.to_string(),
        "x.tmc:2:1: error: unknown command 'FOO'"
    );
}

#[test]
fn windows_sources_assemble_too() {
    // CRLF line ends, a byte-order mark, and a Windows-1252 "™" (0x99) inside a comment.
    let mut bytes = b"\xEF\xBB\xBF// TMCL\x99 demo\r\nLoop: MST 0\r\n  JA Loop\r\n".to_vec();
    assert_eq!(
        load_program(&bytes, "w.tmc", &Profile::builtin()).unwrap(),
        [i(3, 0, 0, 0), i(22, 0, 0, 0)]
    );
    bytes.extend_from_slice(b"  ROL 0, 1\x99\r\n");
    let error = load_program(&bytes, "w.tmc", &Profile::builtin()).unwrap_err();
    assert_eq!(
        error.to_string(),
        "w.tmc:4:11: error: unexpected character '\u{FFFD}'"
    );
}

#[test]
fn the_documented_example_assembles() {
    let section = include_str!("../../../../docs/programs.md");
    let start = section.find("```text\n").unwrap() + "```text\n".len();
    let example = &section[start..start + section[start..].find("```").unwrap()];
    assert_eq!(
        program(example),
        [
            i(5, 4, 0, 500_000),
            i(4, 0, 0, 1_000_016),
            i(27, 1, 0, 0),
            i(21, 2, 0, 5),
            i(22, 0, 0, 1),
            i(28, 0, 0, 0),
        ]
    );
}

mod grammar;
mod hostile;

#[test]
fn a_command_other_modules_have_names_the_profiles_that_have_it() {
    let message = error("EI 0\nSTOP");
    assert!(
        message.starts_with(
            "t.tmc:1:1: error: the TMCM-142 has no command 'EI'; these profiles have it: "
        ),
        "{message}"
    );
    assert!(message.contains("tmcm-1140"), "{message}");
    assert!(!message.contains("tmcm-142,"), "{message}");
    let tmcm_1140 = crate::dialect::tmcl::profile::catalogue::by_name("tmcm-1140").unwrap();
    assert!(load_program(b"EI 0\nSTOP", "t.tmc", &tmcm_1140).is_ok());
}
