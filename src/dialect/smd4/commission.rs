//! The SMD4 session as a [`ParamDevice`]: every readable command with a value reply is a
//! parameter, named by its mnemonic. Settings are read by sending the mnemonic alone and written
//! with the value as its argument; profile settings answer a user/real pair (the user value is the
//! setting, the real one is kept as a note); SYS:MODE answers `1 (Remote)`; SYS:FLAGS answers
//! with nothing but its flag words, which are its value. STORE saves the drive's whole working
//! configuration at once.
//!
//! Which values are settings, live values or link settings, the restore order, whether a restore
//! needs standby and the precision of real values are data: the `[snapshot]` section and the
//! `persistent` and `levels` fields of `data/smd4.toml`.

use crate::commission::Access;
use crate::dialect::session::DialectSession;
use crate::dialect::smd4::protocol::validate::validate;
use crate::dialect::smd4::protocol::{
    ItemType, Kind, ReplyShape, Request, Smd4Command, Smd4Reply, Smd4Spec,
};
use crate::dialect::smd4::protocol::{Value, items::DataItem};
use crate::dialect::smd4::session::{DriveName, Smd4Exchange, Smd4Session};
use crate::session::SessionError;

use crate::commission::actions::failed;
use crate::commission::device::{ParamDevice, ParamError, ParamRef, Scope, StoreStep};
use crate::commission::value::{ParamValue, Reading, Tolerance};

impl ParamDevice for Smd4Session {
    /// From the table: an enumerated value's label, the flags of SYS:FLAGS.
    fn explain(&self, param: &ParamRef, value: &ParamValue) -> Option<String> {
        let spec = self.spec();
        crate::dialect::smd4::values::explain(spec, spec.commands.get(&param.name)?, value)
    }

    fn module_name(&self) -> String {
        "SMD4".into()
    }

    fn address(&self) -> Option<u32> {
        Smd4Session::address(self)
    }

    fn who(&self) -> String {
        DriveName(Smd4Session::address(self)).to_string()
    }

    fn memory(&self) -> &'static str {
        "non-volatile memory"
    }

    fn firmware(&mut self) -> Option<String> {
        let param = self.find("SYS:FW").ok()?;
        match self.read(&param).ok()?.value {
            ParamValue::Text(text) if !text.trim().is_empty() => Some(text.trim().to_string()),
            _ => None,
        }
    }

    fn params(&self) -> Vec<ParamRef> {
        spec_params(self.spec())
    }

    fn find(&self, name: &str) -> Result<ParamRef, ParamError> {
        let spec = self.spec();
        let command = find_command(spec, name)?;
        if !is_param(command) {
            return Err(ParamError::Unknown(format!(
                "{} has no value to read ({}); :params lists the settings",
                command.mnemonic,
                why_not(command)
            )));
        }
        Ok(param_ref(spec, command))
    }

    fn read(&mut self, param: &ParamRef) -> Result<Reading, SessionError> {
        let command = self.command(param)?;
        let response = self.reply(Request::new(&command.mnemonic))?;
        reading(command, &response).ok_or_else(|| {
            SessionError::Link(format!(
                "no value in the reply '{}' to {}",
                response.raw, command.mnemonic
            ))
        })
    }

    fn write(&mut self, param: &ParamRef, value: &ParamValue) -> Result<(), SessionError> {
        let command = self.command(param)?;
        self.request(Request::new(&command.mnemonic).arg(argument(value)))?
            .checked()?;
        Ok(())
    }

    fn check_write(&self, param: &ParamRef, value: &ParamValue) -> Result<(), ParamError> {
        if !self.options().validate {
            return Ok(()); // --no-validate: the drive judges.
        }
        let request = Request::new(&param.name).arg(argument(value));
        validate(&request, &self.spec().commands)
            .map(|_| ())
            .map_err(|e| ParamError::Value(e.to_string()))
    }

    fn write_line(&self, param: &ParamRef, value: &ParamValue) -> String {
        self.format(&Request::new(&param.name).arg(argument(value)))
    }

    fn store_steps(&self, params: &[&ParamRef]) -> Vec<StoreStep> {
        if params.is_empty() {
            return Vec::new();
        }
        vec![StoreStep {
            line: self.format(&Request::new(store_mnemonic(self.spec()))),
            params: params.iter().map(|&p| p.clone()).collect(),
            whole: true,
        }]
    }

    fn store(&mut self, _step: &StoreStep) -> Result<(), SessionError> {
        let store = Request::new(store_mnemonic(self.spec()));
        self.request(store)?.checked()?;
        Ok(())
    }

    fn ready_to_restore(&mut self) -> Result<(), SessionError> {
        if !self.spec().snapshot.needs_standby {
            return Ok(());
        }
        let flags = self.reply(Request::new("SYS:FLAGS"))?;
        if flags.sflags.standby() {
            return Ok(());
        }
        Err(failed(format!(
            "{} is moving (no standby flag): a restore needs the motor standing still — \
             MOTOR:RES, SYS:MODE and SYS:JSMODE are refused while it moves, and changing \
             MOTOR:AMAX or MOTOR:DMAX interrupts a stop. Stop it (MOTOR:STOP) and try again",
            ParamDevice::who(self)
        )))
    }
}

