//! The misbehaving device: the real simulator (a TMCL bus or an SMD4 drive) behind a thread of the
//! test that serves a real pseudo-terminal or a TCP socket, and a rule that decides, request by
//! request, what goes on the wire instead of the simulator's answer.

use std::collections::VecDeque;
use std::fs::File;
use std::io::{self, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::os::fd::{AsRawFd, OwnedFd};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use tmclsh::dialect::smd4::sim::{Smd4Sim, Smd4SimOptions};
use tmclsh::dialect::tmcl::profile::Profile;
use tmclsh::dialect::tmcl::sim::{Bus, BusOptions};
use tmclsh::sim::Device;

use super::HANG_GUARD;

/// How much later a device busy with a held-back answer answers the next request.
const BUSY: Duration = Duration::from_millis(20);

/// How tmclsh reaches the device.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Via {
    Pty,
    Tcp,
}

/// Both ways.
pub const BOTH: [Via; 2] = [Via::Pty, Via::Tcp];

/// What the device does with its answer to one request line.
pub enum Act {
    /// Sends the simulator's answer.
    Answer,
    /// Sends the answer changed by a function.
    Map(fn(&[u8]) -> Vec<u8>),
    /// Sends the answer this much later.
    Late(Duration),
    /// Holds the answer (changed by a function) back until the next request arrives, and sends
    /// it just before that request's answer: later than any wait for quiet.
    HoldUntilNext(fn(&[u8]) -> Vec<u8>),
    /// Sends `at_once`, then `paced` one byte at a time, `gap` apart (a paced serial line).
    Paced {
        at_once: Vec<u8>,
        paced: Vec<u8>,
        gap: Duration,
    },
    /// Sends the answer (if `answer`), then `unit` every `every` for this long (a reply that
    /// goes on and on at the pace of a line).
    Trickle {
        answer: bool,
        unit: Vec<u8>,
        every: Duration,
        lasting: Duration,
    },
    /// Sends the answer (if `answer`), then `unit` over and over, as fast as the line takes it,
    /// for this long.
    Flood {
        answer: bool,
        unit: Vec<u8>,
        lasting: Duration,
    },
    /// Sends the first `n` bytes of the answer and hangs up.
    HangUp(usize),
    /// Behind an adapter that echoes ([`Fake::echoing`]): hands back the request changed by a
    /// function (a collision), then the answer.
    GarbleEcho(fn(&[u8]) -> Vec<u8>),
}

/// Changes an answer.
pub type Corruption = fn(&[u8]) -> Vec<u8>;

/// Decides per request line (as received, without its line end) what the device does.
pub type Rule = Box<dyn FnMut(&str) -> Act + Send>;

/// A rule that misbehaves `times` times on requests containing `pattern`, then answers normally.
pub fn on(
    pattern: &'static str,
    times: usize,
    mut act: impl FnMut() -> Act + Send + 'static,
) -> Rule {
    let mut left = times;
    Box::new(move |line| {
        if left > 0 && line.contains(pattern) {
            left -= 1;
            act()
        } else {
            Act::Answer
        }
    })
}

/// A misbehaving device serving on a thread until dropped.
pub struct Fake {
    /// The pty path or the TCP address.
    pub address: String,
    pub via: Via,
    /// The request lines received, in order.
    pub requests: Arc<Mutex<Vec<String>>>,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

/// One of the device's two ends: a pty master or a TCP connection.
enum Port {
    Pty { master: File, _slave: OwnedFd },
    Listening(TcpListener),
    Tcp(TcpListener, TcpStream),
    Closed,
}

impl Fake {
    /// A simulated TMCM-142 (module 1) behind `rule`.
    pub fn tmcl(via: Via, rule: Rule) -> Fake {
        Fake::start(via, rule, || {
            Box::new(Bus::new(Profile::builtin(), BusOptions::default()))
        })
    }

    /// A simulated SMD4 drive behind `rule`.
    pub fn smd4(via: Via, rule: Rule) -> Fake {
        Fake::start(via, rule, || {
            Box::new(Smd4Sim::new(Smd4SimOptions::default()))
        })
    }

