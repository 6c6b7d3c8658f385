//! Each validation error, with the message the user sees.

use crate::dialect::smd4::protocol::{
    Action, ArgValue, Request, Smd4Spec, ValidationError, validate,
};
use crate::exit::{Exit, ExitStatus};

fn check(line: &str) -> Result<Action, ValidationError> {
    let request = Request::parse(line).unwrap();
    validate(&request, &Smd4Spec::builtin().commands).map(|c| c.action)
}

fn message(line: &str) -> String {
    let error = check(line).unwrap_err();
    assert_eq!(error.exit(), Exit::Refused, "{line}");
    error.to_string()
}

#[test]
fn valid_requests_say_what_they_do() {
    assert_eq!(check("MOTOR:VMAX"), Ok(Action::Read));
    assert_eq!(
        check("motor:vmax,1000"),
        Ok(Action::Write(ArgValue::Float(1000.0)))
    );
    assert_eq!(check("SYS:CLR"), Ok(Action::Run));
    assert_eq!(
        check("MOTOR:RUNV,-"),
        Ok(Action::Write(ArgValue::Text("-".into())))
    );
    assert_eq!(
        check("MOTOR:RES,0x80"),
        Ok(Action::Write(ArgValue::Int(128)))
    );
    assert_eq!(check("@247MOTOR:STOP"), Ok(Action::Run));
    assert_eq!(check("@0SYS:CLR"), Ok(Action::Run));
    assert_eq!(
        check("MOTOR:IR,100e-3"),
        Ok(Action::Write(ArgValue::Float(0.1)))
    );
    assert_eq!(check("SYS:STORE"), Ok(Action::Run));
    assert!(check("COMS:SERIAL:BAUD,115200").is_ok());
}

#[test]
fn unknown_mnemonic_with_nearest_suggestion() {
    assert_eq!(
        message("MOTOR:VMX,10"),
        "unknown mnemonic 'MOTOR:VMX'; did you mean MOTOR:VMAX?"
    );
    assert_eq!(
        message("TZW"),
        "unknown mnemonic 'TZW'; did you mean MOTOR:TZW?"
    );
    assert_eq!(message("QQQQQ"), "unknown mnemonic 'QQQQQ'");
}

#[test]
fn read_of_a_write_only_command() {
    assert_eq!(
        message("MOTOR:RUNV"),
        "MOTOR:RUNV cannot be read (the drive answers -3): it needs an argument; usage: MOTOR:RUNV,<+|->"
    );
    assert_eq!(
        message("LIMIT:POL"),
        "LIMIT:POL cannot be read (the drive answers -3): it needs an argument; usage: LIMIT:POL,<0|1>"
    );
}

#[test]
fn write_of_a_read_only_command() {
    assert_eq!(
        message("MOTOR:T,30"),
        "MOTOR:T is read-only; send MOTOR:T without arguments to read it"
    );
    assert_eq!(
        message("SYS:FW,1"),
        "SYS:FW is read-only; send SYS:FW without arguments to read it"
    );
}

#[test]
fn argument_count() {
    assert_eq!(
        message("SYS:CLR,1"),
        "SYS:CLR takes no arguments, got 1; usage: SYS:CLR"
    );
    assert_eq!(
        message("MOTOR:VMAX,1,2"),
        "MOTOR:VMAX takes one argument, got 2; usage: MOTOR:VMAX[,<FLOAT Hz>]"
    );
}

#[test]
fn argument_type() {
    assert_eq!(
        message("MOTOR:VMAX,fast"),
        "'fast' is not a valid argument of MOTOR:VMAX: expected FLOAT, a number such as 10.23, 100e-3 or 10; usage: MOTOR:VMAX[,<FLOAT Hz>]"
    );
    assert_eq!(
        message("MOTOR:RUNA,1.5"),
        "'1.5' is not a valid argument of MOTOR:RUNA: expected INT, an integer such as 100, -10 or +7; usage: MOTOR:RUNA,<INT steps>"
    );
    assert!(message("SYS:IDENT,yes").contains("expected BOOL, 0 or 1"));
    assert!(message("COMS:NET:IP,10.0.0").contains("expected DOTTED DECIMAL"));
    assert!(message("MOTOR:IR,").starts_with("the argument of MOTOR:IR is empty"));
}

#[test]
fn range() {
    assert_eq!(
        message("MOTOR:VMAX,20000"),
        "20000 is out of range for MOTOR:VMAX: allowed 1..15000 Hz"
    );
    assert_eq!(
        message("MOTOR:IR,1.1"),
        "1.1 is out of range for MOTOR:IR: allowed 0..1.044 A rms"
    );
    assert_eq!(
        message("MOTOR:RUNA,8388608"),
        "8388608 is out of range for MOTOR:RUNA: allowed -8388608..8388607 steps"
    );
    assert!(check("MOTOR:RUNA,-8388608").is_ok());
    assert_eq!(
        message("COMS:SERIAL:SLAVEADDR,0"),
        "0 is out of range for COMS:SERIAL:SLAVEADDR: allowed 1..247"
    );
}

#[test]
fn allowed_values() {
    assert_eq!(
        message("MOTOR:RES,100"),
        "100 is not accepted by MOTOR:RES: use one of 8, 16, 32, 64, 128, 256"
    );
    assert_eq!(
        message("MOTOR:RES,4"),
        "4 is not accepted by MOTOR:RES: use one of 8, 16, 32, 64, 128, 256"
    );
    assert_eq!(
        message("MOTOR:RUNV,x"),
        "x is not accepted by MOTOR:RUNV: use one of +, -"
    );
    assert_eq!(
        message("SYS:MODE,5"),
        "5 is not accepted by SYS:MODE: use one of 0, 1, 2, 3, 4"
    );
    assert!(message("COMS:SERIAL:BAUD,1234").contains("4800, 9600"));
}

#[test]
fn address() {
    assert_eq!(
        message("@248SYS:FW"),
        "address 248 is out of range: use 0 to broadcast (no reply) or 1..247 for one drive"
    );
}
