//! Session logic against a small scripted module whose quirks each test chooses (echo mode, line
//! endings, 139 reply, noise). The real simulator over ptys is exercised by the integration tests.

use crate::dialect::session::DialectSession;
use std::collections::VecDeque;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::frame::{CommandFrame, FrameDecoder, ReplyFrame};
use crate::dialect::tmcl::protocol::line::{self, Op};
use crate::dialect::tmcl::protocol::{Instruction, Status};
use crate::link::{Link, LinkError};

use super::{Echo, TmclReply, TmclSession, WireMode};
use crate::session::{SessionError, SessionOptions};

/// How the scripted module behaves.
#[derive(Clone)]
struct Quirks {
    ascii: bool,
    gp67: i32,
    replies_to_139: bool,
    reply_ending: &'static [u8],
    echo_ending: &'static [u8],
    silent: bool,
    echo_noise: bool,
    garbage_before_reply: &'static [u8],
    foreign_reply_first: bool,
    /// Sent before the echo: a reply that arrived late from an earlier exchange.
    stale_before_echo: &'static [u8],
    /// The link hands over one byte per read, as a slow serial line does.
    trickle: bool,
    /// The first `GAP 1, 0` is answered `7777`, and only just before the next line's answer:
    /// later than any wait for a quiet line.
    late_first_gap: bool,
    /// Replaces the reply line of the first `GAP 1, 0` (line end included).
    first_gap_reply: Option<&'static [u8]>,
    /// BIN gets no reply.
    bin_silent: bool,
}

impl Default for Quirks {
    fn default() -> Self {
        Quirks {
            ascii: false,
            gp67: 0,
            replies_to_139: true,
            reply_ending: b"\r",
            echo_ending: b"\r",
            silent: false,
            echo_noise: false,
            garbage_before_reply: b"",
            foreign_reply_first: false,
            stale_before_echo: b"",
            trickle: false,
            late_first_gap: false,
            first_gap_reply: None,
            bin_silent: false,
        }
    }
}

#[derive(Default)]
struct Wire {
    sent: Vec<u8>,
    out: VecDeque<u8>,
    /// Reads that waited for bytes that did not come.
    waits: usize,
    /// Every answer comes only when the next line arrives (a module a reply behind).
    lagging: bool,
}

struct FakeModule {
    quirks: Quirks,
    wire: Arc<Mutex<Wire>>,
    frames: FrameDecoder,
    line: Vec<u8>,
    position: i32,
    gaps: usize,
    /// Output held back (see `Quirks::late_first_gap`), and whether output goes there now.
    held: Vec<u8>,
    holding: bool,
}

impl FakeModule {
    fn input(&mut self, bytes: &[u8]) {
        for &b in bytes {
            if self.quirks.ascii {
                self.ascii_byte(b);
            } else {
                self.frames.push(&[b]);
                if let Some(Ok(frame)) = self.frames.next_frame() {
                    self.binary_frame(CommandFrame::decode(&frame).unwrap());
                }
            }
        }
    }

    fn emit(&mut self, bytes: &[u8]) {
        if self.holding {
            self.held.extend_from_slice(bytes);
        } else if !self.quirks.silent {
            self.wire.lock().unwrap().out.extend(bytes);
        }
    }

    fn binary_frame(&mut self, frame: CommandFrame) {
        if frame.address != 1 {
            return;
        }
        let i = frame.instruction;
        // GGP 3, 2 reads a user variable the other requests here do not.
        let value = match (i.command.number(), i.type_) {
            (6, 1) => self.position,
            (10, 3) => 333,
            _ => 0,
        };
        let lagging = self.wire.lock().unwrap().lagging;
        let held = std::mem::take(&mut self.held);
        self.emit(&held);
        self.holding = lagging;
        if i.command.number() == 139 {
            self.quirks.ascii = true;
            if !self.quirks.replies_to_139 {
                return;
            }
        }
        let reply = ReplyFrame {
            host: 2,
            module: 1,
            status: Status::Ok,
            command: i.command,
            value,
        };
        self.emit(&reply.encode());
        self.holding = false;
    }

