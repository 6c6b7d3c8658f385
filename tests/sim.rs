//! `tmclsh sim` as a process: talked to over its pseudo-terminal (opened with `serialport`, as a
//! real serial port) and over loopback TCP, steered through its stdin console. Replies are
//! awaited by reading until a deadline, never by sleeping.

mod ascii;
mod binary;
mod bus;
mod family;
mod faults;
mod motion;
mod programs;
mod pytrinamic;
mod state;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, ChildStderr, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

use tmclsh::dialect::tmcl::protocol::{CommandFrame, Instruction, ReplyFrame};

use crate::util::bin;

/// How long any single expected event may take before the test fails.
pub const PATIENCE: Duration = Duration::from_secs(10);

/// The simulated motor's velocity after `time` more simulated time (a `--manual-clock` simulator).
pub fn velocity_after(sim: &mut Sim, time: &str) -> f64 {
    assert!(sim.console(&format!("advance {time}")).starts_with("ok"));
    let motor = sim.console("motor");
    let words: Vec<&str> = motor.split_whitespace().collect();
    let at = words.iter().position(|w| *w == "velocity").expect(&motor);
    words[at + 1].parse().expect(&motor)
}

/// A running `tmclsh sim`.
pub struct Sim {
    child: Child,
    stdin: ChildStdin,
    lines: Receiver<String>,
    /// The first line printed: the pty path or the TCP address.
    pub first: String,
    stderr: Option<ChildStderr>,
}

impl Sim {
    /// Starts `tmclsh sim ARGS` and waits for its first line.
    pub fn start(args: &[&str]) -> Sim {
        Sim::spawn(args, false)
    }

    /// Like [`Sim::start`], keeping stderr for [`Sim::quit`] to return.
    pub fn start_capturing_stderr(args: &[&str]) -> Sim {
        Sim::spawn(args, true)
    }

    fn spawn(args: &[&str], capture: bool) -> Sim {
        let mut child = Command::new(bin())
            .arg("sim")
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(if capture {
                Stdio::piped()
            } else {
                Stdio::inherit()
            })
            .spawn()
            .expect("tmclsh sim starts");
        let stderr = child.stderr.take();
        let stdin = child.stdin.take().unwrap();
        let stdout = child.stdout.take().unwrap();
        let (tx, lines) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let Ok(line) = line else { break };
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        let mut sim = Sim {
            child,
            stdin,
            lines,
            first: String::new(),
            stderr,
        };
        sim.first = sim.line();
        sim
    }

    /// The next line on stdout.
    pub fn line(&mut self) -> String {
        self.lines
            .recv_timeout(PATIENCE)
            .expect("tmclsh sim printed a line in time")
    }

    /// Runs a console command and returns its answer line.
    pub fn console(&mut self, command: &str) -> String {
        writeln!(self.stdin, "{command}").unwrap();
        self.stdin.flush().unwrap();
        self.line()
    }

    /// Ends the simulator through its console; returns what it wrote to stderr if captured.
    pub fn quit(mut self) -> String {
        writeln!(self.stdin, "quit").unwrap();
        let _ = self.stdin.flush();
        let mut stderr = String::new();
        if let Some(mut pipe) = self.stderr.take() {
            // Ends when the process exits and closes its end.
            pipe.read_to_string(&mut stderr).unwrap();
        }
        let deadline = Instant::now() + PATIENCE;
        loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                assert!(status.success(), "sim exited with {status}");
                return stderr;
            }
            assert!(Instant::now() < deadline, "sim did not quit");
            std::thread::yield_now();
        }
    }

    /// Opens the pty as a serial port.
    pub fn pty(&self) -> Port {
        Port::Serial(open_serial(&self.first))
    }

    /// Connects to the TCP address.
    pub fn tcp(&self) -> Port {
        let stream = TcpStream::connect(&self.first).expect("connect to the simulator");
        stream.set_nodelay(true).unwrap();
        Port::Tcp(stream)
    }
}