impl Smd4Session {
    /// The command behind `param`.
    fn command(&self, param: &ParamRef) -> Result<&'static Smd4Command, SessionError> {
        let spec: &'static Smd4Spec = self.spec();
        spec.commands
            .get(&param.name)
            .ok_or_else(|| SessionError::Usage(format!("the SMD4 has no command {}", param.name)))
    }

    /// Sends `request` and returns its reply, or why there is none.
    fn reply(&mut self, request: Request) -> Result<Smd4Reply, SessionError> {
        let exchange = self.request(request)?.checked()?;
        let Smd4Exchange { reply, sent, .. } = exchange;
        reply.ok_or_else(|| {
            SessionError::Usage(format!(
                "'{sent}' gets no reply (broadcast @0): choose one drive with --address N or :target N"
            ))
        })
    }
}

/// Every parameter of the SMD4 table, in the document's order.
pub fn spec_params(spec: &Smd4Spec) -> Vec<ParamRef> {
    spec.commands
        .iter()
        .filter(|c| is_param(c))
        .map(|c| param_ref(spec, c))
        .collect()
}

/// Whether a command reads a value: readable, with one value, a user/real pair, a named number
/// or (SYS:FLAGS) the flag words alone. Multi-line listings are text for people, not values.
fn is_param(command: &Smd4Command) -> bool {
    command.readable
        && matches!(
            command.reply,
            ReplyShape::Value | ReplyShape::UserReal | ReplyShape::Named | ReplyShape::Literal(_)
        )
}

fn why_not(command: &Smd4Command) -> &'static str {
    match (command.kind, &command.reply) {
        (_, ReplyShape::MultiLine) => "a multi-line listing for people",
        (Kind::Motion, _) => "it starts a move",
        (Kind::Action, _) => "it is an action",
        _ => "it cannot be read",
    }
}

fn param_ref(spec: &Smd4Spec, command: &Smd4Command) -> ParamRef {
    let rules = &spec.snapshot.rules;
    let writable = command.writable && command.kind == Kind::Setting && command.arg.is_some();
    let mut role = rules.role_of(&command.mnemonic, writable);
    if writable && !command.persistent {
        role = crate::commission::SnapshotRole::Live;
    }
    ParamRef {
        scope: Scope::Drive,
        name: command.mnemonic.clone(),
        number: None,
        unit: command.unit.clone(),
        access: Access {
            read: true,
            write: writable,
            store: command.persistent,
        },
        role,
        rank: rules.rank(&command.mnemonic),
        tolerance: tolerance(spec, command),
    }
}

/// Currents round to `max / levels`; other real values compare to the digits replies carry.
fn tolerance(spec: &Smd4Spec, command: &Smd4Command) -> Tolerance {
    let arg = command.arg.as_ref();
    if let (Some(levels), Some(max)) = (arg.and_then(|a| a.levels), arg.and_then(|a| a.max)) {
        if levels > 0 {
            return Tolerance::Step(max / f64::from(levels));
        }
    }
    match (&command.reply, command.value_item_type()) {
        (ReplyShape::UserReal, _) | (_, Some(ItemType::Float)) => {
            Tolerance::Digits(spec.snapshot.float_digits)
        }
        _ => Tolerance::Exact,
    }
}