    fn ascii_byte(&mut self, b: u8) {
        if b != b'\r' {
            self.line.push(b);
            return;
        }
        let text = String::from_utf8_lossy(&std::mem::take(&mut self.line)).into_owned();
        if !text.starts_with('A') {
            return; // not addressed to us (or garbage)
        }
        let held = std::mem::take(&mut self.held);
        self.emit(&held);
        let first_gap = text.contains("GAP 1, 0") && {
            self.gaps += 1;
            self.gaps == 1
        };
        let lagging = self.wire.lock().unwrap().lagging;
        self.holding = (first_gap && self.quirks.late_first_gap) || lagging;
        self.answer_line(&text, first_gap);
        self.holding = false;
    }

    fn answer_line(&mut self, text: &str, first_gap: bool) {
        self.emit(self.quirks.stale_before_echo);
        let echo = Echo::from_gp67(self.quirks.gp67);
        if echo != Echo::None {
            let mut shown = text.as_bytes().to_vec();
            if self.quirks.echo_noise {
                *shown.last_mut().unwrap() ^= 0x01;
            }
            self.emit(&shown);
            self.emit(self.quirks.echo_ending);
        }
        if self.quirks.foreign_reply_first {
            self.emit(b"BC 100 7\r");
        }
        self.emit(self.quirks.garbage_before_reply);
        if let (true, Some(reply)) = (first_gap, self.quirks.first_gap_reply) {
            self.emit(reply);
            return;
        }
        let profile = Profile::builtin();
        if text.ends_with(", 255") {
            // No motor 255: the barrier's refusal.
            self.emit(b"BA 4 0");
            self.emit(self.quirks.reply_ending);
            return;
        }
        let (status, value) = match line::parse(text, &profile).map(|l| l.op) {
            Ok(Op::Command(i)) if i.command.number() == 10 && i.type_ == 67 => {
                (100, self.quirks.gp67)
            }
            Ok(Op::Command(i)) if i.command.number() == 9 && i.type_ == 67 => {
                self.quirks.gp67 = i.value;
                (100, 0)
            }
            Ok(Op::Command(i))
                if i.command.number() == 6 && i.type_ == 1 && first_gap && self.holding =>
            {
                (100, 7777)
            }
            Ok(Op::Command(i)) if i.command.number() == 6 && i.type_ == 1 => (100, self.position),
            Ok(Op::Command(i)) if i.command.number() == 5 && i.type_ == 1 => {
                self.position = i.value;
                (100, 0)
            }
            Ok(Op::Command(i)) if i.command.number() == 6 && i.type_ == 200 => (3, 0),
            Ok(Op::Ascii(crate::dialect::tmcl::protocol::AsciiWord::Bin)) => {
                if !self.quirks.bin_silent {
                    self.emit(b"BA 100 0");
                    self.emit(self.quirks.reply_ending);
                }
                self.quirks.ascii = false;
                return;
            }
            Ok(_) => (100, 0),
            Err(_) => (2, 0),
        };
        self.emit(format!("BA {status} {value}").as_bytes());
        self.emit(self.quirks.reply_ending);
    }
}

struct FakeLink {
    module: FakeModule,
}

impl Link for FakeLink {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        self.module
            .wire
            .lock()
            .unwrap()
            .sent
            .extend_from_slice(bytes);
        self.module.input(bytes);
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        let mut wire = self.module.wire.lock().unwrap();
        if wire.out.is_empty() {
            if deadline > Instant::now() {
                wire.waits += 1;
            }
            drop(wire);
            // Nothing will ever arrive: the wait a real link would do until the deadline.
            std::thread::sleep(deadline.saturating_duration_since(Instant::now()));
            return Err(LinkError::Timeout);
        }
        let mut n = buf.len().min(wire.out.len());
        if self.module.quirks.trickle {
            n = n.min(1);
        }
        for slot in buf.iter_mut().take(n) {
            *slot = wire.out.pop_front().unwrap();
        }
        Ok(n)
    }

    fn describe(&self) -> String {
        "scripted module".into()
    }
}

fn options() -> SessionOptions {
    SessionOptions {
        timeout: Duration::from_millis(30),
        ..SessionOptions::default()
    }
}

