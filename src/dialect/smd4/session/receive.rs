//! Reading an SMD4 reply: whole lines fed to a collector, a multi-line reply ended by the quiet
//! gap, a single-line one taken once the bytes after it were seen, each checked against what the
//! command declares — line noise and other drives' replies reported, never taken.

use std::time::Instant;

use crate::dialect::smd4::protocol::{
    CollectorState, Expectation, PrefixStyle, ReplyCollector, Request, Smd4Reply, check_reply,
    is_reply_to,
};
use crate::session::SessionError;
use crate::session::rx::is_line_break;
use crate::session::transcript::{Entry, escape_into};
use crate::session::wire::{MAX_LINE, Settled};

use super::{DriveName, Smd4Session, barrier};

/// The most a reply may hold, all its lines together.
const MAX_REPLY: usize = 64 * 1024;

/// What is discarded most often.
const UNEXPECTED: &str = "unexpected data from the line";

/// A reply being read: what its request expects, the lines collected so far and their bytes (for
/// the transcript), and whether the rest of an overlong line is still being dropped.
struct Reading {
    expect: Expectation,
    collector: ReplyCollector,
    bytes: Vec<u8>,
    in_junk: bool,
}

impl Smd4Session {
    /// Reads the reply to `request`: whole lines, fed to a collector; a multi-line reply ends
    /// when nothing arrived for the quiet gap, a single-line one once the bytes after it were
    /// seen. Lines are consumed as they are judged, so a flood costs neither time beyond the
    /// deadline nor memory.
    pub(super) fn receive(&mut self, request: &Request) -> Result<Smd4Reply, SessionError> {
        let expect = Expectation::for_request(&self.spec.commands, request);
        let mut reading = Reading {
            collector: ReplyCollector::new(expect.clone()),
            expect,
            bytes: Vec::new(),
            in_junk: false,
        };
        let deadline = Instant::now() + self.core.options.timeout;
        // A multi-line reply's last line may come up to the deadline; its quiet gap after that.
        let multi_line_end = deadline + self.smd4.quiet_gap;
        loop {
            if let Some(outcome) = self.judge_lines(&mut reading, request, deadline) {
                return outcome;
            }
            if let Some(outcome) = self.await_more(&mut reading, request, deadline, multi_line_end)
            {
                return outcome;
            }
        }
    }

    /// Judges the whole lines received so far: the reply's outcome once one is known, `None`
    /// while more must be read.
    fn judge_lines(
        &mut self,
        reading: &mut Reading,
        request: &Request,
        deadline: Instant,
    ) -> Option<Result<Smd4Reply, SessionError>> {
        loop {
            if reading.in_junk && !self.skip_junk(reading) {
                return None;
            }
            let bytes = self.core.wire.rx.bytes();
            let breaks = bytes.iter().take_while(|&&b| is_line_break(b)).count();
            if breaks > 0 {
                reading.bytes.extend(self.core.wire.rx.take(breaks));
                continue;
            }
            let Some(end) = self.core.wire.rx.line_end(0) else {
                if self.core.wire.rx.len() > MAX_LINE {
                    let n = self.core.wire.rx.len();
                    self.core.wire.discard(n, UNEXPECTED);
                    reading.in_junk = true;
                }
                return None;
            };
            let used = end + 1;
            if end > MAX_LINE {
                self.core.wire.discard(used, UNEXPECTED);
                continue;
            }
            let line = String::from_utf8_lossy(&self.core.wire.rx.bytes()[..end]).into_owned();
            match reading.collector.push_line(&line) {
                Ok(CollectorState::Complete(reply)) if foreign(&reply, request) => {
                    self.discard_foreign(used, &reply, request);
                    reading.collector = ReplyCollector::new(reading.expect.clone());
                }
                Ok(CollectorState::Complete(reply)) if self.late(&reply, request) => {
                    let what = if request.mnemonic == barrier::BARRIER {
                        "late reply, before the barrier's refusal"
                    } else {
                        "late refusal of a barrier given up earlier"
                    };
                    self.core.wire.discard_quietly(used, what);
                    reading.collector = ReplyCollector::new(reading.expect.clone());
                }
                Ok(CollectorState::Complete(reply)) => {
                    let bytes = std::mem::take(&mut reading.bytes);
                    let expect = &reading.expect;
                    return Some(self.settle(*reply, bytes, used, deadline, expect, request));
                }
                Ok(CollectorState::AwaitQuiet) => {
                    reading.bytes.extend(self.core.wire.rx.take(used));
                    if reading.bytes.len() > MAX_REPLY {
                        let bytes = std::mem::take(&mut reading.bytes);
                        return Some(Err(self.endless(request, bytes, "is longer than 64 KiB")));
                    }
                }
                Err(_) => self.core.wire.discard(used, UNEXPECTED),
            }
        }
    }

    /// Drops the rest of an overlong line: `false` while its end has not come yet.
    fn skip_junk(&mut self, reading: &mut Reading) -> bool {
        match self.core.wire.rx.line_end(0) {
            Some(end) => {
                self.core.wire.discard_more(end);
                reading.in_junk = false;
                true
            }
            None => {
                let n = self.core.wire.rx.len();
                self.core.wire.discard_more(n);
                false
            }
        }
    }

