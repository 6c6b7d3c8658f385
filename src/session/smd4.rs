//! The SMD4 session: validated requests `[@addr]MNEMONIC[,arg…]` CR LF, replies collected line by
//! line — including the multi-line ones, which end only when the line has been quiet for the gap
//! (`--quiet-gap`) because the document defines no end marker — replies from other drives and
//! line noise reported, not taken, and MOTOR:STOP for drives the session set moving when a run
//! is aborted. SMD4 drives have no echo and no separate ASCII mode, so there is nothing to enter
//! or restore.

use std::collections::BTreeSet;
use std::time::{Duration, Instant};

use crate::link::Link;
use crate::protocol::smd4::{
    Expectation, PrefixStyle, Progress, ReplyCollector, Request, Response, Smd4Spec, check_reply,
    is_reply_to, validate,
};

use super::transcript::{Entry, Transcript, escape_into};
use super::wire::Wire;
use super::{SessionError, SessionOptions};

/// SMD4-specific settings.
#[derive(Debug, Clone, Copy)]
pub struct Smd4Options {
    /// `@N` prefix for requests without one (`--address`); `None` sends no prefix.
    pub address: Option<u32>,
    /// Whether a comma follows the prefix (`--prefix-comma`).
    pub prefix: PrefixStyle,
    /// How long the line must be quiet to end a multi-line reply (`--quiet-gap`).
    pub quiet_gap: Duration,
}