fn open_with(
    quirks: Quirks,
    options: SessionOptions,
) -> (Result<TmclSession, SessionError>, Arc<Mutex<Wire>>) {
    let (link, wire) = fake_link(quirks);
    (
        TmclSession::open(link, Profile::builtin(), options, None),
        wire,
    )
}

/// A link to a fake module with `quirks`, and what crossed it.
fn fake_link(quirks: Quirks) -> (Box<FakeLink>, Arc<Mutex<Wire>>) {
    let wire = Arc::new(Mutex::new(Wire::default()));
    let module = FakeModule {
        quirks,
        wire: wire.clone(),
        frames: FrameDecoder::new(),
        line: Vec::new(),
        position: -5000,
        gaps: 0,
        held: Vec::new(),
        holding: false,
    };
    (Box::new(FakeLink { module }), wire)
}

/// How many times the frame of `instruction` to module 1 went out on `wire`.
fn frames_sent(wire: &Mutex<Wire>, instruction: Instruction) -> usize {
    let frame = CommandFrame {
        address: 1,
        instruction,
    }
    .encode();
    let sent = wire.lock().unwrap().sent.clone();
    sent.windows(9).filter(|w| *w == frame).count()
}

fn open(quirks: Quirks) -> (TmclSession, Arc<Mutex<Wire>>) {
    let (session, wire) = open_with(quirks, options());
    (session.expect("session opens"), wire)
}

fn sent_text(wire: &Arc<Mutex<Wire>>) -> String {
    String::from_utf8_lossy(&wire.lock().unwrap().sent).into_owned()
}

#[test]
fn enters_ascii_mode_reads_a_value_and_restores_binary_mode() {
    let (mut s, wire) = open(Quirks::default());
    assert_eq!(s.module_state(1), Some((WireMode::Ascii, Echo::Character)));
    let x = s.exchange_line("GAP actual_position, 0").unwrap();
    assert_eq!(x.sent, "AGAP 1, 0");
    assert_eq!(x.raw, "BA 100 -5000");
    assert_eq!(
        x.reply,
        TmclReply::Status {
            status: Status::Ok,
            value: -5000
        }
    );
    s.close();
    let sent = wire.lock().unwrap().sent.clone();
    let enter = CommandFrame {
        address: 1,
        instruction: Instruction::new(139, 0, 0, 0),
    }
    .encode();
    assert!(sent.starts_with(&enter), "139 frame first");
    assert_eq!(sent[9], b'\r', "a CR right after the frame clears garbage");
    assert!(sent_text(&wire).ends_with("ABIN\r"), "binary mode restored");
}

#[test]
fn every_echo_mode_with_every_line_ending() {
    let endings: [&'static [u8]; 4] = [b"", b"\r", b"\n", b"\r\n"];
    for gp67 in [0x00, 0x10, 0x20] {
        for echo_ending in endings {
            for reply_ending in &endings[1..] {
                let quirks = Quirks {
                    gp67,
                    echo_ending,
                    reply_ending,
                    ..Quirks::default()
                };
                let (mut s, _) = open(quirks);
                for round in 0..3 {
                    let x = s.exchange_line(&format!("SAP 1, 0, {round}")).unwrap();
                    assert!(
                        x.ok(),
                        "gp67={gp67:#x} echo_end={echo_ending:?} reply_end={reply_ending:?}"
                    );
                    let x = s.exchange_line("GAP 1, 0").unwrap();
                    assert_eq!(
                        x.value(),
                        Some(round),
                        "gp67={gp67:#x} {echo_ending:?} {reply_ending:?}"
                    );
                    assert_eq!(x.raw, format!("BA 100 {round}"));
                }
                assert!(s.take_notices().is_empty(), "no noise reported");
            }
        }
    }
}

#[test]
fn a_reply_arriving_byte_by_byte_is_read_without_noise_in_every_echo_mode() {
    for gp67 in [0x00, 0x10, 0x20] {
        let (mut s, _) = open(Quirks {
            gp67,
            trickle: true,
            ..Quirks::default()
        });
        for round in 0..3 {
            assert!(s.exchange_line(&format!("SAP 1, 0, {round}")).unwrap().ok());
            assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(round));
        }
        assert_eq!(s.take_notices(), Vec::<String>::new(), "gp67={gp67:#x}");
    }
}

