//! Where a link goes, decided before it is opened: a TCP address, a serial device (a `usb:` name
//! resolved to the device file the adapter has now), or the built-in simulator. The transcript's
//! file name in a `--log` directory comes from it too.

use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

use crate::dialect::{Dialect, DialectConfig};
use crate::exit::Failure;
use crate::link::{LineOptions, Link, LinkError, SerialLink, TcpLink};

use super::can::{CanSettings, CanSpec};
use super::ports::usb::{UsbSpec, find};

/// The place a link goes to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// A TCP address.
    Tcp(String),
    /// A serial device file (or a symlink to one, followed anew at each reopen).
    Serial(String),
    /// A USB adapter named by its ids (`name`, `usb:VID:PID[:SERIAL]`), at `path` now; looked up
    /// again at each reopen, since a replugged adapter comes back under another name.
    Usb {
        /// The name as given.
        name: String,
        /// The device file it has now.
        path: String,
    },
    /// A CAN adapter, with the bus's settings.
    Can {
        /// The adapter.
        spec: CanSpec,
        /// Bit rate, reply ID, the serial rate to an slcan adapter.
        settings: CanSettings,
    },
    /// The built-in simulated module.
    Builtin,
}

impl Target {
    /// Where `--tcp` and `--port` point (`--tcp`, which only the command line gives, wins over a
    /// port from the environment or a file); a `usb:` name is looked up now: exit 3 when no such
    /// adapter is plugged in, exit 2 when the name is malformed or fits several.
    pub fn of(port: Option<&str>, tcp: Option<&str>) -> Result<Target, Failure> {
        if let Some(address) = tcp {
            return Ok(Target::Tcp(address.to_string()));
        }
        let Some(port) = port else {
            return Ok(Target::Builtin);
        };
        match UsbSpec::parse(port) {
            None => Ok(Target::Serial(port.to_string())),
            Some(spec) => {
                let path = find(&spec?)?;
                Ok(Target::Usb {
                    name: port.to_string(),
                    path: path.to_string_lossy().into_owned(),
                })
            }
        }
    }

    /// Opens the link with the line as the system leaves it; the built-in simulator is
    /// `config`'s dialect's.
    pub fn open(
        &self,
        baud: u32,
        config: &dyn DialectConfig,
        timeout: Duration,
    ) -> Result<Box<dyn Link>, Failure> {
        self.open_line(baud, &LineOptions::default(), config, timeout)
    }

    /// Opens the link with the line settings `line`; what the line says of itself (a rate
    /// the driver changed, modem lines a port lacks, a latency timer that stays high) is said
    /// on stderr, once.
    pub fn open_line(
        &self,
        baud: u32,
        line: &LineOptions,
        config: &dyn DialectConfig,
        timeout: Duration,
    ) -> Result<Box<dyn Link>, Failure> {
        Ok(match self {
            Target::Tcp(address) => {
                let link = TcpLink::connect(address, timeout)?;
                if line.wants_modem_lines() {
                    super::diagnose(&format!(
                        "a TCP link has no modem lines: {} not applied (a serial server sets \
                         its own port's)",
                        line.named().join(", ")
                    ));
                }
                Box::new(link)
            }
            Target::Serial(path) => {
                let mut link = SerialLink::open_with(path, baud, line.clone())?;
                for note in link.take_notes() {
                    super::diagnose(&note);
                }
                Box::new(link)
            }
            Target::Usb { name, path } => {
                let first = std::sync::Mutex::new(Some(path.clone()));
                let spec = UsbSpec::parse(name).and_then(Result::ok);
                let resolve = move || {
                    // The path found a moment ago first, then the adapter looked up anew.
                    if let Some(path) = first.lock().ok().and_then(|mut p| p.take()) {
                        return Ok(path);
                    }
                    let spec = spec
                        .as_ref()
                        .ok_or_else(|| LinkError::Open("bad name".into()))?;
                    find(spec)
                        .map(|p| p.to_string_lossy().into_owned())
                        .map_err(|why| LinkError::Open(why.to_string()))
                };
                let mut link = SerialLink::open_named(name, baud, line.clone(), Box::new(resolve))?;
                for note in link.take_notes() {
                    super::diagnose(&note);
                }
                Box::new(link)
            }
            Target::Can { spec, settings } => {
                super::can::open(spec, *settings, line, config, timeout)?
            }
            Target::Builtin => {
                let name = format!("simulated {} (built-in)", config.simulated_module());
                crate::sim::builtin_link(config.simulator(), name)
            }
        })
    }

