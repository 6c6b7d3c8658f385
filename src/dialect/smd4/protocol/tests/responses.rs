//! The reply grammar beyond the document's examples: error items in every spelling, address
//! prefixes, malformed lines, the multi-line collector, and format/parse round trips.

use proptest::prelude::*;

use crate::dialect::smd4::protocol::format::{format_error, format_flags, format_float};
use crate::dialect::smd4::protocol::{
    CollectorState, ErrorCode, ErrorSpelling, Expectation, FlagCase, FloatStyle, ReplyCollector,
    Smd4Spec, Value, parse_reply,
};

fn expect(mnemonic: &str) -> Expectation {
    Expectation::for_command(Smd4Spec::builtin().commands.get(mnemonic).unwrap())
}

#[test]
fn error_items_in_every_plausible_spelling() {
    for line in [
        "0x0000,0x0000,-103 (Invalid Mnemonic)",
        "0x0000,0x0000,-103,Invalid Mnemonic",
        "0x0000,0x0000,-103",
    ] {
        for expectation in [
            Expectation::unknown(),
            expect("MOTOR:VMAX"),
            expect("SYS:CLR"),
        ] {
            let reply = parse_reply(line, &expectation).unwrap();
            let error = reply.error.as_ref().unwrap_or_else(|| panic!("{line}"));
            assert_eq!(error.code, ErrorCode::InvalidMnemonic, "{line}");
            assert!(reply.data.is_empty());
            assert!(!reply.is_ok());
        }
    }
    let reply = parse_reply("0x0080,0x0000,-1 (Stop motor first)", &expect("MOTOR:RES")).unwrap();
    assert_eq!(
        reply.error.unwrap().text.as_deref(),
        Some("Stop motor first")
    );
    // Codes the table does not list are kept.
    let reply = parse_reply("0x0000,0x0000,-42 (Something new)", &Expectation::unknown()).unwrap();
    assert_eq!(reply.error.unwrap().code, ErrorCode::Other(-42));
}

#[test]
fn a_bare_negative_integer_is_data_where_the_command_returns_an_int() {
    // MOTOR:T returns an INT temperature, which may be negative.
    let reply = parse_reply("0x0000,0x0000,-5", &expect("MOTOR:T")).unwrap();
    assert!(reply.is_ok());
    assert_eq!(reply.data[0].value, Value::Int(-5));
    // Spelled with its text it is an error there too.
    let reply = parse_reply("0x0000,0x0000,-5 (Action failed)", &expect("MOTOR:T")).unwrap();
    assert_eq!(reply.error.unwrap().code, ErrorCode::ActionFailed);
    // Unknown bare codes: an error where only flags are expected, data where nothing is known.
    assert!(
        parse_reply("0x0000,0x0000,-42", &expect("SYS:CLR"))
            .unwrap()
            .error
            .is_some()
    );
    assert!(
        parse_reply("0x0000,0x0000,-42", &Expectation::unknown())
            .unwrap()
            .error
            .is_none()
    );
    // A negative position in fixed point is data.
    let reply = parse_reply("0x0000,0x0000,-2.00", &expect("MOTOR:PACT")).unwrap();
    assert_eq!(reply.data[0].value, Value::Float(-2.0));
}

#[test]
fn address_prefix_and_flags() {
    for line in [
        "@5,0x0880,0x0020,1",
        "@5,0x0880,0x0020,1\r\n",
        "@50x0880,0x0020,1",
    ] {
        let reply = parse_reply(line, &expect("SYS:IDENT")).unwrap();
        assert_eq!(reply.address, Some(5), "{line}");
        assert_eq!((reply.sflags.0, reply.eflags.0), (0x0880, 0x0020));
        assert_eq!(reply.data[0].value, Value::Bool(true));
        assert_eq!(reply.raw, line.trim_end());
    }
    let reply = parse_reply("0xabcd,0XEF01", &Expectation::unknown()).unwrap();
    assert_eq!(
        (reply.sflags.0, reply.eflags.0, reply.address),
        (0xABCD, 0xEF01, None)
    );
}

