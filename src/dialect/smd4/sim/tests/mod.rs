//! Tests of the simulated SMD4 through the pure Device API, with explicit times. Replies are read
//! back with the protocol library's own parser, so the simulator and the client are checked
//! against each other.

mod addressing;
mod commands;
mod motion;
mod persistence;
mod quirks;
mod replies;

use std::time::Duration;

use crate::dialect::smd4::protocol::{
    CollectorState, Expectation, ReplyCollector, Request, Smd4Reply, Smd4Spec, check_reply,
    parse_reply,
};
use crate::sim::Device;

use super::{Smd4Sim, Smd4SimOptions};

/// A simulator and the time the next bytes arrive at.
pub(super) struct Bench {
    pub sim: Smd4Sim,
    pub now: Duration,
}

impl Bench {
    pub(super) fn new() -> Bench {
        Bench::with(Smd4SimOptions::default())
    }

    pub(super) fn with(options: Smd4SimOptions) -> Bench {
        Bench {
            sim: Smd4Sim::new(options),
            now: Duration::ZERO,
        }
    }

    /// Moves time to `seconds` since power-up.
    pub(super) fn at(&mut self, seconds: f64) -> &mut Bench {
        let target = Duration::from_secs_f64(seconds);
        assert!(target >= self.now, "time goes forward");
        self.now = target;
        self
    }

    /// Sends raw bytes and returns everything the drive answered.
    pub(super) fn raw(&mut self, bytes: &[u8]) -> String {
        self.sim.receive(self.now, bytes);
        let mut out = Vec::new();
        self.sim.poll_output(self.now, &mut out);
        String::from_utf8(out).expect("replies are ASCII")
    }

    /// Sends `line` with CR LF and returns the reply text without its final CR LF.
    pub(super) fn send(&mut self, line: &str) -> String {
        let text = self.raw(format!("{line}\r\n").as_bytes());
        text.strip_suffix("\r\n").unwrap_or(&text).to_string()
    }

    /// Sends `line` and parses and checks the reply as a client would, multi-line replies
    /// included.
    pub(super) fn reply(&mut self, line: &str) -> Smd4Reply {
        let request = Request::parse(line).unwrap();
        let expect = Expectation::for_request(&Smd4Spec::builtin().commands, &request);
        let reply = self.collect(line, expect.clone());
        if let Err(noise) = check_reply(&reply, &expect, request.address) {
            panic!(
                "{line} -> {}: the client calls it line noise: {noise}",
                reply.raw
            );
        }
        reply
    }

    fn collect(&mut self, line: &str, expect: Expectation) -> Smd4Reply {
        let text = self.raw(format!("{line}\r\n").as_bytes());
        let mut collector = ReplyCollector::new(expect);
        let mut lines = text.split_terminator("\r\n");
        let first = lines.next().unwrap_or_else(|| panic!("no reply to {line}"));
        match collector.push_line(first).unwrap() {
            CollectorState::Complete(reply) => {
                assert!(
                    lines.next().is_none(),
                    "{line}: one line expected in {text:?}"
                );
                *reply
            }
            CollectorState::AwaitQuiet => {
                for more in lines {
                    collector.push_line(more).unwrap();
                }
                collector.finish_quiet().unwrap()
            }
        }
    }

    /// The data items of a successful reply.
    pub(super) fn data(&mut self, line: &str) -> Vec<String> {
        let reply = self.reply(line);
        assert!(reply.is_ok(), "{line} -> {}", reply.raw);
        reply.data_strings()
    }

    /// The error code of a failed command.
    pub(super) fn error(&mut self, line: &str) -> i32 {
        let reply = self.reply(line);
        reply
            .error
            .unwrap_or_else(|| panic!("{line} should fail: {}", reply.raw))
            .code
            .code()
    }

    /// A number read back.
    pub(super) fn number(&mut self, line: &str) -> f64 {
        let reply = parse_reply(&self.send(line), &Expectation::unknown()).unwrap();
        reply.data[0].value.as_f64().unwrap()
    }

    /// Whether the standby flag is set at the current time.
    pub(super) fn standby(&mut self) -> bool {
        self.sim.sflags(self.now).standby()
    }
}
