//! The wire's trust rules against a scripted link whose bytes arrive at chosen times.

use super::trust::RESYNC_MAX;
use super::*;

use std::collections::VecDeque;
use std::sync::{Arc, Mutex};

/// What the scripted link saw and will deliver.
#[derive(Default)]
struct Script {
    /// Bytes that become readable at a time.
    arrivals: VecDeque<(Instant, Vec<u8>)>,
    /// Bytes that arrive without end, in chunks (a flood).
    flood: Option<Vec<u8>>,
    /// recv calls that waited for something (deadline in the future, nothing readable).
    waits: usize,
    sent: Vec<u8>,
}

struct ScriptedLink(Arc<Mutex<Script>>);

impl Link for ScriptedLink {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        self.0.lock().unwrap().sent.extend_from_slice(bytes);
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        loop {
            let mut script = self.0.lock().unwrap();
            if let Some(flood) = &script.flood {
                let n = flood.len().min(buf.len());
                buf[..n].copy_from_slice(&flood[..n]);
                return Ok(n);
            }
            let now = Instant::now();
            if let Some((at, _)) = script.arrivals.front() {
                if *at <= now {
                    let (_, mut bytes) = script.arrivals.pop_front().unwrap();
                    let n = bytes.len().min(buf.len());
                    buf[..n].copy_from_slice(&bytes[..n]);
                    if n < bytes.len() {
                        script.arrivals.push_front((now, bytes.split_off(n)));
                    }
                    return Ok(n);
                }
            }
            if now >= deadline {
                return Err(LinkError::Timeout);
            }
            script.waits += 1;
            let next = script
                .arrivals
                .front()
                .map_or(deadline, |(at, _)| (*at).min(deadline));
            drop(script);
            std::thread::sleep(next.saturating_duration_since(now));
        }
    }

    fn describe(&self) -> String {
        "scripted".into()
    }
}

fn wire() -> (Wire, Arc<Mutex<Script>>) {
    let script = Arc::new(Mutex::new(Script::default()));
    (
        Wire::new(Box::new(ScriptedLink(script.clone())), None),
        script,
    )
}

fn arrive(script: &Arc<Mutex<Script>>, after: Duration, bytes: &[u8]) {
    script
        .lock()
        .unwrap()
        .arrivals
        .push_back((Instant::now() + after, bytes.to_vec()));
}

fn waits(script: &Arc<Mutex<Script>>) -> usize {
    script.lock().unwrap().waits
}

const TIMEOUT: Duration = Duration::from_millis(40);
const A: Peer = Peer::Module(1);
const B: Peer = Peer::Module(2);

#[test]
fn a_clean_line_never_waits_before_an_exchange() {
    let (mut w, script) = wire();
    for _ in 0..3 {
        w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
        w.finish(true);
    }
    assert_eq!(waits(&script), 0, "only polls");
    assert!(w.notices.is_empty());
}

#[test]
fn after_a_failure_a_late_reply_is_discarded_before_the_next_request() {
    let (mut w, script) = wire();
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(false);
    // The answer to the failed request turns up after the timeout.
    arrive(&script, TIMEOUT / 2, b"BA 100 -5000\r");
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    assert_eq!(w.rx.len(), 0, "nothing left for the next exchange");
    assert!(waits(&script) > 0, "waited for the line to go quiet");
    w.finish(true);
    assert!(
        w.notices
            .iter()
            .any(|n| n.contains("outside any exchange") && n.contains("BA 100 -5000")),
        "{:?}",
        w.notices
    );
    // Trusted again: the next exchange does not wait.
    let before = waits(&script);
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    assert_eq!(waits(&script), before);
}