    /// A simulated TMCM-142 (`tmcl`) or SMD4 drive behind an adapter that hands back every byte
    /// it is sent, before the answer (a 2-wire RS-485 converter), and behind `rule`.
    pub fn echoing(dialect: &str, via: Via, rule: Rule) -> Fake {
        let device: fn() -> Box<dyn Device> = match dialect {
            "tmcl" => || Box::new(Bus::new(Profile::builtin(), BusOptions::default())),
            _ => || Box::new(Smd4Sim::new(Smd4SimOptions::default())),
        };
        Fake::start_with(via, rule, device, true)
    }

    fn start(via: Via, rule: Rule, device: fn() -> Box<dyn Device>) -> Fake {
        Fake::start_with(via, rule, device, false)
    }

    fn start_with(via: Via, rule: Rule, device: fn() -> Box<dyn Device>, echo: bool) -> Fake {
        let (port, address) = match via {
            Via::Pty => {
                let pair = nix::pty::openpty(None, None).unwrap();
                let mut termios = nix::sys::termios::tcgetattr(&pair.slave).unwrap();
                nix::sys::termios::cfmakeraw(&mut termios);
                nix::sys::termios::tcsetattr(
                    &pair.slave,
                    nix::sys::termios::SetArg::TCSANOW,
                    &termios,
                )
                .unwrap();
                let path = nix::unistd::ttyname(&pair.slave).unwrap();
                nix::fcntl::fcntl(
                    &pair.master,
                    nix::fcntl::FcntlArg::F_SETFL(nix::fcntl::OFlag::O_NONBLOCK),
                )
                .unwrap();
                // Processes the tests start must not inherit the device's ends: a hang-up has
                // to close the line.
                for fd in [&pair.master, &pair.slave] {
                    nix::fcntl::fcntl(
                        fd,
                        nix::fcntl::FcntlArg::F_SETFD(nix::fcntl::FdFlag::FD_CLOEXEC),
                    )
                    .unwrap();
                }
                let port = Port::Pty {
                    master: File::from(pair.master),
                    _slave: pair.slave,
                };
                (port, path.display().to_string())
            }
            Via::Tcp => {
                let listener = TcpListener::bind("127.0.0.1:0").unwrap();
                listener.set_nonblocking(true).unwrap();
                let address = listener.local_addr().unwrap().to_string();
                (Port::Listening(listener), address)
            }
        };
        let stop = Arc::new(AtomicBool::new(false));
        let requests = Arc::new(Mutex::new(Vec::new()));
        let mut server = Server {
            port,
            device: device(),
            rule,
            started: Instant::now(),
            line: Vec::new(),
            scheduled: VecDeque::new(),
            held: None,
            flood: None,
            requests: requests.clone(),
            echo,
        };
        let stopping = stop.clone();
        let thread = std::thread::spawn(move || server.run(&stopping));
        Fake {
            address,
            via,
            requests,
            stop,
            thread: Some(thread),
        }
    }