#[test]
fn malformed_lines_are_errors_not_panics() {
    for line in [
        "",
        "0x0000",
        "0x0000,",
        "0x00000,0x0000",
        "0x0000,0x0000x",
        "0x,0x0000",
        "1234,5678",
        "Ethernet interface:",
        "@,0x0000,0x0000",
        "@99999999999,0x0000,0x0000",
    ] {
        let error = parse_reply(line, &Expectation::unknown()).unwrap_err();
        assert!(error.to_string().starts_with("not an SMD4 reply"), "{line}");
    }
}

#[test]
fn multi_line_collector() {
    let gap = crate::dialect::smd4::protocol::default_quiet_gap();
    assert_eq!(gap.as_millis(), 100);
    // A single-line reply completes at once.
    let mut single = ReplyCollector::new(expect("SYS:FW"));
    assert!(matches!(
        single.push_line("0x0000,0x0000,24044.12"),
        Ok(CollectorState::Complete(_))
    ));
    // A multi-line command that failed completes at once too: no waiting for quiet.
    let mut failed = ReplyCollector::new(expect("SYS:FLAGSV"));
    match failed
        .push_line("0x0000,0x0000,-102 (Argument count)")
        .unwrap()
    {
        CollectorState::Complete(reply) => {
            assert_eq!(reply.error.unwrap().code, ErrorCode::ArgumentCount)
        }
        other => panic!("{other:?}"),
    }
    // Noise before the first line is reported and skipped.
    let mut flagsv = ReplyCollector::new(expect("SYS:FLAGSV"));
    assert!(flagsv.push_line("garbage").is_err());
    assert!(!flagsv.awaiting_quiet());
    assert_eq!(
        flagsv.push_line("0x0080,0x0000,\r\n").unwrap(),
        CollectorState::AwaitQuiet
    );
    assert!(flagsv.awaiting_quiet());
    assert_eq!(
        flagsv.push_line("[X]Standby\r\n").unwrap(),
        CollectorState::AwaitQuiet
    );
    let reply = flagsv.finish_quiet().unwrap();
    assert_eq!(reply.lines, ["[X]Standby"]);
    assert!(
        ReplyCollector::new(expect("SYS:FLAGSV"))
            .finish_quiet()
            .is_none()
    );
}

proptest! {
    #[test]
    fn formatted_floats_parse_back(value in -1e12f64..1e12, decimals in 4u8..=5, missing_e in any::<bool>()) {
        let style = FloatStyle { decimals, missing_e };
        let text = format_float(value, style);
        let line = format!("0x0000,0x0000,{text}");
        let reply = parse_reply(&line, &expect("MOTOR:VACT")).unwrap();
        let Value::Float(parsed) = reply.data[0].value else { panic!("{text}") };
        let tolerance = value.abs().max(1e-300) * 10f64.powi(-i32::from(decimals)) ;
        prop_assert!((parsed - value).abs() <= tolerance, "{} -> {} -> {}", value, text, parsed);
    }

    #[test]
    fn formatted_flags_and_errors_parse_back(
        s in any::<u16>(), e in any::<u16>(), lower in any::<bool>(), spelling in 0usize..3,
        code in prop::sample::select(vec![-1, -2, -3, -5, -6, -7, -101, -102, -103, -104]),
    ) {
        let case = if lower { FlagCase::Lower } else { FlagCase::Upper };
        let spelling = [ErrorSpelling::Parenthesised, ErrorSpelling::Comma, ErrorSpelling::Bare][spelling];
        let code = ErrorCode::from_code(code);
        let line = format!("{},{},{}", format_flags(s, case), format_flags(e, case), format_error(code, spelling));
        let reply = parse_reply(&line, &expect("MOTOR:VMAX")).unwrap();
        prop_assert_eq!((reply.sflags.0, reply.eflags.0), (s, e));
        prop_assert_eq!(reply.error.unwrap().code, code);
    }

    #[test]
    fn arbitrary_text_never_panics(line in "\\PC{0,40}") {
        let _ = parse_reply(&line, &Expectation::unknown());
        let _ = crate::dialect::smd4::protocol::Request::parse(&line);
    }
}
