//! ASCII requests whose exchange failed: their echo and reply may still come, and must be known
//! for what they are — neither taken for a later request's answer nor reported as noise. A
//! request repeated while an identical one is unanswered is spelled differently (see `ascii.rs`).

use std::collections::{BTreeMap, VecDeque};

use crate::dialect::tmcl::protocol::frame::{FRAME_LEN, ReplyFrame};
use crate::dialect::tmcl::protocol::line::address_of;
use crate::dialect::tmcl::protocol::reply::parse_reply_bytes;
use crate::dialect::tmcl::protocol::{ModuleName, Status};

use crate::session::rx::is_line_break;
use crate::session::wire::{Harmless, Peer};

/// How many failed requests are remembered.
const KEPT: usize = 8;

/// Failed requests, oldest first.
#[derive(Debug, Default)]
pub(super) struct Unanswered {
    entries: VecDeque<Entry>,
    /// Barriers given up, per module character, whose refusal may still come (see `barrier.rs`).
    lost_barriers: BTreeMap<char, u32>,
}

#[derive(Debug)]
struct Entry {
    /// The line as sent, without CR.
    line: Vec<u8>,
    /// Its echo has been seen: what comes next from its module is its reply.
    echoed: bool,
}

impl Unanswered {
    /// Remembers a request whose exchange failed, and whether its echo had come.
    pub(super) fn remember(&mut self, line: Vec<u8>, echoed: bool) {
        self.entries.retain(|e| e.line != line);
        self.entries.push_back(Entry { line, echoed });
        while self.entries.len() > KEPT {
            self.entries.pop_front();
        }
    }

    /// Whether `line` is an unanswered request as sent.
    pub(super) fn contains(&self, line: &[u8]) -> bool {
        self.entries.iter().any(|e| e.line == line)
    }

    /// A line arrived outside its exchange: whether it is the late echo of an unanswered
    /// request (which then waits only for its reply).
    pub(super) fn echo_arrived(&mut self, line: &[u8]) -> bool {
        match self
            .entries
            .iter_mut()
            .find(|e| e.line == line && !e.echoed)
        {
            Some(entry) => {
                entry.echoed = true;
                true
            }
            None => false,
        }
    }

    /// A reply of module character `module` arrived outside its exchange: whether it is the late
    /// reply of an unanswered request already echoed (which is then answered and forgotten).
    pub(super) fn reply_arrived(&mut self, module: char) -> bool {
        let position = self
            .entries
            .iter()
            .position(|e| e.echoed && e.line.first() == Some(&(module as u8)));
        position.map(|i| self.entries.remove(i)).is_some()
    }

    /// A barrier to module character `module` was answered: a module answers in order, so
    /// every request to it given up before has been answered or never will be.
    pub(super) fn forget(&mut self, module: char) {
        self.entries
            .retain(|e| e.line.first() != Some(&(module as u8)));
    }

    /// A barrier to module character `module` failed: its refusal may still come.
    pub(super) fn barrier_lost(&mut self, module: char) {
        *self.lost_barriers.entry(module).or_default() += 1;
    }

    /// A refusal like a barrier's arrived from module character `module` during another
    /// request: whether it is the late one of a barrier given up earlier (then counted off).
    pub(super) fn barrier_arrived(&mut self, module: char) -> bool {
        match self.lost_barriers.get_mut(&module) {
            Some(n) if *n > 0 => {
                *n -= 1;
                true
            }
            _ => false,
        }
    }

    /// A request to module character `module` was answered: in order, no barrier's refusal
    /// given up before it can come any more.
    pub(super) fn replied(&mut self, module: char) {
        self.lost_barriers.remove(&module);
    }

    /// Whether requests to module character `module` still wait for late answers.
    pub(super) fn pending(&self, module: char) -> bool {
        self.entries
            .iter()
            .any(|e| e.line.first() == Some(&(module as u8)))
    }
}

/// Recognises what may arrive between exchanges without making the line suspect: position-reached
/// events (the delayed second reply of command 138, as ASCII lines with status 128 or binary
/// frames of command 138), and the late echo and reply of a request given up earlier (a module
/// with none left is trusted again).
pub(super) fn harmless(bytes: &[u8], unanswered: &mut Unanswered) -> Option<Harmless> {
    let event = |module: ModuleName| format!("{module}: target position reached (event)");
    let mut found = Harmless::default();
    let mut ascii = true;
    for line in bytes.split(|&b| is_line_break(b)).filter(|l| !l.is_empty()) {
        match parse_reply_bytes(line) {
            Some(r) if r.status == Status::PositionReachedEvent => {
                found.notices.push(event(ModuleName::of_char(r.module)));
            }
            Some(r) if unanswered.reply_arrived(r.module) => {
                if let (false, Some(module)) = (unanswered.pending(r.module), address_of(r.module))
                {
                    found.answered.push(Peer::Module(module.into()));
                }
            }
            None if unanswered.echo_arrived(line) => {}
            _ => {
                ascii = false;
                break;
            }
        }
    }
    if ascii {
        return Some(found);
    }
    if bytes.is_empty() || bytes.len() % FRAME_LEN != 0 {
        return None;
    }
    let notices: Option<Vec<String>> = bytes
        .chunks(FRAME_LEN)
        .map(|chunk| {
            let frame: &[u8; FRAME_LEN] = chunk.try_into().ok()?;
            ReplyFrame::decode(frame)
                .ok()
                .filter(ReplyFrame::is_position_event)
                .map(|r| event(ModuleName(r.module)))
        })
        .collect();
    notices.map(|notices| Harmless {
        notices,
        answered: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_late_echo_then_its_reply_answers_a_request() {
        let mut u = Unanswered::default();
        u.remember(b"AGAP 1, 0".to_vec(), false);
        u.remember(b"BGAP 1, 0".to_vec(), true);
        assert!(!u.reply_arrived('A'), "A's echo has not come yet");
        assert!(u.echo_arrived(b"AGAP 1, 0"));
        assert!(!u.echo_arrived(b"AGAP 1, 0"), "one echo per request");
        assert!(u.reply_arrived('A'));
        assert!(!u.pending('A'));
        assert!(u.pending('B'));
        assert!(u.reply_arrived('B'), "B was echoed before it failed");
        assert!(!u.contains(b"BGAP 1, 0"));
    }

    #[test]
    fn only_the_latest_failures_are_kept() {
        let mut u = Unanswered::default();
        for i in 0..20 {
            u.remember(format!("AGAP {i}, 0").into_bytes(), false);
        }
        assert!(!u.contains(b"AGAP 0, 0"));
        assert!(u.contains(b"AGAP 19, 0"));
        assert_eq!(u.entries.len(), KEPT);
    }
}
