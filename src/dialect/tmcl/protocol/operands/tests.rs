use std::convert::Infallible;

use proptest::prelude::*;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::syntax::Arg;

use super::*;

fn num(value: i64) -> Arg {
    Arg::Number { value, hex: false }
}

fn name(text: &str) -> Arg {
    Arg::Name(text.into())
}

fn encode_typed(mnemonic: &str, args: &[Arg]) -> Result<Instruction, Refused<Infallible>> {
    let profile = Profile::builtin();
    let spec = profile.commands.by_mnemonic(mnemonic).unwrap();
    encode(spec, args, &profile)
}

/// Where the table refuses: the index of the operand at fault.
fn refused_at(mnemonic: &str, args: &[Arg]) -> (Option<usize>, InputError) {
    match encode_typed(mnemonic, args) {
        Err(Refused::Table { operand, error }) => (operand, error),
        other => panic!("{mnemonic} {args:?}: {other:?}"),
    }
}

#[test]
fn operands_fill_the_fields_the_table_names() {
    let cases: [(&str, Vec<Arg>, Instruction); 5] = [
        (
            "MVP",
            vec![name("rel"), num(0), num(-5)],
            Instruction::new(4, 1, 0, -5),
        ),
        (
            "SAP",
            vec![name("max_current"), num(0), num(9)],
            Instruction::new(5, 6, 0, 9),
        ),
        (
            "GGP",
            vec![name("user_variable_5")],
            Instruction::new(10, 5, 2, 0),
        ),
        ("ROR", vec![num(0), num(7)], Instruction::new(1, 0, 0, 7)),
        (
            "SCO",
            vec![num(3), num(0), num(-1)],
            Instruction::new(30, 3, 0, -1),
        ),
    ];
    for (mnemonic, args, expected) in cases {
        assert_eq!(encode_typed(mnemonic, &args), Ok(expected), "{mnemonic}");
    }
}

#[test]
fn each_refusal_names_the_operand_at_fault() {
    let (at, error) = refused_at("SAP", &[num(4), num(0), num(1 << 40)]);
    assert_eq!(at, Some(2));
    assert!(matches!(error, InputError::FieldOverflow { .. }), "{error}");
    let (at, error) = refused_at("MVP", &[name("sideways"), num(0), num(1)]);
    assert_eq!(at, Some(0));
    assert!(matches!(error, InputError::BadKeyword { .. }), "{error}");
    let (at, error) = refused_at("GAP", &[name("no_such_param"), num(0)]);
    assert_eq!(at, Some(0));
    assert!(matches!(error, InputError::Param(_)), "{error}");
    let (at, error) = refused_at("ROR", &[name("fast"), num(0)]);
    assert_eq!(at, Some(0));
    assert!(
        matches!(error, InputError::ExpectedNumber { .. }),
        "{error}"
    );
    // The bank given against the parameter's own: the bank operand.
    let (at, error) = refused_at("GGP", &[name("user_variable_5"), num(0)]);
    assert_eq!(at, Some(1));
    assert!(
        matches!(
            error,
            InputError::BankMismatch {
                bank: 2,
                given: 0,
                ..
            }
        ),
        "{error}"
    );
    // Too few or too many: the operands as a whole.
    let (at, error) = refused_at("SAP", &[num(4)]);
    assert_eq!(at, None);
    assert_eq!(
        error.to_string(),
        "SAP takes 3 arguments, got 1; usage: SAP <parameter>, <motor>, <value>"
    );
    let (at, _) = refused_at("GGP", &[num(5)]);
    assert_eq!(at, None, "a bank is implied only by a parameter's name");
}

/// Operands that are constants of a program: numbers come from the text, and its errors pass
/// through as they are.
struct Constant(Result<i64, &'static str>);

impl OperandText for Constant {
    type Error = &'static str;

    fn name(&self) -> Option<&str> {
        Some("ABS")
    }

    fn table_name(&self) -> Option<&str> {
        None
    }

    fn number(&self, _: OperandKind) -> Result<Option<Number>, &'static str> {
        self.0.map(|value| Some(Number { value, hex: false }))
    }
}

#[test]
fn names_the_text_defines_are_its_own_and_so_are_their_errors() {
    let profile = Profile::builtin();
    let ror = profile.commands.by_mnemonic("ROR").unwrap();
    let mvp = profile.commands.by_mnemonic("MVP").unwrap();
    assert_eq!(
        encode(ror, &[Constant(Ok(1)), Constant(Ok(2))], &profile),
        Ok(Instruction::new(1, 0, 1, 2))
    );
    assert_eq!(
        encode(ror, &[Constant(Ok(1)), Constant(Err("broken"))], &profile),
        Err(Refused::Operand("broken"))
    );
    // A keyword is a keyword even where the text defines the name (`ABS` here): its number
    // is never asked for.
    let keyword_first = [Constant(Err("asked")), Constant(Ok(0)), Constant(Ok(5))];
    assert_eq!(
        encode(mvp, &keyword_first, &profile),
        Ok(Instruction::new(4, 0, 0, 5))
    );
}

#[test]
fn fields_take_what_fits_them() {
    assert_eq!(byte("<motor>", 255), Ok(255));
    assert!(byte("<motor>", 256).is_err());
    assert!(byte("<motor>", -1).is_err());
    assert_eq!(word32("<value>", 0xFFFF_FFFF, true), Ok(-1));
    assert!(word32("<value>", 0xFFFF_FFFF, false).is_err());
    assert!(word32("<value>", -0x8000_0001, true).is_err());
    assert_eq!(word32("<value>", i64::from(i32::MIN), false), Ok(i32::MIN));
    assert_eq!(count_text(0), "no arguments");
    assert_eq!(count_text(1), "1 argument");
    assert_eq!(count_text(3), "3 arguments");
}

proptest! {
    /// A number is stored exactly when it fits its field, and then as itself.
    #[test]
    fn store_keeps_every_number_that_fits(value in any::<i64>(), hex in any::<bool>()) {
        let number = Number { value, hex };
        let mut out = Instruction::default();
        let fits_byte = (0..=255).contains(&value);
        prop_assert_eq!(store(&mut out, Field::Type, "<type>", number).is_ok(), fits_byte);
        prop_assert_eq!(store(&mut out, Field::Motor, "<motor>", number).is_ok(), fits_byte);
        let fits_word = i32::try_from(value).is_ok() || (hex && u32::try_from(value).is_ok());
        prop_assert_eq!(store(&mut out, Field::Value, "<value>", number).is_ok(), fits_word);
        if fits_byte {
            prop_assert_eq!((i64::from(out.type_), i64::from(out.motor)), (value, value));
        }
        if fits_word {
            prop_assert_eq!(out.value, value as u32 as i32);
        }
    }
}
