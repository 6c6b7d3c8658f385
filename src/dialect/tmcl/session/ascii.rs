//! One ASCII exchange: send the line and CR, strip the echo (in whichever of the three echo modes,
//! with CR, LF, CR LF or nothing after it), and take the reply line whose module character is the
//! addressed module's, once nothing but line ends has followed it. Anything else is reported, not
//! taken as the answer.
//!
//! Which request a reply answers: with an echo, only a reply after the complete echo of *this*
//! request is taken. A request whose exchange failed may still be echoed and answered late, so an
//! identical request after it is spelled differently — spaces after the address character, which
//! the manual allows (`A GAP 1, 0`) — and a late echo cannot pass for its echo. Without an echo
//! nothing in a reply says which request it answers: after a failure the next request to that
//! module is preceded by a barrier the module refuses, and every reply before that refusal is
//! discarded (see `barrier.rs`).

use std::borrow::Cow;
use std::time::{Duration, Instant};

use crate::dialect::tmcl::protocol::line::{Op, address_char};
use crate::dialect::tmcl::protocol::reply::{AsciiReply, parse_reply_bytes};
use crate::dialect::tmcl::protocol::{AsciiWord, ModuleName, Status};

use super::{TmclExchange, TmclReply, TmclSession};
use crate::session::SessionError;
use crate::session::rx::is_line_break;
use crate::session::transcript::{Entry, escape_into};
use crate::session::wire::{MAX_LINE, Peer, Settled, Wire};

/// The most spaces put after the address character to tell a request from an unanswered one.
const MAX_SPACES: usize = 8;

/// What is discarded most often.
const UNEXPECTED: &str = "unexpected data from the line";

/// How far one exchange has got through the receive buffer. What it has judged is consumed as it
/// goes — its own bytes (line ends, the echo) into `held` for the transcript, everything else
/// discarded and counted — so a stale reply before the echo stays ignored when the echo arrives
/// in a later read, and a flood never piles up.
struct Scan<'a> {
    /// The line as sent, without CR.
    sent: &'a [u8],
    echo_seen: bool,
    /// The rest of an overlong line is still arriving: discard it up to its end.
    in_junk: bool,
    /// This is a barrier: only its refusal is its reply (see `barrier.rs`).
    barrier: bool,
    /// This exchange's bytes taken so far, for the transcript record of the reply.
    held: Vec<u8>,
}

impl Scan<'_> {
    /// Takes the first `n` buffered bytes as this exchange's own.
    fn hold(&mut self, wire: &mut Wire, n: usize) {
        self.held.extend_from_slice(&wire.rx.bytes()[..n]);
        wire.rx.consume(n);
        if self.held.len() > MAX_LINE {
            // A flood of line ends: keep the record small.
            let held = std::mem::take(&mut self.held);
            wire.log(
                Entry::Received,
                &held,
                "while waiting for the reply, discarded",
            );
        }
    }
}

/// The buffers of ASCII exchanges, kept between them so that a transaction allocates only what
/// it returns: the line sent (and then each line judged), and the record of its own bytes; and
/// the last line read as a reply, with what it read as (a polling loop gets the same reply
/// again and again, and reading one is a pure function of its bytes).
#[derive(Debug, Default)]
pub(super) struct Buffers {
    line: Vec<u8>,
    record: Vec<u8>,
    reply: Option<(Vec<u8>, Option<AsciiReply>)>,
}

impl Buffers {
    /// `line` read as a reply ([`parse_reply_bytes`]), the last answer again for the same bytes.
    fn parse_reply(&mut self, line: &[u8]) -> Option<AsciiReply> {
        if let Some((last, read)) = &self.reply {
            if last.as_slice() == line {
                return *read;
            }
        }
        let read = parse_reply_bytes(line);
        let (last, kept) = self.reply.get_or_insert_with(|| (Vec::new(), None));
        last.clear();
        last.extend_from_slice(line);
        *kept = read;
        read
    }
}

/// A reply found in the buffer: the reply, its text, and the bytes its line takes.
type Found = (AsciiReply, String, usize);

/// What an ASCII request waits for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Wait {
    /// Its reply, up to the session timeout.
    Reply,
    /// A reply the module may not send at all (BIN), this long; its absence leaves the line
    /// trusted.
    Optional(Duration),
    /// The refusal of a barrier (see `barrier.rs`), up to the session timeout.
    Barrier,
}