    /// Reads more, up to the deadline, or for a multi-line reply up to its quiet gap: the
    /// reply's outcome when the time is up, `None` when bytes came.
    fn await_more(
        &mut self,
        reading: &mut Reading,
        request: &Request,
        deadline: Instant,
        multi_line_end: Instant,
    ) -> Option<Result<Smd4Reply, SessionError>> {
        let now = Instant::now();
        if !reading.collector.awaiting_quiet() {
            return match (now >= deadline, self.core.wire.fill(deadline)) {
                (false, Ok(true)) => None,
                (false, Err(e)) => Some(Err(e)),
                _ => Some(Err(
                    self.no_reply(request, std::mem::take(&mut reading.bytes))
                )),
            };
        }
        let late = "did not end in time";
        if now >= multi_line_end {
            return Some(Err(self.endless(
                request,
                std::mem::take(&mut reading.bytes),
                late,
            )));
        }
        let gap_end = now + self.smd4.quiet_gap;
        match self.core.wire.fill(gap_end.min(multi_line_end)) {
            Ok(true) => None,
            Err(e) => Some(Err(e)),
            Ok(false) if gap_end > multi_line_end => Some(Err(self.endless(
                request,
                std::mem::take(&mut reading.bytes),
                late,
            ))),
            Ok(false) => {
                let fresh = ReplyCollector::new(reading.expect.clone());
                let reply = std::mem::replace(&mut reading.collector, fresh)
                    .finish_quiet()
                    .expect("awaiting quiet means a first line came");
                Some(self.finish(reply, &reading.bytes, &reading.expect, request))
            }
        }
    }

    /// Drops the line of `used` bytes that carried `reply`, another drive's.
    fn discard_foreign(&mut self, used: usize, reply: &Smd4Reply, request: &Request) {
        let kind = format!(
            "a reply from {} while waiting for {}",
            DriveName(reply.address),
            DriveName(request.address)
        );
        self.core.wire.discard(used, &kind);
    }

    /// Nothing (complete) came back in time: what did is logged, and the error says what may
    /// be wrong.
    fn no_reply(&mut self, request: &Request, mut reply_bytes: Vec<u8>) -> SessionError {
        let partial = self.core.wire.rx.clear();
        reply_bytes.extend_from_slice(&partial);
        if !reply_bytes.is_empty() {
            self.core
                .wire
                .log(Entry::Received, &reply_bytes, "no complete reply");
        }
        let module = DriveName(request.address);
        self.core.wire.note(&format!("no reply from {module}"));
        SessionError::Timeout {
            module: module.to_string(),
            timeout: self.core.options.timeout,
            hint: timeout_hint(&partial, request.address, self.smd4.prefix),
        }
    }

    /// Takes a single-line reply whose line takes the first `used` buffered bytes, once what
    /// follows it has been seen: nothing but the rest of its CR LF. A drive ends every line with
    /// CR LF, so a line ended by a bare LF lost its CR to a corrupted byte, which may have been
    /// appended to the last item (`5.7750E+014`): noise.
    fn settle(
        &mut self,
        reply: Smd4Reply,
        mut reply_bytes: Vec<u8>,
        used: usize,
        deadline: Instant,
        expect: &Expectation,
        request: &Request,
    ) -> Result<Smd4Reply, SessionError> {
        let ended_by_cr = used > 0 && self.core.wire.rx.bytes()[used - 1] == b'\r';
        // The refusal taken for a barrier's may be an earlier barrier's: its own may follow.
        let barrier = request.mnemonic == barrier::BARRIER;
        let lost = &mut self.doubt;
        let settled = if ended_by_cr {
            self.core.wire.settle(used, deadline, &mut |line| {
                barrier && barrier::barrier_line(line) && lost.barrier_arrived(request.address)
            })?
        } else {
            Settled::Noise
        };
        match settled {
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
                let message = if ended_by_cr {
                    format!(
                        "line noise: the reply {shown} was followed by {after}, so it may be cut \
                         short or not the answer; not taken"
                    )
                } else {
                    format!(
                        "line noise: the reply {shown} ended in a line feed without its carriage \
                         return, so a byte of it was damaged; not taken"
                    )
                };
                self.core.wire.note(&message);
                Err(SessionError::noise(message))
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
        SessionError::noise(message)
    }

    /// A complete reply, checked against what the command declares: one that fails is line
    /// noise, never a value.
    fn finish(
        &mut self,
        reply: Smd4Reply,
        consumed: &[u8],
        expect: &Expectation,
        request: &Request,
    ) -> Result<Smd4Reply, SessionError> {
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
            return Err(SessionError::noise(message));
        }
        let meaning = match &reply.error {
            Some(error) => format!("error {error}"),
            None => format!("sflags {:#06x}", reply.sflags.0),
        };
        self.core.wire.log(Entry::Received, consumed, &meaning);
        Ok(reply)
    }
}

impl Smd4Session {
    /// Whether a complete reply is a late one: before a barrier's refusal, anything else; during
    /// another request, the refusal of a barrier given up earlier.
    fn late(&mut self, reply: &Smd4Reply, request: &Request) -> bool {
        if request.mnemonic == barrier::BARRIER {
            !barrier::barrier_like(reply)
        } else {
            barrier::barrier_like(reply) && self.lost_barrier_arrived(request.address)
        }
    }
}

/// A reply carrying another drive's address prefix (any prefix when the request had none).
fn foreign(reply: &Smd4Reply, request: &Request) -> bool {
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
