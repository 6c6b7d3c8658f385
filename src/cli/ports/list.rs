//! The serial ports of this machine, with the USB vendor and product ids, serial number,
//! interface, manufacturer and product of USB adapters. On Linux the ports are read from sysfs
//! (`/sys/class/tty`) as serialport's own listing does without libudev, with the stable names
//! udev gives them (`/dev/serial/by-id`, `by-path`), an FTDI adapter's latency timer, and
//! whether a `ttyS` port is a placeholder with no UART behind it; elsewhere serialport lists
//! them.

use std::path::PathBuf;
use std::time::Duration;

/// A serial port.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Port {
    /// The device file (`/dev/ttyUSB0`).
    pub path: PathBuf,
    /// What kind of port it is.
    pub kind: Kind,
    /// The stable names that point to it (`/dev/serial/by-id/…`, `/dev/serial/by-path/…`).
    pub links: Vec<PathBuf>,
    /// An FTDI adapter's latency timer.
    pub latency: Option<Duration>,
    /// A `ttyS` port the kernel reserves with no UART behind it (its type is unknown).
    pub placeholder: bool,
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
    /// The USB interface: which port of a multi-port adapter (FT2232, FT4232) this is.
    pub interface: Option<u8>,
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
            links: Vec::new(),
            latency: None,
            placeholder: false,
            kind: match p.port_type {
                SerialPortType::UsbPort(u) => Kind::Usb(Usb {
                    vid: u.vid,
                    pid: u.pid,
                    serial: u.serial_number,
                    manufacturer: u.manufacturer,
                    product: u.product,
                    interface: None,
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

    use crate::cli::ports::list::{Kind, Port, Usb};

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
        let links = stable_links(root);
        entries
            .filter_map(Result::ok)
            .filter_map(|entry| {
                let name = entry.file_name();
                let kind = kind(&entry.path(), &name.to_string_lossy())?;
                let path = root.join("dev").join(&name);
                if !path.exists() {
                    return None;
                }
                let latency = crate::link::line::latency::timer_file(root, &path)
                    .and_then(|file| crate::link::line::latency::read(&file));
                // serial8250 reserves ttyS ports with no UART; their type is 0 (unknown).
                let placeholder = std::fs::read_to_string(entry.path().join("type"))
                    .is_ok_and(|t| t.trim() == "0");
                Some(Port {
                    links: links
                        .iter()
                        .filter(|(_, to)| *to == path)
                        .map(|(link, _)| link.clone())
                        .collect(),
                    path,
                    kind,
                    latency,
                    placeholder,
                })
            })
            .collect()
    }

    /// The udev links under `dev/serial/by-id` and `by-path`, each with the device file it
    /// points to (resolved one step, as udev writes them: `../../ttyUSB0`).
    fn stable_links(root: &Path) -> Vec<(PathBuf, PathBuf)> {
        let mut links = Vec::new();
        for dir in ["by-id", "by-path"] {
            let dir = root.join("dev/serial").join(dir);
            let Ok(entries) = dir.read_dir() else {
                continue;
            };
            for entry in entries.filter_map(Result::ok) {
                let link = entry.path();
                if let Ok(to) = std::fs::read_link(&link) {
                    links.push((link, normalise(&dir.join(to))));
                }
            }
        }
        links.sort();
        links
    }

    /// `a/b/../c` as `a/c`, without touching the file system.
    fn normalise(path: &Path) -> PathBuf {
        let mut out = PathBuf::new();
        for part in path.components() {
            match part {
                std::path::Component::ParentDir => {
                    out.pop();
                }
                std::path::Component::CurDir => {}
                other => out.push(other),
            }
        }
        out
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
            interface: interface_number(interface),
        })
    }

    /// The interface's number: its `bInterfaceNumber` (hex), else the end of its name
    /// (`1-1.2:1.3` is interface 3).
    fn interface_number(interface: &Path) -> Option<u8> {
        if let Ok(text) = std::fs::read_to_string(interface.join("bInterfaceNumber")) {
            return u8::from_str_radix(text.trim(), 16).ok();
        }
        let name = interface.file_name()?.to_str()?;
        let (_, config) = name.rsplit_once(':')?;
        config.rsplit_once('.')?.1.parse().ok()
    }
}