impl TmclSession {
    /// Sends `text` to `module` and waits up to the session timeout for its reply.
    pub(super) fn ascii_request(
        &mut self,
        module: u8,
        text: String,
        op: Option<Op>,
    ) -> Result<TmclExchange, SessionError> {
        self.ascii_request_with(module, text, op, Wait::Reply)
    }

    /// Sends the ASCII barrier `text` to `module` and waits for its refusal (see `barrier.rs`,
    /// which decides when one is due).
    pub(super) fn ascii_barrier_request(
        &mut self,
        module: u8,
        text: String,
    ) -> Result<TmclExchange, SessionError> {
        self.ascii_request_with(module, text, None, Wait::Barrier)
    }

    /// As [`Self::ascii_request`], waiting for what `wait` says. A request puts a barrier on
    /// the line first when an earlier one's reply may still come without an echo to tell it.
    /// The exchange returned holds `text` as what was sent.
    pub(super) fn ascii_request_with(
        &mut self,
        module: u8,
        text: String,
        op: Option<Op>,
        wait: Wait,
    ) -> Result<TmclExchange, SessionError> {
        if wait == Wait::Reply {
            self.ascii_barrier(module)?;
        }
        if std::mem::take(&mut self.line_dirty) {
            self.end_partial_line()?;
        }
        self.ascii_sent = true;
        self.frames_aligned = false;
        let wire_text = self.spelling(&text);
        let optional = matches!(wait, Wait::Optional(_));
        let mut echoed = false;
        let result = self.exchange(module, optional, |s| {
            s.ascii_exchange(module, &text, &wire_text, op, wait, &mut echoed)
        });
        let c = address_char(module).unwrap_or('?');
        match &result {
            // In order: a barrier's refusal given up earlier can no longer come.
            Ok(_) if wait != Wait::Barrier => self.unanswered.replied(c),
            Ok(_) => {}
            Err(SessionError::Timeout { .. }) if optional => {}
            // A barrier's failure is the barrier's to record.
            Err(_) if wait == Wait::Barrier => {}
            Err(_) => self
                .unanswered
                .remember(wire_text.into_owned().into_bytes(), echoed),
        }
        // The line typed, not a copy of it.
        result.map(|exchange| TmclExchange {
            sent: text,
            ..exchange
        })
    }

    fn ascii_exchange(
        &mut self,
        module: u8,
        text: &str,
        wire_text: &str,
        op: Option<Op>,
        wait: Wait,
        echoed: &mut bool,
    ) -> Result<TmclExchange, SessionError> {
        let name = ModuleName(module);
        let mut line = std::mem::take(&mut self.buffers.line);
        line.clear();
        line.extend_from_slice(wire_text.as_bytes());
        line.push(b'\r');
        if let Some(Op::Command(instruction)) = op {
            self.forget_host(&instruction);
        }
        let sent = self.core.wire.send(&line, format_args!("to {name}"))?;
        self.buffers.line = line;
        let timeout = match wait {
            Wait::Optional(wait) => wait,
            Wait::Reply | Wait::Barrier => self.core.options.timeout,
        };
        let deadline = sent + timeout;
        let state = self.modules.get(&module);
        let echo_known = state.is_some_and(|m| m.echo_known);
        let echo_required = state.is_some_and(|m| m.echo_known && m.echo != super::Echo::None);
        let mut held = std::mem::take(&mut self.buffers.record);
        held.clear();
        // Room for the echo and the line ends around it, taken without growing.
        held.reserve(wire_text.len() + 8);
        let mut scan = Scan {
            sent: wire_text.as_bytes(),
            echo_seen: false,
            in_junk: false,
            barrier: wait == Wait::Barrier,
            held,
        };
        // When the line was last read (at first, when the request went out): bytes that keep
        // coming cannot hold the exchange past its deadline, and the first wait reads no clock
        // of its own.
        let mut read_at = sent;
        loop {
            let found = self.scan(&mut scan, module, echo_required);
            *echoed = scan.echo_seen;
            if let Some(found) = found? {
                if !echo_known
                    && !scan.echo_seen
                    && self.echo_follows(&found, scan.sent, deadline)?
                {
                    // Taken without an echo (the echo mode is still being learnt), but the echo
                    // of this request came after it: it was an earlier request's reply.
                    self.core
                        .wire
                        .discard(found.2, "a reply that came before the echo");
                    continue;
                }
                let held = std::mem::take(&mut scan.held);
                return self.accept(module, text, op, held, found, deadline);
            }
            if read_at >= deadline || !self.core.wire.fill(deadline)? {
                // After BIN the module may be in binary mode, where a CR would start a frame.
                let resync_cr = !leaves_ascii(op, text);
                return Err(self.timed_out(module, timeout, &mut scan, resync_cr));
            }
            read_at = self.core.wire.heard_at().unwrap_or(deadline);
        }
    }

