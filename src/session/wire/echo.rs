//! An adapter that echoes (`--local-echo`): a 2-wire RS-485 converter without echo suppression
//! hands back every byte the host sends, before the answer. The wire strips exactly those bytes
//! from what comes back, comparing each with what was sent, before any dialect matches a reply —
//! so ASCII in every echo mode, binary frames, SMD4 lines, identification and scans see only what
//! the modules sent. A byte that differs is line noise (a collision, or an adapter that does not
//! echo after all). Unless told, the wire finds out at open: the first request a dialect marks as
//! a probe ([`Wire::probe_echo`]) either comes straight back, byte for byte, before anything
//! else, or it does not.

use std::collections::VecDeque;
use std::fmt::Write as _;

use super::super::{LocalEcho, NoiseKind, SessionError};
use super::Wire;
use crate::session::transcript::Entry;

/// What the transcript says of stripped bytes (replays skip what is "discarded").
const STRIPPED: &str = "the adapter's echo of what was sent, discarded";

/// How the error of an echo that differs from what was sent begins: a scan stops there rather
/// than take the address for empty.
pub(crate) const MISMATCH: &str = "line noise: the adapter's echo of what was sent";

/// The notice of an echo found at open.
pub(crate) const FOUND: &str =
    "the adapter echoes what it sends (2-wire RS-485?): stripping it (--local-echo)";

/// The echo state of a wire.
#[derive(Debug, Default)]
pub(super) struct Echo {
    mode: LocalEcho,
    /// Bytes sent whose echo has not come back yet (when stripping).
    expected: VecDeque<u8>,
    /// Detection: the bytes of the probe sent, and those of them that came back so far, held
    /// aside until it is known whether they are an echo.
    probe: Option<(Vec<u8>, usize)>,
}

impl Echo {
    pub(super) fn new(mode: LocalEcho) -> Echo {
        Echo {
            mode,
            ..Echo::default()
        }
    }
}

/// Where received bytes went.
pub(super) enum Taken {
    /// Some or none reached the receive buffer; the echo (if any) was stripped.
    Kept,
    /// The receive buffer is full.
    Overflow,
}

impl Wire {
    /// Whether the wire strips an echo: said so, or found at open.
    #[cfg(test)]
    pub(crate) fn strips_echo(&self) -> bool {
        self.echo.mode == LocalEcho::On
    }

