use crate::dialect::tmcl::profile::Profile;

use super::*;

fn canonical(text: &str) -> String {
    let profile = Profile::builtin();
    format_line(&parse(text, &profile).unwrap(), 1, &profile)
}

fn error(text: &str) -> InputError {
    parse(text, &Profile::builtin()).unwrap_err()
}

#[test]
fn lines_format_back_to_one_canonical_form() {
    let cases = [
        ("GAP 1, 0", "AGAP 1, 0"),
        ("agap 1 0", "AGAP 1, 0"),
        ("A GAP actual_position, 0", "AGAP 1, 0"),
        ("CGAP 4, 0", "CGAP 4, 0"),
        ("C GAP 4, 0", "CGAP 4, 0"),
        ("mvp abs 0 -5000", "AMVP ABS, 0, -5000"),
        ("MVP 1, 0, 10", "AMVP REL, 0, 10"),
        ("RFS status, 0", "ARFS STATUS, 0"),
        ("SAP max_current, 0, 0xA", "ASAP 6, 0, 10"),
        ("SGP serial_host_address, 0, 3", "ASGP 76, 0, 3"),
        ("SGP serial_host, 0, 3", "ASGP 76, 0, 3"),
        ("GGP user_variable_5, 2", "AGGP 5, 2"),
        ("GGP user_variable_5", "AGGP 5, 2"),
        ("RSAP 4, 0", "ARSAP 4, 0"),
        ("R SAP 4, 0, 7", "RSAP 4, 0, 7"),
        ("abin", "ABIN"),
        ("B RUN", "BRUN"),
        ("stop", "ASTOP"),
        ("136 1", "A136 1"),
        ("135", "A135"),
        ("CALC NOT", "ACALC NOT"),
        ("SAP 4, 0, 0xFFFFFFFF", "ASAP 4, 0, -1"),
        ("WAIT TICKS, 0, 500", "AWAIT TICKS, 0, 500"),
    ];
    for (typed, sent) in cases {
        assert_eq!(canonical(typed), sent, "{typed}");
    }
}

#[test]
fn command_28_is_written_by_number_not_as_the_ascii_word_stop() {
    // STOP is command 28's mnemonic and also ASCII mode's "stop the program"; a line that
    // names command 28 must not be sent as the other one.
    let profile = Profile::builtin();
    let line = parse("C28", &profile).unwrap();
    assert_eq!(line.op, Op::Command(Instruction::new(28, 0, 0, 0)));
    assert_eq!(format_line(&line, 1, &profile), "C28");
    assert_eq!(canonical("stop"), "ASTOP", "the ASCII word stays a word");
}

#[test]
fn every_command_formats_to_a_line_that_resolves_to_it_again() {
    let profile = Profile::builtin();
    for spec in profile.commands.iter() {
        let instruction = Instruction::new(spec.number, 0, 0, 0);
        let text = format_instruction(&instruction, &profile);
        let again = parse(&text, &profile).unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(again.op, Op::Command(instruction), "{text}");
    }
}

#[test]
fn resolution_fills_the_instruction_fields() {
    let profile = Profile::builtin();
    let line = parse("BMVP COORD, 0, 3", &profile).unwrap();
    assert_eq!(line.address, Some(2));
    assert_eq!(line.op, Op::Command(Instruction::new(4, 2, 0, 3)));
    let line = parse("SIO 1, 2, 1", &profile).unwrap();
    assert_eq!(line.op, Op::Command(Instruction::new(14, 1, 2, 1)));
}

#[test]
fn address_characters_map_to_module_numbers() {
    assert_eq!(address_char(1), Some('A'));
    assert_eq!(address_char(26), Some('Z'));
    assert_eq!(address_char(0), None);
    assert_eq!(address_char(27), None);
    assert_eq!(address_of('c'), Some(3));
    assert_eq!(address_of('1'), None);
}

#[test]
fn unknown_commands_suggest_the_nearest() {
    match error("GAPP 1, 0") {
        InputError::UnknownCommand { word, suggestion } => {
            assert_eq!(word, "GAPP");
            assert_eq!(suggestion.as_deref(), Some("GAP"));
        }
        other => panic!("{other:?}"),
    }
    match error("AGAPP 1, 0") {
        InputError::UnknownCommand { suggestion, .. } => {
            assert_eq!(suggestion.as_deref(), Some("GAP"))
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(error("XYZZYQ").to_string(), "unknown command 'XYZZYQ'");
    assert_eq!(
        error("16 0").to_string(),
        "command 16 is not supported by the TMCM-142"
    );
}

#[test]
fn argument_count_errors_show_usage() {
    let e = error("GAP 1");
    assert_eq!(
        e.to_string(),
        "GAP takes 2 arguments, got 1; usage: GAP <parameter>, <motor>"
    );
    let e = error("MST 0, 1");
    assert!(
        e.to_string().starts_with("MST takes 1 argument, got 2"),
        "{e}"
    );
    let e = error("CALC ADD, 1, 2");
    assert!(e.to_string().contains("takes 1 to 2 arguments"), "{e}");
    let e = error("BIN 1");
    assert!(e.to_string().contains("BIN takes no arguments"), "{e}");
}

#[test]
fn keyword_errors_list_the_keywords() {
    let e = error("MVP ABX, 0, 5");
    assert_eq!(
        e.to_string(),
        "'ABX' is not a keyword of MVP; use ABS, REL, COORD"
    );
}

#[test]
fn names_where_numbers_belong_are_refused() {
    let e = error("MST zero");
    assert_eq!(
        e.to_string(),
        "the motor of MST must be a number, not 'zero'"
    );
}

#[test]
fn numbers_that_do_not_fit_their_field() {
    assert!(
        error("GAP 300, 0")
            .to_string()
            .contains("the parameter 300 does not fit")
    );
    assert!(
        error("GAP 1, -1")
            .to_string()
            .contains("must lie in 0..255")
    );
    assert!(
        error("SAP 4, 0, 3000000000")
            .to_string()
            .contains("does not fit")
    );
    assert!(
        error("SAP 4, 0, 0x1FFFFFFFF")
            .to_string()
            .contains("does not fit")
    );
}

#[test]
fn parameter_names_resolve_or_fail_clearly() {
    let e = error("GAP actual_positon, 0");
    assert!(
        e.to_string()
            .contains("unknown axis parameter 'actual_positon'; did you mean actual_position?"),
        "{e}"
    );
    let e = error("GAP actual, 0");
    assert!(
        e.to_string()
            .contains("'actual' is ambiguous: actual_position, actual_speed"),
        "{e}"
    );
    let e = error("SGP serial_address, 2, 5");
    assert_eq!(
        e.to_string(),
        "global parameter 'serial_address' is in bank 0, not bank 2"
    );
}

#[test]
fn syntax_errors_pass_through_with_their_column() {
    assert_eq!(
        error("GAP 1,,0").to_string(),
        "column 7: empty argument between commas"
    );
}

#[test]
fn raw_lines_keep_their_words_for_no_validate() {
    let raw =
        crate::dialect::tmcl::protocol::syntax::parse_line("gapp 1, 0x10", |_| false).unwrap();
    assert_eq!(format_raw(&raw, 2), "BGAPP 1, 0x10");
}
