//! Serial ports (USB adapters, RS-232/485) at 8N1 without flow control, with the line settings
//! of `line/`: DTR and RTS as asked, RS-485 direction, an FTDI adapter's latency timer lowered,
//! the rate read back; a port that cannot be opened says who holds it or what to do.
//!
//! A port that goes away (a USB adapter unplugged) is closed at once, and every reopen finds the
//! device file anew through the link's [`Resolve`]: a replugged adapter usually comes back under
//! another name (ttyUSB0 → ttyUSB1), which a `/dev/serial/by-id` link or a `usb:` name follows.

use std::io::Read;
use std::path::Path;
use std::time::{Duration, Instant};

use serialport::{DataBits, FlowControl, Parity, SerialPort, StopBits};

#[cfg(unix)]
use super::fd;
use super::line::{
    LineOptions, LineState, Modem, Os, Rs485, Saved, holder, latency, refusal, sysfs,
};
use super::{Link, LinkError};

#[cfg(unix)]
type Native = serialport::TTYPort;
#[cfg(windows)]
type Native = serialport::COMPort;

/// How RS-485 direction is driven.
#[derive(Debug, Clone, Copy)]
enum Direction {
    /// By the driver (TIOCSRS485), its settings as found put back on closing.
    Kernel(Rs485, Option<Saved>),
    /// By tmclsh: RTS raised around each write.
    Software(Rs485),
}

/// How long a write waits for room in the driver besides the bytes' own time on the wire.
const WRITE_SLACK: Duration = Duration::from_millis(100);

/// Finds the device file a port name stands for now: the path as given (a symlink is followed
/// when it is opened), or a `usb:` name looked up again. Run at every reopen.
pub type Resolve = Box<dyn Fn() -> Result<String, LinkError> + Send>;

/// A serial port, open or lost.
pub struct SerialLink {
    /// The name the user gave (a path, a symlink, a `usb:` name).
    name: String,
    /// The device file opened last.
    path: String,
    baud: u32,
    options: LineOptions,
    /// `None` once the port went away: closed at once, not kept half dead.
    port: Option<Open>,
    resolve: Resolve,
    /// The rate the driver set, when it differs from `baud`.
    actual: Option<u32>,
    direction: Option<Direction>,
    /// Whether the port has modem lines (a pty has none).
    modem: bool,
    /// Notes for the user not yet taken, and every note given (each is said once, reopening
    /// included).
    notes: Vec<String>,
    said: Vec<String>,
    bytes_in: u64,
    bytes_out: u64,
}

/// An open port, with a second descriptor of it to watch for a hang-up while nobody reads.
struct Open {
    port: Native,
    #[cfg(unix)]
    watch: Option<std::os::fd::OwnedFd>,
}

impl SerialLink {
    /// Opens `path` at `baud` with the line settings `options`.
    /// A rate of 0 is refused before the port is opened (the command line refuses it earlier; a
    /// byte would take for ever).
    pub fn open_with(path: &str, baud: u32, options: LineOptions) -> Result<Self, LinkError> {
        let fixed = path.to_string();
        Self::open_named(path, baud, options, Box::new(move || Ok(fixed.clone())))
    }

    /// Opens the port `name` stands for, found by `resolve` now and again at every reopen.
    pub fn open_named(
        name: &str,
        baud: u32,
        options: LineOptions,
        resolve: Resolve,
    ) -> Result<Self, LinkError> {
        if baud == 0 {
            return Err(LinkError::Open(format!(
                "cannot open serial port {name} at 0 baud: a bit rate is a positive number"
            )));
        }
        let path = resolve()?;
        let mut notes = Vec::new();
        let port = open_port(&path, baud, &mut notes)?;
        let mut link = SerialLink {
            name: name.to_string(),
            path,
            baud,
            options,
            port: Some(port),
            resolve,
            actual: None,
            direction: None,
            modem: true,
            notes: Vec::new(),
            said: Vec::new(),
            bytes_in: 0,
            bytes_out: 0,
        };
        for note in notes {
            link.note(note);
        }
        link.configure();
        Ok(link)
    }

    /// The notes about the line not taken yet: a rate the driver changed, modem lines a port
    /// lacks, a latency timer that stays high. Each is given once.
    pub fn take_notes(&mut self) -> Vec<String> {
        std::mem::take(&mut self.notes)
    }