    /// The connection options for tmclsh.
    pub fn args(&self) -> Vec<String> {
        let flag = match self.via {
            Via::Pty => "--port",
            Via::Tcp => "--tcp",
        };
        vec![flag.to_string(), self.address.clone()]
    }
}

impl Drop for Fake {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

struct Flood {
    unit: Vec<u8>,
    until: Instant,
}

struct Server {
    port: Port,
    device: Box<dyn Device>,
    rule: Rule,
    started: Instant,
    /// The request line being received.
    line: Vec<u8>,
    /// Bytes to write at a time, in order.
    scheduled: VecDeque<(Instant, Vec<u8>)>,
    /// An answer held back until the next request.
    held: Option<Vec<u8>>,
    flood: Option<Flood>,
    requests: Arc<Mutex<Vec<String>>>,
    /// Every byte received goes back first (an adapter that echoes).
    echo: bool,
}

impl Server {
    fn run(&mut self, stop: &AtomicBool) {
        let mut buf = [0u8; 4096];
        while !stop.load(Ordering::SeqCst) {
            self.accept();
            let n = self.read(&mut buf);
            let now = self.started.elapsed();
            let mut completed = Vec::new();
            if n > 0 {
                self.device.receive(now, &buf[..n]);
                for &b in &buf[..n] {
                    if b == b'\r' || b == b'\n' {
                        if !self.line.is_empty() {
                            completed.push(std::mem::take(&mut self.line));
                        }
                    } else {
                        self.line.push(b);
                    }
                }
            }
            let mut out = Vec::new();
            self.device.poll_output(now, &mut out);
            let texts: Vec<String> = completed
                .iter()
                .map(|line| line.iter().map(|&b| char::from(b)).collect())
                .collect();
            self.requests.lock().unwrap().extend(texts.iter().cloned());
            let mut echo = if self.echo {
                buf[..n].to_vec()
            } else {
                Vec::new()
            };
            if let Some(text) = texts.last() {
                // A device still busy with an earlier request answers this one a little later.
                let mut busy = Duration::ZERO;
                if let Some(held) = self.held.take() {
                    self.schedule(Duration::ZERO, held);
                    busy = BUSY;
                }
                let act = match (self.rule)(text) {
                    Act::GarbleEcho(f) => {
                        echo = f(&echo);
                        Act::Answer
                    }
                    act => act,
                };
                self.schedule(Duration::ZERO, echo);
                self.act(act, out, busy);
            } else {
                self.schedule(Duration::ZERO, echo);
                if !out.is_empty() {
                    self.schedule(Duration::ZERO, out);
                }
            }
            self.write_due();
        }
    }

    fn act(&mut self, act: Act, answer: Vec<u8>, busy: Duration) {
        match act {
            Act::Answer => self.schedule(busy, answer),
            Act::Map(f) => self.schedule(busy, f(&answer)),
            Act::Late(after) => self.schedule(busy + after, answer),
            Act::HoldUntilNext(f) => self.held = Some(f(&answer)),
            Act::Paced {
                at_once,
                paced,
                gap,
            } => {
                self.schedule(busy, at_once);
                for (i, b) in paced.into_iter().enumerate() {
                    self.schedule(busy + gap * (i as u32 + 1), vec![b]);
                }
            }
            Act::Trickle {
                answer: send,
                unit,
                every,
                lasting,
            } => {
                if send {
                    self.schedule(busy, answer);
                }
                let times = (lasting.as_micros() / every.as_micros().max(1)) as u32;
                for i in 1..=times {
                    self.schedule(busy + every * i, unit.clone());
                }
            }
            Act::Flood {
                answer: send,
                unit,
                lasting,
            } => {
                if send {
                    self.schedule(busy, answer);
                }
                let mut unit = unit.repeat(4096 / unit.len().max(1) + 1);
                unit.truncate(4096);
                self.flood = Some(Flood {
                    unit,
                    until: Instant::now() + lasting,
                });
            }
            Act::GarbleEcho(_) => unreachable!("taken with the echo"),
            Act::HangUp(n) => {
                let mut part = answer;
                part.truncate(n);
                self.write_now(&part);
                self.port = match std::mem::replace(&mut self.port, Port::Closed) {
                    // Closing both ends of the pty hangs up the line.
                    Port::Pty { .. } => Port::Closed,
                    Port::Tcp(listener, stream) => {
                        let _ = stream.shutdown(std::net::Shutdown::Both);
                        Port::Listening(listener)
                    }
                    other => other,
                };
            }
        }
    }

    /// Queues bytes to go out after `after`, and never before what was queued earlier: the
    /// device answers its requests in order, so a late answer holds back the ones after it.
    fn schedule(&mut self, after: Duration, bytes: Vec<u8>) {
        if !bytes.is_empty() {
            let at = Instant::now() + after;
            let at = self.scheduled.back().map_or(at, |(last, _)| at.max(*last));
            self.scheduled.push_back((at, bytes));
        }
    }

    fn write_due(&mut self) {
        let now = Instant::now();
        while self.scheduled.front().is_some_and(|(at, _)| *at <= now) {
            let (_, bytes) = self.scheduled.pop_front().expect("a front");
            self.write_now(&bytes);
        }
        if let Some(flood) = &self.flood {
            if now >= flood.until {
                self.flood = None;
            } else {
                let unit = flood.unit.clone();
                let _ = self.write_some(&unit);
            }
        }
    }

