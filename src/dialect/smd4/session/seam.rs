//! The SMD4 session as the faces see every session's wire ([`DialectSession`]): replies decoded
//! with the command table, stops, the commissioning device, scan and scripts.

use std::sync::Arc;
use std::time::Duration;

use crate::commission::ParamDevice;
use crate::dialect::Dialect;
use crate::dialect::session::{BusScan, DialectSession, Reply, run_script};
use crate::dialect::smd4::protocol::Request;
use crate::dialect::smd4::{config, render, scan};
use crate::exit::Failure;
use crate::script::Script;
use crate::session::SessionError;
use crate::session::core::SessionCore;
use crate::session::transcript::Header;

use super::{DriveName, Smd4Session};

impl DialectSession for Smd4Session {
    fn dialect(&self) -> &'static Dialect {
        &crate::dialect::smd4::DIALECT
    }

    fn wrong_dialect(&mut self) -> Option<crate::exit::Failure> {
        self.sniff_other_dialect()
    }

    fn core(&self) -> &SessionCore {
        &self.core
    }

    fn core_mut(&mut self) -> &mut SessionCore {
        &mut self.core
    }

    fn execute(&mut self, line: &str) -> Result<Reply, SessionError> {
        let exchange = self.exchange_line(line)?;
        Ok(Reply {
            shown: exchange.raw(),
            decoded: render::decode(&exchange, self.spec).text,
            refusal: exchange.refusal(),
            forms: Arc::new(exchange),
        })
    }

    /// MOTOR:STOP to every drive this session set moving.
    fn stop_motion(&mut self) -> Vec<String> {
        self.urgently(Self::stop_drives)
    }

    /// Each drive this session set moving whose standby flag (motor stationary) is clear.
    fn turning_at_exit(&mut self) -> Vec<String> {
        let drives: Vec<Option<u32>> = self.core.moved.iter().copied().collect();
        let mut warnings = Vec::new();
        // A broadcast (@0) gets no reply to read the flags from.
        for address in drives.into_iter().filter(|a| *a != Some(0)) {
            let name = DriveName(address);
            let mut flags = Request::new("SYS:FLAGS");
            flags.address = address;
            match self.request(flags).and_then(|x| x.checked()) {
                Ok(x) if x.reply.as_ref().is_none_or(|r| r.sflags.standby()) => {}
                Ok(_) => warnings.push(format!(
                    "the motor of {name} is still turning (no standby flag): leaving the shell \
                     does not stop it; MOTOR:STOP does"
                )),
                Err(e) => warnings.push(format!(
                    "could not check whether the motor of {name} still turns: {e}"
                )),
            }
        }
        warnings
    }

    fn target_address(&self) -> Option<u32> {
        self.smd4.address
    }

    /// Nothing to restore on an SMD4.
    fn close(&mut self) -> Vec<String> {
        self.core.wire.note("session closed");
        Vec::new()
    }

    fn header(&self) -> Header {
        config::header()
    }

    fn param_device(&mut self) -> &mut dyn ParamDevice {
        self
    }

    fn scan_bus(&mut self, addresses: &[u8], per_reply: Duration) -> Result<BusScan, SessionError> {
        scan::bus_scan(self, addresses, per_reply)
    }

    fn run_script(
        self: Box<Self>,
        script: &Script,
    ) -> (Box<dyn DialectSession>, Result<(), Failure>) {
        run_script(*self, script, |engine, s, _| {
            crate::dialect::smd4::script::register(engine, s)
        })
    }
}

/// An SMD4 session dropped during a panic stops its drives (see [`crate::dialect::guard`]).
impl Drop for Smd4Session {
    fn drop(&mut self) {
        crate::dialect::guard::on_panic(self, |session| session.close());
    }
}
