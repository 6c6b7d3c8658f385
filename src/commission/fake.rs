//! An in-memory module for the unit tests of the pure parts: the built-in profile's parameters,
//! values in a map, refusals where a test asks, and a log of every write and store. The real
//! session against the simulator is exercised by the integration tests.

use std::collections::BTreeMap;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::Status;
use crate::session::SessionError;

use super::device::{ParamDevice, ParamError, ParamRef, Scope, StoreStep};
use super::value::{ParamValue, Reading};
use crate::dialect::tmcl::commission::param_ref;

pub(super) struct FakeDevice {
    pub params: Vec<ParamRef>,
    pub values: BTreeMap<(Scope, String), i64>,
    /// Parameters whose reads are refused.
    pub refuse_read: Vec<String>,
    /// Parameters whose writes are refused.
    pub refuse_write: Vec<String>,
    /// Parameters that keep their value whatever is written.
    pub stuck: Vec<String>,
    /// A parameter whose write times out (the link fails there).
    pub time_out_at: Option<String>,
    /// "write NAME VALUE" / "store NAME", in order.
    pub log: Vec<String>,
}

impl FakeDevice {
    /// The built-in profile's parameters, all at their defaults (or 0).
    pub(super) fn new() -> FakeDevice {
        let profile = Profile::builtin();
        let mut params = Vec::new();
        let mut values = BTreeMap::new();
        for p in &profile.axis {
            let r = param_ref(&profile, p, Scope::Axis { motor: 0 });
            values.insert((r.scope, r.name.clone()), p.default.unwrap_or(0));
            params.push(r);
        }
        for p in &profile.global {
            let r = param_ref(&profile, p, Scope::Global { bank: p.bank() });
            values.insert((r.scope, r.name.clone()), p.default.unwrap_or(0));
            params.push(r);
        }
        FakeDevice {
            params,
            values,
            refuse_read: Vec::new(),
            refuse_write: Vec::new(),
            stuck: Vec::new(),
            time_out_at: None,
            log: Vec::new(),
        }
    }

    pub(super) fn param(&self, name: &str) -> ParamRef {
        self.params.iter().find(|p| p.name == name).unwrap().clone()
    }

    pub(super) fn set(&mut self, name: &str, value: i64) {
        let p = self.param(name);
        self.values.insert((p.scope, p.name), value);
    }

    pub(super) fn get(&self, name: &str) -> i64 {
        let p = self.param(name);
        self.values[&(p.scope, p.name)]
    }

    fn refused(name: &str) -> SessionError {
        SessionError::Device {
            module: "module 1 (A)".into(),
            sent: name.to_string(),
            reason: format!("status {}", Status::WrongType),
        }
    }
}

impl ParamDevice for FakeDevice {
    fn module_name(&self) -> String {
        "TMCM-142".into()
    }

    fn address(&self) -> Option<u32> {
        Some(1)
    }

    fn who(&self) -> String {
        "module 1 (A)".into()
    }

    fn memory(&self) -> &'static str {
        "EEPROM"
    }

    fn firmware(&mut self) -> Option<String> {
        Some("142V9.99".into())
    }

    fn params(&self) -> Vec<ParamRef> {
        self.params.clone()
    }

    fn find(&self, name: &str) -> Result<ParamRef, ParamError> {
        self.params
            .iter()
            .find(|p| p.name == name)
            .cloned()
            .ok_or_else(|| ParamError::Unknown(format!("unknown parameter '{name}'")))
    }

    fn read(&mut self, param: &ParamRef) -> Result<Reading, SessionError> {
        if self.refuse_read.contains(&param.name) {
            return Err(Self::refused(&param.name));
        }
        Ok(Reading::of(self.values[&(param.scope, param.name.clone())]))
    }

    fn write(&mut self, param: &ParamRef, value: &ParamValue) -> Result<(), SessionError> {
        if self.refuse_write.contains(&param.name) {
            return Err(Self::refused(&param.name));
        }
        if self.time_out_at.as_ref() == Some(&param.name) {
            return Err(SessionError::Timeout {
                module: "module 1 (A)".into(),
                timeout: std::time::Duration::from_millis(1000),
                hint: String::new(),
            });
        }
        let value = value.as_i64().expect("the fake holds integers");
        self.log.push(format!("write {} {value}", param.name));
        if !self.stuck.contains(&param.name) {
            self.values.insert((param.scope, param.name.clone()), value);
        }
        Ok(())
    }

    fn check_write(&self, param: &ParamRef, value: &ParamValue) -> Result<(), ParamError> {
        crate::dialect::tmcl::commission::check_write(&Profile::builtin(), param, value)
    }

    fn write_line(&self, param: &ParamRef, value: &ParamValue) -> String {
        format!("SET {} {value}", param.name)
    }

    fn store_steps(&self, params: &[&ParamRef]) -> Vec<StoreStep> {
        params
            .iter()
            .map(|p| StoreStep {
                line: format!("STORE {}", p.name),
                params: vec![(*p).clone()],
                whole: false,
            })
            .collect()
    }

    fn store(&mut self, step: &StoreStep) -> Result<(), SessionError> {
        for param in &step.params {
            self.log.push(format!("store {}", param.name));
        }
        Ok(())
    }
}
