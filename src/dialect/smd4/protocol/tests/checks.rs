//! The reply check: every declared reply type and shape, item counts, the hostile spellings a
//! line or a device can produce, and foreign address prefixes with and without `--address`.

use proptest::prelude::*;

use crate::dialect::smd4::protocol::format::{format_flags, format_float};
use crate::dialect::smd4::protocol::{
    ErrorCode, Expectation, FlagCase, FloatStyle, Noise, Smd4Spec, check_reply, is_reply_to,
    parse_reply,
};

fn expect(mnemonic: &str) -> Expectation {
    Expectation::for_command(Smd4Spec::builtin().commands.get(mnemonic).unwrap())
}

/// The check of `line` as the reply of `mnemonic` to a request without an address.
fn check(mnemonic: &str, line: &str) -> Result<(), Noise> {
    check_to(mnemonic, line, None)
}

fn check_to(mnemonic: &str, line: &str, to: Option<u32>) -> Result<(), Noise> {
    let expect = expect(mnemonic);
    let reply = parse_reply(line, &expect).unwrap_or_else(|e| panic!("{e}"));
    check_reply(&reply, &expect, to)
}

#[track_caller]
fn passes(mnemonic: &str, data: &str) {
    let line = format!("0x0888,0x0000{data}");
    if let Err(noise) = check(mnemonic, &line) {
        panic!("{mnemonic}: {line} is noise: {noise}");
    }
}

#[track_caller]
fn noise(mnemonic: &str, data: &str) -> Noise {
    let line = format!("0x0888,0x0000{data}");
    check(mnemonic, &line).expect_err(&format!("{mnemonic}: {line} passed"))
}

#[test]
fn every_value_type_in_its_reply_spellings() {
    for (mnemonic, good) in [
        ("MOTOR:T", ",25"),                                    // INT
        ("MOTOR:T", ",-40"),   // INT, negative: data, not an error code
        ("MOTOR:RES", ",256"), // UINT
        ("SYS:UPTIME", ",9223372036854775807"), // UINT, the largest
        ("MOTOR:SDMODE", ",1"), // ENUM
        ("SYS:IDENT", ",0"),   // BOOL
        ("SYS:FW", ",24044.12"), // STRING
        ("SYS:PSN", ",00000-000"), // STRING
        ("SYS:BSN", ","),      // STRING, empty
        ("COMS:NET:IP", ",10.0.97.70"), // DOTTED DECIMAL
        ("SYS:UUID", ",f4562fb1-d002-11ee-b3e5-44b7d0c71675"), // UUID
        ("BAKE:ELAPSED", ",2:34:12"), // h:m:s
        ("BAKE:ELAPSED", ",1234:05:59"),
        ("SYS:MODE", ",1 (Remote)"), // named
        ("SYS:MODE", ",2 (Remote)"), // named: labels are not checked (smd4-notes §7.10)
        ("SYS:FLAGS", ",1"),         // literal
        ("MOTOR:RUNR,5", ",1"),
        ("SYS:CLR", ""),     // flags only
        ("SYS:FLAGSV", ","), // multi-line: the first line
        ("SYS:FLAGSV", ""),
    ] {
        passes(mnemonic.split(',').next().unwrap(), good);
    }
}

#[test]
fn floats_in_every_spelling_a_drive_uses() {
    for good in [
        ",1.0000E+03",
        ",1.00000E+03",
        ",1.0000e+03",
        ",1.0000+03",
        ",1.00000-03",
        ",0.0000E+00",
        ",0.0000+00",
        ",-2.5000E+120",
        ",5.76159E-10",
    ] {
        passes("MOTOR:VACT", good);
        passes("MOTOR:PACT", good);
    }
    for good in [",1000.00", ",-2.00", ",0.00"] {
        passes("MOTOR:PACT", good);
        passes("MOTOR:PREL", good);
    }
    passes("MOTOR:VMAX", ",1.5000E+02,1.4988E+02");
    passes("MOTOR:VSTOP", ",1.0000+01,9.9996+00");
}

