//! The hot path counted, not timed: how many link operations one transaction makes once a session
//! is open — sends, reads that wait and reads that only look (a deadline already past) — through
//! a counting wrapper around the in-process simulator's link. Over a serial port each look is a
//! system call and each wait a blocking poll and a read, so a check added to every transaction
//! shows here as a changed count, on any machine and under any load.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use tmclsh::clock::ManualClock;
use tmclsh::dialect::session::DialectSession;
use tmclsh::dialect::smd4::session::{Smd4Session, Smd4SessionOptions};
use tmclsh::dialect::smd4::sim::{Smd4Sim, Smd4SimOptions};
use tmclsh::dialect::tmcl::profile::Profile;
use tmclsh::dialect::tmcl::protocol::can::TmclFramer;
use tmclsh::dialect::tmcl::session::{Connect, TmclSession};
use tmclsh::dialect::tmcl::sim::Bus;
use tmclsh::dialect::tmcl::sim::can::CanBus;
use tmclsh::link::can::{CanLink, SlcanLink};
use tmclsh::link::{Link, LinkError};
use tmclsh::session::SessionOptions;
use tmclsh::sim::Device;
use tmclsh::sim::inprocess::SimLink;
use tmclsh::sim::slcan::{SlcanAdapter, SlcanOptions};

/// The link operations counted.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
struct Ops {
    sends: usize,
    /// Reads whose deadline had passed: a look at what has arrived.
    looks: usize,
    /// Reads that could wait for bytes.
    waits: usize,
}

/// A link that counts what its session asks of it and passes everything on.
struct Counting {
    inner: Box<dyn Link>,
    ops: Arc<Mutex<Ops>>,
}

impl Link for Counting {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        self.ops.lock().unwrap().sends += 1;
        self.inner.send(bytes)
    }

    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        {
            let mut ops = self.ops.lock().unwrap();
            if deadline <= Instant::now() {
                ops.looks += 1;
            } else {
                ops.waits += 1;
            }
        }
        self.inner.recv(buf, deadline)
    }

    fn describe(&self) -> String {
        self.inner.describe()
    }

    fn private(&self) -> bool {
        self.inner.private()
    }

    fn byte_time(&self) -> Option<Duration> {
        self.inner.byte_time()
    }

    fn frames_only(&self) -> bool {
        self.inner.frames_only()
    }

    fn reads_all(&self) -> bool {
        self.inner.reads_all()
    }
}

/// `device` in-process behind a counting link.
fn counted(device: Box<dyn Device>) -> (Box<dyn Link>, Arc<Mutex<Ops>>) {
    let ops = Arc::new(Mutex::new(Ops::default()));
    let inner = Box::new(SimLink::new(device, Arc::new(ManualClock::new())));
    let link = Counting {
        inner,
        ops: ops.clone(),
    };
    (Box::new(link), ops)
}

/// The operations of one transaction of `line`, the same in each of 20 runs after a first.
fn per_transaction(session: &mut dyn DialectSession, ops: &Mutex<Ops>, line: &str) -> Ops {
    assert!(session.execute(line).unwrap().ok(), "{line}");
    let mut each = Vec::new();
    for _ in 0..20 {
        let before = *ops.lock().unwrap();
        assert!(session.execute(line).unwrap().ok(), "{line}");
        let after = *ops.lock().unwrap();
        each.push(Ops {
            sends: after.sends - before.sends,
            looks: after.looks - before.looks,
            waits: after.waits - before.waits,
        });
    }
    assert!(each.windows(2).all(|w| w[0] == w[1]), "{line}: {each:?}");
    each[0]
}

/// One look before the request (what arrived between exchanges), the request, and one wait
/// that reads the whole reply: what follows it is already known from that read.
const ONE_WAIT: Ops = Ops {
    sends: 1,
    looks: 1,
    waits: 1,
};

#[test]
fn a_tmcl_ascii_transaction_is_one_look_one_send_one_wait() {
    let (link, ops) = counted(Box::new(Bus::builtin()));
    let options = SessionOptions::default();
    let mut session = TmclSession::open(link, Profile::builtin(), options, None).unwrap();
    assert_eq!(per_transaction(&mut session, &ops, "GAP 1, 0"), ONE_WAIT);
}

#[test]
fn a_tmcl_binary_transaction_is_one_look_one_send_one_wait() {
    let (link, ops) = counted(Box::new(Bus::builtin()));
    let connect = Connect {
        binary: true,
        ..Connect::default()
    };
    let options = SessionOptions::default();
    let mut session =
        TmclSession::connect(link, Profile::builtin(), connect, options, None).unwrap();
    assert_eq!(per_transaction(&mut session, &ops, "GAP 1, 0"), ONE_WAIT);
}

#[test]
fn an_smd4_transaction_is_one_look_one_send_one_wait() {
    let (link, ops) = counted(Box::new(Smd4Sim::new(Smd4SimOptions::default())));
    let options = SessionOptions::default();
    let smd4 = Smd4SessionOptions::default();
    let mut session = Smd4Session::open(link, options, smd4, None).unwrap();
    assert_eq!(per_transaction(&mut session, &ops, "SYS:FW"), ONE_WAIT);
}

#[test]
fn a_tmcl_transaction_over_slcan_is_one_look_one_send_one_wait_on_the_serial_line() {
    // Counted under the adapter, on its serial line, where each operation is a system call:
    // the acknowledgement and the reply frame come in one read, and what follows is known.
    let adapter = SlcanAdapter::new(
        Box::new(CanBus::new(Box::new(Bus::builtin()))),
        SlcanOptions::default(),
    );
    let (serial, ops) = counted(Box::new(adapter));
    let bus = SlcanLink::open(serial, "sim", 1_000_000, Duration::from_secs(1)).unwrap();
    let link = Box::new(CanLink::new(Box::new(bus), Box::new(TmclFramer::new(2))));
    let connect = Connect {
        binary: true,
        ..Connect::default()
    };
    let options = SessionOptions::default();
    let mut session =
        TmclSession::connect(link, Profile::builtin(), connect, options, None).unwrap();
    assert_eq!(per_transaction(&mut session, &ops, "GAP 1, 0"), ONE_WAIT);
}
