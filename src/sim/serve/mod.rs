//! Serving a device to other programs: on a pseudo-terminal, where it looks like a serial port,
//! or on TCP. One thread per adapter; it waits on I/O with a timeout derived from the device's
//! `next_due` (or until woken by the console), never with fixed sleeps.

mod pty;
mod tcp;

use std::fs::File;
use std::io::{self, Read, Write};
use std::os::fd::{AsFd, BorrowedFd};
use std::os::unix::net::UnixStream;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use nix::errno::Errno;
use nix::poll::{PollFd, PollFlags, PollTimeout, poll};

use super::Device;
use super::console::{Line, Unplug};
use super::inprocess::SharedDevice;
use crate::clock::Clock;

/// Wakes a serving thread, e.g. after a console command changed the device or the clock.
#[derive(Debug, Clone)]
pub struct Waker(Arc<UnixStream>);

impl Waker {
    /// Makes the server look at the device again now.
    pub fn wake(&self) {
        // Non-blocking: when the pipe is full a wake-up is pending anyway.
        let _ = (&*self.0).write(&[1]);
    }
}

/// The receiving end of a [`Waker`], owned by the server.
#[derive(Debug)]
pub struct WakeReceiver {
    stream: UnixStream,
    /// False once every [`Waker`] is gone (the console ended with its input): the socket then
    /// reads as ready for ever and must not be polled any more, or the server would spin.
    open: bool,
}

impl WakeReceiver {
    fn drain(&mut self) {
        let mut buf = [0u8; 64];
        loop {
            match self.stream.read(&mut buf) {
                Ok(0) => {
                    self.open = false;
                    break;
                }
                Ok(_) => {}
                Err(_) => break,
            }
        }
    }

    /// The descriptor to wait on, while a waker may still write to it.
    fn fd(&self) -> Option<BorrowedFd<'_>> {
        self.open.then(|| self.stream.as_fd())
    }
}

/// A connected waker pair.
pub fn wake_pair() -> io::Result<(Waker, WakeReceiver)> {
    let (tx, rx) = UnixStream::pair()?;
    tx.set_nonblocking(true)?;
    rx.set_nonblocking(true)?;
    Ok((
        Waker(Arc::new(tx)),
        WakeReceiver {
            stream: rx,
            open: true,
        },
    ))
}

/// Why serving one connection ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum End {
    /// The peer closed the connection.
    Closed,
    /// The device hung up (fault injection).
    HungUp,
    /// The extra descriptor became readable (a new TCP client is waiting).
    Other,
    /// The console unplugged the adapter for this long.
    Unplugged(Duration),
}

/// The connection being served, as the console reaches it: a second descriptor of the same
/// stream. The server reads and hands over under the device's lock, and so does the console, so
/// every byte reaches the device in the order the client wrote it, before or after a command.
#[derive(Debug, Default)]
struct Served(Mutex<Option<File>>);

impl Served {
    fn set(&self, port: Option<&dyn Port>) {
        let copy = port.and_then(|p| p.as_fd().try_clone_to_owned().ok());
        *self.0.lock().unwrap_or_else(|e| e.into_inner()) = copy.map(File::from);
    }
}

impl Line for Served {
    fn catch_up(&self, device: &mut dyn Device, now: Duration) {
        let served = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let Some(mut port) = served.as_ref() else {
            return;
        };
        let mut buf = [0u8; 4096];
        while let Some(Ok(n @ 1..)) = read_now(&mut port, &mut buf) {
            device.receive(now, &buf[..n]);
        }
    }
}

/// Reads what `port` has readable now, never waiting: `None` when nothing is (the other reader,
/// server or console, took it first; a blocking TCP stream must then not be read).
fn read_now(port: &mut (impl Read + AsFd + ?Sized), buf: &mut [u8]) -> Option<io::Result<usize>> {
    let mut fds = [PollFd::new(port.as_fd(), PollFlags::POLLIN)];
    let ready = poll(&mut fds, PollTimeout::ZERO).is_ok_and(|n| n > 0)
        && fds[0].revents().is_some_and(|r| {
            r.intersects(PollFlags::POLLIN | PollFlags::POLLHUP | PollFlags::POLLERR)
        });
    ready.then(|| port.read(buf))
}

/// A device, its clock and the means to serve it.
pub struct Server {
    device: SharedDevice,
    clock: Arc<dyn Clock>,
    wake: WakeReceiver,
    log: Box<dyn FnMut(&str) + Send>,
    /// An `unplug` from the console, acted on by the pty server.
    unplug: Arc<Unplug>,
    /// The connection being served, for the console.
    served: Arc<Served>,
}

/// A byte stream that can be polled.
trait Port: Read + Write + AsFd {}
impl<T: Read + Write + AsFd> Port for T {}

impl Server {
    /// A server for `device`; `log` receives connection events (connects, hang-ups).
    pub fn new(
        device: SharedDevice,
        clock: Arc<dyn Clock>,
        wake: WakeReceiver,
        log: Box<dyn FnMut(&str) + Send>,
    ) -> Server {
        Server {
            device,
            clock,
            wake,
            log,
            unplug: Arc::default(),
            served: Arc::default(),
        }
    }

