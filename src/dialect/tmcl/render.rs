//! TMCL replies decoded for people: status meaning, value, parameter name and unit.

use crate::dialect::session::Decoded;
use crate::dialect::tmcl::ports;
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
                (true, Some(p), _) => match p.decoding.explain(value.into()) {
                    Some(meaning) => format!("{} = {value} ({meaning})", p.ident),
                    None => format!("{} = {value}{}", p.ident, unit(&p.unit)),
                },
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
                (_, _, Opcode::Gio) => ports::reading(profile, i.motor, i.type_, value)
                    .unwrap_or_else(|| format!("port {} of bank {} = {value}", i.type_, i.motor)),
                (_, _, Opcode::Sio) => match profile.io_port(i.motor, i.type_) {
                    Some(port) => format!("{} set to {}", port.name, i.value),
                    None => "ok".into(),
                },
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
    fn what_the_profile_knows_of_a_value_is_decoded() {
        let p = Profile::builtin();
        let read = |command: u8, param: u8, value: i32| {
            decode(
                &exchange(Instruction::new(command, param, 0, 0), Status::Ok, value),
                &p,
            )
            .text
        };
        assert_eq!(read(10, 65, 0), "serial_baud_rate = 0 (9600 baud)");
        assert_eq!(read(10, 65, 7), "serial_baud_rate = 7 (115200 baud)");
        assert_eq!(read(10, 65, 9), "serial_baud_rate = 9");
        assert_eq!(
            read(6, 129, 5),
            "status_flags = 5 (position reached, standing)"
        );
        assert_eq!(read(6, 129, 0), "status_flags = 0 (no bit set)");
        assert_eq!(
            read(10, 67, 0x11),
            "ascii_mode = 17 (start-up: ASCII; echo: line after CR)"
        );
        assert_eq!(
            read(10, 67, 0x20),
            "ascii_mode = 32 (start-up: binary; echo: none)"
        );
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
        // I/O ports under the names of the profile's port map, by number without one.
        assert_eq!(
            decode(&exchange(Instruction::new(15, 7, 0, 0), Status::Ok, 1), &p).text,
            "IN7 = 1"
        );
        assert_eq!(
            decode(
                &exchange(Instruction::new(15, 2, 1, 0), Status::Ok, 512),
                &p
            )
            .text,
            "IN2_A/D = 512"
        );
        assert_eq!(
            decode(&exchange(Instruction::new(14, 1, 2, 1), Status::Ok, 1), &p).text,
            "OUT_1 set to 1"
        );
        let generic = crate::dialect::tmcl::profile::catalogue::generic();
        assert_eq!(
            decode(
                &exchange(Instruction::new(15, 7, 0, 0), Status::Ok, 1),
                &generic
            )
            .text,
            "port 7 of bank 0 = 1"
        );
        assert_eq!(
            decode(
                &exchange(Instruction::new(14, 7, 2, 1), Status::Ok, 1),
                &generic
            )
            .text,
            "ok"
        );
        let version = TmclExchange {
            reply: TmclReply::Version("142V1.06".into()),
            ..exchange(Instruction::new(136, 0, 0, 0), Status::Ok, 0)
        };
        assert_eq!(decode(&version, &p).text, "firmware version 142V1.06");
    }
}
