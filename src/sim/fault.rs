//! Fault injection for reliability tests: drop, corrupt or delay replies at a given rate, go
//! silent, or hang up after a number of replies. Decisions come from a seeded generator, so a
//! run with the same seed and traffic fails the same way every time.
//!
//! The seed is part of the run's description: `tmclsh sim --seed N` (or the console's `seed N`,
//! which also restarts the counts) replays the same decisions for the same traffic, and the
//! console's `faults` shows how many of each were injected, so a soak can tell what it survived.
//!
//! A "reply" is what the wrapped device sends in answer to one piece of input (or at one event,
//! such as the second reply of command 138): with the strict request/reply protocols served here
//! that is one reply frame or line, together with its echo in ASCII mode. Wrap pacing around
//! faults, not the other way round, so that a reply is whole when it is judged.

use std::collections::VecDeque;
use std::time::Duration;

use super::Device;
use super::error::ConsoleError;

/// Which faults to inject.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Faults {
    /// Probability (0..1) that a reply is dropped.
    pub drop_rate: f64,
    /// Probability that one byte of a reply is changed.
    pub corrupt_rate: f64,
    /// Probability that a reply is held back by `delay`.
    pub delay_rate: f64,
    /// How long a delayed reply is held back.
    pub delay: Duration,
    /// After this many replies the device keeps executing commands but answers nothing more.
    pub silent_after: Option<u64>,
    /// After this many replies the connection is hung up (counted again after a reconnect).
    pub hangup_after: Option<u64>,
    /// Seed of the decisions.
    pub seed: u64,
}

impl Faults {}

/// xorshift64*: tiny, fast and deterministic; quality is ample for fault decisions.
#[derive(Debug, Clone)]
struct Rng(u64);

impl Rng {
    /// The state is the seed through splitmix64's finaliser, a bijection, so every seed starts a
    /// sequence of its own (xorshift needs a non-zero state; the one seed that mixes to zero
    /// takes a fixed one instead).
    fn new(seed: u64) -> Rng {
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        Rng(if z == 0 { 0x9E37_79B9_7F4A_7C15 } else { z })
    }

    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// True with probability `p`.
    fn chance(&mut self, p: f64) -> bool {
        p > 0.0 && ((self.next() >> 11) as f64 / (1u64 << 53) as f64) < p
    }
}

/// How many faults were injected since the seed was last set.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Injected {
    /// Replies judged (delivered, dropped or silenced).
    pub replies: u64,
    /// Replies dropped at `drop_rate` (silence and hang-ups not counted).
    pub dropped: u64,
    /// Replies with one byte changed.
    pub corrupted: u64,
    /// Replies held back by `delay`.
    pub delayed: u64,
}

/// What `seed N` takes: every `u64` (written out, as a message's hint must be a constant).
const SEEDS: &str = "a seed (0..18446744073709551615)";

/// A device whose replies suffer the configured faults.
pub struct Faulty<D> {
    inner: D,
    faults: Faults,
    rng: Rng,
    injected: Injected,
    /// Replies judged since the last (re)connection.
    replies: u64,
    /// Replies delivered since the last (re)connection.
    delivered: u64,
    silent: bool,
    hung: bool,
    queue: VecDeque<(Duration, Vec<u8>)>,
    scratch: Vec<u8>,
}

impl<D: Device> Faulty<D> {
    /// Wraps `inner`.
    pub fn new(inner: D, faults: Faults) -> Faulty<D> {
        Faulty {
            inner,
            rng: Rng::new(faults.seed),
            faults,
            injected: Injected::default(),
            replies: 0,
            delivered: 0,
            silent: false,
            hung: false,
            queue: VecDeque::new(),
            scratch: Vec::new(),
        }
    }

    /// Restarts the fault decisions from `seed` and the counts from zero (console `seed N`):
    /// the same seed and the same traffic from here on give the same faults.
    pub fn reseed(&mut self, seed: u64) {
        self.faults.seed = seed;
        self.rng = Rng::new(seed);
        self.injected = Injected::default();
    }

    /// The faults injected since the seed was set.
    pub fn injected(&self) -> Injected {
        self.injected
    }

    /// Hangs up now (console `hangup`).
    pub fn hang_up(&mut self) {
        self.hung = true;
        self.queue.clear();
    }

    /// Goes silent, or talks again (console `silent on|off`).
    pub fn set_silent(&mut self, silent: bool) {
        self.silent = silent;
    }

