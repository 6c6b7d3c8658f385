//! Serial ports (USB adapters, RS-232/485) at 8N1 without flow control.

use std::io::{Read, Write};
use std::time::{Duration, Instant};

use serialport::{DataBits, FlowControl, Parity, SerialPort, StopBits};

use super::{Link, LinkError};

/// An open serial port.
pub struct SerialLink {
    path: String,
    baud: u32,
    port: Box<dyn SerialPort>,
}

impl SerialLink {
    /// Opens `path` at `baud`, 8N1, no flow control. A rate of 0 is refused before the port is
    /// opened (the command line refuses it earlier; a byte would take for ever).
    pub fn open(path: &str, baud: u32) -> Result<Self, LinkError> {
        if baud == 0 {
            return Err(LinkError::Open(format!(
                "cannot open serial port {path} at 0 baud: a bit rate is a positive number"
            )));
        }
        let port = open_port(path, baud)?;
        Ok(SerialLink {
            path: path.to_string(),
            baud,
            port,
        })
    }
}

fn open_port(path: &str, baud: u32) -> Result<Box<dyn SerialPort>, LinkError> {
    serialport::new(path, baud)
        .data_bits(DataBits::Eight)
        .parity(Parity::None)
        .stop_bits(StopBits::One)
        .flow_control(FlowControl::None)
        .timeout(Duration::from_millis(100))
        .open()
        .map_err(|e| LinkError::Open(open_hint(path, &e)))
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
        self.port.write_all(bytes).map_err(LinkError::from_io)
    }

    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        // A deadline already past still takes what has arrived (a zero-time poll), so the
        // session's drain before each request really empties the port.
        let wait = deadline.saturating_duration_since(Instant::now());
        self.port
            .set_timeout(wait)
            .map_err(|e| LinkError::Lost(e.to_string()))?;
        match self.port.read(buf) {
            Ok(0) => Err(LinkError::Lost(format!("{} closed", self.path))),
            Ok(n) => Ok(n),
            Err(e) => Err(LinkError::from_io(e)),
        }
    }

    fn describe(&self) -> String {
        format!("serial {} at {} baud", self.path, self.baud)
    }

    fn reopen(&mut self) -> Result<(), LinkError> {
        self.port = open_port(&self.path, self.baud)?;
        Ok(())
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
