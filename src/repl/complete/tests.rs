use super::*;

fn words(line: &str) -> Vec<String> {
    match complete(line, line.len(), Grammar::Tmcl(&Profile::builtin())) {
        Completion::Words { candidates, .. } => {
            candidates.into_iter().map(|c| c.replacement).collect()
        }
        Completion::File { .. } => vec!["<file>".into()],
    }
}

#[test]
fn mnemonics_complete_case_insensitively() {
    let got = words("ga");
    assert_eq!(got, vec!["GAP "]);
    assert!(words("S").contains(&"SAP ".to_string()));
    assert!(words("S").contains(&"STOP ".to_string()), "ASCII words too");
}

#[test]
fn an_address_character_is_kept() {
    let got = words("Cga");
    assert_eq!(got, vec!["CGAP "]);
}

#[test]
fn keywords_complete_for_their_command() {
    assert_eq!(words("MVP "), vec!["ABS, ", "REL, ", "COORD, "]);
    assert_eq!(words("AMVP r"), vec!["REL, "]);
    assert_eq!(words("RFS st"), vec!["START, ", "STOP, ", "STATUS, "]);
}

#[test]
fn axis_parameter_names_for_axis_commands() {
    assert_eq!(words("GAP actual_p"), vec!["actual_position, "]);
    assert_eq!(words("SAP max_c"), vec!["max_current, "]);
    assert_eq!(words("A GAP max_c"), vec!["max_current, "]);
    assert!(words("STAP ").len() > 10);
    let all = complete("RSAP max_", 9, Grammar::Tmcl(&Profile::builtin()));
    let Completion::Words { start, candidates } = all else {
        panic!()
    };
    assert_eq!(start, 5);
    assert!(candidates.iter().any(|c| c.display == "max_current (6)"));
}

#[test]
fn global_parameter_names_show_their_bank() {
    let Completion::Words { candidates, .. } =
        complete("GGP serial_ho", 13, Grammar::Tmcl(&Profile::builtin()))
    else {
        panic!()
    };
    assert_eq!(candidates.len(), 1);
    assert_eq!(candidates[0].display, "serial_host_address (76, bank 0)");
    assert!(words("SGP user_variable_1").contains(&"user_variable_12, ".to_string()));
}

#[test]
fn numeric_operands_have_no_candidates() {
    assert!(words("GAP 1, ").is_empty());
    assert!(words("ROR 0, ").is_empty());
}

#[test]
fn helpers_and_their_arguments() {
    assert_eq!(words(":pa"), vec![":params "]);
    assert_eq!(words(":echo l"), vec!["line"]);
    assert_eq!(words(":log tr"), vec!["<file>"]);
    assert!(words(":help G").contains(&"GAP ".to_string()));
    assert_eq!(words(":params actual_s"), vec!["actual_speed"]);
}

#[test]
fn smd4_mnemonics_complete_level_by_level() {
    let spec = crate::dialect::smd4::protocol::Smd4Spec::builtin();
    let Completion::Words { candidates, .. } = complete("MOTOR:VM", 8, Grammar::Smd4(spec)) else {
        panic!()
    };
    assert_eq!(
        candidates
            .iter()
            .map(|c| c.replacement.as_str())
            .collect::<Vec<_>>(),
        ["MOTOR:VMAX"]
    );
    let Completion::Words { candidates, .. } = complete(":fl", 3, Grammar::Smd4(spec)) else {
        panic!()
    };
    assert_eq!(candidates[0].replacement, ":flags ");
    let Completion::Words { candidates, .. } =
        complete(":fl", 3, Grammar::Tmcl(&Profile::builtin()))
    else {
        panic!()
    };
    assert!(candidates.is_empty(), ":flags is SMD4 only");
}

proptest::proptest! {
    /// Whatever is typed and wherever the cursor is, completion, hints and the highlighter's
    /// check answer: a panic here would strike while the line editor holds the terminal.
    #[test]
    fn any_line_and_cursor_is_answered(
        line in "[ -~äé\t]{0,40}",
        cut in 0usize..41,
    ) {
        let profile = Profile::builtin();
        let mut pos = cut.min(line.len());
        while !line.is_char_boundary(pos) {
            pos -= 1;
        }
        for grammar in [Grammar::Tmcl(&profile), Grammar::Smd4(crate::dialect::smd4::protocol::Smd4Spec::builtin())] {
            let _ = complete(&line, pos, grammar);
        }
        let _ = crate::dialect::tmcl::hint::hint(&line[..pos], &profile);
        for tables in [
            crate::repl::editor::Tables::Tmcl(profile.clone()),
            crate::repl::editor::Tables::Smd4(crate::dialect::smd4::protocol::Smd4Spec::builtin()),
        ] {
            let _ = crate::repl::editor::ReplHelper::new(tables, true).is_invalid(&line);
        }
    }
}