#[test]
fn suspicion_is_per_peer_unless_replies_name_no_sender() {
    let (mut w, script) = wire();
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(false);
    w.begin(B, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(true);
    assert_eq!(
        waits(&script),
        0,
        "module B's replies cannot be taken for A's"
    );
    w.begin(Peer::Any, false, TIMEOUT, &mut nothing_benign)
        .unwrap();
    w.finish(true);
    assert!(waits(&script) > 0, "an anonymous reply could be A's");
    let (mut w, script) = wire();
    w.begin(Peer::Any, false, TIMEOUT, &mut nothing_benign)
        .unwrap();
    w.finish(false);
    w.begin(B, false, TIMEOUT, &mut nothing_benign).unwrap();
    assert!(
        waits(&script) > 0,
        "an anonymous late reply could pass for B's"
    );
}

#[test]
fn urgent_requests_go_out_at_once_and_the_line_stays_suspect() {
    let (mut w, script) = wire();
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(false);
    w.begin(A, true, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(true);
    assert_eq!(waits(&script), 0, "a stop does not wait");
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    assert!(waits(&script) > 0, "the next ordinary request does");
}

#[test]
fn stale_bytes_between_exchanges_make_the_line_suspect_but_line_ends_and_events_do_not() {
    let (mut w, script) = wire();
    arrive(&script, Duration::ZERO, b"\r\n\0\r");
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(true);
    arrive(&script, Duration::ZERO, b"EVENT\r");
    let mut events = |b: &[u8]| {
        (b == b"EVENT\r").then(|| Harmless {
            notices: vec!["an event".to_string()],
            answered: Vec::new(),
        })
    };
    w.begin(A, false, TIMEOUT, &mut events).unwrap();
    w.finish(true);
    assert_eq!(waits(&script), 0);
    assert_eq!(w.notices, ["an event"]);
    arrive(&script, Duration::ZERO, b"BA 100 7\r");
    w.begin(A, false, TIMEOUT, &mut events).unwrap();
    assert!(waits(&script) > 0, "a stray reply: resynchronised first");
}

#[test]
fn late_answers_a_dialect_vouches_for_end_the_suspicion_of_their_peer() {
    let (mut w, script) = wire();
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(false);
    arrive(&script, Duration::ZERO, b"LATE\r");
    let mut late = |b: &[u8]| {
        (b == b"LATE\r").then(|| Harmless {
            notices: Vec::new(),
            answered: vec![A],
        })
    };
    w.begin(A, false, TIMEOUT, &mut late).unwrap();
    assert_eq!(waits(&script), 0, "nothing more is on its way from A");
}

#[test]
fn a_line_that_never_goes_quiet_fails_without_sending_in_bounded_time() {
    let (mut w, script) = wire();
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.finish(false);
    script.lock().unwrap().flood = Some(b"junk\r".repeat(200));
    let started = Instant::now();
    let e = w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap_err();
    w.finish(false);
    assert!(e.to_string().contains("did not go quiet"), "{e}");
    assert!(started.elapsed() < Duration::from_secs(10), "hang guard");
    assert!(script.lock().unwrap().sent.is_empty());
    assert_eq!(w.notices.len(), 1, "one summary: {:?}", w.notices);
    assert!(w.notices[0].contains(" times ("), "{:?}", w.notices);
}

#[test]
fn a_flood_between_exchanges_is_read_within_a_budget() {
    let (mut w, script) = wire();
    script.lock().unwrap().flood = Some(vec![b'7'; 4096]);
    let e = w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap_err();
    assert!(e.to_string().contains("did not go quiet"), "{e}");
}

#[test]
fn what_follows_a_reply_decides_whether_it_is_taken() {
    let cases: [(&[u8], Option<usize>); 12] = [
        (b"BA 100 5\r", Some(9)),
        (b"BA 100 5\r\n\0", Some(11)),
        (b"BA 100 5\r\0\n", Some(11)),
        (b"BA 100 -800\r143\r", None),
        (b"BA 100 5\rBA 100 6\r", None),
        (b"BA 100 5\r14", None),
        (b"BA 100 5\rOK\r", Some(12)),
        (b"BA 100 5\rOK\r\n", Some(13)),
        // A line end more than the reply's own: its last digit was corrupted into one.
        (b"BA 100 5\r\r", None),
        (b"BA 100 5\r\n\r\n", None),
        (b"BA 100 5\n\r", None),
        (b"BA 100 5\rOK\r\r", None),
    ];
    for (bytes, expected) in cases {
        let (mut w, _) = wire();
        w.rx.extend(bytes).unwrap();
        let deadline = Instant::now() + TIMEOUT;
        let settled = w.settle(9, deadline, &mut |l| l == b"OK").unwrap();
        let expected = expected.map_or(Settled::Noise, Settled::Clean);
        assert_eq!(settled, expected, "{}", String::from_utf8_lossy(bytes));
    }
}

#[test]
fn bytes_that_follow_at_the_line_pace_are_waited_for() {
    let (mut w, script) = wire();
    let byte = Duration::from_millis(10);
    for (i, b) in b"BA 100 -800\r143\r".iter().enumerate() {
        arrive(&script, byte * (i as u32 + 1), &[*b]);
    }
    let deadline = Instant::now() + Duration::from_secs(5);
    while w.rx.line_end(0).is_none() {
        assert!(w.fill(deadline).unwrap());
    }
    assert!(
        w.settle_time() > Duration::ZERO,
        "paced bytes: wait for the next"
    );
    assert_eq!(
        w.settle(12, deadline, &mut |_| false).unwrap(),
        Settled::Noise
    );
}

#[test]
fn a_burst_costs_only_a_poll() {
    let (mut w, script) = wire();
    arrive(&script, Duration::ZERO, b"AGAP 1, 0\rBA 100 5\r");
    let deadline = Instant::now() + TIMEOUT;
    assert!(w.fill(deadline).unwrap());
    assert_eq!(w.settle_time(), Duration::ZERO);
    assert_eq!(
        w.settle(19, deadline, &mut |_| false).unwrap(),
        Settled::Clean(19)
    );
    assert_eq!(waits(&script), 0);
}

#[test]
fn discards_are_summarised_once_per_kind() {
    let (mut w, _) = wire();
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    for _ in 0..1000 {
        w.rx.extend(b"junk\r").unwrap();
        w.discard(5, "unexpected data from the line");
    }
    w.rx.extend(b"BC 100 1\r").unwrap();
    w.discard(9, "a reply from module C");
    w.finish(true);
    assert_eq!(
        w.notices,
        [
            "ignored unexpected data from the line 1000 times (5000 bytes), the first: \"junk\\r\"",
            "ignored a reply from module C: \"BC 100 1\\r\"",
        ]
    );
}

#[test]
fn the_resync_window_scales_with_the_byte_time() {
    struct Slow;
    impl Link for Slow {
        fn send(&mut self, _: &[u8]) -> Result<(), LinkError> {
            Ok(())
        }
        fn recv(&mut self, _: &mut [u8], _: Instant) -> Result<usize, LinkError> {
            Err(LinkError::Timeout)
        }
        fn describe(&self) -> String {
            "300 baud".into()
        }
        fn byte_time(&self) -> Option<Duration> {
            Some(Duration::from_secs_f64(10.0 / 300.0))
        }
    }
    let w = Wire::new(Box::new(Slow), None);
    let window = w.resync_window(Duration::from_millis(100));
    assert!(window > Duration::from_secs(1), "{window:?}");
    let (w, _) = wire();
    assert_eq!(w.resync_window(TIMEOUT), TIMEOUT);
    assert_eq!(w.resync_window(Duration::from_secs(60)), RESYNC_MAX);
}

#[test]
fn the_quiet_gap_before_a_frame_counts_from_the_last_byte_heard_too() {
    // On a bus a module in binary mode hears the other modules' replies as well as our lines:
    // the gap its frame receiver needs starts after the reply, not after our request.
    let (mut wire, script) = wire();
    let start = Instant::now();
    wire.send(b"AGAP 1, 0\r", "").unwrap();
    arrive(&script, Duration::from_millis(40), b"BA 100 0\r");
    assert!(wire.fill(start + Duration::from_secs(5)).unwrap());
    wire.idle_for(Duration::from_millis(60)).unwrap();
    // The reply came 40 ms or more after `start`, so the line was quiet only 60 ms after that.
    assert!(
        start.elapsed() >= Duration::from_millis(100),
        "idle only until {:?}",
        start.elapsed()
    );
}

#[test]
fn a_shared_line_is_read_until_quiet_from_its_opening_and_a_private_one_is_not_waited_for() {
    // Opened on a shared line, the first quiet gap counts from the opening, and a reply another
    // program left arriving meanwhile is read (for the caller to drain) and starts it again.
    let (mut wire, script) = wire();
    arrive(
        &script,
        Duration::from_millis(20),
        b"\x02\x01\x64\x06\x00\x00\x00\x00\x6D",
    );
    wire.idle_for(Duration::from_millis(60)).unwrap();
    assert_eq!(wire.rx.len(), 9, "the stale reply was read while waiting");
    // A private link (the in-process simulator) has nobody else: nothing to wait for.
    struct Private(ScriptedLink);
    impl Link for Private {
        fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
            self.0.send(bytes)
        }
        fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
            self.0.recv(buf, deadline)
        }
        fn describe(&self) -> String {
            "private".into()
        }
        fn private(&self) -> bool {
            true
        }
    }
    let script = Arc::new(Mutex::new(Script::default()));
    let mut wire = Wire::new(Box::new(Private(ScriptedLink(script.clone()))), None);
    wire.idle_for(Duration::from_millis(60)).unwrap();
    assert_eq!(
        waits(&script),
        0,
        "a private line is not waited for at its opening"
    );
}