    /// Writes all of `bytes` (a reply), waiting for a full pty or socket to drain.
    fn write_now(&mut self, bytes: &[u8]) {
        let mut rest = bytes;
        let give_up = Instant::now() + Duration::from_secs(5);
        while !rest.is_empty() && Instant::now() < give_up {
            match self.write_some(rest) {
                Ok(n) => rest = &rest[n..],
                Err(_) => return,
            }
        }
    }

    /// Writes what the line takes now.
    fn write_some(&mut self, bytes: &[u8]) -> io::Result<usize> {
        let result = match &mut self.port {
            Port::Pty { master, .. } => master.write(bytes),
            Port::Tcp(_, stream) => stream.write(bytes),
            _ => return Err(io::ErrorKind::NotConnected.into()),
        };
        match result {
            Ok(n) => Ok(n),
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => Ok(0),
            Err(e) => Err(e),
        }
    }

    fn accept(&mut self) {
        if let Port::Listening(listener) = &self.port {
            if let Ok((stream, _)) = listener.accept() {
                stream.set_nonblocking(true).unwrap();
                stream.set_nodelay(true).unwrap();
                let listener = listener.try_clone().unwrap();
                self.port = Port::Tcp(listener, stream);
                self.line.clear();
                self.flood = None;
            }
        }
    }

    /// How long the loop may wait for input: until the next scheduled write, at most 1 ms.
    fn wait(&self) -> Duration {
        let now = Instant::now();
        let next = self.scheduled.front().map(|(at, _)| *at);
        match (next, &self.flood) {
            (_, Some(_)) => Duration::ZERO,
            (Some(at), None) => at
                .saturating_duration_since(now)
                .min(Duration::from_millis(1)),
            (None, None) => Duration::from_millis(1),
        }
    }

    /// Reads what has arrived, waiting for it until the next write is due.
    fn read(&mut self, buf: &mut [u8]) -> usize {
        let wait = self.wait();
        let fd = match &self.port {
            Port::Pty { master, .. } => master.as_raw_fd(),
            Port::Tcp(_, stream) => stream.as_raw_fd(),
            _ => {
                std::thread::sleep(Duration::from_millis(1));
                return 0;
            }
        };
        let mut fds = [libc::pollfd {
            fd,
            events: libc::POLLIN,
            revents: 0,
        }];
        let timeout = libc::timespec {
            tv_sec: 0,
            tv_nsec: wait.subsec_nanos().into(),
        };
        // SAFETY: one valid pollfd for a descriptor this thread owns, a valid timespec.
        unsafe { libc::ppoll(fds.as_mut_ptr(), 1, &timeout, std::ptr::null()) };
        let result = match &mut self.port {
            Port::Pty { master, .. } => master.read(buf),
            Port::Tcp(_, stream) => stream.read(buf),
            _ => return 0,
        };
        match result {
            Ok(0) => {
                // A TCP client went away: wait for the next one.
                if let Port::Tcp(listener, _) = std::mem::replace(&mut self.port, Port::Closed) {
                    self.port = Port::Listening(listener);
                }
                0
            }
            Ok(n) => n,
            Err(_) => 0,
        }
    }
}

/// The answer unchanged.
pub fn same(answer: &[u8]) -> Vec<u8> {
    answer.to_vec()
}

/// Replaces the last `old` in `answer` by `new`.
pub fn replace_last(answer: &[u8], old: &[u8], new: &[u8]) -> Vec<u8> {
    let at = answer
        .windows(old.len())
        .rposition(|w| w == old)
        .unwrap_or_else(|| panic!("{old:?} in {:?}", String::from_utf8_lossy(answer)));
    [&answer[..at], new, &answer[at + old.len()..]].concat()
}

/// Waits until the device has received a request containing `pattern`.
pub fn await_request(fake: &Fake, pattern: &str) {
    let give_up = Instant::now() + HANG_GUARD;
    while !fake
        .requests
        .lock()
        .unwrap()
        .iter()
        .any(|r| r.contains(pattern))
    {
        assert!(Instant::now() < give_up, "no request {pattern}");
        std::thread::yield_now();
    }
}