#[test]
fn a_stale_reply_before_a_slow_echo_is_not_taken_for_the_answer() {
    let (mut s, _) = open(Quirks {
        stale_before_echo: b"BA 100 7\r",
        trickle: true,
        ..Quirks::default()
    });
    s.take_notices();
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    let notices = s.take_notices();
    assert!(
        notices.len() == 1 && notices[0].contains("before the echo"),
        "{notices:?}"
    );
}

#[test]
fn a_module_already_in_ascii_mode_is_left_in_it() {
    let quirks = Quirks {
        ascii: true,
        gp67: 0x21,
        ..Quirks::default()
    };
    let (mut s, wire) = open(quirks);
    assert_eq!(s.module_state(1), Some((WireMode::Ascii, Echo::None)));
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    s.close();
    assert!(
        !sent_text(&wire).contains("BIN"),
        "found in ASCII mode, so no BIN"
    );
}

#[test]
fn a_module_that_does_not_answer_139_is_still_entered_and_restored() {
    let quirks = Quirks {
        replies_to_139: false,
        ..Quirks::default()
    };
    let (mut s, wire) = open(quirks);
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    s.close();
    assert!(sent_text(&wire).ends_with("ABIN\r"));
}

#[test]
fn no_enter_skips_the_139_frame() {
    let quirks = Quirks {
        ascii: true,
        gp67: 0x20,
        ..Quirks::default()
    };
    let (link, wire) = fake_link(quirks);
    let mut s = TmclSession::open_idle(link, Profile::builtin(), options(), None).unwrap();
    s.no_enter = true;
    s.contact(1).unwrap();
    assert!(wire.lock().unwrap().sent.starts_with(b"AGGP 67, 0\r"));
    s.close();
    assert!(!sent_text(&wire).contains("BIN"));
}

#[test]
fn a_silent_module_times_out_with_a_clear_message() {
    let (session, _) = open_with(
        Quirks {
            silent: true,
            ..Quirks::default()
        },
        options(),
    );
    let e = session.err().expect("cannot open on a silent module");
    assert_eq!(crate::exit::ExitStatus::exit(&e), crate::exit::Exit::Link);
    let text = e.to_string();
    assert!(
        text.starts_with("no reply from module 1 (A) within 30 ms"),
        "{text}"
    );
    assert!(text.contains("does not answer in ASCII mode"), "{text}");
}

#[test]
fn a_reply_from_another_module_is_reported_not_taken() {
    let (mut s, _) = open(Quirks {
        foreign_reply_first: true,
        gp67: 0x20,
        ..Quirks::default()
    });
    s.take_notices();
    let x = s.exchange_line("GAP 1, 0").unwrap();
    assert_eq!(x.value(), Some(-5000));
    let notices = s.take_notices();
    assert!(
        notices
            .iter()
            .any(|n| n.contains("reply from module 3 (C) while waiting for module 1 (A)")),
        "{notices:?}"
    );
}

#[test]
fn garbage_before_the_reply_is_reported_and_skipped() {
    let (mut s, _) = open(Quirks {
        garbage_before_reply: b"\x8b\x01\x00junk\r",
        ..Quirks::default()
    });
    s.take_notices();
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    let notices = s.take_notices();
    assert!(
        notices
            .iter()
            .any(|n| n.contains("unexpected data") && n.contains("\\x8B")),
        "{notices:?}"
    );
}

#[test]
fn an_echo_that_differs_from_what_was_sent_is_line_noise() {
    let (session, _) = open_with(
        Quirks {
            echo_noise: true,
            ..Quirks::default()
        },
        options(),
    );
    let e = session.err().expect("noise while probing is an error");
    assert!(
        e.to_string()
            .contains("line noise: module 1 (A) echoed 'AGGP 67, 1' for 'AGGP 67, 0'"),
        "{e}"
    );
}

#[test]
fn refused_lines_send_nothing() {
    let (mut s, wire) = open(Quirks::default());
    let before = wire.lock().unwrap().sent.len();
    let e = s.exchange_line("SAP 6, 0, 99").unwrap_err();
    assert!(matches!(e, SessionError::Refused(_)), "{e}");
    assert!(s.exchange_line("CALC ADD, 1").is_err());
    assert!(s.exchange_line("GAPP 1, 0").is_err());
    assert_eq!(wire.lock().unwrap().sent.len(), before);
}

