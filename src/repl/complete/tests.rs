use super::*;
use crate::dialect::smd4::Smd4Grammar;
use crate::dialect::tmcl::TmclGrammar;
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::validate::Mode;

fn tmcl() -> TmclGrammar {
    TmclGrammar::new(Profile::builtin(), Mode::Ascii)
}

fn smd4() -> Smd4Grammar {
    Smd4Grammar::new(crate::dialect::smd4::protocol::Smd4Spec::builtin())
}

fn words(line: &str) -> Vec<String> {
    match complete(line, line.len(), &tmcl()) {
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
    let all = complete("RSAP max_", 9, &tmcl());
    let Completion::Words { start, candidates } = all else {
        panic!()
    };
    assert_eq!(start, 5);
    assert!(candidates.iter().any(|c| c.display == "max_current (6)"));
}

#[test]
fn global_parameter_names_show_their_bank() {
    let Completion::Words { candidates, .. } = complete("GGP serial_ho", 13, &tmcl()) else {
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
    assert_eq!(words(":params --v"), vec!["--values"]);
    assert_eq!(words(":params --values --m"), vec!["--motor"]);
}

#[test]
fn smd4_mnemonics_complete_level_by_level() {
    let Completion::Words { candidates, .. } = complete("MOTOR:VM", 8, &smd4()) else {
        panic!()
    };
    assert_eq!(
        candidates
            .iter()
            .map(|c| c.replacement.as_str())
            .collect::<Vec<_>>(),
        ["MOTOR:VMAX"]
    );
    let Completion::Words { candidates, .. } = complete(":fl", 3, &smd4()) else {
        panic!()
    };
    assert_eq!(candidates[0].replacement, ":flags ");
    let Completion::Words { candidates, .. } = complete(":fl", 3, &tmcl()) else {
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
        let grammars: [std::sync::Arc<dyn Grammar>; 2] = [std::sync::Arc::new(tmcl()), std::sync::Arc::new(smd4())];
        for grammar in &grammars {
            let _ = complete(&line, pos, &**grammar);
        }
        let _ = crate::dialect::tmcl::hint::hint(&line[..pos], &profile);
        for grammar in grammars {
            let helper = crate::repl::editor::ReplHelper::new(grammar, true);
            let _ = helper.check(&line);
            let _ = rustyline::hint::Hinter::hint(&helper, &line[..pos], pos, &rustyline::Context::new(&rustyline::history::DefaultHistory::new()));
        }
    }
}