#[test]
fn hostile_numbers_are_noise() {
    for bad in [
        "3.45O0E+03",
        "NaN",
        "nan",
        "inf",
        "-inf",
        "1e999",
        "9.9999E+999",
        "1.0000E+3",
        "1.0000E+0003",
        "1.0000E03",
        "1.000E+03",
        "1.000000E+03",
        "10000E+03",
        ".0000E+03",
        "1.E+03",
        "10.0000E+03",
        "0.5000E+00",
        "0.0000E+03",
        "+1.0000E+03",
        "1.0000E+03x",
        "1000",
        "1000.00",
        "0x10",
        "",
        " 1.0000E+03",
    ] {
        assert!(
            matches!(
                noise("MOTOR:VACT", &format!(",{bad}")),
                Noise::Item { .. } | Noise::Count { .. }
            ),
            "{bad}"
        );
    }
    for bad in [
        "1000.0", "1000.000", "1000", "1.000.00", "1e3", "01000.00", "-00.50",
    ] {
        assert!(
            matches!(noise("MOTOR:PACT", &format!(",{bad}")), Noise::Item { .. }),
            "{bad}"
        );
    }
    let twenty_three = "12345678901234567890123";
    for (mnemonic, bad) in [
        ("MOTOR:T", twenty_three),
        ("MOTOR:T", "-12345678901234567890123"),
        ("MOTOR:T", "+7"),
        ("MOTOR:T", "25.0"),
        ("MOTOR:T", "2.5000E+01"),
        ("SYS:UPTIME", twenty_three),
        ("SYS:UPTIME", "9223372036854775808"),
        ("SYS:UPTIME", "0x2710"),
        ("SYS:UPTIME", "+1"),
        ("SYS:UPTIME", "1O000"),
        // A first digit corrupted into 0: a drive's printf writes no leading zero.
        ("SYS:UPTIME", "073"),
        ("MOTOR:T", "-025"),
        ("MOTOR:T", "-0"),
        ("MOTOR:SDMODE", "01"),
        ("MOTOR:SDMODE", "one"),
        ("SYS:IDENT", "2"),
        ("SYS:IDENT", "true"),
        ("COMS:NET:IP", "256.0.97.70"),
        ("COMS:NET:IP", "10.0.97"),
        ("SYS:UUID", "f4562fb1-d002-11ee-b3e5-44b7d0c7167"),
        ("BAKE:ELAPSED", "2:61:00"),
        ("BAKE:ELAPSED", "2:34"),
        ("SYS:MODE", "1"),
        ("SYS:MODE", "1 ()"),
        ("SYS:MODE", "-1 (Remote)x"),
        ("SYS:FLAGS", "0"),
        ("SYS:FLAGS", "11"),
    ] {
        let got = noise(mnemonic, &format!(",{bad}"));
        assert!(matches!(got, Noise::Item { .. }), "{mnemonic} {bad}: {got}");
    }
    assert_eq!(
        noise("MOTOR:VACT", ",3.45O0E+03").to_string(),
        "'3.45O0E+03' where one FLOAT item is due"
    );
}

/// Whether a SYS:FLAGS reply with `data` after the flag words is taken.
fn check_flags(data: &str) -> bool {
    check("SYS:FLAGS", &format!("0x0888,0x0000{data}")).is_ok()
}

#[test]
fn item_counts() {
    let count = |mnemonic: &str, data: &str| match noise(mnemonic, data) {
        Noise::Count { got, .. } => got,
        other => panic!("{mnemonic}{data}: {other}"),
    };
    assert_eq!(count("MOTOR:VACT", ",1.0000E+03,1.0000E+03"), 2);
    assert_eq!(count("MOTOR:VACT", ""), 0);
    assert_eq!(count("MOTOR:PACT", ",1000.00,5"), 2);
    assert_eq!(count("SYS:FW", ",24044.12,1"), 2);
    assert_eq!(count("MOTOR:VMAX", ",1.0000E+03"), 1);
    assert_eq!(count("MOTOR:VMAX", ",1.0000E+03,1.0000E+03,1.0000E+03"), 3);
    assert_eq!(count("SYS:CLR", ",1"), 1);
    // SYS:FLAGS declares no return; only its example shows the `1`: with or without it is the
    // answer, two items are not.
    assert!(check_flags(""), "without the example's item");
    assert!(check_flags(",1"), "with it");
    assert_eq!(count("SYS:FLAGS", ",1,1"), 2);
    assert_eq!(count("SYS:FLAGS", ",1,1"), 2);
    assert_eq!(count("SYS:MODE", ",1 (Remote),1 (Remote)"), 2);
    assert_eq!(count("SYS:FLAGSV", ",5"), 1);
    assert_eq!(count("MOTOR:T", ",,25"), 2);
    assert_eq!(
        noise("MOTOR:VACT", ",1.0000E+03,1.0000E+03").to_string(),
        "one FLOAT item due, 2 received"
    );
    assert_eq!(
        noise("MOTOR:VMAX", ",1.0000E+03").to_string(),
        "two FLOAT items due, 1 received"
    );
}

