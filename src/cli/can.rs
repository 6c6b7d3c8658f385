//! `--can`: where a CAN link goes (`slcan:PATH`, `socketcan:IFACE`) and how it is opened — the
//! adapter, the bus, and the dialect's framing over it (`--can-reply-id`; the module's CAN ID is
//! its address, `--module`).

use std::time::Duration;

use crate::dialect::DialectConfig;
use crate::exit::{Exit, Failure};
use crate::link::can::{CanBus, CanLink, SlcanLink};
use crate::link::{LineOptions, Link, SerialLink};

use super::value::ValueError;

/// The modules' CAN bit rate unless told otherwise (the TMCL modules' default, and PyTrinamic's
/// for every CAN interface).
pub const DEFAULT_BITRATE: u32 = 1_000_000;

/// The host's reply ID unless told otherwise: the TMCL modules' default reply ID, the same
/// number as their default serial host address (GP 76).
pub const DEFAULT_REPLY_ID: u16 = 2;

/// A CAN adapter as `--can` names it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CanSpec {
    /// A serial-line (slcan) adapter at a device path.
    Slcan(String),
    /// A SocketCAN interface (Linux).
    SocketCan(String),
}

impl CanSpec {
    /// `slcan:PATH` or `socketcan:IFACE`.
    pub fn parse(text: &str) -> Result<CanSpec, ValueError> {
        match text.split_once(':') {
            Some(("slcan", path)) if !path.is_empty() => Ok(CanSpec::Slcan(path.to_string())),
            Some(("socketcan", iface)) if !iface.is_empty() => {
                Ok(CanSpec::SocketCan(iface.to_string()))
            }
            _ => Err(ValueError::CanAdapter(text.to_string())),
        }
    }

    /// A short name for log file names: `slcan-ttyACM0`, `can0`.
    pub fn file_name(&self) -> String {
        match self {
            CanSpec::Slcan(path) => {
                let name = std::path::Path::new(path)
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_else(|| "serial".into());
                format!("slcan-{name}")
            }
            CanSpec::SocketCan(iface) => iface.clone(),
        }
    }
}

/// A CAN link's settings beside its adapter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CanSettings {
    /// The bus's bit rate (slcan sets it; SocketCAN's is `ip link`'s).
    pub bitrate: u32,
    /// The CAN ID replies to the host carry.
    pub reply_id: u16,
    /// The serial rate to an slcan adapter (USB CDC adapters ignore it).
    pub baud: u32,
}

/// Opens the adapter and carries `config`'s dialect over it.
pub fn open(
    spec: &CanSpec,
    settings: CanSettings,
    line: &LineOptions,
    config: &dyn DialectConfig,
    timeout: Duration,
) -> Result<Box<dyn Link>, Failure> {
    let dialect = config.dialect();
    let framer = config.can_framer(settings.reply_id).ok_or_else(|| {
        Failure::new(
            Exit::Refused,
            format!(
                "{} has no CAN interface: --can is for TMCL modules",
                dialect.devices
            ),
        )
    })?;
    let bus: Box<dyn CanBus> = match spec {
        CanSpec::Slcan(path) => {
            let mut serial = SerialLink::open_with(path, settings.baud, line.clone())?;
            for note in serial.take_notes() {
                super::diagnose(&note);
            }
            Box::new(SlcanLink::open(
                Box::new(serial),
                path,
                settings.bitrate,
                timeout,
            )?)
        }
        CanSpec::SocketCan(iface) => socketcan(iface)?,
    };
    Ok(Box::new(CanLink::new(bus, framer)))
}

#[cfg(target_os = "linux")]
fn socketcan(iface: &str) -> Result<Box<dyn CanBus>, crate::link::LinkError> {
    Ok(Box::new(crate::link::can::SocketCanLink::open(iface)?))
}

#[cfg(not(target_os = "linux"))]
fn socketcan(iface: &str) -> Result<Box<dyn CanBus>, crate::link::LinkError> {
    Err(crate::link::LinkError::Open(format!(
        "socketcan:{iface}: SocketCAN is Linux's; use an slcan adapter (--can slcan:PATH) here"
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adapters_are_named_by_kind() {
        assert_eq!(
            CanSpec::parse("slcan:/dev/ttyACM0"),
            Ok(CanSpec::Slcan("/dev/ttyACM0".into()))
        );
        assert_eq!(
            CanSpec::parse("socketcan:vcan0"),
            Ok(CanSpec::SocketCan("vcan0".into()))
        );
        for bad in ["/dev/ttyACM0", "slcan:", "pcan:1", "socketcan"] {
            assert!(CanSpec::parse(bad).is_err(), "{bad}");
        }
        assert_eq!(
            CanSpec::Slcan("/dev/ttyACM0".into()).file_name(),
            "slcan-ttyACM0"
        );
    }
}