/// The command a user means: its mnemonic in any case (or an alias), or the unique command whose
/// last segment it is (`VACT` for MOTOR:VACT, as the document itself abbreviates).
fn find_command<'a>(spec: &'a Smd4Spec, name: &str) -> Result<&'a Smd4Command, ParamError> {
    let wanted = name.trim();
    if let Some(command) = spec.commands.get(wanted) {
        return Ok(command);
    }
    let leaf = |c: &&Smd4Command| {
        c.mnemonic
            .rsplit(':')
            .next()
            .is_some_and(|l| l.eq_ignore_ascii_case(wanted))
    };
    let matches: Vec<&Smd4Command> = spec.commands.iter().filter(leaf).collect();
    match matches.as_slice() {
        [one] => Ok(one),
        [] => {
            let hint = spec
                .commands
                .suggest(wanted)
                .map(|m| format!("; did you mean {m}?"))
                .unwrap_or_default();
            Err(ParamError::Unknown(format!(
                "unknown setting '{wanted}' (:params lists them){hint}"
            )))
        }
        several => {
            let names: Vec<&str> = several.iter().map(|c| c.mnemonic.as_str()).collect();
            Err(ParamError::Unknown(format!(
                "'{wanted}' could be {}",
                names.join(" or ")
            )))
        }
    }
}

/// The value of a reply to `command`.
fn reading(command: &Smd4Command, response: &Smd4Reply) -> Option<Reading> {
    match &command.reply {
        ReplyShape::UserReal => {
            let (user, real) = response.user_real()?;
            Some(Reading {
                value: ParamValue::Float(user),
                real: Some(real),
                label: None,
            })
        }
        ReplyShape::Literal(_) => Some(Reading::of(ParamValue::Text(format!(
            "0x{:04X} 0x{:04X}",
            response.sflags.0, response.eflags.0
        )))),
        _ => {
            let item = response.data.first()?;
            if let Value::Named { number, name } = &item.value {
                return Some(Reading {
                    value: ParamValue::Int(*number),
                    real: None,
                    label: Some(name.clone()),
                });
            }
            let value = item_value(item);
            let label = match &value {
                ParamValue::Int(i) => command.label_of(&i.to_string()).map(String::from),
                _ => None,
            };
            Some(Reading {
                value,
                real: None,
                label: label.filter(|l| !l.is_empty()),
            })
        }
    }
}

/// A data item as a value: numbers as numbers, everything else as the text received.
fn item_value(item: &DataItem) -> ParamValue {
    match &item.value {
        Value::Int(i) => ParamValue::Int(*i),
        Value::Uint(u) => i64::try_from(*u).map_or(ParamValue::Float(*u as f64), ParamValue::Int),
        Value::Bool(b) => ParamValue::Int(i64::from(*b)),
        Value::Float(f) => ParamValue::Float(*f),
        Value::Named { number, .. } => ParamValue::Int(*number),
        _ => ParamValue::Text(item.raw.clone()),
    }
}

/// The argument that writes `value`: integers and text as they are, real numbers in the shortest
/// form that reads back the same (`1.0103`, `150`).
fn argument(value: &ParamValue) -> String {
    value.to_string()
}

