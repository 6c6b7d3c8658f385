//! The SMD4 session: validated requests `[@addr]MNEMONIC[,arg…]` CR LF, replies collected line by
//! line — including the multi-line ones, which end only when the line has been quiet for the gap
//! (`--quiet-gap`) because the document defines no end marker — replies from other drives and
//! line noise reported, not taken, and MOTOR:STOP for drives the session set moving when a run
//! is aborted. SMD4 drives have no echo and no separate ASCII mode, so there is nothing to enter
//! or restore.
//!
//! With no echo, nothing in a reply says which request it answers: after any failed exchange the
//! wire resynchronises before the next request (see `session/wire.rs`). Replies of an addressed
//! drive carry its `@N,` prefix, so a failure at one address does not hold up the others — unless
//! the drives turn out to answer without the prefix.

use std::time::{Duration, Instant};

use crate::dialect::smd4::protocol::{
    Expectation, PrefixStyle, Progress, ReplyCollector, Request, Response, Smd4Spec, check_reply,
    is_reply_to, validate,
};
use crate::link::Link;

use crate::dialect::session::{DialectSession, Refusal, Reply};
use crate::session::core::SessionCore;
use crate::session::rx::is_line_break;
use crate::session::transcript::{Entry, Transcript, escape_into};
use crate::session::wire::{MAX_LINE, Peer, Settled, nothing_benign};
use crate::session::{SessionError, SessionOptions};

/// The most a reply may hold, all its lines together.
const MAX_REPLY: usize = 64 * 1024;

/// What is discarded most often.
const UNEXPECTED: &str = "unexpected data from the line";

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
        match self.refusal() {
            Some(refusal) => Err(refusal.into()),
            None => Ok(self),
        }
    }

    /// The error code the drive answered with, if any.
    pub fn refusal(&self) -> Option<Refusal> {
        let error = self.response.as_ref()?.error.as_ref()?;
        Some(Refusal {
            module: drive_name(self.request.address),
            sent: self.sent.clone(),
            reason: format!("error {error}"),
        })
    }
}

/// How messages name a drive: `@3`, or `SMD4` when requests carry no prefix.
pub fn drive_name(address: Option<u32>) -> String {
    address.map_or_else(|| "SMD4".to_string(), |a| format!("@{a}"))
}

/// A conversation with the SMD4 drives on one link.
pub struct Smd4Session {
    core: SessionCore,
    spec: &'static Smd4Spec,
    smd4: Smd4Options,
    /// An addressed drive answered without its `@N,` prefix: replies cannot be told apart.
    unprefixed_replies: bool,
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
            core: SessionCore::new(link, options, transcript),
            spec: Smd4Spec::builtin(),
            smd4,
            unprefixed_replies: false,
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

