//! One ASCII exchange: send the line and CR, strip the echo (in whichever of the three echo modes,
//! with CR, LF, CR LF or nothing after it), and take the reply line whose module character is the
//! addressed module's. Anything else is reported, not taken as the answer.

use std::time::{Duration, Instant};

use crate::protocol::tmcl::line::{Op, address_char};
use crate::protocol::tmcl::reply::{AsciiReply, parse_reply};

use super::super::SessionError;
use super::super::transcript::{Entry, escape_into};
use super::{Answer, Exchange, TmclSession};

/// What scanning the receive buffer found.
enum Scan {
    /// The reply, and how many bytes of the buffer belong to this exchange.
    Reply(AsciiReply, String, usize),
    /// Wait for more bytes.
    More,
}

/// How far one exchange has got through the receive buffer. Bytes before `start` have been
/// dealt with (the echo, lines already reported), so a later scan neither reports them again nor
/// reads them anew once the echo has been seen: a stale reply that came before the echo stays
/// ignored when the echo arrives in a later read.
#[derive(Default)]
struct Progress {
    echo_seen: bool,
    start: usize,
}

impl TmclSession {
    /// Sends `text` to `module` and waits up to the session timeout for its reply.
    pub(super) fn ascii_request(
        &mut self,
        module: u8,
        text: &str,
        op: Option<Op>,
    ) -> Result<Exchange, SessionError> {
        self.ascii_request_with(module, text, op, None)
    }

    /// As [`Self::ascii_request`], waiting at most `wait` when given.
    pub(super) fn ascii_request_with(
        &mut self,
        module: u8,
        text: &str,
        op: Option<Op>,
        wait: Option<Duration>,
    ) -> Result<Exchange, SessionError> {
        let c = address_char(module).unwrap_or('?');
        self.wire.drain()?;
        let mut line = Vec::with_capacity(text.len() + 1);
        line.extend_from_slice(text.as_bytes());
        line.push(b'\r');
        self.wire.send(&line, format_args!("to module {c}"))?;
        let timeout = wait
            .unwrap_or(self.options.timeout)
            .min(self.options.timeout);
        let deadline = Instant::now() + timeout;
        let echo_required = self
            .modules
            .get(&module)
            .is_some_and(|m| m.echo_known && m.echo != super::Echo::None);
        let mut progress = Progress::default();
        loop {
            match self.scan(text.as_bytes(), c, echo_required, &mut progress)? {
                Scan::Reply(reply, raw, used) => {
                    self.wire.log_received(
                        used,
                        format_args!("{c}: {}, value {}", reply.status, reply.value),
                    );
                    return Ok(Exchange {
                        module,
                        sent: text.to_string(),
                        op,
                        answer: Answer::Reply {
                            status: reply.status,
                            value: reply.value,
                        },
                        raw,
                    });
                }
                Scan::More => {}
            }
            if !self.wire.fill(deadline)? {
                return Err(self.timed_out(c, timeout, progress.echo_seen));
            }
        }
    }

    /// Looks for this exchange's reply in the receive buffer, from where the last scan stopped.
    /// Lines that are not it are reported once.
    fn scan(
        &mut self,
        sent: &[u8],
        module: char,
        echo_required: bool,
        progress: &mut Progress,
    ) -> Result<Scan, SessionError> {
        let buf = self.wire.rx.bytes();
        let mut pos = progress.start;
        loop {
            progress.start = pos;
            while pos < buf.len() && matches!(buf[pos], b'\r' | b'\n' | 0) {
                pos += 1;
            }
            let rest = &buf[pos..];
            if rest.is_empty() {
                return Ok(Scan::More);
            }
            if !progress.echo_seen {
                if rest.starts_with(sent) {
                    progress.echo_seen = true;
                    pos += sent.len();
                    continue;
                }
                if sent.starts_with(rest) {
                    return Ok(Scan::More); // the echo is still arriving
                }
            }
            let Some(end) = rest.iter().position(|&b| b == b'\r' || b == b'\n') else {
                return Ok(Scan::More);
            };
            let line = &rest[..end];
            let line_end = pos + end + 1;
            let text = String::from_utf8_lossy(line).into_owned();
            match parse_reply(&text) {
                Some(reply) if reply.module == module && (progress.echo_seen || !echo_required) => {
                    return Ok(Scan::Reply(reply, text, line_end));
                }
                Some(reply) if reply.module == module => {
                    self.wire.notices.push(format!(
                        "ignored a reply that came before the echo (stale?): {text}"
                    ));
                }
                Some(reply) => {
                    self.wire.notices.push(format!(
                        "ignored a reply from module {} while waiting for module {module}: {text}",
                        reply.module
                    ));
                }
                None if !progress.echo_seen && looks_like_echo(line, sent) => {
                    let sent_text = String::from_utf8_lossy(sent).into_owned();
                    self.wire.rx.take(line_end);
                    return Err(SessionError::Link(format!(
                        "line noise: module {module} echoed '{text}' for '{sent_text}', so it may have \
                         executed something else; check the cabling and the baud rate"
                    )));
                }
                None => {
                    let mut shown = String::new();
                    escape_into(line, &mut shown);
                    self.wire
                        .notices
                        .push(format!("ignored unexpected data from the line: {shown}"));
                }
            }
            pos = line_end;
        }
    }

    fn timed_out(&mut self, module: char, timeout: Duration, echo_seen: bool) -> SessionError {
        let partial = self.wire.rx.clear();
        let hint = if !partial.is_empty() {
            let mut shown = String::new();
            escape_into(&partial, &mut shown);
            self.wire
                .log(Entry::Received, &partial, "incomplete, no reply");
            format!(" (received only {shown})")
        } else if echo_seen {
            " (the command was echoed but not answered)".to_string()
        } else {
            String::new()
        };
        // A CR ends whatever part of our line the module may still hold, so the next line starts
        // clean; any reply it provokes is drained before the next exchange.
        let _ = self.wire.send(b"\r", "resynchronise after timeout");
        self.wire.note(&format!(
            "no reply from module {module} within {} ms",
            timeout.as_millis()
        ));
        SessionError::Timeout {
            module: module.to_string(),
            timeout,
            hint,
        }
    }
}

/// Whether `line` is a garbled copy of what was sent (same address character, nearly the same
/// text) rather than unrelated data.
fn looks_like_echo(line: &[u8], sent: &[u8]) -> bool {
    line.first() == sent.first()
        && strsim::normalized_levenshtein(
            &String::from_utf8_lossy(line),
            &String::from_utf8_lossy(sent),
        ) >= 0.7
}