/// The store command as the table names it (STORE; the document's prefix is uncertain).
fn store_mnemonic(spec: &Smd4Spec) -> String {
    spec.commands
        .get("STORE")
        .map_or_else(|| "STORE".to_string(), |c| c.mnemonic.clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::commission::SnapshotRole;
    use crate::dialect::smd4::protocol::{Expectation, parse_reply};

    fn spec() -> &'static Smd4Spec {
        Smd4Spec::builtin()
    }

    fn param(name: &str) -> ParamRef {
        spec_params(spec())
            .into_iter()
            .find(|p| p.name == name)
            .unwrap_or_else(|| panic!("{name} is a parameter"))
    }

    fn read(name: &str, line: &str) -> Reading {
        let command = spec().commands.get(name).unwrap();
        let response = parse_reply(line, &Expectation::for_command(command)).unwrap();
        reading(command, &response).unwrap()
    }

    #[test]
    fn settings_queries_and_live_values_take_their_roles_from_the_data() {
        assert_eq!(param("MOTOR:IR").role, SnapshotRole::Setting);
        assert_eq!(param("MOTOR:VACT").role, SnapshotRole::ReadOnly);
        assert_eq!(param("MOTOR:PACT").role, SnapshotRole::Live);
        assert_eq!(param("SYS:IDENT").role, SnapshotRole::Live);
        assert_eq!(param("COMS:SERIAL:BAUD").role, SnapshotRole::Manual);
        assert_eq!(param("SYS:FW").role, SnapshotRole::ReadOnly);
        assert!(param("MOTOR:VMAX").access.store);
        assert!(!param("MOTOR:PACT").access.store);
        let names: Vec<String> = spec_params(spec()).into_iter().map(|p| p.name).collect();
        for absent in [
            "SYS:FLAGSV",
            "COMS:NET:IPCONF",
            "MOTOR:RUNV",
            "LIMIT:POL",
            "STORE",
        ] {
            assert!(!names.iter().any(|n| n == absent), "{absent}");
        }
    }

    #[test]
    fn the_restore_order_follows_the_data() {
        let rank = |n: &str| param(n).rank;
        assert!(rank("MOTOR:RES") < rank("MOTOR:IR"));
        assert!(rank("MOTOR:IR") < rank("MOTOR:IA"));
        assert!(rank("MOTOR:VSTART") < rank("MOTOR:VSTOP"));
        assert!(rank("MOTOR:VSTOP") < rank("MOTOR:VMAX"));
        assert!(rank("MOTOR:DMAX") < rank("LIMIT:EN"));
        assert!(rank("LIMIT:EN") < rank("SYS:MODE"));
    }

    #[test]
    fn currents_compare_by_level_and_other_reals_by_digits() {
        let step = 1.044 / 31.0;
        assert_eq!(param("MOTOR:IR").tolerance, Tolerance::Step(step));
        assert_eq!(param("MOTOR:VMAX").tolerance, Tolerance::Digits(5));
        assert_eq!(param("MOTOR:TZW").tolerance, Tolerance::Digits(5));
        assert_eq!(param("MOTOR:RES").tolerance, Tolerance::Exact);
        assert_eq!(param("COMS:NET:IP").tolerance, Tolerance::Exact);
    }

    #[test]
    fn replies_become_values_with_labels_and_real_values() {
        let amax = read("MOTOR:AMAX", "0x0000,0x0000,1.5000E+02,1.4988E+02");
        assert_eq!(amax.value, ParamValue::Float(150.0));
        assert_eq!(amax.real, Some(149.88));
        let mode = read("SYS:MODE", "0x0000,0x0000,1 (Remote)");
        assert_eq!(
            (mode.value, mode.label.as_deref()),
            (1.into(), Some("Remote"))
        );
        let f = read("MOTOR:F", "0x0000,0x0000,2");
        assert_eq!(f.text(), "2 (Phases shorted to GND)");
        let ir = read("MOTOR:IR", "0x0000,0x0000,1.0103E+00");
        assert_eq!(ir.value, ParamValue::Float(1.0103));
        let pact = read("MOTOR:PACT", "0x0000,0x0000,1000.00");
        assert_eq!(pact.value, ParamValue::Float(1000.0));
        let ip = read("COMS:NET:IP", "0x0000,0x0000,10.0.97.70");
        assert_eq!(ip.value, ParamValue::Text("10.0.97.70".into()));
        let fw = read("SYS:FW", "0x088e,0x0000,24044.12");
        assert_eq!(fw.value, ParamValue::Text("24044.12".into()));
        let flags = read("SYS:FLAGS", "0x088e,0x0000,1");
        assert_eq!(flags.value, ParamValue::Text("0x088E 0x0000".into()));
        let res = read("MOTOR:RES", "0x0000,0x0000,256");
        assert_eq!((res.value, res.label), (256.into(), None));
    }

    #[test]
    fn names_are_mnemonics_in_any_case_or_their_unique_last_segment() {
        let spec = spec();
        assert_eq!(
            find_command(spec, "motor:vact").unwrap().mnemonic,
            "MOTOR:VACT"
        );
        assert_eq!(find_command(spec, "VACT").unwrap().mnemonic, "MOTOR:VACT");
        let ambiguous = find_command(spec, "T").unwrap_err().to_string();
        assert!(
            ambiguous.contains("MOTOR:T") && ambiguous.contains("BAKE:T"),
            "{ambiguous}"
        );
        let unknown = find_command(spec, "MOTOR:VMAXX").unwrap_err().to_string();
        assert!(unknown.contains("did you mean MOTOR:VMAX"), "{unknown}");
    }

    #[test]
    fn arguments_are_the_shortest_form_that_reads_back_the_same() {
        assert_eq!(argument(&ParamValue::Float(150.0)), "150");
        assert_eq!(argument(&ParamValue::Float(1.0103)), "1.0103");
        assert_eq!(argument(&ParamValue::Int(-5)), "-5");
        assert_eq!(argument(&ParamValue::Text("10.0.0.2".into())), "10.0.0.2");
    }
}