#[test]
fn a_line_that_never_falls_quiet_is_reported_not_waited_for_for_ever() {
    let (mut wire, script) = wire();
    script.lock().unwrap().flood = Some(b"BA 100 0\r".to_vec());
    // It ends in an error (here the receive buffer's bound comes first), never a hang.
    let err = wire.idle_for(Duration::from_millis(20)).unwrap_err();
    assert!(
        matches!(err, SessionError::Link(_) | SessionError::Noise { .. }),
        "{err}"
    );
}

/// Sends `bytes` as the first request of a session, marked as the probe of echo detection.
fn probe(w: &mut Wire, bytes: &[u8]) {
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.probe_echo();
    w.send(bytes, "probe").unwrap();
}

#[test]
fn an_echo_found_at_open_is_stripped_then_and_after() {
    let (mut w, script) = wire();
    probe(&mut w, b"REQ1");
    arrive(&script, Duration::ZERO, b"RE");
    arrive(&script, Duration::from_millis(2), b"Q1ANS1");
    let deadline = Instant::now() + TIMEOUT;
    while w.rx.len() < 4 && w.fill(deadline).unwrap() {}
    assert_eq!(w.rx.bytes(), b"ANS1");
    assert!(w.strips_echo());
    assert_eq!(w.notices.len(), 1, "{:?}", w.notices);
    w.rx.clear();
    w.finish(true);
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.send(b"REQ2", "second").unwrap();
    arrive(&script, Duration::ZERO, b"REQ2ANS2");
    while w.rx.len() < 4 && w.fill(deadline).unwrap() {}
    assert_eq!(w.rx.bytes(), b"ANS2");
    assert_eq!(w.notices.len(), 1, "announced once");
}

