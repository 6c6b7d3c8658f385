//! Data that is not a reply: counted per kind for one notice per exchange, and written to the
//! transcript in records of a few KiB.

use std::fmt::Display;

use super::super::transcript::{Entry, escape_into};
use super::Wire;

/// Discarded bytes are written to the transcript in records of about this size.
const DISCARD_RECORD: usize = 4096;

impl Wire {
    /// Consumes the first `n` buffered bytes as discarded data of `kind`, counted for the
    /// exchange's summary (the first occurrence is shown).
    pub(crate) fn discard(&mut self, n: usize, kind: &str) {
        let n = n.min(self.rx.len());
        let bytes = &self.rx.bytes()[..n];
        self.discards.count(kind, bytes);
        self.keep_discarded_from_rx(n);
    }

    /// Consumes the first `n` buffered bytes as the rest of data already counted as discarded
    /// (an overlong line whose end arrives later).
    pub(crate) fn discard_more(&mut self, n: usize) {
        let n = n.min(self.rx.len());
        self.keep_discarded_from_rx(n);
    }

    /// Consumes the first `n` buffered bytes into the transcript only: expected leftovers such
    /// as line ends, or the late answer of a request already given up.
    pub(crate) fn discard_quietly(&mut self, n: usize, meaning: impl Display) {
        let n = n.min(self.rx.len());
        if n == 0 {
            return;
        }
        self.flush_discarded();
        self.log_received(n, format_args!("{meaning}, discarded"));
    }

    fn keep_discarded_from_rx(&mut self, n: usize) {
        if self.transcript.is_some() {
            self.discarded.extend_from_slice(&self.rx.bytes()[..n]);
            if self.discarded.len() >= DISCARD_RECORD {
                self.flush_discarded();
            }
        }
        self.rx.consume(n);
    }

    pub(super) fn keep_discarded(&mut self, bytes: &[u8]) {
        if self.transcript.is_some() {
            self.discarded.extend_from_slice(bytes);
            if self.discarded.len() >= DISCARD_RECORD {
                self.flush_discarded();
            }
        }
    }

    /// Writes the discarded bytes gathered so far as one record.
    pub(super) fn flush_discarded(&mut self) {
        if self.discarded.is_empty() {
            return;
        }
        let bytes = std::mem::take(&mut self.discarded);
        if let Some(t) = &mut self.transcript {
            if let Err(e) = t.record(Entry::Received, &bytes, "not a reply, discarded") {
                self.close_transcript(&e);
            }
        }
        self.discarded = bytes;
        self.discarded.clear();
    }
}

/// What one exchange discarded, by kind.
#[derive(Debug, Default)]
pub(super) struct Discards {
    kinds: Vec<Discarded>,
}

#[derive(Debug)]
struct Discarded {
    kind: String,
    times: u64,
    bytes: u64,
    first: String,
}

/// How much of a discarded line a notice shows.
const SHOWN: usize = 80;

impl Discards {
    pub(super) fn count(&mut self, kind: &str, bytes: &[u8]) {
        if let Some(d) = self.kinds.iter_mut().find(|d| d.kind == kind) {
            // Counted, never shown again: one notice per kind, however long a flood goes on.
            d.times += 1;
            d.bytes += bytes.len() as u64;
            return;
        }
        let mut first = String::new();
        escape_into(&bytes[..bytes.len().min(SHOWN)], &mut first);
        if bytes.len() > SHOWN {
            first.push('…');
        }
        self.kinds.push(Discarded {
            kind: kind.to_string(),
            times: 1,
            bytes: bytes.len() as u64,
            first,
        });
    }

    pub(super) fn summary(&self) -> Vec<String> {
        self.kinds
            .iter()
            .map(|d| match d.times {
                1 => format!("ignored {}: {}", d.kind, d.first),
                n => format!(
                    "ignored {} {n} times ({} bytes), the first: {}",
                    d.kind, d.bytes, d.first
                ),
            })
            .collect()
    }
}
