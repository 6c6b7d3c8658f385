//! Serial ports (USB adapters, RS-232/485) at 8N1 without flow control.
//!
//! A port that goes away (a USB adapter unplugged) is closed at once, and every reopen finds the
//! device file anew through the link's [`Resolve`]: a replugged adapter usually comes back under
//! another name (ttyUSB0 → ttyUSB1), which a `/dev/serial/by-id` link or a `usb:` name follows.

use std::io::{Read, Write};
use std::time::{Duration, Instant};

use serialport::{DataBits, FlowControl, Parity, SerialPort, StopBits};

use super::{Link, LinkError};

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
    /// `None` once the port went away: closed at once, not kept half dead.
    port: Option<Open>,
    resolve: Resolve,
}

/// An open port, with a second descriptor of it to watch for a hang-up while nobody reads.
struct Open {
    port: Box<dyn SerialPort>,
    #[cfg(unix)]
    watch: Option<std::os::fd::OwnedFd>,
}

impl SerialLink {
    /// Opens `path` at `baud`, 8N1, no flow control. A rate of 0 is refused before the port is
    /// opened (the command line refuses it earlier; a byte would take for ever).
    pub fn open(path: &str, baud: u32) -> Result<Self, LinkError> {
        let fixed = path.to_string();
        Self::open_named(path, baud, Box::new(move || Ok(fixed.clone())))
    }

    /// Opens the port `name` stands for, found by `resolve` now and again at every reopen.
    pub fn open_named(name: &str, baud: u32, resolve: Resolve) -> Result<Self, LinkError> {
        if baud == 0 {
            return Err(LinkError::Open(format!(
                "cannot open serial port {name} at 0 baud: a bit rate is a positive number"
            )));
        }
        let path = resolve()?;
        let port = open_port(&path, baud)?;
        Ok(SerialLink {
            name: name.to_string(),
            path,
            baud,
            port: Some(port),
            resolve,
        })
    }

    /// The open port, or the loss it suffered.
    fn port(&mut self) -> Result<&mut Box<dyn SerialPort>, LinkError> {
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
                self.port = None;
                LinkError::Lost(format!("{} went away ({why})", self.path))
            }
            other => other,
        }
    }
}

fn open_port(path: &str, baud: u32) -> Result<Open, LinkError> {
    let builder = serialport::new(path, baud)
        .data_bits(DataBits::Eight)
        .parity(Parity::None)
        .stop_bits(StopBits::One)
        .flow_control(FlowControl::None)
        .timeout(Duration::from_millis(100));
    let failed = |e: serialport::Error| LinkError::Open(open_hint(path, &e));
    #[cfg(unix)]
    {
        use std::os::fd::{AsRawFd, BorrowedFd};
        let native = builder.open_native().map_err(failed)?;
        // SAFETY: the descriptor is the open port's, valid while `native` lives; it is only
        // borrowed here to be duplicated (serialport's port has no `AsFd`).
        let borrowed = unsafe { BorrowedFd::borrow_raw(native.as_raw_fd()) };
        let watch = borrowed.try_clone_to_owned().ok();
        Ok(Open {
            port: Box::new(native),
            watch,
        })
    }
    #[cfg(not(unix))]
    {
        Ok(Open {
            port: builder.open().map_err(failed)?,
        })
    }
}

/// The OS error with what usually fixes it.
fn open_hint(path: &str, error: &serialport::Error) -> String {
    if error.description.contains("exclusive") {
        return format!("cannot open serial port {path}: {error}; another program has it open");
    }
    let hint = match error.kind() {
        serialport::ErrorKind::NoDevice => {
            "; is the adapter plugged in? `tmclsh ports` lists the ports"
        }
        serialport::ErrorKind::Io(std::io::ErrorKind::PermissionDenied) => {
            "; add yourself to the group that owns the port (often `dialout`) and log in again"
        }
        serialport::ErrorKind::Io(std::io::ErrorKind::NotFound) => {
            "; `tmclsh ports` lists the ports"
        }
        _ => "",
    };
    format!("cannot open serial port {path}: {error}{hint}")
}

impl Link for SerialLink {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        // The port writes straight to the kernel; flush() would be tcdrain, which waits until
        // the bytes have left the UART and so adds a wire time (or, on a pty, a scheduler round
        // trip) to every command for nothing.
        let result = self.port()?.write_all(bytes).map_err(LinkError::from_io);
        result.map_err(|e| self.lost(e))
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
        result.map_err(|e| self.lost(e))
    }

    fn describe(&self) -> String {
        if self.name == self.path {
            format!("serial {} at {} baud", self.path, self.baud)
        } else {
            format!("serial {} ({}) at {} baud", self.name, self.path, self.baud)
        }
    }

    fn reopen(&mut self) -> Result<(), LinkError> {
        self.port = None;
        let path = (self.resolve)()?;
        self.port = Some(open_port(&path, self.baud)?);
        self.path = path;
        Ok(())
    }

    fn close(&mut self) {
        self.port = None;
    }

    #[cfg(unix)]
    fn watch(&self) -> Option<std::os::fd::OwnedFd> {
        let open = self.port.as_ref()?;
        open.watch.as_ref()?.try_clone().ok()
    }

    fn byte_time(&self) -> Option<Duration> {
        Some(Duration::from_secs_f64(10.0 / f64::from(self.baud)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rate_of_0_is_refused_before_opening() {
        let Err(LinkError::Open(message)) = SerialLink::open("/dev/null", 0) else {
            panic!("opened at 0 baud");
        };
        assert!(message.contains("at 0 baud"), "{message}");
    }
}