    fn note(&mut self, note: String) {
        if !self.said.contains(&note) {
            self.said.push(note.clone());
            self.notes.push(note);
        }
    }

    fn os(&self) -> Os {
        os_of(self.port.as_ref().map(|open| &open.port))
    }

    /// The open port, or the loss it suffered.
    fn port(&mut self) -> Result<&mut Native, LinkError> {
        match &mut self.port {
            Some(open) => Ok(&mut open.port),
            None => Err(LinkError::Lost(format!(
                "{} went away and is not open again yet",
                self.path
            ))),
        }
    }

    /// Closes the port after a failure that means it is gone; passes the failure on, naming
    /// the port.
    fn lost(&mut self, error: LinkError) -> LinkError {
        match error {
            LinkError::Lost(why) => {
                self.restore();
                self.port = None;
                LinkError::Lost(format!("{} went away ({why})", self.path))
            }
            other => other,
        }
    }

    /// Applies the line settings to the port just opened.
    fn configure(&mut self) {
        let rate = self
            .port
            .as_ref()
            .and_then(|open| open.port.baud_rate().ok());
        self.actual = rate.filter(|rate| *rate != self.baud);
        if let Some(actual) = self.actual {
            self.note(format!(
                "{}: asked for {} baud, the driver set {actual} (a rate it cannot make is \
                 rounded or refused; choose one both ends have)",
                self.path, self.baud
            ));
        }
        self.modem_lines();
        self.latency();
    }

    /// DTR, RTS and RS-485 as asked; a port without modem lines notes it once and goes on.
    fn modem_lines(&mut self) {
        let options = self.options.clone();
        if !options.wants_modem_lines() {
            return;
        }
        let os = self.os();
        // Reading them first tells a port without modem lines before anything is changed.
        let mut failed = os.modem_lines().err().map(|e| e.to_string());
        if let (true, Some(open)) = (failed.is_none(), self.port.as_mut()) {
            let port = &mut open.port;
            let mut results = Vec::new();
            match options.dtr {
                Some(Modem::On) => results.push(port.write_data_terminal_ready(true)),
                Some(Modem::Off) => results.push(port.write_data_terminal_ready(false)),
                _ => {}
            }
            match (options.rts, options.rs485) {
                (_, Some(_)) => results.push(port.write_request_to_send(false)),
                (Some(Modem::On), None) => results.push(port.write_request_to_send(true)),
                (Some(Modem::Off), None) => results.push(port.write_request_to_send(false)),
                _ => {}
            }
            failed = results
                .into_iter()
                .find_map(|r| r.err().map(|e| e.to_string()));
        }
        if let Some(why) = failed {
            self.modem = false;
            let named = options.named().join(", ");
            self.note(format!(
                "{} has no modem lines ({why}), as a pseudo-terminal has none: {named} not \
                 applied; the session goes on without them",
                self.path
            ));
            return;
        }
        if options.dtr == Some(Modem::Keep) || options.rts == Some(Modem::Keep) {
            if let Err(why) = os.keep_lines_on_close() {
                self.note(format!(
                    "{}: cannot keep DTR and RTS up on closing ({why})",
                    self.path
                ));
            }
        }
        if let (Some(_), Some(rts)) = (options.rs485, options.rts) {
            self.note(format!(
                "{}: --rs485 drives RTS itself (high while sending), so --rts {rts} is not applied",
                self.path
            ));
        }
        if let Some(mode) = options.rs485 {
            let saved = os.rs485_saved();
            self.direction = Some(match os.set_rs485(&mode) {
                Ok(()) => Direction::Kernel(mode, saved),
                Err(why) => {
                    self.note(format!(
                        "{}: the driver has no RS-485 mode ({why}); tmclsh raises RTS around \
                         each write itself",
                        self.path
                    ));
                    Direction::Software(mode)
                }
            });
        }
    }

    /// An FTDI adapter's latency timer lowered, or what it costs said once.
    fn latency(&mut self) {
        let root = sysfs::root();
        let Some(file) = latency::timer_file(&root, Path::new(&self.path)) else {
            return;
        };
        let Some(found) = latency::read(&file) else {
            return;
        };
        let os = self.os();
        let outcome = latency::settle(
            found,
            self.options.keep_latency,
            || os.set_low_latency(),
            || latency::read(&file),
        );
        if let latency::Outcome::High { timer, why } = outcome {
            let tty = file
                .parent()
                .and_then(|d| d.file_name())
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            self.note(latency::advice(&tty, timer, why.as_deref(), self.baud));
        }
    }

