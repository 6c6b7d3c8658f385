//! The serial ports of this machine, with the USB vendor and product ids, serial number,
//! manufacturer and product of USB adapters. On Linux the ports are read from sysfs
//! (`/sys/class/tty`) as serialport's own listing does without libudev; elsewhere serialport
//! lists them.

use std::path::PathBuf;

/// A serial port.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Port {
    /// The device file (`/dev/ttyUSB0`).
    pub path: PathBuf,
    /// What kind of port it is.
    pub kind: Kind,
}

/// What kind of port.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Kind {
    /// A USB adapter.
    Usb(Usb),
    /// On a PCI card.
    Pci,
    /// Bluetooth (rfcomm).
    Bluetooth,
    /// Built into the machine, or unknown.
    Other,
}

/// What a USB adapter says about itself.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Usb {
    /// Vendor id.
    pub vid: u16,
    /// Product id.
    pub pid: u16,
    /// Serial number, where the adapter has one.
    pub serial: Option<String>,
    /// Manufacturer.
    pub manufacturer: Option<String>,
    /// Product name.
    pub product: Option<String>,
}

/// The serial ports, sorted by path.
pub(super) fn ports() -> std::io::Result<Vec<Port>> {
    let mut ports = platform()?;
    ports.sort_by(|a, b| a.path.cmp(&b.path));
    Ok(ports)
}

#[cfg(target_os = "linux")]
fn platform() -> std::io::Result<Vec<Port>> {
    Ok(sysfs::ports(&sysfs::root()))
}

#[cfg(not(target_os = "linux"))]
fn platform() -> std::io::Result<Vec<Port>> {
    use serialport::SerialPortType;
    let ports = serialport::available_ports().map_err(std::io::Error::other)?;
    Ok(ports
        .into_iter()
        .map(|p| Port {
            path: PathBuf::from(p.port_name),
            kind: match p.port_type {
                SerialPortType::UsbPort(u) => Kind::Usb(Usb {
                    vid: u.vid,
                    pid: u.pid,
                    serial: u.serial_number,
                    manufacturer: u.manufacturer,
                    product: u.product,
                }),
                SerialPortType::PciPort => Kind::Pci,
                SerialPortType::BluetoothPort => Kind::Bluetooth,
                SerialPortType::Unknown => Kind::Other,
            },
        })
        .collect())
}

#[cfg(target_os = "linux")]
mod sysfs {
    use std::path::{Path, PathBuf};

    use super::{Kind, Port, Usb};

    /// Where `sys/` and `dev/` are: `/`, or the made-up tree in `TMCLSH_TEST_SYSFS`.
    pub(super) fn root() -> PathBuf {
        crate::link::line::sysfs::root()
    }

    /// The ports under `root`: every entry of `sys/class/tty` backed by a device whose file
    /// exists in `dev/`.
    pub(super) fn ports(root: &Path) -> Vec<Port> {
        let Ok(entries) = root.join("sys/class/tty").read_dir() else {
            return Vec::new();
        };
        entries
            .filter_map(Result::ok)
            .filter_map(|entry| {
                let name = entry.file_name();
                let kind = kind(&entry.path(), &name.to_string_lossy())?;
                let path = root.join("dev").join(&name);
                path.exists().then_some(Port { path, kind })
            })
            .collect()
    }

    /// What the port of the class entry `entry` is; `None` for virtual terminals (no device).
    fn kind(entry: &Path, name: &str) -> Option<Kind> {
        if name.starts_with("rfcomm") {
            return Some(Kind::Bluetooth);
        }
        let device = entry.join("device").canonicalize().ok()?;
        let subsystem = device.join("subsystem").canonicalize().ok()?;
        match subsystem.file_name()?.to_str()? {
            "usb" => usb(&device).map(Kind::Usb),
            "usb-serial" => usb(device.parent()?).map(Kind::Usb),
            "pci" => Some(Kind::Pci),
            _ => Some(Kind::Other),
        }
    }

    /// The adapter whose USB interface directory is `interface`.
    fn usb(interface: &Path) -> Option<Usb> {
        let device = interface.parent()?;
        let read = |file: &str| {
            std::fs::read_to_string(device.join(file))
                .ok()
                .map(|s| s.trim().to_string())
                .filter(|s| !s.is_empty())
        };
        let hex = |file: &str| read(file).and_then(|s| u16::from_str_radix(&s, 16).ok());
        Some(Usb {
            vid: hex("idVendor")?,
            pid: hex("idProduct")?,
            serial: read("serial"),
            manufacturer: read("manufacturer"),
            product: read("product"),
        })
    }
}