    /// What `:line` says of echo stripping.
    pub(crate) fn echo_state(&self) -> &'static str {
        match self.echo.mode {
            LocalEcho::On => "on: the adapter hands back what is sent, and it is stripped",
            LocalEcho::Off => "off",
            LocalEcho::Auto => "auto: not decided yet (no request that can tell has gone out)",
        }
    }

    /// Marks the next bytes sent as the probe of echo detection, if it is still undecided: a
    /// dialect calls it before a request whose answer never begins like the request itself (a
    /// binary frame; an SMD4 line), not before an ASCII line a module may echo.
    pub(crate) fn probe_echo(&mut self) {
        if self.echo.mode != LocalEcho::Auto {
            return;
        }
        if let Some((_, held)) = self.echo.probe.take() {
            if held > 0 {
                // Part of the last probe came back and nothing more: not an echo after all.
                self.echo.mode = LocalEcho::Off;
                self.note("no echo from the adapter");
                return;
            }
        }
        self.echo.probe = Some((Vec::new(), 0));
    }

    /// After sending `bytes`: their echo is expected, or they are the probe.
    pub(super) fn sent_for_echo(&mut self, bytes: &[u8]) {
        match (&self.echo.mode, &mut self.echo.probe) {
            (LocalEcho::On, _) => self.echo.expected.extend(bytes),
            (LocalEcho::Auto, Some((probe, 0))) if probe.is_empty() => probe.extend(bytes),
            _ => {}
        }
    }

    /// Takes bytes that arrived: strips the echo of what was sent, comparing it (a byte that
    /// differs is line noise, the error), and puts the rest in the receive buffer.
    pub(super) fn take_in(&mut self, bytes: &[u8]) -> Result<Taken, SessionError> {
        let mut rest = bytes;
        if self.echo.mode == LocalEcho::Auto {
            rest = self.detect(rest);
        }
        if self.echo.mode == LocalEcho::On && !self.echo.expected.is_empty() {
            let n = rest.len().min(self.echo.expected.len());
            let matching = rest[..n]
                .iter()
                .zip(self.echo.expected.iter())
                .take_while(|(a, b)| a == b)
                .count();
            self.echo.expected.drain(..matching);
            self.log(Entry::Received, &rest[..matching], STRIPPED);
            if matching < n {
                return Err(self.echo_mismatch(&rest[matching..]));
            }
            rest = &rest[matching..];
        }
        if rest.is_empty() {
            return Ok(Taken::Kept);
        }
        Ok(match self.rx.extend(rest) {
            Ok(()) => Taken::Kept,
            Err(_) => Taken::Overflow,
        })
    }

    /// Detection at open: compares what arrives with the probe sent. Returns what is left for
    /// the receive buffer (all of `bytes` once it is known there is no echo).
    fn detect<'b>(&mut self, bytes: &'b [u8]) -> &'b [u8] {
        let Some((probe, held)) = self.echo.probe.as_mut() else {
            return bytes;
        };
        if probe.is_empty() || bytes.is_empty() {
            return bytes;
        }
        let want = &probe[*held..];
        let n = want.len().min(bytes.len());
        let matching = bytes[..n]
            .iter()
            .zip(want)
            .take_while(|(a, b)| a == b)
            .count();
        if matching < n {
            // Not the echo: what was held aside and all of this is the answer.
            let held_bytes = probe[..*held].to_vec();
            self.echo.probe = None;
            self.echo.mode = LocalEcho::Off;
            self.note("no echo from the adapter");
            let _ = self.rx.extend(&held_bytes);
            return bytes;
        }
        *held += matching;
        if *held < probe.len() {
            return &[];
        }
        let (probe, _) = self.echo.probe.take().expect("probing");
        self.echo.mode = LocalEcho::On;
        self.log(Entry::Received, &probe, STRIPPED);
        self.note("the adapter echoes what is sent: stripping it from now on");
        self.notices.push(FOUND.to_string());
        &bytes[matching..]
    }

    /// The error of an echo that differs from what was sent: everything received is dropped and
    /// the echo still expected forgotten (the failed exchange makes the line suspect).
    fn echo_mismatch(&mut self, got: &[u8]) -> SessionError {
        let wanted: Vec<u8> = self.echo.expected.drain(..).collect();
        self.log(
            Entry::Received,
            got,
            "not the echo of what was sent: line noise, discarded",
        );
        let held = self.rx.clear();
        self.log(Entry::Received, &held, "line noise, discarded");
        let message = format!(
            "{MISMATCH} came back as {} instead of {}; \
             not taken (a collision on the line, or an adapter that does not echo: \
             --local-echo off)",
            hex(&got[..got.len().min(12)]),
            hex(&wanted[..wanted.len().min(12)])
        );
        self.note(&message);
        SessionError::Noise {
            said: message,
            kind: NoiseKind::Echo,
        }
    }

    /// Forgets echo still expected (a link opened anew).
    pub(super) fn reset_echo(&mut self) {
        self.echo.expected.clear();
        if self.echo.mode == LocalEcho::Auto {
            self.echo.probe = None;
        }
    }
}

/// Bytes as hex, `01 88 00`.
fn hex(bytes: &[u8]) -> String {
    let mut out = String::new();
    for (i, b) in bytes.iter().enumerate() {
        if i > 0 {
            out.push(' ');
        }
        let _ = write!(out, "{b:02X}");
    }
    out
}