    /// The timer now, if the port has one.
    fn latency_timer(&self) -> Option<Duration> {
        let file = latency::timer_file(&sysfs::root(), Path::new(&self.path))?;
        latency::read(&file)
    }

    /// How long a write may wait for room in the driver: the bytes' time on the wire twice, and
    /// [`WRITE_SLACK`] besides.
    fn write_bound(&self, len: usize) -> Duration {
        let len = u32::try_from(len).unwrap_or(u32::MAX);
        self.byte_time()
            .unwrap_or_default()
            .saturating_mul(len.saturating_mul(2))
            + WRITE_SLACK
    }

    /// Puts the driver's RS-485 settings back as found (the port may be gone: then nothing).
    fn restore(&mut self) {
        if let Some(Direction::Kernel(_, Some(saved))) = self.direction.take() {
            let _ = self.os().restore_rs485(&saved);
        }
    }

    /// Writes `bytes` with RTS raised around them and held until they have left the UART.
    fn send_rs485(&mut self, bytes: &[u8], mode: Rs485) -> Result<(), LinkError> {
        let lost = |e: serialport::Error| LinkError::Lost(e.to_string());
        self.port()?.write_request_to_send(true).map_err(lost)?;
        if !mode.before.is_zero() {
            std::thread::sleep(mode.before);
        }
        let bound = self.write_bound(bytes.len());
        let written = write_all(self.port()?, bytes, bound);
        let drained = self.os().drain().map_err(LinkError::from_os);
        if !mode.after.is_zero() {
            std::thread::sleep(mode.after);
        }
        self.port()?.write_request_to_send(false).map_err(lost)?;
        written.and(drained)
    }
}

impl Drop for SerialLink {
    /// Puts the driver's RS-485 mode back as it was found, so that the next program meets the
    /// port it knew.
    fn drop(&mut self) {
        self.restore();
    }
}

/// The ioctls of the open port; on a port that went away (-1) each says so.
#[cfg(unix)]
fn os_of(port: Option<&Native>) -> Os {
    #[cfg(target_os = "linux")]
    {
        Os::new(port.map_or(-1, std::os::fd::AsRawFd::as_raw_fd))
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = port;
        Os
    }
}

#[cfg(windows)]
fn os_of(_: Option<&Native>) -> Os {
    Os
}

fn open_port(path: &str, baud: u32, notes: &mut Vec<String>) -> Result<Open, LinkError> {
    if let Some(lock) = holder::lock(&sysfs::root(), Path::new(path)) {
        let own = lock
            .holder
            .as_ref()
            .is_some_and(|h| h.pid == std::process::id());
        match &lock.holder {
            Some(holder) if lock.live && !own => {
                return Err(LinkError::Open(format!(
                    "cannot open serial port {path}: it is locked by {holder} (lock file {}); \
                     end that program, or remove the lock file if nothing uses the port",
                    lock.file.display()
                )));
            }
            Some(holder) if !own => notes.push(format!(
                "ignoring the stale lock file {} ({} is not running)",
                lock.file.display(),
                holder.pid
            )),
            _ => {}
        }
    }
    let port = serialport::new(path, baud)
        .data_bits(DataBits::Eight)
        .parity(Parity::None)
        .stop_bits(StopBits::One)
        .flow_control(FlowControl::None)
        .timeout(Duration::from_millis(100))
        .open_native()
        .map_err(|e| LinkError::Open(refusal::open_hint(path, &e)))?;
    #[cfg(unix)]
    {
        fd::set_nonblocking(borrow(&port))?;
        let watch = borrow(&port).try_clone_to_owned().ok();
        Ok(Open { port, watch })
    }
    #[cfg(not(unix))]
    {
        Ok(Open { port })
    }
}

/// The open port's descriptor (serialport's port has no `AsFd`).
#[cfg(unix)]
fn borrow(port: &Native) -> std::os::fd::BorrowedFd<'_> {
    use std::os::fd::AsRawFd;
    // SAFETY: the descriptor is the open port's, valid while `port` lives, which the borrow
    // cannot outlive.
    unsafe { std::os::fd::BorrowedFd::borrow_raw(port.as_raw_fd()) }
}