impl Drop for Sim {
    fn drop(&mut self) {
        // Our own child, by its id.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Opens a pty like a serial port. Not exclusive: tests run in parallel and spawn processes, and
/// a child forked between our open and its exec briefly shares our descriptor, and with it an
/// exclusive lock we have already released.
pub fn open_serial(path: &str) -> Box<dyn serialport::SerialPort> {
    serialport::new(path, 9600)
        .timeout(Duration::from_millis(50))
        .exclusive(false)
        .open()
        .unwrap_or_else(|e| panic!("open {path}: {e}"))
}

/// A connection to the simulator.
pub enum Port {
    Serial(Box<dyn serialport::SerialPort>),
    Tcp(TcpStream),
}

/// What a read found.
#[derive(Debug, PartialEq, Eq)]
pub enum Closed {
    /// The other end hung up.
    Yes,
}

impl Port {
    pub fn send(&mut self, bytes: &[u8]) {
        match self {
            Port::Serial(p) => p.write_all(bytes).unwrap(),
            Port::Tcp(s) => s.write_all(bytes).unwrap(),
        }
    }

    /// Reads whatever arrives within a short poll, or reports that the peer hung up.
    fn read_some(&mut self, buf: &mut [u8]) -> Result<usize, Closed> {
        let result = match self {
            Port::Serial(p) => p.read(buf),
            Port::Tcp(s) => {
                s.set_read_timeout(Some(Duration::from_millis(50))).unwrap();
                s.read(buf)
            }
        };
        match result {
            Ok(0) => Err(Closed::Yes),
            Ok(n) => Ok(n),
            Err(e)
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::TimedOut | std::io::ErrorKind::WouldBlock
                ) =>
            {
                Ok(0)
            }
            Err(_) => Err(Closed::Yes),
        }
    }

    /// Reads until `done` says the bytes are complete; panics after [`PATIENCE`].
    pub fn read_until(&mut self, done: impl Fn(&[u8]) -> bool) -> Vec<u8> {
        self.try_read_until(done)
            .expect("the simulator did not hang up")
    }

    /// Like [`Port::read_until`], but a hang-up is an answer.
    pub fn try_read_until(&mut self, done: impl Fn(&[u8]) -> bool) -> Result<Vec<u8>, Closed> {
        let deadline = Instant::now() + PATIENCE;
        let mut got = Vec::new();
        let mut buf = [0u8; 256];
        while !done(&got) {
            assert!(
                Instant::now() < deadline,
                "timed out; got so far {got:02X?} ({:?})",
                String::from_utf8_lossy(&got)
            );
            let n = self.read_some(&mut buf)?;
            got.extend_from_slice(&buf[..n]);
        }
        Ok(got)
    }

    /// What arrives within one short poll.
    pub fn read_available(&mut self) -> Vec<u8> {
        let mut buf = [0u8; 256];
        let n = self
            .read_some(&mut buf)
            .expect("the simulator did not hang up");
        buf[..n].to_vec()
    }

    /// Reads exactly `n` bytes.
    pub fn read_n(&mut self, n: usize) -> Vec<u8> {
        let got = self.read_until(|b| b.len() >= n);
        assert_eq!(got.len(), n, "more than {n} bytes: {got:02X?}");
        got
    }

    /// Reads one ASCII line ending in CR.
    pub fn read_line(&mut self) -> String {
        let got = self.read_until(|b| b.ends_with(b"\r"));
        String::from_utf8(got).unwrap()
    }

    /// Sends a command frame and decodes the reply.
    pub fn transact(
        &mut self,
        address: u8,
        command: u8,
        type_: u8,
        motor: u8,
        value: i32,
    ) -> ReplyFrame {
        self.send(&frame(address, command, type_, motor, value));
        decode(&self.read_n(9))
    }
}

pub fn frame(address: u8, command: u8, type_: u8, motor: u8, value: i32) -> [u8; 9] {
    CommandFrame {
        address,
        instruction: Instruction::new(command, type_, motor, value),
    }
    .encode()
}

pub fn decode(bytes: &[u8]) -> ReplyFrame {
    ReplyFrame::decode(bytes.try_into().unwrap()).expect("reply checksum")
}
