//! The CAN link over a scripted serial line: the slcan open sequence, acknowledgements of each
//! style, BEL, silence, and frames not for the host.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use super::slcan::{AckStyle, Decoder, Event};
use super::*;

/// The far end's answer to one line.
type Answer = Box<dyn FnMut(&str) -> Vec<u8> + Send>;

/// A serial line whose far end answers each CR-ended command through `answer`.
struct Scripted {
    sent: Arc<Mutex<Vec<u8>>>,
    incoming: VecDeque<u8>,
    answer: Answer,
    line: Vec<u8>,
    /// Whether a read takes everything there is, as a port's read(2) does.
    reads_all: bool,
}

impl Scripted {
    fn new(
        answer: impl FnMut(&str) -> Vec<u8> + Send + 'static,
    ) -> (Scripted, Arc<Mutex<Vec<u8>>>) {
        let sent = Arc::new(Mutex::new(Vec::new()));
        let link = Scripted {
            sent: sent.clone(),
            incoming: VecDeque::new(),
            answer: Box::new(answer),
            line: Vec::new(),
            reads_all: false,
        };
        (link, sent)
    }
}

impl Link for Scripted {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        self.sent.lock().unwrap().extend_from_slice(bytes);
        for &b in bytes {
            if b == b'\r' {
                let line = String::from_utf8(std::mem::take(&mut self.line)).unwrap();
                let reply = (self.answer)(&line);
                self.incoming.extend(reply);
            } else {
                self.line.push(b);
            }
        }
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], _deadline: Instant) -> Result<usize, LinkError> {
        if self.incoming.is_empty() {
            return Err(LinkError::Timeout);
        }
        let n = buf.len().min(self.incoming.len());
        for (slot, b) in buf.iter_mut().zip(self.incoming.drain(..n)) {
            *slot = b;
        }
        Ok(n)
    }

    fn describe(&self) -> String {
        "scripted".into()
    }

    fn reads_all(&self) -> bool {
        self.reads_all
    }
}

/// An adapter acknowledging frames in `style`, with a module 1 answering every request with
/// status 100 (and a heartbeat of node 0x705 before it).
fn adapter(style: AckStyle) -> impl FnMut(&str) -> Vec<u8> + Send {
    move |line: &str| {
        let mut out = Vec::new();
        if line.starts_with('t') {
            out.extend_from_slice(style.bytes());
            out.extend_from_slice(b"t705105\r");
            let mut events = Vec::new();
            Decoder::default().push(format!("{line}\r").as_bytes(), &mut events);
            if let [Event::Frame(f)] = events.as_slice() {
                let d = f.data();
                let reply =
                    CanFrame::new(2, &[f.id() as u8, 100, d[0], d[3], d[4], d[5], d[6]]).unwrap();
                out.extend_from_slice(slcan::encode(&reply).as_bytes());
            }
        } else {
            out.push(b'\r');
        }
        out
    }
}

/// Bytes in, bytes out: a framer that sends each byte as a one-byte frame to ID 1 and takes
/// frames to ID 2.
struct Echoing;

impl Framer for Echoing {
    fn frames(&mut self, bytes: &[u8]) -> Vec<CanFrame> {
        vec![CanFrame::new(1, bytes).unwrap()]
    }

    fn bytes(&mut self, frame: &CanFrame) -> Option<Vec<u8>> {
        (frame.id() == 2).then(|| frame.data().to_vec())
    }

    fn describe(&self) -> String {
        "test".into()
    }
}

const TIMEOUT: Duration = Duration::from_millis(50);

#[test]
fn the_open_sequence_closes_sets_the_rate_and_opens() {
    let (serial, sent) = Scripted::new(adapter(AckStyle::Lower));
    SlcanLink::open(Box::new(serial), "test", 500_000, TIMEOUT).unwrap();
    assert_eq!(&*sent.lock().unwrap(), b"C\rS6\rO\r");
}

#[test]
fn every_ack_style_gives_the_same_replies_and_foreign_frames_are_counted() {
    for style in [
        AckStyle::Lower,
        AckStyle::Upper,
        AckStyle::Cr,
        AckStyle::None,
    ] {
        let (serial, _) = Scripted::new(adapter(style));
        let bus = SlcanLink::open(Box::new(serial), "test", 1_000_000, TIMEOUT).unwrap();
        let mut link = CanLink::new(Box::new(bus), Box::new(Echoing));
        link.send(&[6, 1, 0, 0, 0, 0, 7]).unwrap();
        let mut buf = [0u8; 16];
        let n = link.recv(&mut buf, Instant::now() + TIMEOUT).unwrap();
        assert_eq!(&buf[..n], &[1, 100, 6, 0, 0, 0, 7], "{style:?}");
        assert_eq!(link.foreign_frames(), 1);
        assert!(matches!(
            link.recv(&mut buf, Instant::now()),
            Err(LinkError::Timeout)
        ));
    }
}