/// Writes all of `bytes`: on Unix one write(2) to the non-blocking port while the driver has
/// room (serialport's own `Write` polls before every write).
fn write_all(port: &mut Native, bytes: &[u8], bound: Duration) -> Result<(), LinkError> {
    #[cfg(unix)]
    {
        fd::write_all(borrow(port), bytes, bound)
    }
    #[cfg(not(unix))]
    {
        let _ = bound;
        std::io::Write::write_all(port, bytes).map_err(LinkError::from_io)
    }
}

impl Link for SerialLink {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        if let Some(Direction::Software(mode)) = self.direction {
            self.send_rs485(bytes, mode)?;
        } else {
            // The port writes straight to the kernel; flush() would be tcdrain, which waits
            // until the bytes have left the UART and so adds a wire time (or, on a pty, a
            // scheduler round trip) to every command for nothing.
            let bound = self.write_bound(bytes.len());
            let result = write_all(self.port()?, bytes, bound);
            result.map_err(|e| self.lost(e))?;
        }
        self.bytes_out += bytes.len() as u64;
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        // A deadline already past still takes what has arrived (a zero-time poll), so the
        // session's drain before each request really empties the port.
        let wait = deadline.saturating_duration_since(Instant::now());
        let path = self.path.clone();
        let port = self.port()?;
        let result = match port.set_timeout(wait) {
            Err(e) => Err(LinkError::Lost(e.to_string())),
            Ok(()) => match port.read(buf) {
                Ok(0) => Err(LinkError::Lost(format!("end of file on {path}"))),
                Ok(n) => Ok(n),
                Err(e) => Err(LinkError::from_io(e)),
            },
        };
        let n = result.map_err(|e| self.lost(e))?;
        self.bytes_in += n as u64;
        Ok(n)
    }

    fn describe(&self) -> String {
        if self.name == self.path {
            format!("serial {} at {} baud", self.path, self.baud)
        } else {
            format!("serial {} ({}) at {} baud", self.name, self.path, self.baud)
        }
    }

    fn reopen(&mut self) -> Result<(), LinkError> {
        self.restore();
        self.port = None;
        let path = (self.resolve)()?;
        let mut notes = Vec::new();
        self.port = Some(open_port(&path, self.baud, &mut notes)?);
        self.path = path;
        for note in notes {
            self.note(note);
        }
        self.configure();
        Ok(())
    }

    fn close(&mut self) {
        self.restore();
        self.port = None;
    }

    #[cfg(unix)]
    fn watch(&self) -> Option<std::os::fd::OwnedFd> {
        let open = self.port.as_ref()?;
        open.watch.as_ref()?.try_clone().ok()
    }

    fn reads_all(&self) -> bool {
        true
    }

    fn byte_time(&self) -> Option<Duration> {
        let rate = self.actual.unwrap_or(self.baud);
        Some(Duration::from_secs_f64(10.0 / f64::from(rate.max(1))))
    }

    fn line_state(&mut self) -> LineState {
        let os = self.os();
        LineState {
            rate: Some(self.actual.unwrap_or(self.baud)),
            asked_rate: self.actual.map(|_| self.baud),
            modem: if self.modem {
                os.modem_lines().ok()
            } else {
                None
            },
            latency: self.latency_timer(),
            rs485: self.direction.map(|d| match d {
                Direction::Kernel(m, _) => format!(
                    "driver's RS-485 mode, RTS during sends, delays {} ms before, {} ms after",
                    m.before.as_millis(),
                    m.after.as_millis()
                ),
                Direction::Software(m) => format!(
                    "RTS raised by tmclsh around each write, delays {} ms before, {} ms after",
                    m.before.as_millis(),
                    m.after.as_millis()
                ),
            }),
            bytes_out: Some(self.bytes_out),
            bytes_in: Some(self.bytes_in),
            counters: os.counters().ok(),
            notes: self.said.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rate_of_0_is_refused_before_opening() {
        let Err(LinkError::Open(message)) =
            SerialLink::open_with("/dev/null", 0, LineOptions::default())
        else {
            panic!("opened at 0 baud");
        };
        assert!(message.contains("at 0 baud"), "{message}");
    }
}