#[test]
fn no_validate_sends_what_parses_in_canonical_form() {
    let (s, wire) = open_with(
        Quirks::default(),
        SessionOptions {
            validate: false,
            ..options()
        },
    );
    let mut s = s.unwrap();
    let x = s.exchange_line("sap 6 0 99").unwrap();
    assert_eq!(x.sent, "ASAP 6, 0, 99");
    let x = s.exchange_line("gapp 1 0").unwrap();
    assert_eq!(x.sent, "AGAPP 1, 0");
    assert_eq!(x.status(), Some(Status::InvalidCommand));
    assert!(
        s.take_notices()
            .iter()
            .any(|n| n.starts_with("not validated"))
    );
    assert!(sent_text(&wire).contains("AGAPP 1, 0\r"));
}

#[test]
fn device_errors_come_back_as_unsuccessful_exchanges() {
    let (mut s, _) = open(Quirks::default());
    let x = s.exchange_line("GAP 200, 0").unwrap();
    assert!(!x.ok());
    assert_eq!(x.raw, "BA 3 0");
    let e = x.checked().unwrap_err();
    assert_eq!(
        e.to_string(),
        "module 1 (A) refused 'AGAP 200, 0': status 3 (wrong type)"
    );
}

#[test]
fn changing_the_echo_setting_is_followed() {
    let (mut s, _) = open(Quirks::default());
    assert_eq!(s.set_echo(1, Echo::Line).unwrap(), Echo::Line);
    assert_eq!(s.module_state(1), Some((WireMode::Ascii, Echo::Line)));
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    s.exchange_line("SGP 67, 0, 0x20").unwrap();
    assert_eq!(s.module_state(1), Some((WireMode::Ascii, Echo::None)));
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
}

#[test]
fn after_bin_lines_go_as_binary_frames() {
    let (mut s, wire) = open(Quirks::default());
    s.exchange_line("BIN").unwrap();
    assert_eq!(s.module_state(1).unwrap().0, WireMode::Binary);
    let x = s.exchange_line("GAP 1, 0").unwrap();
    assert_eq!(x.value(), Some(-5000));
    assert_eq!(x.raw, "BA 100 -5000");
    let frame = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 1, 0, 0),
    }
    .encode();
    assert!(wire.lock().unwrap().sent.ends_with(&frame));
    assert!(matches!(
        s.exchange_line("RUN"),
        Err(SessionError::Refused(_))
    ));
}

#[test]
fn stop_motion_sends_mst_to_modules_that_were_moved() {
    let (mut s, wire) = open(Quirks::default());
    assert!(s.stop_motion().is_empty());
    s.exchange_line("ROR 0, 1000").unwrap();
    assert!(s.may_be_moving());
    let report = s.stop_motion();
    assert_eq!(
        report,
        vec!["stopped motor 0 of module 1 (A) with MST".to_string()]
    );
    assert!(sent_text(&wire).ends_with("AMST 0\r"));
    assert!(!s.may_be_moving());
}

fn waits(wire: &Arc<Mutex<Wire>>) -> usize {
    wire.lock().unwrap().waits
}

#[test]
fn with_an_echo_an_identical_request_after_a_failure_is_spelled_so_its_echo_is_its_own() {
    for gp67 in [0x00, 0x10] {
        let (mut s, wire) = open(Quirks {
            gp67,
            late_first_gap: true,
            ..Quirks::default()
        });
        let e = s.exchange_line("GAP 1, 0").unwrap_err();
        assert!(matches!(e, SessionError::Timeout { .. }), "{e}");
        // The first request's echo and answer (7777) come just before the second's.
        let x = s.exchange_line("GAP 1, 0").unwrap();
        assert_eq!(x.value(), Some(-5000), "gp67={gp67:#x}");
        assert_eq!(x.sent, "AGAP 1, 0", "the canonical line is reported");
        assert!(
            sent_text(&wire).ends_with("A GAP 1, 0\r"),
            "{}",
            sent_text(&wire)
        );
        assert!(
            s.take_notices().iter().all(|n| !n.contains("ignored")),
            "late answers of a request given up are expected, not noise"
        );
        // Every late answer has come: the module is trusted again without a wait.
        let before = waits(&wire);
        let x = s.exchange_line("GAP 1, 0").unwrap();
        assert_eq!(x.value(), Some(-5000));
        assert!(
            sent_text(&wire).ends_with("\rAGAP 1, 0\r"),
            "back to the plain line"
        );
        assert_eq!(waits(&wire), before, "gp67={gp67:#x}");
    }
}