#[test]
fn no_echo_at_open_leaves_the_answer_whole() {
    let (mut w, script) = wire();
    // The answer begins like the request and then differs: held aside, then given back.
    probe(&mut w, b"\x01REQ");
    arrive(&script, Duration::ZERO, b"\x01RE");
    arrive(&script, Duration::from_millis(2), b"PLY");
    let deadline = Instant::now() + TIMEOUT;
    while w.rx.len() < 6 && w.fill(deadline).unwrap() {}
    assert_eq!(w.rx.bytes(), b"\x01REPLY");
    assert!(!w.strips_echo());
    w.rx.clear();
    w.finish(true);
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.probe_echo();
    w.send(b"AB", "second").unwrap();
    arrive(&script, Duration::ZERO, b"AB");
    while w.rx.len() < 2 && w.fill(deadline).unwrap() {}
    assert_eq!(
        w.rx.bytes(),
        b"AB",
        "decided once: an answer like the request is kept"
    );
    assert!(w.notices.is_empty());
}

#[test]
fn an_echo_that_differs_is_line_noise() {
    let (mut w, script) = wire();
    w.set_local_echo(crate::session::LocalEcho::On);
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.send(b"SAP 4", "request").unwrap();
    arrive(&script, Duration::ZERO, b"SAX 4 and more");
    let deadline = Instant::now() + TIMEOUT;
    let error = loop {
        match w.fill(deadline) {
            Ok(true) => continue,
            Ok(false) => panic!("no error"),
            Err(e) => break e,
        }
    };
    assert!(
        error
            .to_string()
            .starts_with("line noise: the adapter's echo"),
        "{error}"
    );
    assert_eq!(w.rx.len(), 0, "nothing of it is kept");
    w.finish(false);
    // The next exchange begins on a clean line: nothing more is expected back.
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.send(b"GAP", "next").unwrap();
    arrive(&script, Duration::ZERO, b"GAPok");
    while w.rx.len() < 2 && w.fill(deadline).unwrap() {}
    assert_eq!(w.rx.bytes(), b"ok");
}

#[test]
fn an_echo_of_a_request_without_answer_is_stripped_between_exchanges() {
    let (mut w, script) = wire();
    w.set_local_echo(crate::session::LocalEcho::On);
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    w.send(b"RESET", "no answer").unwrap();
    w.finish(true);
    arrive(&script, Duration::ZERO, b"RESET");
    std::thread::sleep(Duration::from_millis(2));
    w.begin(A, false, TIMEOUT, &mut nothing_benign).unwrap();
    assert_eq!(w.rx.len(), 0);
    assert!(w.notices.is_empty(), "{:?}", w.notices);
    assert!(!w.suspect.covers(A), "an echo is no stray data");
}