#[test]
fn control_and_non_ascii_bytes_are_noise_on_every_line() {
    for data in [
        ",24044.12\x1b]0;owned\x07",
        ",\x1b[2J",
        ",24044\x0012",
        ",24044.12\x7f",
        ",24044.12\u{9b}",
        ",24044.12\u{fffd}",
        ",2404\t4.12",
    ] {
        assert_eq!(
            noise("SYS:FW", data),
            Noise::NotPrintable { line: 1 },
            "{data:?}"
        );
    }
    // Unknown commands (sent with --no-validate) are held to printable text too.
    let reply = parse_reply("0x0888,0x0000,\x1b[2J", &Expectation::unknown()).unwrap();
    assert_eq!(
        check_reply(&reply, &Expectation::unknown(), None),
        Err(Noise::NotPrintable { line: 1 })
    );
    // A line of a multi-line listing.
    let mut reply = parse_reply("0x0888,0x0000,", &expect("SYS:FLAGSV")).unwrap();
    reply.lines = vec!["[X]Standby".into(), "[ ]Ident\x1b[2J".into()];
    let got = check_reply(&reply, &expect("SYS:FLAGSV"), None).unwrap_err();
    assert_eq!(got, Noise::NotPrintable { line: 3 });
    assert_eq!(
        got.to_string(),
        "a control or non-ASCII character in line 3"
    );
    reply.lines.pop();
    assert_eq!(check_reply(&reply, &expect("SYS:FLAGSV"), None), Ok(()));
}

#[test]
fn flag_words_have_four_digits() {
    for line in [
        "0x888,0x0000,24044.12",
        "0x0888,0x000,24044.12",
        "0x0,0x0,24044.12",
        "@3,0x088,0x0000,24044.12",
    ] {
        assert_eq!(
            check_to("SYS:FW", line, Some(3)),
            Err(Noise::FlagWord),
            "{line}"
        );
    }
    assert_eq!(check("SYS:FW", "0x088e,0X00AB,24044.12"), Ok(()));
}

#[test]
fn foreign_prefixes_with_and_without_an_address() {
    let line = "@5,0x0888,0x0000,1.0000E+03";
    // Without --address no reply carries a prefix: a drive in addressing mode ignores our
    // unprefixed packets, so an @5 reply answers someone else.
    assert_eq!(
        check_to("MOTOR:VACT", line, None),
        Err(Noise::Foreign { from: 5, to: None })
    );
    assert_eq!(
        check_to("MOTOR:VACT", line, Some(3)),
        Err(Noise::Foreign {
            from: 5,
            to: Some(3)
        })
    );
    assert_eq!(check_to("MOTOR:VACT", line, Some(5)), Ok(()));
    // The attached form of the prefix.
    assert_eq!(
        check_to("MOTOR:VACT", "@50x0888,0x0000,1.0000E+03", None),
        Err(Noise::Foreign { from: 5, to: None })
    );
    assert_eq!(
        check_to("MOTOR:VACT", "@50x0888,0x0000,1.0000E+03", Some(5)),
        Ok(())
    );
    // A drive may answer an addressed packet without the prefix (--no-reply-prefix).
    assert_eq!(
        check_to("MOTOR:VACT", "0x0888,0x0000,1.0000E+03", Some(3)),
        Ok(())
    );
    // Error replies are attributed the same way.
    assert_eq!(
        check_to(
            "MOTOR:VACT",
            "@7,0x0888,0x0000,-103 (Invalid Mnemonic)",
            Some(3)
        ),
        Err(Noise::Foreign {
            from: 7,
            to: Some(3)
        })
    );
    assert!(is_reply_to(None, None) && is_reply_to(None, Some(2)) && is_reply_to(Some(2), Some(2)));
    assert!(!is_reply_to(Some(2), None) && !is_reply_to(Some(2), Some(3)));
    assert_eq!(
        Noise::Foreign { from: 5, to: None }.to_string(),
        "a reply from drive @5, but requests carry no address"
    );
}