#[test]
fn without_an_echo_a_reply_later_than_the_quiet_wait_is_stopped_by_a_barrier() {
    let (mut s, wire) = open(Quirks {
        gp67: 0x20,
        ..Quirks::default()
    });
    // From now on the module answers each line only when the next one arrives.
    wire.lock().unwrap().lagging = true;
    assert!(s.exchange_line("GAP 1, 0").is_err());
    // The late 7777 comes when the barrier goes out: discarded, and the barrier's own refusal
    // is late too.
    let e = s.exchange_line("GAP 1, 0").unwrap_err();
    assert!(
        matches!(e, SessionError::Timeout { .. })
            && e.to_string().contains("barrier 'AGAP 1, 255'"),
        "{e}"
    );
    let sent = sent_text(&wire);
    let after = &sent[sent.rfind("AGAP 1, 255").unwrap()..];
    assert!(
        !after.contains("GAP 1, 0"),
        "the request was not sent: {sent:?}"
    );
    wire.lock().unwrap().lagging = false;
    // The next barrier's refusal follows the late one of the first; then the answer.
    let x = s.exchange_line("GAP 1, 0").unwrap();
    assert_eq!(x.value(), Some(-5000));
    assert_eq!(sent_text(&wire).matches("AGAP 1, 255\r").count(), 2);
    // The line is clean: no barrier before the next request.
    s.exchange_line("GAP 1, 0").unwrap();
    assert_eq!(sent_text(&wire).matches("AGAP 1, 255\r").count(), 2);
}

#[test]
fn with_an_echo_no_barrier_is_needed() {
    let (mut s, wire) = open(Quirks::default());
    wire.lock().unwrap().lagging = true;
    assert!(s.exchange_line("GAP 1, 0").is_err());
    wire.lock().unwrap().lagging = false;
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    assert!(!sent_text(&wire).contains("255"), "{}", sent_text(&wire));
}

#[test]
fn in_binary_mode_a_late_frame_is_stopped_by_a_barrier_of_another_command() {
    let (mut s, wire) = open(Quirks::default());
    s.exchange_line("BIN").unwrap();
    wire.lock().unwrap().lagging = true;
    assert!(s.exchange_line("GGP 3, 2").is_err());
    wire.lock().unwrap().lagging = false;
    // GGP 3, 2's 333 comes late, when the next frame goes out: the barrier (136, whose reply
    // names another command) is sent first and its reply discards it.
    let x = s.exchange_line("GGP 4, 2").unwrap();
    assert_eq!(x.value(), Some(0), "not GGP 3, 2's 333");
    let barrier = Instruction::new(136, 1, 0, 0);
    assert_eq!(frames_sent(&wire, barrier), 1);
    // A request of a command not in doubt needs none; the line is clean again anyway.
    s.exchange_line("GGP 4, 2").unwrap();
    assert_eq!(frames_sent(&wire, barrier), 1);
}

#[test]
fn in_binary_mode_a_lost_barrier_fails_the_request_unsent_and_the_next_tries_another() {
    let (mut s, wire) = open(Quirks::default());
    s.exchange_line("BIN").unwrap();
    wire.lock().unwrap().lagging = true;
    assert!(s.exchange_line("GGP 3, 2").is_err());
    let e = s.exchange_line("GGP 3, 2").unwrap_err();
    assert!(e.to_string().contains("to the barrier"), "{e}");
    wire.lock().unwrap().lagging = false;
    // GGP and 136 are in doubt: the next barrier is 135.
    assert_eq!(s.exchange_line("GGP 3, 2").unwrap().value(), Some(333));
    assert_eq!(frames_sent(&wire, Instruction::new(135, 0, 0, 0)), 1);
}