    /// Looks for this exchange's reply in the receive buffer, consuming what it judges.
    fn scan(
        &mut self,
        scan: &mut Scan,
        module: u8,
        echo_required: bool,
    ) -> Result<Option<Found>, SessionError> {
        loop {
            if scan.in_junk {
                match self.core.wire.rx.line_end(0) {
                    Some(end) => {
                        self.core.wire.discard_more(end);
                        scan.in_junk = false;
                    }
                    None => {
                        let n = self.core.wire.rx.len();
                        self.core.wire.discard_more(n);
                        return Ok(None);
                    }
                }
            }
            let rest = self.core.wire.rx.bytes();
            let breaks = rest.iter().take_while(|&&b| is_line_break(b)).count();
            if breaks > 0 {
                scan.hold(&mut self.core.wire, breaks);
                continue;
            }
            if rest.is_empty() {
                return Ok(None);
            }
            if !scan.echo_seen {
                if rest.starts_with(scan.sent) {
                    scan.echo_seen = true;
                    scan.hold(&mut self.core.wire, scan.sent.len());
                    continue;
                }
                if scan.sent.starts_with(rest) {
                    return Ok(None); // the echo is still arriving
                }
            }
            let Some(end) = self.core.wire.rx.line_end(0) else {
                if self.core.wire.rx.len() > MAX_LINE {
                    let n = self.core.wire.rx.len();
                    self.core.wire.discard(n, UNEXPECTED);
                    scan.in_junk = true;
                }
                return Ok(None);
            };
            let used = end + 1;
            if end > MAX_LINE {
                self.core.wire.discard(used, UNEXPECTED);
                continue;
            }
            let mut line = std::mem::take(&mut self.buffers.line);
            line.clear();
            line.extend_from_slice(&self.core.wire.rx.bytes()[..end]);
            let judged = self.judge(scan, module, &line, used, echo_required);
            self.buffers.line = line;
            if let Some(found) = judged? {
                return Ok(Some(found));
            }
        }
    }

    /// Judges a whole line of `used` bytes at the front of the buffer: this exchange's reply
    /// (returned), an event, a late or stray reply or echo (discarded), or line noise (an error).
    fn judge(
        &mut self,
        scan: &mut Scan,
        module: u8,
        line: &[u8],
        used: usize,
        echo_required: bool,
    ) -> Result<Option<Found>, SessionError> {
        let c = address_char(module).unwrap_or('?');
        let acceptable = scan.echo_seen || !echo_required;
        match self.buffers.parse_reply(line) {
            Some(reply) if reply.status == Status::PositionReachedEvent => {
                self.core.wire.notices.push(format!(
                    "{}: target position reached (event)",
                    ModuleName::of_char(reply.module)
                ));
                self.core
                    .wire
                    .discard_quietly(used, "target position reached event, not a reply");
            }
            Some(reply)
                if reply.module == c && acceptable && scan.barrier != barrier_like(&reply) =>
            {
                if scan.barrier {
                    self.core
                        .wire
                        .discard_quietly(used, "late reply, before the barrier's refusal");
                } else if self.unanswered.barrier_arrived(c) {
                    self.core
                        .wire
                        .discard_quietly(used, "late refusal of a barrier given up earlier");
                } else {
                    return Ok(Some((reply, latin1(line), used)));
                }
            }
            Some(reply) if reply.module == c && acceptable => {
                return Ok(Some((reply, latin1(line), used)));
            }
            Some(reply) if reply.module == c && self.unanswered.reply_arrived(c) => {
                self.core
                    .wire
                    .discard_quietly(used, "late reply to a request given up earlier");
                // Every request to this module given up has now been answered: nothing
                // more is on its way.
                if !self.unanswered.pending(c) {
                    self.core.wire.trust(Peer::Module(module.into()));
                }
            }
            Some(reply) if reply.module == c => {
                self.core
                    .wire
                    .discard(used, "a reply that came before the echo");
            }
            Some(reply) => {
                let kind = format!(
                    "a reply from {} while waiting for {}",
                    ModuleName::of_char(reply.module),
                    ModuleName(module)
                );
                self.core.wire.discard(used, &kind);
            }
            None if !scan.echo_seen && self.unanswered.echo_arrived(line) => {
                self.core
                    .wire
                    .discard_quietly(used, "late echo of a request given up earlier");
            }
            None if !scan.echo_seen && looks_like_echo(line, scan.sent) => {
                let sent = latin1(scan.sent);
                let message = format!(
                    "line noise: {} echoed '{}' for '{sent}', so it may have executed \
                     something else; check the cabling and the baud rate",
                    ModuleName(module),
                    latin1(line)
                );
                return Err(self.noise(scan, used, "garbled echo", message));
            }
            None if acceptable && reply_shaped(line, c) => {
                let message = format!(
                    "line noise: {} answered '{}', which is not a valid reply (garbled, or an \
                     unknown status); not taken",
                    ModuleName(module),
                    latin1(line)
                );
                return Err(self.noise(scan, used, "not a valid reply", message));
            }
            None => self.core.wire.discard(used, UNEXPECTED),
        }
        Ok(None)
    }