    /// Where the console reads what a client wrote before its command (see [`Line`]).
    pub fn line(&self) -> Arc<dyn Line> {
        self.served.clone()
    }

    /// Where the console's `unplug` reaches this server.
    pub fn unplug_handle(&self) -> Arc<Unplug> {
        self.unplug.clone()
    }

    /// `f` on the device, with the time read under its lock (so it never goes backwards between
    /// the server's and the console's calls).
    fn with_device<R>(&self, f: impl FnOnce(&mut dyn Device, Duration) -> R) -> R {
        let mut device = self.device.lock().unwrap_or_else(|e| e.into_inner());
        f(&mut *device, self.clock.now())
    }

    /// A new connection: the device may talk again and stale output is dropped.
    fn fresh_connection(&self) {
        self.with_device(|device, now| {
            device.reconnect();
            let mut stale = Vec::new();
            device.poll_output(now, &mut stale);
        });
    }

    /// Moves bytes between `port` and the device until the connection ends; the console reaches
    /// the port meanwhile.
    fn pump(&mut self, port: &mut dyn Port, extra: Option<BorrowedFd>) -> io::Result<End> {
        self.served.set(Some(&*port));
        let end = self.pump_served(port, extra);
        self.served.set(None);
        end
    }

    fn pump_served(&mut self, port: &mut dyn Port, extra: Option<BorrowedFd>) -> io::Result<End> {
        precise_timers();
        let mut out = Vec::new();
        let mut buf = [0u8; 4096];
        loop {
            let (due, hung) = self.with_device(|device, now| {
                device.poll_output(now, &mut out);
                (device.next_due(now), device.hung_up())
            });
            let wrote = !out.is_empty();
            if wrote {
                match port.write_all(&out).and_then(|()| port.flush()) {
                    Ok(()) => {}
                    Err(e) if e.kind() == io::ErrorKind::WouldBlock => {
                        (self.log)(&format!("nobody reads: {} bytes dropped", out.len()));
                    }
                    Err(_) => return Ok(End::Closed),
                }
                out.clear();
            }
            if hung {
                return Ok(End::HungUp);
            }
            if let Some(outage) = self.unplug.take() {
                return Ok(End::Unplugged(outage));
            }
            let mut timeout = due.and_then(|d| self.clock.real_time_until(d));
            if timeout == Some(Duration::ZERO) && !wrote {
                // Due but nothing came: look again shortly rather than spin.
                timeout = Some(Duration::from_millis(1));
            }
            let (port_ready, wake_ready, extra_ready) = {
                // The port first, then the waker and the extra descriptor where there are any.
                let others = [self.wake.fd(), extra];
                let unused = || PollFd::new(port.as_fd(), PollFlags::empty());
                let mut fds = [
                    PollFd::new(port.as_fd(), PollFlags::POLLIN),
                    unused(),
                    unused(),
                ];
                let mut at = [None; 2];
                let mut used = 1;
                for (slot, fd) in others.into_iter().enumerate() {
                    if let Some(fd) = fd {
                        fds[used] = PollFd::new(fd, PollFlags::POLLIN);
                        at[slot] = Some(used);
                        used += 1;
                    }
                }
                match wait(&mut fds[..used], timeout) {
                    Ok(_) => {}
                    Err(Errno::EINTR) => continue,
                    Err(e) => return Err(e.into()),
                }
                let ready = |fd: &PollFd| {
                    fd.revents().is_some_and(|r| {
                        r.intersects(PollFlags::POLLIN | PollFlags::POLLHUP | PollFlags::POLLERR)
                    })
                };
                let ready_at = |i: Option<usize>| i.is_some_and(|i| ready(&fds[i]));
                (ready(&fds[0]), ready_at(at[0]), ready_at(at[1]))
            };
            if wake_ready {
                self.wake.drain();
            }
            if port_ready {
                // Read under the device's lock, as the console catches up (see `Served`).
                let read = self.with_device(|device, now| {
                    let read = read_now(port, &mut buf);
                    if let Some(Ok(n @ 1..)) = read {
                        device.receive(now, &buf[..n]);
                    }
                    read
                });
                match read {
                    None | Some(Ok(1..)) => {}
                    Some(Ok(0)) => return Ok(End::Closed),
                    Some(Err(e))
                        if matches!(
                            e.kind(),
                            io::ErrorKind::WouldBlock | io::ErrorKind::Interrupted
                        ) => {}
                    Some(Err(_)) => return Ok(End::Closed),
                }
            }
            if extra_ready {
                return Ok(End::Other);
            }
        }
    }
}

/// Waits until a descriptor is ready or `timeout` has passed. Where the system has ppoll(2) the
/// timeout is kept to the nanosecond: a paced line at 115200 baud has a byte every 87 µs, and a
/// wait rounded up to whole milliseconds would deliver each byte up to a millisecond late.
#[cfg(any(target_os = "linux", target_os = "android"))]
fn wait(fds: &mut [PollFd], timeout: Option<Duration>) -> nix::Result<nix::libc::c_int> {
    nix::poll::ppoll(fds, timeout.map(nix::sys::time::TimeSpec::from), None)
}