#[test]
fn after_a_timeout_the_next_request_waits_for_a_quiet_line_and_a_stop_does_not() {
    let (mut s, wire) = open(Quirks {
        gp67: 0x20,
        first_gap_reply: Some(b""),
        ..Quirks::default()
    });
    assert!(s.exchange_line("GAP 1, 0").is_err());
    let before = waits(&wire);
    let stops = s.stop_motors(1);
    assert!(stops.iter().all(|(_, r)| r.is_ok()), "{stops:?}");
    assert_eq!(waits(&wire), before, "MST went out at once");
    s.exchange_line("GAP 4, 0").unwrap();
    assert!(
        waits(&wire) > before,
        "an ordinary request resynchronised first"
    );
}

#[test]
fn a_reply_cut_short_by_a_corrupted_byte_is_line_noise() {
    for reply in [
        &b"BA 100 -50\r00\r"[..],
        b"BA 100 -5000\rBA 100 7\r",
        b"BA 150 -5000\r",
        b"BA 1\r00 -5000\r",
    ] {
        let (mut s, _) = open(Quirks {
            first_gap_reply: Some(reply),
            ..Quirks::default()
        });
        let e = s.exchange_line("GAP 1, 0").unwrap_err();
        assert!(e.to_string().starts_with("line noise"), "{e}");
        assert_eq!(crate::exit::ExitStatus::exit(&e), crate::exit::Exit::Link);
        assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    }
}

#[test]
fn no_cr_follows_a_bin_that_got_no_answer() {
    let (mut s, wire) = open(Quirks {
        bin_silent: true,
        ..Quirks::default()
    });
    let x = s.exchange_line("BIN").unwrap();
    assert_eq!(x.reply, TmclReply::Nothing);
    assert!(sent_text(&wire).ends_with("ABIN\r"), "{}", sent_text(&wire));
    assert_eq!(s.exchange_line("GAP 1, 0").unwrap().value(), Some(-5000));
    let frame = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 1, 0, 0),
    }
    .encode();
    let sent = wire.lock().unwrap().sent.clone();
    assert!(sent.ends_with(&[b"ABIN\r".as_slice(), &frame].concat()));
}

#[test]
fn ctrl_c_stops_the_target_and_what_was_moved_once_each() {
    let (s, wire) = open(Quirks::default());
    let mut session: Box<dyn DialectSession> = Box::new(s);
    session.execute("ROR 0, 1000").unwrap();
    let report = session.stop_target();
    assert_eq!(
        report,
        ["interrupted: stopped motor 0 of module 1 (A) with MST".to_string()]
    );
    assert_eq!(sent_text(&wire).matches("MST").count(), 1);
}

#[test]
fn the_late_reply_of_an_echoed_request_is_known_for_what_it_is() {
    let (mut s, wire) = open(Quirks {
        first_gap_reply: Some(b""),
        ..Quirks::default()
    });
    s.take_notices();
    // Echoed at once, answered only after the timeout: between exchanges…
    let e = s.exchange_line("GAP 1, 0").unwrap_err();
    assert!(e.to_string().contains("echoed but not answered"), "{e}");
    wire.lock().unwrap().out.extend(b"BA 100 7777\r");
    let before = waits(&wire);
    assert_eq!(s.exchange_line("GAP 4, 0").unwrap().value(), Some(0));
    assert_eq!(waits(&wire), before, "nothing more to wait for");
    // … or while the next request waits for its echo.
    let (mut s, _) = open(Quirks {
        first_gap_reply: Some(b""),
        stale_before_echo: b"BA 100 7777\r",
        ..Quirks::default()
    });
    assert!(s.exchange_line("GAP 1, 0").is_err());
    s.take_notices();
    assert_eq!(s.exchange_line("GAP 4, 0").unwrap().value(), Some(0));
    assert_eq!(
        s.take_notices(),
        Vec::<String>::new(),
        "the late answer is expected, not noise"
    );
    // With nothing unanswered, the same bytes are a stray reply again.
    assert_eq!(s.exchange_line("GAP 4, 0").unwrap().value(), Some(0));
    assert!(
        s.take_notices()
            .iter()
            .any(|n| n.contains("before the echo")),
        "reported"
    );
}