#[test]
fn error_codes_that_do_not_fit_are_noise_and_never_wrap() {
    for (mnemonic, data) in [
        ("MOTOR:VACT", ",-99999999999 (Invalid Mnemonic)"),
        ("MOTOR:VACT", ",-99999999999,Invalid Mnemonic"),
        ("MOTOR:VACT", ",-99999999999"),
        ("SYS:CLR", ",-99999999999"),
        ("MOTOR:T", ",-99999999999 (Action failed)"),
        ("MOTOR:T", ",-2147483649,Action failed"),
    ] {
        let reply = parse_reply(&format!("0x0888,0x0000{data}"), &expect(mnemonic)).unwrap();
        assert!(reply.error.is_none(), "{data}: never a wrapped code");
        let code = data[1..].split([' ', ',']).next().unwrap();
        assert_eq!(
            check_reply(&reply, &expect(mnemonic), None),
            Err(Noise::ErrorCode(code.into())),
            "{mnemonic}{data}"
        );
    }
    // The INT a temperature is: a large negative number is a value there, if it fits 64 bits.
    passes("MOTOR:T", ",-99999999999");
    // The edges of an i32 are codes.
    for code in [i32::MIN, -1] {
        let reply = parse_reply(
            &format!("0x0888,0x0000,{code} (Edge)"),
            &expect("MOTOR:VACT"),
        )
        .unwrap();
        assert_eq!(
            reply.error.as_ref().unwrap().code,
            ErrorCode::from_code(code)
        );
        assert_eq!(check_reply(&reply, &expect("MOTOR:VACT"), None), Ok(()));
    }
}

#[test]
fn unknown_error_codes_are_device_errors_shown_as_received() {
    let line = "0x0888,0x0000,-42 (Something new)";
    let reply = parse_reply(line, &expect("MOTOR:VACT")).unwrap();
    assert_eq!(check_reply(&reply, &expect("MOTOR:VACT"), None), Ok(()));
    let error = reply.error.unwrap();
    assert_eq!(error.code, ErrorCode::Other(-42));
    assert!(
        error.to_string().starts_with("-42 (Something new)"),
        "{error}"
    );
}

#[test]
fn unknown_commands_are_checked_for_form_only() {
    let unknown = Expectation::unknown();
    for line in [
        "0x0888,0x0000",
        "0x0888,0x0000,1,2,3,abc",
        "0x0888,0x0000,-42",
    ] {
        let reply = parse_reply(line, &unknown).unwrap();
        assert_eq!(check_reply(&reply, &unknown, None), Ok(()), "{line}");
    }
    let reply = parse_reply("0x0888,0x0000,-99999999999,Oops", &unknown).unwrap();
    assert_eq!(
        check_reply(&reply, &unknown, None),
        Err(Noise::ErrorCode("-99999999999".into()))
    );
}

