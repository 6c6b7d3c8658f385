//! Each switch of Smd4SimOptions changes exactly what it says, and the client parser reads every
//! variant.

use super::Bench;
use crate::dialect::smd4::protocol::{ErrorSpelling, FlagCase, FloatStyle, PrefixStyle};
use crate::dialect::smd4::sim::{Limit, PositionFormat, PrefixAcceptance, Smd4SimOptions};

fn with(change: impl FnOnce(&mut Smd4SimOptions)) -> Bench {
    let mut options = Smd4SimOptions::default();
    change(&mut options);
    Bench::with(options)
}

#[test]
fn flag_hex_case() {
    let setup = |b: &mut Bench| {
        b.send("SYS:IDENT,1");
        b.sim.set_limit_input(b.now, Limit::Positive, true);
    };
    let mut upper = Bench::new();
    setup(&mut upper);
    assert_eq!(upper.send("SYS:FW"), "0x089C,0x0000,24044.12");
    let mut lower = with(|o| o.flag_case = FlagCase::Lower);
    setup(&mut lower);
    assert_eq!(lower.send("SYS:FW"), "0x089c,0x0000,24044.12");
    assert_eq!(lower.reply("SYS:FW").sflags.0, 0x089C);
}

#[test]
fn float_digits_and_the_missing_e() {
    assert_eq!(
        Bench::new().send("MOTOR:VMAX"),
        "0x0888,0x0000,1.0000E+03,1.0000E+03"
    );
    let mut five = with(|o| {
        o.float_style = FloatStyle {
            decimals: 5,
            missing_e: false,
        }
    });
    assert_eq!(
        five.send("MOTOR:VMAX"),
        "0x0888,0x0000,1.00000E+03,1.00000E+03"
    );
    assert_eq!(five.reply("MOTOR:VMAX").user_real(), Some((1000.0, 1000.0)));
    let mut no_e = with(|o| {
        o.float_style = FloatStyle {
            decimals: 4,
            missing_e: true,
        }
    });
    assert_eq!(
        no_e.send("MOTOR:VSTOP,10"),
        "0x0888,0x0000,1.0000+01,1.0000+01"
    );
    assert_eq!(no_e.reply("MOTOR:VSTOP").user_real(), Some((10.0, 10.0)));
}

#[test]
fn error_spellings() {
    for (spelling, text) in [
        (
            ErrorSpelling::Parenthesised,
            "0x0888,0x0000,-103 (Invalid Mnemonic)",
        ),
        (ErrorSpelling::Comma, "0x0888,0x0000,-103,Invalid Mnemonic"),
        (ErrorSpelling::Bare, "0x0888,0x0000,-103"),
    ] {
        let mut b = with(|o| o.error_spelling = spelling);
        assert_eq!(b.send("NOPE"), text);
        assert_eq!(b.error("NOPE"), -103);
        assert_eq!(b.error("MOTOR:RUNV"), -3);
    }
}

#[test]
fn current_rounding_switch() {
    assert_eq!(Bench::new().send("MOTOR:IR,1"), "0x0888,0x0000,1.0103E+00");
    // Off, the drive echoes like the document's examples.
    let mut off = with(|o| o.current_rounding = false);
    assert_eq!(off.send("MOTOR:IR,1"), "0x0888,0x0000,1.0000E+00");
    assert_eq!(off.send("MOTOR:IH,0.5"), "0x0888,0x0000,5.0000E-01");
}

#[test]
fn address_prefix_forms() {
    let mut attached = with(|o| o.prefix = PrefixAcceptance::Only(PrefixStyle::Attached));
    assert!(attached.send("@1,SYS:FW").ends_with(",-104 (Packet error)"));
    assert!(
        !attached.sim.addressing_mode(),
        "a malformed packet does not switch"
    );
    assert_eq!(attached.send("@1SYS:FW"), "@1,0x0888,0x0000,24044.12");
    assert_eq!(
        attached.send("@1,SYS:FW"),
        "",
        "malformed in addressing mode: ignored"
    );
    let mut comma = with(|o| o.prefix = PrefixAcceptance::Only(PrefixStyle::Comma));
    assert!(comma.send("@1SYS:FW").ends_with(",-104 (Packet error)"));
    assert_eq!(comma.send("@1,SYS:FW"), "@1,0x0888,0x0000,24044.12");
    let mut bare = with(|o| o.reply_prefix = false);
    assert_eq!(bare.send("@1SYS:FW"), "0x0888,0x0000,24044.12");
}

#[test]
fn position_format_tzw_unit_and_real_values() {
    let mut sci = with(|o| o.position_format = PositionFormat::Scientific);
    assert_eq!(sci.send("MOTOR:PACT,-1000"), "0x0888,0x0000,-1.0000E+03");
    assert_eq!(
        Bench::new().send("MOTOR:PACT,-1000"),
        "0x0888,0x0000,-1000.00"
    );
    assert_eq!(
        Bench::new().send("MOTOR:TZW,0.1"),
        "0x0888,0x0000,1.0000E-01"
    );
    let mut ms = with(|o| o.tzw_reply_ms = true);
    assert_eq!(
        ms.send("MOTOR:TZW,0.1"),
        "0x0888,0x0000,1.0000E+02",
        "as the example"
    );
    // A frequency grid of 12 MHz / 2^24 / 256 reproduces the VSTOP example's real value.
    let mut grid = with(|o| o.real_value_grid = Some(12e6 / 16_777_216.0 / 256.0));
    assert_eq!(
        grid.send("MOTOR:VSTOP,10"),
        "0x0888,0x0000,1.0000E+01,9.9996E+00"
    );
}