    /// Judges what the inner device sent by `now`.
    fn collect(&mut self, now: Duration) {
        self.inner.poll_output(now, &mut self.scratch);
        if self.scratch.is_empty() {
            return;
        }
        let mut reply = std::mem::take(&mut self.scratch);
        self.replies += 1;
        self.injected.replies += 1;
        let silenced = self.silent || self.faults.silent_after.is_some_and(|n| self.replies > n);
        let dropped = !(self.hung || silenced) && self.rng.chance(self.faults.drop_rate);
        if self.hung || silenced || dropped {
            self.injected.dropped += u64::from(dropped);
            reply.clear();
            self.scratch = reply;
            return;
        }
        if self.rng.chance(self.faults.corrupt_rate) {
            let at = (self.rng.next() % reply.len() as u64) as usize;
            reply[at] ^= (self.rng.next() as u8) | 1;
            self.injected.corrupted += 1;
        }
        let release = if self.rng.chance(self.faults.delay_rate) {
            self.injected.delayed += 1;
            now + self.faults.delay
        } else {
            now
        };
        // Replies keep their order: a reply never overtakes a delayed one.
        let release = self.queue.back().map_or(release, |(t, _)| release.max(*t));
        self.queue.push_back((release, reply));
    }
}

impl<D: Device> Device for Faulty<D> {
    pass_on!(inner: byte_time);

    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        if self.hung {
            return;
        }
        self.inner.receive(now, bytes);
        self.collect(now);
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        self.collect(now);
        while let Some((at, _)) = self.queue.front() {
            if *at > now || self.hung {
                break;
            }
            let (_, reply) = self.queue.pop_front().expect("front exists");
            out.extend_from_slice(&reply);
            self.delivered += 1;
            if self.faults.hangup_after == Some(self.delivered) {
                self.hang_up();
            }
        }
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        if self.hung {
            return None;
        }
        match (self.queue.front(), self.inner.next_due(now)) {
            (Some((t, _)), Some(d)) => Some((*t).min(d)),
            (Some((t, _)), None) => Some(*t),
            (None, d) => d,
        }
    }

    fn hung_up(&self) -> bool {
        self.hung || self.inner.hung_up()
    }

    fn reconnect(&mut self) {
        self.hung = false;
        self.replies = 0;
        self.delivered = 0;
        self.queue.clear();
        self.inner.reconnect();
    }

    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        let words: Vec<&str> = command.split_whitespace().collect();
        let rate = |text: &str| {
            text.parse::<f64>()
                .ok()
                .filter(|r| (0.0..=1.0).contains(r))
                .ok_or_else(|| ConsoleError::bad(text, "a rate between 0 and 1"))
        };
        let result = match words.as_slice() {
            ["hangup"] => {
                self.hang_up();
                Ok("hung up".to_string())
            }
            ["silent", "on"] => {
                self.set_silent(true);
                Ok("silent".to_string())
            }
            ["silent", "off"] => {
                self.set_silent(false);
                Ok("talking".to_string())
            }
            ["seed", n] => n
                .parse::<u64>()
                .map_err(|_| ConsoleError::bad(n, SEEDS))
                .map(|seed| {
                    self.reseed(seed);
                    format!("seed {seed}")
                }),
            ["faults"] => {
                let Injected {
                    replies,
                    dropped,
                    corrupted,
                    delayed,
                } = self.injected;
                Ok(format!(
                    "seed {} replies {replies} dropped {dropped} corrupted {corrupted} delayed {delayed}",
                    self.faults.seed
                ))
            }
            ["drop", r] => rate(r).map(|r| {
                self.faults.drop_rate = r;
                format!("drop rate {r}")
            }),
            ["corrupt", r] => rate(r).map(|r| {
                self.faults.corrupt_rate = r;
                format!("corrupt rate {r}")
            }),
            ["delay", r, ms] => rate(r).and_then(|r| {
                let ms: u64 = ms
                    .parse()
                    .map_err(|_| ConsoleError::bad(ms, "a number of milliseconds"))?;
                self.faults.delay_rate = r;
                self.faults.delay = Duration::from_millis(ms);
                Ok(format!("delay rate {r}, {ms} ms"))
            }),
            _ => return self.inner.control(now, command),
        };
        Some(result)
    }
}

#[cfg(test)]
mod tests;