    /// A short name for file names: `ttyUSB0`, `pts-3`, `tcp-127.0.0.1-4001`, `sim-tmcl`.
    pub fn file_name(&self, dialect: &Dialect) -> String {
        let name = match self {
            Target::Tcp(address) => format!("tcp-{address}"),
            Target::Serial(path) | Target::Usb { path, .. } => {
                let path = Path::new(path);
                match path.strip_prefix("/dev") {
                    Ok(rest) => rest.to_string_lossy().into_owned(),
                    Err(_) => path
                        .file_name()
                        .map(|n| n.to_string_lossy().into_owned())
                        .unwrap_or_else(|| "serial".into()),
                }
            }
            Target::Can { spec, .. } => spec.file_name(),
            Target::Builtin => format!("sim-{}", dialect.name),
        };
        name.chars()
            .map(|c| match c {
                'a'..='z' | 'A'..='Z' | '0'..='9' | '.' | '_' | '-' => c,
                _ => '-',
            })
            .collect()
    }
}

/// Whether `--log PATH` names a directory: one that exists, or a path ending with a separator
/// (created when the session opens).
pub(super) fn is_log_dir(path: &Path) -> bool {
    path.is_dir()
        || path
            .as_os_str()
            .to_string_lossy()
            .ends_with(['/', std::path::MAIN_SEPARATOR])
}

/// The transcript file for a session with `device` in the log directory `dir`:
/// `DEVICE-YYYY-MM-DDTHH-MM-SS.log`, the time in UTC like the transcript's own timestamps; the
/// `n`th choice (from 1) after the first is numbered (`…-2.log`), so sessions started in the same
/// second get files of their own.
pub(super) fn log_file(dir: &Path, device: &str, now: SystemTime, n: u32) -> PathBuf {
    let stamp = humantime::format_rfc3339_seconds(now).to_string();
    let stamp = stamp.trim_end_matches('Z').replace(':', "-");
    let number = if n > 1 {
        format!("-{n}")
    } else {
        String::new()
    };
    dir.join(format!("{device}-{stamp}{number}.log"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn devices_name_their_files() {
        let serial = |p: &str| Target::Serial(p.into()).file_name(&crate::dialect::tmcl::DIALECT);
        assert_eq!(serial("/dev/ttyUSB0"), "ttyUSB0");
        assert_eq!(serial("/dev/pts/3"), "pts-3");
        assert_eq!(
            serial("/dev/serial/by-id/usb-FTDI_FT232R_A50285BI-if00-port0"),
            "serial-by-id-usb-FTDI_FT232R_A50285BI-if00-port0"
        );
        assert_eq!(serial("COM3"), "COM3");
        assert_eq!(
            Target::Tcp("127.0.0.1:4001".into()).file_name(&crate::dialect::tmcl::DIALECT),
            "tcp-127.0.0.1-4001"
        );
        assert_eq!(
            Target::Builtin.file_name(&crate::dialect::smd4::DIALECT),
            "sim-smd4"
        );
    }

    #[test]
    fn log_files_are_named_by_device_and_date() {
        let at = SystemTime::UNIX_EPOCH + Duration::from_secs(1_796_120_102);
        assert_eq!(
            log_file(Path::new("logs"), "ttyUSB0", at, 1),
            Path::new("logs/ttyUSB0-2026-12-01T10-15-02.log")
        );
        assert_eq!(
            log_file(Path::new("logs"), "ttyUSB0", at, 2),
            Path::new("logs/ttyUSB0-2026-12-01T10-15-02-2.log")
        );
    }
}
