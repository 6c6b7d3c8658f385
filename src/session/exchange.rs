//! One line out, one line back: the exchange of the simplest line protocol, for a dialect
//! outside the crate, whose session reaches the wire only through its [`SessionCore`]. The
//! wire's rules hold as for the built-in dialects: a failed exchange leaves the line suspect and
//! the next one resynchronises first, and a reply followed by more than its line end is line
//! noise.

use super::core::SessionCore;
use super::rx::is_line_break;
use super::wire::{Peer, Settled, Wire, nothing_benign};
use super::{SessionError, transcript::Entry};

impl SessionCore {
    /// Sends `line` and CR LF, and returns the first line that comes back (without its line
    /// end) within the session's timeout; `whom` names the device in a time-out's message.
    /// Public because the wire is the crate's own: this is all of it a dialect outside the
    /// crate needs to speak a line protocol.
    pub fn exchange_line(&mut self, line: &str, whom: &str) -> Result<String, SessionError> {
        let timeout = self.options.timeout;
        self.wire
            .begin(Peer::Any, self.urgent, timeout, &mut nothing_benign)?;
        let result = round_trip(&mut self.wire, line, whom, timeout);
        self.wire.finish(result.is_ok());
        result
    }
}

/// The exchange between [`Wire::begin`] and [`Wire::finish`].
fn round_trip(
    wire: &mut Wire,
    line: &str,
    whom: &str,
    timeout: std::time::Duration,
) -> Result<String, SessionError> {
    let bytes = format!("{line}\r\n");
    let sent = wire.send(bytes.as_bytes(), format_args!("{line}"))?;
    let deadline = sent + timeout + wire.wire_time(bytes.len() as u32);
    loop {
        let breaks = wire.rx.bytes().iter().take_while(|&&b| is_line_break(b));
        let breaks = breaks.count();
        if breaks > 0 {
            wire.discard_quietly(breaks, "a line end before the reply");
        }
        if let Some(end) = wire.rx.line_end(0) {
            let reply = String::from_utf8_lossy(&wire.rx.bytes()[..end]).into_owned();
            return match wire.settle(end + 1, deadline, &mut |_| false)? {
                Settled::Clean(n) => {
                    wire.log_received(n, format_args!("reply {reply}"));
                    Ok(reply)
                }
                Settled::Noise => {
                    let rest = wire.rx.clear();
                    wire.log(
                        Entry::Received,
                        &rest,
                        "a reply followed by more data, discarded",
                    );
                    let message = format!(
                        "line noise: the reply {reply:?} was followed by more data, so it may \
                         not be the answer; not taken"
                    );
                    wire.note(&message);
                    Err(SessionError::noise(message))
                }
            };
        }
        if !wire.fill(deadline)? {
            let partial = wire.rx.len();
            wire.discard(partial, "a partial reply");
            wire.note(&format!("no reply from {whom}"));
            return Err(SessionError::Timeout {
                module: whom.to_string(),
                timeout,
                hint: String::new(),
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use super::*;
    use crate::session::SessionOptions;
    use crate::sim::{Device, builtin_link};

    /// Answers each line it receives with the same bytes.
    struct Answering(&'static [u8], Vec<u8>);

    impl Device for Answering {
        fn receive(&mut self, _: Duration, bytes: &[u8]) {
            if bytes.contains(&b'\n') {
                self.1.extend_from_slice(self.0);
            }
        }

        fn poll_output(&mut self, _: Duration, out: &mut Vec<u8>) {
            out.append(&mut self.1);
        }

        fn next_due(&self, now: Duration) -> Option<Duration> {
            (!self.1.is_empty()).then_some(now)
        }
    }

    fn core(answer: &'static [u8]) -> SessionCore {
        let link = builtin_link(Box::new(Answering(answer, Vec::new())), "it".into());
        let options = SessionOptions {
            timeout: Duration::from_millis(20),
            ..SessionOptions::default()
        };
        SessionCore::new(link, options, None)
    }

    #[test]
    fn the_first_line_that_comes_back_is_the_reply() {
        let reply = core(b"\r\nhello\r\n").exchange_line("ECHO hello", "the loopback");
        assert_eq!(reply.unwrap(), "hello");
    }

    #[test]
    fn a_reply_followed_by_more_data_is_line_noise() {
        let error = core(b"hello\r\nworld\r\n").exchange_line("ECHO hello", "it");
        let error = error.unwrap_err();
        assert!(matches!(error, SessionError::Noise { .. }), "{error}");
        assert!(
            error
                .to_string()
                .contains("\"hello\" was followed by more data")
        );
    }

    #[test]
    fn silence_is_a_time_out_naming_the_device() {
        let error = core(b"")
            .exchange_line("ECHO hello", "the loopback")
            .unwrap_err();
        assert_eq!(error.to_string(), "no reply from the loopback within 20 ms");
    }
}