#[test]
fn a_silent_adapter_is_named_and_a_refusing_one_reported() {
    let (serial, _) = Scripted::new(|_: &str| Vec::new());
    let Err(LinkError::Open(why)) = SlcanLink::open(Box::new(serial), "/dev/x", 1_000_000, TIMEOUT)
    else {
        panic!("a silent adapter opened");
    };
    assert!(
        why.contains("did not answer the slcan command `C`"),
        "{why}"
    );
    let (serial, _) = Scripted::new(|line: &str| if line == "O" { vec![7] } else { vec![13] });
    let Err(LinkError::Adapter(why)) =
        SlcanLink::open(Box::new(serial), "/dev/x", 1_000_000, TIMEOUT)
    else {
        panic!("a refused open was taken");
    };
    assert!(why.contains("refused `O` (BEL)"), "{why}");
}

#[test]
fn a_bell_while_receiving_is_the_adapters_error() {
    let (serial, _) = Scripted::new(|line: &str| {
        if line.starts_with('t') {
            vec![7]
        } else {
            vec![13]
        }
    });
    let bus = SlcanLink::open(Box::new(serial), "/dev/x", 1_000_000, TIMEOUT).unwrap();
    let mut link = CanLink::new(Box::new(bus), Box::new(Echoing));
    link.send(&[1]).unwrap();
    let mut buf = [0u8; 4];
    assert!(matches!(
        link.recv(&mut buf, Instant::now() + TIMEOUT),
        Err(LinkError::Adapter(why)) if why.contains("BEL")
    ));
}

#[test]
fn an_unknown_bit_rate_is_refused_before_anything_is_sent() {
    let (serial, sent) = Scripted::new(adapter(AckStyle::Lower));
    assert!(matches!(
        SlcanLink::open(Box::new(serial), "x", 83_333, TIMEOUT),
        Err(LinkError::Open(why)) if why.contains("83333")
    ));
    assert!(sent.lock().unwrap().is_empty());
}

#[test]
fn answers_left_by_an_earlier_program_are_not_taken_for_the_open_sequences() {
    // Closed already: `C` is refused with BEL; a CR and a frame left unread wait in the line.
    let (mut serial, _) = Scripted::new(|line: &str| if line == "C" { vec![7] } else { vec![13] });
    serial.incoming.extend(b"\rt0021FF\r");
    SlcanLink::open(Box::new(serial), "/dev/x", 1_000_000, TIMEOUT).unwrap();
}

/// An adapter on a line that reads all, answering a frame with `frames` one-byte frames to the
/// host, then `tail`.
fn answering(frames: usize, tail: &'static [u8]) -> CanLink {
    let (mut serial, _) = Scripted::new(move |line: &str| {
        let mut out = b"\r".to_vec();
        if line.starts_with('t') {
            for i in 0..frames {
                out.extend_from_slice(format!("t00210{}\r", i % 10).as_bytes());
            }
            out.extend_from_slice(tail);
        }
        out
    });
    serial.reads_all = true;
    let bus = SlcanLink::open(Box::new(serial), "test", 1_000_000, TIMEOUT).unwrap();
    let link = CanLink::new(Box::new(bus), Box::new(Echoing));
    assert!(link.reads_all());
    link
}

#[test]
fn on_a_line_that_reads_all_every_frame_at_hand_comes_in_one_read_and_a_bell_stays() {
    let mut link = answering(2, b"\x07");
    link.send(&[1]).unwrap();
    let mut buf = [0u8; 16];
    let n = link.recv(&mut buf, Instant::now() + TIMEOUT).unwrap();
    assert_eq!(&buf[..n], &[0, 1], "both frames, so a short read took all");
    assert!(matches!(
        link.recv(&mut buf, Instant::now()),
        Err(LinkError::Adapter(why)) if why.contains("BEL")
    ));
}

#[test]
fn a_read_that_filled_its_buffer_is_followed_by_a_look() {
    // 40 frames of 8 characters: more than one read of the line takes.
    let mut link = answering(40, b"");
    link.send(&[1]).unwrap();
    let mut buf = [0u8; 64];
    let n = link.recv(&mut buf, Instant::now() + TIMEOUT).unwrap();
    assert_eq!(n, 40);
}