#[test]
fn an_answer_to_136_that_is_no_version_string_picks_no_profile() {
    // The scripted module answers 136 with an ordinary reply frame: eight bytes that are not
    // printable characters ('????????' before the check).
    let link = || {
        let module = FakeModule {
            quirks: Quirks::default(),
            wire: Arc::new(Mutex::new(Wire::default())),
            frames: FrameDecoder::new(),
            line: Vec::new(),
            position: -5000,
            gaps: 0,
            held: Vec::new(),
            holding: false,
        };
        Box::new(FakeLink { module })
    };
    // Without a profile given, nothing is guessed: the session is refused.
    let refused = TmclSession::connect(
        link(),
        Profile::builtin(),
        super::Connect::default(),
        options(),
        None,
    );
    let Err(SessionError::Failed(failure)) = refused else {
        panic!("opened without an identified module");
    };
    assert!(
        failure.message.contains("which is not a firmware version")
            && failure.message.contains("--profile NAME"),
        "{}",
        failure.message
    );
    // With one, the session goes on with it, and says so.
    let given = super::Connect {
        profile_given: true,
        ..super::Connect::default()
    };
    let mut s = TmclSession::connect(link(), Profile::builtin(), given, options(), None)
        .expect("the session opens");
    assert!(
        matches!(s.identity(), super::Identity::NoAnswer(_)),
        "{:?}",
        s.identity()
    );
    let notices = s.take_notices().join("\n");
    assert!(
        notices.contains("which is not a firmware version") && notices.contains("not identified"),
        "{notices}"
    );
    assert_eq!(s.profile().name, "tmcm-142", "the profile it started with");
    s.close();
}

/// A session on the built-in simulator in-process, on a manual clock.
fn on_the_simulator() -> TmclSession {
    let clock = Arc::new(crate::clock::ManualClock::new());
    let bus = crate::dialect::tmcl::sim::Bus::builtin();
    let link = crate::sim::inprocess::SimLink::new(Box::new(bus), clock);
    TmclSession::open(Box::new(link), Profile::builtin(), options(), None).unwrap()
}

#[test]
fn a_repeated_request_gets_each_reply_as_it_comes() {
    // The spelling and the checks of the last request, and the reading of the last reply, are
    // kept for a polling loop: what comes back must still be each reply's own.
    let mut s = on_the_simulator();
    let gap = Instruction::new(crate::dialect::tmcl::protocol::Opcode::Gap, 4, 0, 0);
    let sap = |v| Instruction::new(crate::dialect::tmcl::protocol::Opcode::Sap, 4, 0, v);
    for value in [100, 100, 2047, 100, 0, 0, 1] {
        s.request(1, sap(value)).unwrap();
        for _ in 0..2 {
            let x = s.request(1, gap).unwrap();
            assert_eq!(x.value(), Some(value));
            assert_eq!(x.sent, "AGAP 4, 0");
            assert_eq!(x.raw, format!("BA 100 {value}"));
        }
    }
    // Another module's line, then the same again: spelled for each.
    let x = s.exchange_line("GAP 4, 0").unwrap();
    assert_eq!((x.sent.as_str(), x.value()), ("AGAP 4, 0", Some(1)));
    // A line refused after one that was kept is checked on its own.
    let x = s.request(
        1,
        Instruction::new(crate::dialect::tmcl::protocol::Opcode::Gap, 4, 3, 0),
    );
    assert!(
        matches!(x, Err(SessionError::Refused(_))),
        "the module has one motor: {x:?}"
    );
    s.close();
}

#[test]
fn a_request_with_a_warning_warns_each_time() {
    let mut s = on_the_simulator();
    let profile = Profile::builtin();
    let unknown = (0..=255u8)
        .find(|&n| profile.axis_param(n).is_none())
        .expect("a number the profile does not describe");
    let line = format!("GAP {unknown}, 0");
    for _ in 0..3 {
        let _ = s.exchange_line(&line);
        let notices = s.take_notices().join("\n");
        assert!(notices.contains(&unknown.to_string()), "{notices}");
    }
    s.close();
}
