//! `--port usb:VID:PID[:SERIAL][:IF]`: a USB adapter named by what it is rather than by the
//! device file it happens to get, resolved to that file when the port is opened; `IF` picks one
//! port of a multi-port adapter (FT2232, FT4232) by its USB interface.

use std::path::PathBuf;

use crate::exit::{Exit, ExitStatus};

use super::list::{Kind, Port, Usb, ports};

/// The prefix of a port named by USB ids.
pub(crate) const PREFIX: &str = "usb:";

/// An adapter named by USB ids.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct UsbSpec {
    vid: u16,
    pid: u16,
    serial: Option<String>,
    interface: Option<u8>,
}

impl UsbSpec {
    /// `usb:VID:PID[:SERIAL][:IF]`, ids in hex, the interface a decimal number (`usb:VID:PID::IF`
    /// without a serial number); `None` when `port` is a path.
    pub(crate) fn parse(port: &str) -> Option<Result<UsbSpec, UsbError>> {
        let rest = port.strip_prefix(PREFIX)?;
        let bad = || UsbError::Malformed(port.to_string());
        let mut parts = rest.splitn(3, ':');
        let hex = |s: Option<&str>| {
            s.filter(|s| (1..=4).contains(&s.len()))
                .and_then(|s| u16::from_str_radix(s, 16).ok())
        };
        let vid = hex(parts.next());
        let pid = hex(parts.next());
        let (serial, interface) = match parts.next() {
            None => (None, None),
            Some(tail) => match tail.rsplit_once(':') {
                Some((serial, number))
                    if (1..=2).contains(&number.len())
                        && number.bytes().all(|b| b.is_ascii_digit()) =>
                {
                    let serial = (!serial.is_empty()).then(|| serial.to_string());
                    (serial, number.parse::<u8>().ok())
                }
                _ if tail.is_empty() => return Some(Err(bad())),
                _ => (Some(tail.to_string()), None),
            },
        };
        Some(match (vid, pid) {
            (Some(vid), Some(pid)) => Ok(UsbSpec {
                vid,
                pid,
                serial,
                interface,
            }),
            _ => Err(bad()),
        })
    }

    fn matches(&self, port: &Port) -> bool {
        match &port.kind {
            Kind::Usb(usb) => {
                usb.vid == self.vid
                    && usb.pid == self.pid
                    && (self.serial.is_none() || self.serial == usb.serial)
                    && (self.interface.is_none() || self.interface == usb.interface)
            }
            _ => false,
        }
    }
}

impl std::fmt::Display for UsbSpec {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{PREFIX}{:04x}:{:04x}", self.vid, self.pid)?;
        match (&self.serial, self.interface) {
            (Some(serial), Some(interface)) => write!(f, ":{serial}:{interface}"),
            (None, Some(interface)) => write!(f, "::{interface}"),
            (Some(serial), None) => write!(f, ":{serial}"),
            (None, None) => Ok(()),
        }
    }
}

/// Why a `usb:` name gives no one port: a malformed name and one several adapters fit are
/// refused (they do not get better by waiting); one no adapter answers to is a link that is not
/// there.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub(crate) enum UsbError {
    /// Not of the form `usb:VID:PID[:SERIAL][:IF]`.
    #[error(
        "`{0}`: a USB adapter is named usb:VID:PID, usb:VID:PID:SERIAL or, for one port of a \
         multi-port adapter, usb:VID:PID:SERIAL:IF, with the ids in hex as `tmclsh ports` shows \
         them (e.g. usb:0403:6001)"
    )]
    Malformed(String),
    /// No adapter of these ids is plugged in.
    #[error("no USB adapter {0} is plugged in (`tmclsh ports` lists the serial ports)")]
    Absent(UsbSpec),
    /// Several ports fit the name: they are listed, with a name that picks one.
    #[error("{spec} matches {count} ports: {listed}{hint}")]
    Several {
        /// The name as parsed.
        spec: UsbSpec,
        /// How many ports fit.
        count: usize,
        /// The ports, with what tells them apart.
        listed: String,
        /// How to name one of them.
        hint: String,
    },
}