    /// Whether the echo of this request follows a reply found before any echo: waits as long
    /// as a trailing byte would take, and no longer.
    fn echo_follows(
        &mut self,
        (_, _, used): &Found,
        sent: &[u8],
        deadline: Instant,
    ) -> Result<bool, SessionError> {
        let follows = |rx: &[u8]| {
            let rest = &rx[*used..];
            let start = rest.iter().take_while(|&&b| is_line_break(b)).count();
            let rest = &rest[start..];
            !rest.is_empty() && (rest.starts_with(sent) || sent.starts_with(rest))
        };
        if self.core.wire.rx.len() == *used && Instant::now() < deadline {
            self.core.wire.await_more(deadline)?;
        }
        Ok(follows(self.core.wire.rx.bytes()))
    }

    /// Takes a found reply once what follows it has been seen: nothing but line ends and events.
    fn accept(
        &mut self,
        module: u8,
        text: &str,
        op: Option<Op>,
        mut record: Vec<u8>,
        (reply, raw, used): Found,
        deadline: Instant,
    ) -> Result<TmclExchange, SessionError> {
        let c = reply.module;
        let mut events = Vec::new();
        // The refusal taken for a barrier's may be an earlier barrier's: its own may follow.
        let barrier = text.get(1..) == Some(super::barrier::ASCII_BARRIER);
        let unanswered = &mut self.unanswered;
        let settled =
            self.core
                .wire
                .settle(used, deadline, &mut |line| match parse_reply_bytes(line) {
                    Some(r) if r.status == Status::PositionReachedEvent => {
                        events.push(format!(
                            "{}: target position reached (event)",
                            ModuleName::of_char(r.module)
                        ));
                        true
                    }
                    Some(r) if barrier && r.module == c && barrier_like(&r) => {
                        unanswered.barrier_arrived(c)
                    }
                    _ => false,
                })?;
        self.core.wire.notices.extend(events);
        match settled {
            Settled::Clean(n) => {
                record.extend_from_slice(&self.core.wire.rx.bytes()[..n]);
                self.core.wire.rx.consume(n);
                self.core.wire.log(
                    Entry::Received,
                    &record,
                    format_args!("{c}: {}, value {}", reply.status, reply.value),
                );
                self.buffers.record = record;
                Ok(TmclExchange {
                    module,
                    // Filled in by `ascii_request_with`, which owns the line.
                    sent: String::new(),
                    op,
                    reply: TmclReply::Status {
                        status: reply.status,
                        value: reply.value,
                    },
                    raw,
                })
            }
            Settled::Noise => {
                let mut after = String::new();
                let rest = &self.core.wire.rx.bytes()[used..];
                escape_into(&rest[..rest.len().min(40)], &mut after);
                record.extend(self.core.wire.rx.clear());
                self.core.wire.log(
                    Entry::Received,
                    &record,
                    "a reply followed by more data: line noise, discarded",
                );
                let message = format!(
                    "line noise: the reply '{raw}' from {} was followed by {after}, so it may be \
                     cut short or not the answer; not taken",
                    ModuleName(module)
                );
                self.core.wire.note(&message);
                Err(SessionError::noise(message))
            }
        }
    }