    /// Parses, validates and sends one request line; an error code is an `Ok` exchange whose
    /// [`Smd4Exchange::ok`] is false.
    pub fn exchange_line(&mut self, line: &str) -> Result<Smd4Exchange, SessionError> {
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
            Err(error) if self.core.options.validate => {
                return Err(SessionError::Rejected(error.to_string()));
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
        let peer = match request.address {
            Some(address) if !self.unprefixed_replies => Peer::Module(address),
            _ => Peer::Any,
        };
        let timeout = self.core.options.timeout;
        let result = self
            .core
            .wire
            .begin(peer, self.core.urgent, timeout, &mut nothing_benign)
            .and_then(|()| self.transact(&request, silent));
        self.core.wire.finish(result.is_ok());
        let exchange = Smd4Exchange {
            sent,
            request,
            response: result?,
        };
        if exchange.ok() && spec.is_some_and(|s| s.starts_motion) {
            self.core.moved.insert(exchange.request.address);
        }
        Ok(exchange)
    }

    /// Sends a request and reads its reply (none for broadcasts and silent commands). Any error
    /// returned from here, whatever finds it, leaves the line suspect until it has settled.
    fn transact(
        &mut self,
        request: &Request,
        silent: bool,
    ) -> Result<Option<Response>, SessionError> {
        self.core.wire.send(
            &request.wire(self.smd4.prefix),
            format_args!("to {}", drive_name(request.address)),
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

    /// Reads the reply to `request`: whole lines, fed to a collector; a multi-line reply ends
    /// when nothing arrived for the quiet gap, a single-line one once the bytes after it were
    /// seen. Lines are consumed as they are judged, so a flood costs neither time beyond the
    /// deadline nor memory.
    fn receive(&mut self, request: &Request) -> Result<Response, SessionError> {
        let expect = Expectation::for_request(&self.spec.commands, request);
        let mut collector = ReplyCollector::new(expect.clone());
        let deadline = Instant::now() + self.core.options.timeout;
        // A multi-line reply's last line may come up to the deadline; its quiet gap after that.
        let multi_line_end = deadline + self.smd4.quiet_gap;
        // This reply's bytes, for the transcript.
        let mut reply_bytes = Vec::new();
        let mut in_junk = false;
        loop {
            loop {
                if in_junk {
                    match self.core.wire.rx.line_end(0) {
                        Some(end) => {
                            self.core.wire.discard_more(end);
                            in_junk = false;
                        }
                        None => {
                            let n = self.core.wire.rx.len();
                            self.core.wire.discard_more(n);
                            break;
                        }
                    }
                }
                let bytes = self.core.wire.rx.bytes();
                let breaks = bytes.iter().take_while(|&&b| is_line_break(b)).count();
                if breaks > 0 {
                    reply_bytes.extend(self.core.wire.rx.take(breaks));
                    continue;
                }
                let Some(end) = self.core.wire.rx.line_end(0) else {
                    if self.core.wire.rx.len() > MAX_LINE {
                        let n = self.core.wire.rx.len();
                        self.core.wire.discard(n, UNEXPECTED);
                        in_junk = true;
                    }
                    break;
                };
                let used = end + 1;
                if end > MAX_LINE {
                    self.core.wire.discard(used, UNEXPECTED);
                    continue;
                }
                let line = String::from_utf8_lossy(&self.core.wire.rx.bytes()[..end]).into_owned();
                match collector.push_line(&line) {
                    Ok(Progress::Complete(reply)) if foreign(&reply, request) => {
                        let kind = format!(
                            "a reply from drive {} while waiting for {}",
                            drive_name(reply.address),
                            drive_name(request.address)
                        );
                        self.core.wire.discard(used, &kind);
                        collector = ReplyCollector::new(expect.clone());
                    }
                    Ok(Progress::Complete(reply)) => {
                        return self.settle(*reply, reply_bytes, used, deadline, &expect, request);
                    }
                    Ok(Progress::AwaitQuiet) => {
                        reply_bytes.extend(self.core.wire.rx.take(used));
                        if reply_bytes.len() > MAX_REPLY {
                            return Err(self.endless(
                                request,
                                reply_bytes,
                                "is longer than 64 KiB",
                            ));
                        }
                    }
                    Err(_) => self.core.wire.discard(used, UNEXPECTED),
                }
            }
            let now = Instant::now();
            if collector.awaiting_quiet() {
                if now >= multi_line_end {
                    return Err(self.endless(request, reply_bytes, "did not end in time"));
                }
                let gap_end = now + self.smd4.quiet_gap;
                if !self.core.wire.fill(gap_end.min(multi_line_end))? {
                    if gap_end > multi_line_end {
                        return Err(self.endless(request, reply_bytes, "did not end in time"));
                    }
                    let reply = collector
                        .finish_quiet()
                        .expect("awaiting quiet means a first line came");
                    return self.finish(reply, &reply_bytes, &expect, request);
                }
            } else if now >= deadline || !self.core.wire.fill(deadline)? {
                let partial = self.core.wire.rx.clear();
                reply_bytes.extend_from_slice(&partial);
                if !reply_bytes.is_empty() {
                    self.core
                        .wire
                        .log(Entry::Received, &reply_bytes, "no complete reply");
                }
                let module = drive_name(request.address);
                self.core.wire.note(&format!("no reply from {module}"));
                return Err(SessionError::Timeout {
                    module,
                    timeout: self.core.options.timeout,
                    hint: timeout_hint(&partial, request.address, self.smd4.prefix),
                });
            }
        }
    }

    /// Takes a single-line reply whose line takes the first `used` buffered bytes, once what
    /// follows it has been seen: nothing but line ends.
    fn settle(
        &mut self,
        reply: Response,
        mut reply_bytes: Vec<u8>,
        used: usize,
        deadline: Instant,
        expect: &Expectation,
        request: &Request,
    ) -> Result<Response, SessionError> {
        match self.core.wire.settle(used, deadline, &mut |_| false)? {
            Settled::Clean(n) => {
                reply_bytes.extend(self.core.wire.rx.take(n));
                self.finish(reply, &reply_bytes, expect, request)
            }
            Settled::Noise => {
                let mut after = String::new();
                let rest = &self.core.wire.rx.bytes()[used..];
                escape_into(&rest[..rest.len().min(40)], &mut after);
                reply_bytes.extend(self.core.wire.rx.clear());
                self.core.wire.log(
                    Entry::Received,
                    &reply_bytes,
                    "a reply followed by more data: line noise, discarded",
                );
                let mut shown = String::new();
                escape_into(reply.raw.as_bytes(), &mut shown);
                let message = format!(
                    "line noise: the reply {shown} was followed by {after}, so it may be cut short \
                     or not the answer; not taken"
                );
                self.core.wire.note(&message);
                Err(SessionError::Link(message))
            }
        }
    }

    /// A multi-line reply that does not end: line noise.
    fn endless(&mut self, request: &Request, mut bytes: Vec<u8>, what: &str) -> SessionError {
        bytes.extend(self.core.wire.rx.clear());
        self.core.wire.log(
            Entry::Received,
            &bytes,
            "a reply that does not end: line noise, discarded",
        );
        let message = format!(
            "line noise: the reply to {} {what} (--timeout {} ms, then --quiet-gap {} ms); not taken",
            request.mnemonic,
            self.core.options.timeout.as_millis(),
            self.smd4.quiet_gap.as_millis()
        );
        self.core.wire.note(&message);
        SessionError::Link(message)
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
            self.core.wire.log(
                Entry::Received,
                consumed,
                format_args!("line noise: {noise}"),
            );
            let mut shown = String::new();
            escape_into(reply.raw.as_bytes(), &mut shown);
            let message = format!(
                "line noise: {noise}, in the reply {shown} to {}",
                request.format(self.smd4.prefix)
            );
            self.core.wire.note(&message);
            return Err(SessionError::Link(message));
        }
        let meaning = match &reply.error {
            Some(error) => format!("error {error}"),
            None => format!("sflags {:#06x}", reply.sflags.0),
        };
        self.core.wire.log(Entry::Received, consumed, &meaning);
        Ok(reply)
    }

    /// Stops every drive this session set moving (MOTOR:STOP). Returns what was done.
    fn stop_drives(&mut self) -> Vec<String> {
        let moved: Vec<Option<u32>> = std::mem::take(&mut self.core.moved).into_iter().collect();
        let wire = self
            .core
            .wire
            .link
            .byte_time()
            .map_or(Duration::ZERO, |b| b * 64);
        let wait = self
            .core
            .options
            .timeout
            .min(crate::session::STOP_CONFIRMATION + wire);
        let mut report = Vec::new();
        for address in moved {
            let mut stop = Request::new("MOTOR:STOP");
            stop.address = address;
            let name = drive_name(address);
            let result = self.with_timeout(wait, |s| s.request(stop));
            match result.and_then(Smd4Exchange::checked) {
                Ok(_) => report.push(format!("stopped the motor of drive {name} (MOTOR:STOP)")),
                Err(SessionError::Timeout { timeout, .. }) => report.push(format!(
                    "sent MOTOR:STOP to drive {name}; no answer within {} ms",
                    timeout.as_millis()
                )),
                Err(e) => report.push(format!("could not stop the motor of drive {name}: {e}")),
            }
        }
        for line in &report {
            self.core.wire.note(line);
        }
        report
    }
}

impl DialectSession for Smd4Session {
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
            decoded: super::render::decode(&exchange, self.spec).text,
            refusal: exchange.refusal(),
        })
    }

    /// MOTOR:STOP to every drive this session set moving.
    fn stop_motion(&mut self) -> Vec<String> {
        self.urgently(Self::stop_drives)
    }

    fn target_address(&self) -> Option<u32> {
        self.smd4.address
    }

    /// Nothing to restore on an SMD4.
    fn close(&mut self) -> Vec<String> {
        self.core.wire.note("session closed");
        Vec::new()
    }

    /// `smd4>`, with the address prefix requests get.
    fn prompt(&self) -> String {
        match self.smd4.address {
            Some(_) => format!("smd4 {}> ", drive_name(self.smd4.address)),
            None => "smd4> ".to_string(),
        }
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