/// A name no adapter answers to is a link not there (exit 3); the others are refused (exit 2).
impl ExitStatus for UsbError {
    fn exit(&self) -> Exit {
        match self {
            UsbError::Absent(_) => Exit::Link,
            UsbError::Malformed(_) | UsbError::Several { .. } => Exit::Refused,
        }
    }
}

/// Looks the adapter up among the ports of this machine.
pub(crate) fn find(spec: &UsbSpec) -> Result<PathBuf, UsbError> {
    let ports = ports().unwrap_or_default();
    let found: Vec<&Port> = ports.iter().filter(|p| spec.matches(p)).collect();
    match found.as_slice() {
        [one] => Ok(one.path.clone()),
        [] => Err(UsbError::Absent(spec.clone())),
        several => {
            let listed: Vec<String> = several
                .iter()
                .map(|p| match &p.kind {
                    Kind::Usb(usb) => {
                        let serial = match &usb.serial {
                            Some(serial) => format!("serial {serial}"),
                            None => "no serial number".into(),
                        };
                        match usb.interface {
                            Some(i) if one_adapter(several) => {
                                format!("{} ({serial}, interface {i})", p.path.display())
                            }
                            _ => format!("{} ({serial})", p.path.display()),
                        }
                    }
                    _ => p.path.display().to_string(),
                })
                .collect();
            let example = several.iter().find_map(|p| match &p.kind {
                Kind::Usb(usb) if one_adapter(several) => usb.interface.map(|i| {
                    let named = UsbSpec {
                        serial: usb.serial.clone(),
                        interface: Some(i),
                        ..spec.clone()
                    };
                    format!("; name one by its interface, e.g. {named}")
                }),
                Kind::Usb(Usb {
                    serial: Some(serial),
                    ..
                }) => Some(format!(
                    "; name one by its serial number, e.g. {spec}:{serial}"
                )),
                _ => None,
            });
            Err(UsbError::Several {
                spec: spec.clone(),
                count: several.len(),
                listed: listed.join(", "),
                hint: example.unwrap_or_else(|| "; give the device file instead".into()),
            })
        }
    }
}

/// Whether the ports are all of one adapter (the same serial number): the ports of a multi-port
/// adapter, told apart by interface only.
fn one_adapter(ports: &[&Port]) -> bool {
    let serials: Vec<Option<&String>> = ports
        .iter()
        .map(|p| match &p.kind {
            Kind::Usb(usb) => usb.serial.as_ref(),
            _ => None,
        })
        .collect();
    serials[0].is_some() && serials.iter().all(|s| *s == serials[0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_parse_with_hex_ids_and_an_optional_serial() {
        let spec = UsbSpec::parse("usb:0403:6001").unwrap().unwrap();
        assert_eq!(spec.to_string(), "usb:0403:6001");
        let spec = UsbSpec::parse("usb:2E8A:a:AB:CD").unwrap().unwrap();
        assert_eq!(spec.to_string(), "usb:2e8a:000a:AB:CD");
        assert!(UsbSpec::parse("/dev/ttyUSB0").is_none());
        let spec = UsbSpec::parse("usb:0403:6011:FT4232A:2").unwrap().unwrap();
        assert_eq!(spec.serial.as_deref(), Some("FT4232A"));
        assert_eq!(spec.interface, Some(2));
        assert_eq!(spec.to_string(), "usb:0403:6011:FT4232A:2");
        let spec = UsbSpec::parse("usb:0403:6010::1").unwrap().unwrap();
        assert_eq!((spec.serial, spec.interface), (None, Some(1)));
        // A serial number with a colon in it stays whole unless it ends in a short number.
        let spec = UsbSpec::parse("usb:0403:6001:AB:CD").unwrap().unwrap();
        assert_eq!(spec.serial.as_deref(), Some("AB:CD"));
        for bad in [
            "usb:",
            "usb:0403",
            "usb:0403:",
            "usb:xyz:6001",
            "usb:12345:1",
            "usb:1:2:",
        ] {
            assert!(UsbSpec::parse(bad).unwrap().is_err(), "{bad}");
        }
    }
}