/// Waits until a descriptor is ready or `timeout` has passed (rounded up to whole milliseconds,
/// so the server never wakes too early).
#[cfg(not(any(target_os = "linux", target_os = "android")))]
fn wait(fds: &mut [PollFd], timeout: Option<Duration>) -> nix::Result<nix::libc::c_int> {
    let timeout = match timeout {
        None => PollTimeout::NONE,
        Some(d) => {
            let ms = d.as_nanos().div_ceil(1_000_000).min(i32::MAX as u128) as i32;
            PollTimeout::try_from(ms).unwrap_or(PollTimeout::MAX)
        }
    };
    poll(fds, timeout)
}

/// Asks the kernel to wake this thread at its timers' exact times. The default timer slack of
/// a Linux thread (50 µs) lets a wake-up come that much late, which at 115200 baud is more than
/// half a byte on the simulated line.
fn precise_timers() {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    let _ = nix::sys::prctl::set_timerslack(1);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A device that keeps what it receives.
    #[derive(Default)]
    struct Heard(Vec<u8>);

    impl Device for Heard {
        fn receive(&mut self, _: Duration, bytes: &[u8]) {
            self.0.extend_from_slice(bytes);
        }
        fn poll_output(&mut self, _: Duration, _: &mut Vec<u8>) {}
        fn next_due(&self, _: Duration) -> Option<Duration> {
            None
        }
    }

    #[test]
    fn the_console_catches_up_with_what_the_client_wrote_without_waiting() {
        let (mut client, port) = UnixStream::pair().unwrap();
        let served = Served::default();
        let mut device = Heard::default();
        served.catch_up(&mut device, Duration::ZERO);
        assert!(device.0.is_empty(), "no connection, nothing to read");
        served.set(Some(&port));
        served.catch_up(&mut device, Duration::ZERO);
        assert!(
            device.0.is_empty(),
            "nothing written: no wait on a blocking stream"
        );
        client.write_all(b"SYS:FW\n").unwrap();
        served.catch_up(&mut device, Duration::ZERO);
        assert_eq!(device.0, b"SYS:FW\n");
        served.set(None);
        client.write_all(b"later").unwrap();
        served.catch_up(&mut device, Duration::ZERO);
        assert_eq!(device.0, b"SYS:FW\n", "the connection ended");
    }

    /// A device that sends one byte at each of its times, then hangs up.
    struct Timed {
        due: Vec<Duration>,
        sent: usize,
    }

    impl Device for Timed {
        fn receive(&mut self, _: Duration, _: &[u8]) {}
        fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
            while self.due.get(self.sent).is_some_and(|&d| d <= now) {
                out.push(self.sent as u8);
                self.sent += 1;
            }
        }
        fn next_due(&self, _: Duration) -> Option<Duration> {
            self.due.get(self.sent).copied()
        }
        fn hung_up(&self) -> bool {
            self.sent == self.due.len()
        }
    }

    #[test]
    fn a_paced_byte_never_leaves_before_its_time() {
        // Bytes 87 µs apart, as at 115200 baud: late by a wake-up at most, never early.
        let due: Vec<Duration> = (0..20u32)
            .map(|i| Duration::from_millis(2) + Duration::from_micros(87) * i)
            .collect();
        let device: SharedDevice = Arc::new(Mutex::new(Timed {
            due: due.clone(),
            sent: 0,
        }));
        let clock = Arc::new(crate::clock::SystemClock::new());
        // Taken after the clock's start, so a byte's time here is never ahead of the clock's.
        let start = std::time::Instant::now();
        let (mut client, mut port) = UnixStream::pair().unwrap();
        let (_waker, wake) = wake_pair().unwrap();
        let serving = std::thread::spawn(move || {
            let mut server = Server::new(device, clock, wake, Box::new(|_| {}));
            server.pump(&mut port, None).unwrap()
        });
        let mut arrived = Vec::new();
        let mut buf = [0u8; 64];
        while arrived.len() < due.len() {
            let n = client.read(&mut buf).unwrap();
            assert!(n > 0, "the server ended early");
            let at = start.elapsed();
            arrived.extend(buf[..n].iter().map(|&b| (b, at)));
        }
        assert_eq!(serving.join().unwrap(), End::HungUp);
        for (byte, at) in arrived {
            let due = due[usize::from(byte)];
            assert!(at >= due, "byte {byte} came at {at:?}, before {due:?}");
        }
    }

    #[test]
    fn the_waker_is_polled_until_every_waker_is_gone() {
        let (waker, mut receiver) = wake_pair().unwrap();
        let second = waker.clone();
        waker.wake();
        receiver.drain();
        assert!(receiver.fd().is_some(), "a wake-up is not the end");
        drop(waker);
        receiver.drain();
        assert!(receiver.fd().is_some(), "a clone can still wake the server");
        drop(second);
        receiver.drain();
        assert!(
            receiver.fd().is_none(),
            "a closed waker reads as ready for ever; polling it would spin"
        );
    }
}
