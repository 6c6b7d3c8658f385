//! An open echo session: every line goes out as typed (checked first unless `--no-validate`)
//! and the line that comes back is the reply; nothing moves, so there is nothing to stop or
//! restore. The loopback has no parameters for the commissioning tools.

use std::sync::Arc;
use std::time::Duration;

use tmclsh::commission::{ParamDevice, ParamError, ParamRef, ParamValue, Reading, StoreStep};
use tmclsh::dialect::session::{BusScan, Refusal, ReplyForms, run_script};
use tmclsh::dialect::{Dialect, DialectSession, Opening, Reply, elsewhere};
use tmclsh::exit::Failure;
use tmclsh::script::Script;
use tmclsh::session::SessionError;
use tmclsh::session::core::SessionCore;
use tmclsh::session::transcript::Header;

use super::protocol::{self, UNKNOWN};
use super::{DIALECT, MODULE};

/// What the commissioning helpers hear from the loopback.
pub const NO_PARAMS: &str = "the echo loopback has no parameters";

/// A conversation with the loopback.
pub struct EchoSession {
    core: SessionCore,
}

impl EchoSession {
    /// A session over the opening's link; nothing is sent until a line is.
    pub fn open(opening: Opening<'_>) -> EchoSession {
        let core = SessionCore::new(opening.link, opening.options, opening.transcript);
        EchoSession { core }
    }
}

/// The reply's forms for `--value` and `--json`: the text that came back.
#[derive(Debug)]
struct Echoed(String);

impl ReplyForms for Echoed {
    fn value(&self) -> String {
        self.0.clone()
    }

    fn json_fields(&self) -> Vec<(&'static str, serde_json::Value)> {
        vec![("reply", self.0.clone().into())]
    }
}

impl DialectSession for EchoSession {
    fn dialect(&self) -> &'static Dialect {
        &DIALECT
    }

    fn core(&self) -> &SessionCore {
        &self.core
    }

    fn core_mut(&mut self) -> &mut SessionCore {
        &mut self.core
    }

    /// A line another dialect knows is refused naming its `--protocol`.
    fn execute(&mut self, line: &str) -> Result<Reply, SessionError> {
        let line = line.trim();
        if self.core.options.validate {
            protocol::parse(line)
                .map_err(|why| elsewhere::explain(&DIALECT, line, SessionError::Refused(why)))?;
        }
        let answer = self.core.exchange_line(line, MODULE)?;
        let refusal = (answer == UNKNOWN).then(|| Refusal {
            module: MODULE.to_string(),
            sent: line.to_string(),
            reason: "unknown command".to_string(),
        });
        Ok(Reply {
            shown: answer.clone(),
            decoded: answer.clone(),
            refusal,
            forms: Arc::new(Echoed(answer)),
        })
    }

    fn stop_motion(&mut self) -> Vec<String> {
        Vec::new()
    }

    fn target_address(&self) -> Option<u32> {
        None
    }

    fn close(&mut self) -> Vec<String> {
        self.core.note("session closed");
        Vec::new()
    }

    fn header(&self) -> Header {
        super::config::header()
    }

    fn param_device(&mut self) -> &mut dyn ParamDevice {
        self
    }

    fn scan_bus(&mut self, _: &[u8], _: Duration) -> Result<BusScan, SessionError> {
        Err(SessionError::Refused(
            "the echo loopback is alone on its link: there is no bus to scan".to_string(),
        ))
    }

    fn run_script(
        self: Box<Self>,
        script: &Script,
    ) -> (Box<dyn DialectSession>, Result<(), Failure>) {
        run_script(*self, script, |engine, s, _| {
            super::script::register(engine, s)
        })
    }
}

/// Every commissioning request is refused: the loopback has no parameters.
impl ParamDevice for EchoSession {
    fn module_name(&self) -> String {
        MODULE.to_string()
    }

    fn address(&self) -> Option<u32> {
        None
    }

    fn who(&self) -> String {
        format!("the {MODULE}")
    }

    fn memory(&self) -> &'static str {
        "no memory"
    }

    fn firmware(&mut self) -> Option<String> {
        None
    }

    fn params(&self) -> Vec<ParamRef> {
        Vec::new()
    }

    fn find(&self, _: &str) -> Result<ParamRef, ParamError> {
        Err(ParamError::Unknown(NO_PARAMS.to_string()))
    }

    fn read(&mut self, _: &ParamRef) -> Result<Reading, SessionError> {
        Err(SessionError::Refused(NO_PARAMS.to_string()))
    }

    fn write(&mut self, _: &ParamRef, _: &ParamValue) -> Result<(), SessionError> {
        Err(SessionError::Refused(NO_PARAMS.to_string()))
    }

    fn check_write(&self, _: &ParamRef, _: &ParamValue) -> Result<(), ParamError> {
        Err(ParamError::Value(NO_PARAMS.to_string()))
    }

    fn write_line(&self, _: &ParamRef, _: &ParamValue) -> String {
        String::new()
    }

    fn store_steps(&self, _: &[&ParamRef]) -> Vec<StoreStep> {
        Vec::new()
    }

    fn store(&mut self, _: &StoreStep) -> Result<(), SessionError> {
        Err(SessionError::Refused(NO_PARAMS.to_string()))
    }
}