    /// Ends the exchange on line noise: the bytes up to the offending line's end go to the
    /// transcript with the event.
    fn noise(&mut self, scan: &mut Scan, used: usize, what: &str, message: String) -> SessionError {
        let mut record = std::mem::take(&mut scan.held);
        record.extend(self.core.wire.rx.take(used));
        self.core.wire.log(
            Entry::Received,
            &record,
            format_args!("{what}: line noise, discarded"),
        );
        self.core.wire.note(&message);
        SessionError::noise(message)
    }

    fn timed_out(
        &mut self,
        module: u8,
        timeout: Duration,
        scan: &mut Scan,
        resync_cr: bool,
    ) -> SessionError {
        let leftover = self.core.wire.rx.clear();
        let mut partial = std::mem::take(&mut scan.held);
        partial.extend_from_slice(&leftover);
        let hint = if scan.echo_seen && leftover.iter().all(|&b| is_line_break(b)) {
            " (the command was echoed but not answered)".to_string()
        } else if partial.iter().any(|&b| !is_line_break(b)) {
            let mut shown = String::new();
            escape_into(&partial[..partial.len().min(80)], &mut shown);
            format!(" (received only {shown})")
        } else {
            String::new()
        };
        if !partial.is_empty() {
            self.core
                .wire
                .log(Entry::Received, &partial, "incomplete, no reply");
        }
        if resync_cr {
            // A CR ends whatever part of our line the module may still hold, so the next line
            // starts clean; what it provokes is discarded while the line resynchronises.
            let _ = self.core.wire.send(b"\r", "resynchronise after timeout");
        }
        let module = ModuleName(module);
        self.core.wire.note(&format!(
            "no reply from {module} within {} ms",
            timeout.as_millis()
        ));
        SessionError::Timeout {
            module: module.to_string(),
            timeout,
            hint,
        }
    }

    /// The line as it goes on the wire: the canonical text, or — while an identical request is
    /// unanswered — the same with spaces after the address character, so each echo is unique.
    fn spelling<'a>(&self, text: &'a str) -> Cow<'a, str> {
        if !self.unanswered.contains(text.as_bytes()) {
            return Cow::Borrowed(text);
        }
        let split = text.chars().next().map_or(0, char::len_utf8);
        let (address, rest) = text.split_at(split);
        (0..=MAX_SPACES)
            .map(|spaces| format!("{address}{}{rest}", " ".repeat(spaces)))
            .find(|t| !self.unanswered.contains(t.as_bytes()))
            .map_or(Cow::Borrowed(text), Cow::Owned)
    }
}

/// Whether a reply is what the ASCII barrier is answered with.
fn barrier_like(reply: &AsciiReply) -> bool {
    super::barrier::refuses_barrier(reply.status)
}

/// Whether a request may leave the module in binary mode (BIN, typed or sent unvalidated).
fn leaves_ascii(op: Option<Op>, text: &str) -> bool {
    matches!(op, Some(Op::Ascii(AsciiWord::Bin)))
        || text
            .get(1..)
            .is_some_and(|rest| rest.trim().eq_ignore_ascii_case("BIN"))
}

/// Whether `line` is laid out like a reply from module `c` (host character, `c`, a space): such
/// a line that does not parse is a damaged reply, not unrelated data.
fn reply_shaped(line: &[u8], c: char) -> bool {
    let start = line.iter().take_while(|&&b| b == b' ').count();
    [0, start]
        .iter()
        .any(|&s| line.get(s + 1) == Some(&(c as u8)) && line.get(s + 2) == Some(&b' '))
}

/// Bytes as text, one character per byte (Latin-1), so no byte is lost or merged.
fn latin1(bytes: &[u8]) -> String {
    // ASCII is the same in both: copied whole.
    match std::str::from_utf8(bytes) {
        Ok(text) if bytes.is_ascii() => text.to_owned(),
        _ => bytes.iter().map(|&b| char::from(b)).collect(),
    }
}

/// Whether `line` is a garbled copy of what was sent (same address character, nearly the same
/// text) rather than unrelated data.
fn looks_like_echo(line: &[u8], sent: &[u8]) -> bool {
    line.first() == sent.first()
        && strsim::normalized_levenshtein(&latin1(line), &latin1(sent)) >= 0.7
}