impl Default for Smd4Options {
    fn default() -> Self {
        Smd4Options {
            address: None,
            prefix: PrefixStyle::Attached,
            quiet_gap: crate::protocol::smd4::default_quiet_gap(),
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
    pub response: Option<Response>,
}

impl Smd4Exchange {
    /// Whether no error code came back.
    pub fn ok(&self) -> bool {
        self.response.as_ref().is_none_or(Response::is_ok)
    }

    /// The reply as received: the first line, then any following lines, without line endings.
    pub fn raw(&self) -> String {
        match &self.response {
            None => String::new(),
            Some(r) if r.lines.is_empty() => r.raw.clone(),
            Some(r) => format!("{}\n{}", r.raw, r.lines.join("\n")),
        }
    }

    /// The exchange, or a device error when the reply carries an error code.
    pub fn checked(self) -> Result<Smd4Exchange, SessionError> {
        match self.response.as_ref().and_then(|r| r.error.clone()) {
            Some(error) => Err(SessionError::Device {
                module: drive_name(self.request.address),
                sent: self.sent,
                reason: format!("error {error}"),
            }),
            None => Ok(self),
        }
    }
}

/// How messages name a drive: `@3`, or `SMD4` when requests carry no prefix.
pub fn drive_name(address: Option<u32>) -> String {
    address.map_or_else(|| "SMD4".to_string(), |a| format!("@{a}"))
}

/// A conversation with the SMD4 drives on one link.
pub struct Smd4Session {
    wire: Wire,
    spec: &'static Smd4Spec,
    options: SessionOptions,
    smd4: Smd4Options,
    moved: BTreeSet<Option<u32>>,
}

impl Smd4Session {
    /// Opens a session (SMD4 drives need no mode change).
    pub fn open(
        link: Box<dyn Link>,
        options: SessionOptions,
        smd4: Smd4Options,
        transcript: Option<Transcript>,
    ) -> Result<Self, SessionError> {
        let mut session = Smd4Session {
            wire: Wire::new(link, transcript),
            spec: Smd4Spec::builtin(),
            options,
            smd4,
            moved: BTreeSet::new(),
        };
        let opened = format!("SMD4 session opened on {}", session.wire.link.describe());
        session.wire.note(&opened);
        Ok(session)
    }

    /// The command table, flags and errors.
    pub fn spec(&self) -> &'static Smd4Spec {
        self.spec
    }

    /// What the link talks to.
    pub fn describe(&self) -> String {
        self.wire.link.describe()
    }

    /// The session's settings.
    pub fn options(&self) -> &SessionOptions {
        &self.options
    }

    /// Runs `f` with replies awaited at most `timeout` (a bus scan's time per address).
    pub fn with_timeout<T>(&mut self, timeout: Duration, f: impl FnOnce(&mut Self) -> T) -> T {
        let saved = std::mem::replace(&mut self.options.timeout, timeout);
        let result = f(self);
        self.options.timeout = saved;
        result
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

    /// Messages gathered since the last call.
    pub fn take_notices(&mut self) -> Vec<String> {
        std::mem::take(&mut self.wire.notices)
    }

    /// Starts or stops writing the transcript.
    pub fn set_transcript(&mut self, transcript: Option<Transcript>) {
        self.wire.transcript = transcript;
    }

    /// The transcript being written, if any.
    pub fn transcript(&self) -> Option<&Transcript> {
        self.wire.transcript.as_ref()
    }

    /// Writes a remark into the transcript; false when no transcript is being written.
    pub fn annotate(&mut self, text: &str) -> bool {
        self.wire.note(text);
        self.wire.transcript.is_some()
    }

    /// Parses, validates and sends one request line; an error code is an `Ok` exchange whose
    /// [`Smd4Exchange::ok`] is false.
    pub fn execute(&mut self, line: &str) -> Result<Smd4Exchange, SessionError> {
        let request = Request::parse(line).map_err(|e| SessionError::Rejected(e.to_string()))?;
        self.request(request)
    }

    /// Validates and sends a request (the session's address applies when it has none).
    pub fn request(&mut self, mut request: Request) -> Result<Smd4Exchange, SessionError> {
        if request.address.is_none() {
            request.address = self.smd4.address;
        }
        match validate(&request, &self.spec.commands) {
            Ok(_) => {}
            Err(error) if self.options.validate => {
                return Err(SessionError::Rejected(error.to_string()));
            }
            Err(error) => self.wire.notices.push(format!("not validated: {error}")),
        }
        let spec = self.spec.commands.get(&request.mnemonic);
        let sent = request.format(self.smd4.prefix);
        self.wire.drain()?;
        self.wire.send(
            &request.wire(self.smd4.prefix),
            format_args!("to {}", drive_name(request.address)),
        )?;
        let silent = request.is_broadcast() || spec.is_some_and(|s| s.no_response);
        let response = if silent {
            None
        } else {
            Some(self.receive(&request)?)
        };
        let exchange = Smd4Exchange {
            sent,
            request,
            response,
        };
        if exchange.ok() && spec.is_some_and(|s| s.starts_motion) {
            self.moved.insert(exchange.request.address);
        }
        Ok(exchange)
    }

    /// Reads the reply to `request`: whole lines, fed to a collector; a multi-line reply ends
    /// when nothing arrived for the quiet gap.
    fn receive(&mut self, request: &Request) -> Result<Response, SessionError> {
        let expect = Expectation::for_request(&self.spec.commands, request);
        let mut collector = ReplyCollector::new(expect.clone());
        let deadline = Instant::now() + self.options.timeout;
        let mut consumed = Vec::new();
        loop {
            while let Some(line) = self.next_line(&mut consumed) {
                match collector.push_line(&line) {
                    Ok(Progress::Complete(reply)) if foreign(&reply, request) => {
                        self.wire.notices.push(format!(
                            "ignored a reply from drive {} while waiting for {}: {line}",
                            drive_name(reply.address),
                            drive_name(request.address)
                        ));
                        collector = ReplyCollector::new(expect.clone());
                    }
                    Ok(Progress::Complete(reply)) => {
                        return self.finish(*reply, &consumed, &expect, request);
                    }
                    Ok(Progress::AwaitQuiet) => {}
                    Err(_) => {
                        let mut shown = String::new();
                        escape_into(line.as_bytes(), &mut shown);
                        self.wire
                            .notices
                            .push(format!("ignored unexpected data from the line: {shown}"));
                    }
                }
            }
            if collector.awaiting_quiet() {
                if !self.wire.fill(Instant::now() + self.smd4.quiet_gap)? {
                    let reply = collector
                        .finish_quiet()
                        .expect("awaiting quiet means a first line came");
                    return self.finish(reply, &consumed, &expect, request);
                }
            } else if !self.wire.fill(deadline)? {
                let partial = self.wire.rx.clear();
                consumed.extend_from_slice(&partial);
                if !consumed.is_empty() {
                    self.wire
                        .log(Entry::Received, &consumed, "no complete reply");
                }
                let module = drive_name(request.address);
                self.wire.note(&format!("no reply from {module}"));
                return Err(SessionError::Timeout {
                    module,
                    timeout: self.options.timeout,
                    hint: timeout_hint(&partial, request.address, self.smd4.prefix),
                });
            }
        }
    }

    /// The next complete line (CR LF, LF or CR terminated) from the receive buffer.
    fn next_line(&mut self, consumed: &mut Vec<u8>) -> Option<String> {
        loop {
            let bytes = self.wire.rx.bytes();
            let end = bytes.iter().position(|&b| b == b'\n' || b == b'\r')?;
            let mut used = end + 1;
            if bytes[end] == b'\r' && bytes.get(end + 1) == Some(&b'\n') {
                used += 1;
            }
            let taken = self.wire.rx.take(used);
            consumed.extend_from_slice(&taken);
            let line = String::from_utf8_lossy(&taken[..end]).into_owned();
            if !line.is_empty() {
                return Some(line);
            }
        }
    }

    /// A complete reply, checked against what the command declares: one that fails is line
    /// noise, never a value.
    fn finish(
        &mut self,
        reply: Response,
        consumed: &[u8],
        expect: &Expectation,
        request: &Request,
    ) -> Result<Response, SessionError> {
        if let Err(noise) = check_reply(&reply, expect, request.address) {
            self.wire.log(
                Entry::Received,
                consumed,
                format_args!("line noise: {noise}"),
            );
            let mut shown = String::new();
            escape_into(reply.raw.as_bytes(), &mut shown);
            return Err(SessionError::Link(format!(
                "line noise: {noise}, in the reply {shown} to {}",
                request.format(self.smd4.prefix)
            )));
        }
        let meaning = match &reply.error {
            Some(error) => format!("error {error}"),
            None => format!("sflags {:#06x}", reply.sflags.0),
        };
        self.wire.log(Entry::Received, consumed, &meaning);
        Ok(reply)
    }

    /// Stops every drive this session set moving (MOTOR:STOP). Returns what was done.
    pub fn stop_motion(&mut self) -> Vec<String> {
        let moved: Vec<Option<u32>> = std::mem::take(&mut self.moved).into_iter().collect();
        let mut report = Vec::new();
        for address in moved {
            let mut stop = Request::new("MOTOR:STOP");
            stop.address = address;
            let name = drive_name(address);
            match self.request(stop).and_then(Smd4Exchange::checked) {
                Ok(_) => report.push(format!("stopped the motor of drive {name} (MOTOR:STOP)")),
                Err(e) => report.push(format!("could not stop the motor of drive {name}: {e}")),
            }
        }
        for line in &report {
            self.wire.note(line);
        }
        report
    }

    /// Whether this session started motion that may still be going.
    pub fn may_be_moving(&self) -> bool {
        !self.moved.is_empty()
    }

    /// Ends the session (nothing to restore on an SMD4).
    pub fn close(&mut self) -> Vec<String> {
        self.wire.note("session closed");
        Vec::new()
    }

    /// Reopens a lost link.
    pub fn reconnect(&mut self) -> Result<(), SessionError> {
        self.wire.link.reopen()?;
        self.wire.rx.clear();
        let reopened = format!("link reopened: {}", self.wire.link.describe());
        self.wire.note(&reopened);
        Ok(())
    }
}

/// A reply carrying another drive's address prefix (any prefix when the request had none).
fn foreign(reply: &Response, request: &Request) -> bool {
    !is_reply_to(reply.address, request.address)
}

/// What may be wrong when nothing came back. A drive in addressing mode ignores packets silently,
/// so the likely causes differ with and without a prefix.
fn timeout_hint(partial: &[u8], address: Option<u32>, prefix: PrefixStyle) -> String {
    if !partial.is_empty() {
        let mut shown = String::new();
        escape_into(partial, &mut shown);
        return format!(" (received only {shown})");
    }
    match address {
        None => " (check the port and the baud rate; a drive that has seen an @N packet since it \
                 powered up is in addressing mode and silently ignores packets without a prefix: \
                 use --address N)"
            .to_string(),
        Some(a) => {
            let other = match prefix {
                PrefixStyle::Attached => "with --prefix-comma",
                PrefixStyle::Comma => "without --prefix-comma",
            };
            format!(
                " (check the port, the baud rate and that the drive's COMS:SERIAL:SLAVEADDR is \
                 {a}; a drive that does not understand this prefix form ignores the packet: try \
                 {other})"
            )
        }
    }
}
