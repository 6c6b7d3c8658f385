//! The SMD4 session: validated requests `[@addr]MNEMONIC[,arg…]` CR LF, replies collected line by
//! line — including the multi-line ones, which end only when the line has been quiet for the gap
//! (`--quiet-gap`) because the document defines no end marker — replies from other drives and
//! line noise reported, not taken, and MOTOR:STOP for drives the session set moving when a run
//! is aborted. SMD4 drives have no echo and no separate ASCII mode, so there is nothing to enter
//! or restore.
//!
//! With no echo, nothing in a reply says which request it answers: after any failed exchange the
//! wire resynchronises before the next request (see `session/wire.rs`), and a barrier the drive
//! refuses goes out first, everything before its refusal discarded (see `barrier.rs`), so no late
//! reply is taken for an answer. Replies of an addressed
//! drive carry its `@N,` prefix, so a failure at one address does not hold up the others — unless
//! the drives turn out to answer without the prefix.

mod barrier;
mod faces;
mod receive;
mod seam;
mod sniff;

use std::time::Duration;

use crate::dialect::session::{DialectSession, Refusal};
use crate::dialect::smd4::protocol::{
    PrefixStyle, Request, Smd4Reply, Smd4Spec, commands, validate,
};
use crate::link::Link;
use crate::session::core::SessionCore;
use crate::session::transcript::Transcript;
use crate::session::wire::{Peer, nothing_benign};
use crate::session::{SessionError, SessionOptions};

/// SMD4-specific settings.
#[derive(Debug, Clone, Copy)]
pub struct Smd4SessionOptions {
    /// `@N` prefix for requests without one (`--address`); `None` sends no prefix.
    pub address: Option<u32>,
    /// Whether a comma follows the prefix (`--prefix-comma`).
    pub prefix: PrefixStyle,
    /// How long the line must be quiet to end a multi-line reply (`--quiet-gap`).
    pub quiet_gap: Duration,
}

impl Default for Smd4SessionOptions {
    fn default() -> Self {
        Smd4SessionOptions {
            address: None,
            prefix: PrefixStyle::Attached,
            quiet_gap: crate::dialect::smd4::protocol::default_quiet_gap(),
        }
    }
}

/// One request and its reply.
#[derive(Debug, Clone, PartialEq)]
pub struct Smd4Exchange {
    /// The line sent (without CR LF).
    pub sent: String,
    /// What was sent.
    pub request: Request,
    /// The reply; `None` for broadcasts and commands the drive does not answer.
    pub reply: Option<Smd4Reply>,
}

impl Smd4Exchange {
    /// Whether no error code came back.
    pub fn ok(&self) -> bool {
        self.reply.as_ref().is_none_or(Smd4Reply::is_ok)
    }

    /// The reply as received: the first line, then any following lines, without line endings.
    pub fn raw(&self) -> String {
        match &self.reply {
            None => String::new(),
            Some(r) if r.lines.is_empty() => r.raw.clone(),
            Some(r) => format!("{}\n{}", r.raw, r.lines.join("\n")),
        }
    }

    /// The exchange, or a device error when the reply carries an error code.
    pub fn checked(self) -> Result<Smd4Exchange, SessionError> {
        match self.refusal() {
            Some(refusal) => Err(refusal.into()),
            None => Ok(self),
        }
    }

    /// The error code the drive answered with, if any.
    pub fn refusal(&self) -> Option<Refusal> {
        let error = self.reply.as_ref()?.error.as_ref()?;
        Some(Refusal {
            module: DriveName(self.request.address).to_string(),
            sent: self.sent.clone(),
            reason: format!("error {error}"),
        })
    }
}

/// How every message names a drive: `drive @3`, or `the drive` when requests carry no address
/// prefix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DriveName(pub Option<u32>);

impl std::fmt::Display for DriveName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            Some(address) => write!(f, "drive @{address}"),
            None => f.write_str("the drive"),
        }
    }
}

/// A conversation with the SMD4 drives on one link.
pub struct Smd4Session {
    core: SessionCore,
    spec: &'static Smd4Spec,
    smd4: Smd4SessionOptions,
    /// An addressed drive answered without its `@N,` prefix: replies cannot be told apart.
    unprefixed_replies: bool,
    /// Failed requests whose replies may still come, and barriers given up (`barrier.rs`).
    doubt: barrier::Doubt,
}

impl Smd4Session {
    /// Opens a session (SMD4 drives need no mode change).
    pub fn open(
        link: Box<dyn Link>,
        options: SessionOptions,
        smd4: Smd4SessionOptions,
        transcript: Option<Transcript>,
    ) -> Result<Self, SessionError> {
        let mut session = Smd4Session {
            core: SessionCore::new(link, options, transcript),
            spec: Smd4Spec::builtin(),
            smd4,
            unprefixed_replies: false,
            doubt: barrier::Doubt::default(),
        };
        let opened = format!(
            "SMD4 session opened on {}",
            session.core.wire.link.describe()
        );
        session.core.wire.note(&opened);
        Ok(session)
    }

