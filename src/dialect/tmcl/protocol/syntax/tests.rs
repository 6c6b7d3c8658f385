use super::*;

const WORDS: &[&str] = &[
    "ROR", "ROL", "MST", "MVP", "SAP", "GAP", "STAP", "RSAP", "SGP", "GGP", "STGP", "RSGP", "RFS",
    "SIO", "GIO", "AGP", "AAP", "UF0", "BIN", "RUN", "STOP",
];

fn parse(line: &str) -> Result<RawLine, SyntaxError> {
    parse_line(line, |w| WORDS.contains(&w))
}

fn num(value: i64) -> Arg {
    Arg::Number { value, hex: false }
}

fn name(s: &str) -> Word {
    Word::Name(s.into())
}

#[test]
fn address_character_with_and_without_space() {
    for line in ["AGAP 1, 0", "A GAP 1, 0", "A  GAP 1,0", "  agap 1 , 0"] {
        let raw = parse(line).unwrap();
        assert_eq!(raw.address, Some('A'), "{line}");
        assert_eq!(raw.word, name("GAP"), "{line}");
        assert_eq!(raw.args, vec![num(1), num(0)], "{line}");
    }
}

#[test]
fn no_address_character() {
    let raw = parse("GAP 1 0").unwrap();
    assert_eq!((raw.address, raw.word), (None, name("GAP")));
    assert_eq!(raw.args, vec![num(1), num(0)]);
}

#[test]
fn whole_mnemonic_wins_over_address_plus_mnemonic() {
    let raw = parse("RSAP 4, 0").unwrap();
    assert_eq!((raw.address, raw.word), (None, name("RSAP")));
    let raw = parse("R SAP 4, 0, 5").unwrap();
    assert_eq!((raw.address, raw.word), (Some('R'), name("SAP")));
    let raw = parse("RRSAP 4, 0").unwrap();
    assert_eq!((raw.address, raw.word), (Some('R'), name("RSAP")));
    let raw = parse("CGAP 4, 0").unwrap();
    assert_eq!((raw.address, raw.word), (Some('C'), name("GAP")));
    // AGP is a mnemonic of its own; AAGP addresses module A.
    assert_eq!(parse("AGP 4, 0").unwrap().word, name("AGP"));
    assert_eq!(parse("AAGP 4, 0").unwrap().address, Some('A'));
}

#[test]
fn mnemonics_are_case_insensitive_and_may_contain_digits() {
    let raw = parse("auf0 1, 0, 5").unwrap();
    assert_eq!((raw.address, raw.word), (Some('A'), name("UF0")));
    assert_eq!(parse("mst 0").unwrap().word, name("MST"));
}

#[test]
fn ascii_only_words() {
    assert_eq!(parse("ABIN").unwrap().word, name("BIN"));
    assert_eq!(parse("ABIN").unwrap().address, Some('A'));
    assert_eq!(parse("BIN").unwrap().address, None);
    assert_eq!(parse("A RUN").unwrap().word, name("RUN"));
    assert_eq!(parse("bstop").unwrap().address, Some('B'));
}

#[test]
fn numbers_decimal_negative_and_hex() {
    let raw = parse("MVP ABS, 0, -5000").unwrap();
    assert_eq!(raw.args, vec![Arg::Name("ABS".into()), num(0), num(-5000)]);
    let raw = parse("SAP 4, 0, 0x1f4").unwrap();
    assert_eq!(
        raw.args[2],
        Arg::Number {
            value: 500,
            hex: true
        }
    );
    let raw = parse("SAP 4, 0, $1F4").unwrap();
    assert_eq!(
        raw.args[2],
        Arg::Number {
            value: 500,
            hex: true
        }
    );
    let raw = parse("SAP 4, 0, +7").unwrap();
    assert_eq!(raw.args[2], num(7));
    let raw = parse("SAP 4, 0, 0xFFFFFFFF").unwrap();
    assert_eq!(
        raw.args[2],
        Arg::Number {
            value: 0xFFFF_FFFF,
            hex: true
        }
    );
}

#[test]
fn names_in_place_of_numbers() {
    let raw = parse("GAP actual_position, 0").unwrap();
    assert_eq!(raw.args, vec![Arg::Name("actual_position".into()), num(0)]);
}

#[test]
fn commands_by_number() {
    let raw = parse("136 1").unwrap();
    assert_eq!((raw.address, raw.word), (None, Word::Number(136)));
    assert_eq!(raw.args, vec![num(1)]);
    let raw = parse("A136 1").unwrap();
    assert_eq!((raw.address, raw.word), (Some('A'), Word::Number(136)));
    let raw = parse("B 135").unwrap();
    assert_eq!((raw.address, raw.word), (Some('B'), Word::Number(135)));
}

#[test]
fn line_endings_are_ignored() {
    for line in ["AGAP 1, 0\r", "AGAP 1, 0\n", "AGAP 1, 0\r\n", "AGAP 1, 0  "] {
        assert_eq!(parse(line).unwrap().args, vec![num(1), num(0)], "{line:?}");
    }
}

#[test]
fn unknown_words_are_kept_whole() {
    let raw = parse("GAPP 1, 0").unwrap();
    assert_eq!((raw.address, raw.word), (None, name("GAPP")));
    let raw = parse("AGAPP 1, 0").unwrap();
    assert_eq!((raw.address, raw.word), (None, name("AGAPP")));
}

#[test]
fn errors_name_the_column() {
    let cases = [
        ("", 1, "empty line"),
        ("   ", 1, "empty line"),
        ("GAP 1,,0", 7, "empty argument"),
        ("GAP 1,", 7, "argument missing"),
        ("GAP ,1", 4, "unexpected ','"),
        ("GAP 1;0", 6, "unexpected ';'"),
        ("GAP 12abc, 0", 5, "expected a number or a name"),
        ("GAP 1.5, 0", 5, "'1.5' is not a whole number"),
        ("A", 2, "command missing after address character A"),
        ("A ,", 3, "expected a command"),
        ("300 1", 1, "not in 0..255"),
        ("!GAP", 1, "expected a command"),
    ];
    for (line, column, message) in cases {
        let err = parse(line).unwrap_err();
        assert_eq!(err.column, column, "{line:?}: {err}");
        assert!(err.message.contains(message), "{line:?}: {err}");
    }
}