proptest! {
    #[test]
    fn every_float_a_drive_writes_passes(
        value in prop_oneof![-1e300f64..1e300, -1e6f64..1e6, -1e-6f64..1e-6, Just(0.0)],
        decimals in 4u8..=5,
        missing_e in any::<bool>(),
        lower in any::<bool>(),
        s in any::<u16>(),
        e in any::<u16>(),
    ) {
        let case = if lower { FlagCase::Lower } else { FlagCase::Upper };
        let text = format_float(value, FloatStyle { decimals, missing_e });
        let line = format!("{},{},{text},{text}", format_flags(s, case), format_flags(e, case));
        prop_assert_eq!(check("MOTOR:VMAX", &line), Ok(()), "{}", line);
    }

    /// A byte lost from a float written with 4 decimals is caught, except the `E` (the
    /// `E`-less spelling reads the same value) and the sign, which no grammar can miss.
    #[test]
    fn a_dropped_byte_in_a_float_is_caught(value in 1e-30f64..1e30, at in 0usize..12) {
        let text = format_float(value, FloatStyle::default());
        let at = at % text.len();
        prop_assume!(text.as_bytes()[at] != b'E');
        let mut dropped = text.clone();
        dropped.remove(at);
        let line = format!("0x0888,0x0000,{dropped}");
        prop_assert!(check("MOTOR:VACT", &line).is_err(), "{} -> {}", text, dropped);
    }

    #[test]
    fn any_line_is_checked_without_panicking(line in "\\PC{0,60}|[@0-9xX,.Ee+-]{0,40}") {
        for mnemonic in ["MOTOR:VMAX", "MOTOR:PACT", "SYS:MODE", "SYS:FLAGSV", "MOTOR:T", "SYS:BSN"] {
            if let Ok(reply) = parse_reply(&line, &expect(mnemonic)) {
                let _ = check_reply(&reply, &expect(mnemonic), None);
                let _ = check_reply(&reply, &expect(mnemonic), Some(3));
            }
        }
    }
}

#[test]
fn user_and_real_values_that_agree_pass() {
    // The document's pairs: the widest is THIGH's 500 -> 504 (0.8 %).
    passes("MOTOR:THIGH", ",5.0000E+02,5.0400E+02");
    passes("MOTOR:AMAX", ",1.5000E+02,1.4988E+02");
    passes("MOTOR:VSTOP", ",1.0000+01,9.9996+00");
    passes("MOTOR:VSTART", ",0.0000+00,0.0000+00");
    // Near zero the absolute part (0.5 Hz) rules.
    passes("MOTOR:VSTART", ",1.0000E+00,1.4000E+00");
}

#[test]
fn user_and_real_values_that_disagree_are_noise() {
    // A corrupted leading digit or exponent: far beyond any clock divider's rounding.
    for data in [
        ",1.5000E+02,2.4988E+02",
        ",1.5000E+02,1.4988E+03",
        ",1.0000E+03,1.1000E+03",
        ",1.0000E+00,2.0000E+00",
    ] {
        assert_eq!(
            noise("MOTOR:AMAX", data),
            Noise::Disagree {
                user: data[1..11].to_string(),
                real: data[12..].to_string(),
            },
            "{data}"
        );
    }
    assert_eq!(
        noise("MOTOR:VMAX", ",1.0000E+03,9.0000E+02").to_string(),
        "user value 1.0000E+03 and real value 9.0000E+02 disagree beyond the drive's resolution"
    );
}

#[test]
fn real_values_on_the_widest_grid_the_simulator_takes_pass() {
    let tolerance = Smd4Spec::builtin()
        .commands
        .get("MOTOR:VMAX")
        .and_then(|c| c.real_tolerance)
        .expect("user/real commands carry the data's tolerance");
    let step = 2.0 * tolerance.absolute;
    for user in [0.0, 1.0, 1.5, 2.5, 7.49, 100.0, 149.5, 700.0, 15000.0] {
        let real = (user / step).round() * step;
        let line = format!(
            "0x0888,0x0000,{},{}",
            format_float(user, FloatStyle::default()),
            format_float(real, FloatStyle::default())
        );
        assert_eq!(check("MOTOR:VMAX", &line), Ok(()), "{line}");
    }
}

#[test]
fn without_a_tolerance_in_the_data_pairs_are_not_compared() {
    let text = crate::dialect::smd4::protocol::spec::BUILTIN_TOML
        .replace("relative_tolerance = 0.01\n", "")
        .replace("absolute_tolerance = 0.5\n", "");
    let spec = Smd4Spec::from_toml(&text).unwrap();
    let expect = Expectation::for_command(spec.commands.get("MOTOR:VMAX").unwrap());
    let reply = parse_reply("0x0888,0x0000,1.0000E+03,9.0000E+02", &expect).unwrap();
    assert_eq!(check_reply(&reply, &expect, None), Ok(()));
}