    /// The command table, flags and errors.
    pub fn spec(&self) -> &'static Smd4Spec {
        self.spec
    }

    /// The `@N` prefix used for requests without one.
    pub fn address(&self) -> Option<u32> {
        self.smd4.address
    }

    /// The line `request` is sent as (the session's address applied), for dry runs.
    pub fn format(&self, request: &Request) -> String {
        let mut request = request.clone();
        if request.address.is_none() {
            request.address = self.smd4.address;
        }
        request.format(self.smd4.prefix)
    }

    /// Changes the prefix used for requests without one.
    pub fn set_address(&mut self, address: Option<u32>) {
        self.smd4.address = address;
    }

    /// Parses, validates and sends one request line (a trailing `//` comment aside); an error
    /// code is an `Ok` exchange whose [`Smd4Exchange::ok`] is false; a refused line of another
    /// dialect says so.
    pub fn exchange_line(&mut self, line: &str) -> Result<Smd4Exchange, SessionError> {
        let typed =
            crate::dialect::smd4::protocol::request::without_comment(&self.spec.commands, line);
        Request::parse(typed)
            .map_err(|e| SessionError::Refused(e.to_string()))
            .and_then(|request| self.request(request))
            .map_err(|e| {
                crate::dialect::elsewhere::explain(&crate::dialect::smd4::DIALECT, line, e)
            })
    }

    /// Validates and sends a request (the session's address applies when it has none). A link
    /// lost on the way is waited for where `--reconnect` asks for it, and a read sent again.
    pub fn request(&mut self, mut request: Request) -> Result<Smd4Exchange, SessionError> {
        if request.address.is_none() {
            request.address = self.smd4.address;
        }
        match self.request_once(request.clone()) {
            Err(SessionError::Lost(why)) => {
                let spec = self.spec.commands.get(&request.mnemonic);
                if spec.is_some_and(|s| s.starts_motion) {
                    // The drive may have got it: stopped on the way out of a failed run.
                    self.core.moved.insert(request.address);
                }
                let read = request.args.is_empty()
                    && spec.is_some_and(|s| {
                        s.readable
                            && matches!(s.kind, commands::Kind::Setting | commands::Kind::Query)
                    });
                let what = request.format(self.smd4.prefix);
                let whom = DriveName(request.address).to_string();
                self.after_cut_short(&what, &whom, read, why)?;
                self.request_once(request)
            }
            other => other,
        }
    }

    fn request_once(&mut self, request: Request) -> Result<Smd4Exchange, SessionError> {
        match validate(&request, &self.spec.commands) {
            Ok(_) => {}
            Err(error) if self.core.options.validate => {
                return Err(SessionError::Refused(error.to_string()));
            }
            Err(error) => self
                .core
                .wire
                .notices
                .push(format!("not validated: {error}")),
        }
        let spec = self.spec.commands.get(&request.mnemonic);
        let sent = request.format(self.smd4.prefix);
        let silent = request.is_broadcast() || spec.is_some_and(|s| s.no_response);
        if !silent {
            self.barrier(request.address)?;
        }
        let result = self.round_trip(&request, silent);
        match &result {
            Ok(_) => self.request_answered(request.address),
            Err(_) if silent => {}
            Err(_) => self.request_failed(request.address),
        }
        let exchange = Smd4Exchange {
            sent,
            request,
            reply: result?,
        };
        if exchange.ok() && spec.is_some_and(|s| s.starts_motion) {
            self.core.moved.insert(exchange.request.address);
        }
        Ok(exchange)
    }

    /// One exchange between the wire's begin and finish: a failure leaves the line suspect.
    fn round_trip(
        &mut self,
        request: &Request,
        silent: bool,
    ) -> Result<Option<Smd4Reply>, SessionError> {
        let peer = match request.address {
            Some(address) if !self.unprefixed_replies => Peer::Module(address),
            _ => Peer::Any,
        };
        let timeout = self.core.options.timeout;
        let result = self
            .core
            .wire
            .begin(peer, self.core.urgent, timeout, &mut nothing_benign)
            .and_then(|()| self.transact(request, silent));
        self.core.wire.finish(result.is_ok());
        result
    }

    /// Sends a request and reads its reply (none for broadcasts and silent commands). Any error
    /// returned from here, whatever finds it, leaves the line suspect until it has settled.
    fn transact(
        &mut self,
        request: &Request,
        silent: bool,
    ) -> Result<Option<Smd4Reply>, SessionError> {
        // A drive has no echo, and no reply begins like its request: the first one tells
        // whether the adapter echoes.
        self.core.wire.probe_echo();
        self.core.wire.send(
            &request.wire(self.smd4.prefix),
            format_args!("to {}", DriveName(request.address)),
        )?;
        if silent {
            return Ok(None);
        }
        let response = self.receive(request)?;
        if request.address.is_some() && response.address.is_none() {
            self.unprefixed_replies = true;
        }
        Ok(Some(response))
    }

    /// Stops every drive this session set moving (MOTOR:STOP). Returns what was done.
    fn stop_drives(&mut self) -> Vec<String> {
        let moved: Vec<Option<u32>> = std::mem::take(&mut self.core.moved).into_iter().collect();
        let wire = self.core.wire.wire_time(64);
        let wait = self
            .core
            .options
            .timeout
            .min(crate::session::STOP_CONFIRMATION + wire);
        let mut report = Vec::new();
        for address in moved {
            let mut stop = Request::new("MOTOR:STOP");
            stop.address = address;
            let name = DriveName(address);
            let result = self.with_timeout(wait, |s| s.request(stop));
            match result.and_then(Smd4Exchange::checked) {
                Ok(_) => report.push(format!("stopped the motor of {name} with MOTOR:STOP")),
                Err(SessionError::Timeout { timeout, .. }) => report.push(format!(
                    "sent MOTOR:STOP to {name}; no answer within {} ms",
                    timeout.as_millis()
                )),
                Err(e) => report.push(format!("could not stop the motor of {name}: {e}")),
            }
        }
        for line in &report {
            self.core.wire.note(line);
        }
        report
    }
}
