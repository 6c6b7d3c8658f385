//! TMCL replies decoded for people: status meaning, value, parameter name and unit.

use crate::dialect::session::Decoded;
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::{Field, OperandKind, ParamUse};
use crate::dialect::tmcl::protocol::Opcode;
use crate::dialect::tmcl::protocol::line::Op;
use crate::dialect::tmcl::session::{TmclExchange, TmclReply};

/// Decodes an exchange using the profile's names and units.
pub fn decode(exchange: &TmclExchange, profile: &Profile) -> Decoded {
    let (status, value) = match &exchange.reply {
        TmclReply::Nothing => {
            return Decoded {
                text: "sent (the module sends no reply)".into(),
                ok: true,
            };
        }
        TmclReply::Version(text) => {
            return Decoded {
                text: format!("firmware version {text}"),
                ok: true,
            };
        }
        TmclReply::Status { status, value } => (*status, *value),
    };
    if !status.is_success() {
        return Decoded {
            text: format!("error {}: {}", status.code(), status.meaning()),
            ok: false,
        };
    }
    let text = match exchange.op {
        Some(Op::Command(i)) => {
            let spec = profile.commands.by_number(i.command);
            let reads = spec.is_some_and(|s| s.param_use == Some(ParamUse::Read));
            let kind = spec
                .and_then(|s| s.operand_for(Field::Type))
                .map(|o| o.kind);
            let param = match kind {
                Some(OperandKind::AxisParam) => profile.axis_param(i.type_),
                Some(OperandKind::GlobalParam) => profile.global_param(i.motor, i.type_),
                _ => None,
            };
            match (reads, param, i.command) {
                (true, Some(p), _) => format!("{} = {value}{}", p.ident, unit(&p.unit)),
                (true, None, _) => format!("parameter {} = {value}", i.type_),
                (_, _, Opcode::Rfs) if i.type_ == 2 => {
                    if value == 0 {
                        "reference search done (not running)".into()
                    } else {
                        format!("reference search running ({value})")
                    }
                }
                (_, _, Opcode::ApplicationStatus) => {
                    format!("application {}", application_status(value))
                }
                (_, _, Opcode::Gio) => format!("input {} of bank {} = {value}", i.type_, i.motor),
                (_, _, Opcode::Gco) => format!("coordinate {} = {value}", i.type_),
                _ if value != 0 => format!("ok, value {value}"),
                _ => "ok".into(),
            }
        }
        _ if value != 0 => format!("ok, value {value}"),
        _ => "ok".into(),
    };
    Decoded { text, ok: true }
}

/// A short unit after the value; long explanations (such as AP6's) are left to `:params`.
fn unit(unit: &str) -> String {
    if unit.is_empty() || unit.len() > 16 {
        String::new()
    } else {
        format!(" {unit}")
    }
}

/// The meaning of an application status (command 135, global parameter 128).
pub fn application_status(value: i32) -> &'static str {
    match value {
        0 => "stopped",
        1 => "running",
        2 => "stepping",
        3 => "reset",
        _ => "in an unknown state",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::tmcl::protocol::{Instruction, Status};

    fn exchange(i: Instruction, status: Status, value: i32) -> TmclExchange {
        TmclExchange {
            module: 1,
            sent: String::new(),
            op: Some(Op::Command(i)),
            reply: TmclReply::Status { status, value },
            raw: String::new(),
        }
    }

    #[test]
    fn reads_show_the_parameter_name_and_unit() {
        let p = Profile::builtin();
        let d = decode(
            &exchange(Instruction::new(6, 1, 0, 0), Status::Ok, -5000),
            &p,
        );
        assert_eq!(
            d,
            Decoded {
                text: "actual_position = -5000 usteps".into(),
                ok: true
            }
        );
        let d = decode(&exchange(Instruction::new(10, 76, 0, 0), Status::Ok, 2), &p);
        assert_eq!(d.text, "serial_host_address = 2");
        let d = decode(&exchange(Instruction::new(6, 200, 0, 0), Status::Ok, 7), &p);
        assert_eq!(d.text, "parameter 200 = 7");
    }

    #[test]
    fn errors_show_the_status_meaning() {
        let d = decode(
            &exchange(Instruction::new(5, 6, 0, 99), Status::InvalidValue, 0),
            &Profile::builtin(),
        );
        assert_eq!(
            d,
            Decoded {
                text: "error 4: invalid value".into(),
                ok: false
            }
        );
    }

    #[test]
    fn other_commands() {
        let p = Profile::builtin();
        assert_eq!(
            decode(&exchange(Instruction::new(5, 6, 0, 9), Status::Ok, 0), &p).text,
            "ok"
        );
        assert_eq!(
            decode(&exchange(Instruction::new(13, 2, 0, 0), Status::Ok, 1), &p).text,
            "reference search running (1)"
        );
        assert_eq!(
            decode(&exchange(Instruction::new(135, 0, 0, 0), Status::Ok, 1), &p).text,
            "application running"
        );
        let version = TmclExchange {
            reply: TmclReply::Version("142V1.06".into()),
            ..exchange(Instruction::new(136, 0, 0, 0), Status::Ok, 0)
        };
        assert_eq!(decode(&version, &p).text, "firmware version 142V1.06");
    }
}
