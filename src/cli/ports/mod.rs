//! `tmclsh ports`: the serial ports of this machine, with what USB adapters say about themselves
//! (vendor and product id, serial number, product), and the `usb:VID:PID[:SERIAL]` names that
//! `--port` resolves to them; with `--probe`, what module answers on each (`probe.rs`).

mod list;
mod probe;
pub(super) mod usb;

use std::io::{self, Write};
use std::path::Path;

use crate::dialect::Configured;

use list::{Kind, ports};

/// Arguments of `ports`.
#[derive(Debug, Clone, clap::Args)]
pub(super) struct PortsArgs {
    /// Ask each port which TMCL module is there: command 136 to address 1 at 9600 baud, each
    /// reply awaited 100 ms (a port in use by another program is reported, not waited for).
    #[arg(long)]
    pub probe: bool,
}

/// Prints one row per port: device file, kind, VID:PID, serial number, product (manufacturer);
/// with `--probe`, then what answers on each.
pub(super) fn run(args: &PortsArgs, configs: &Configured, out: &mut dyn Write) -> io::Result<()> {
    list_ports(out)?;
    if args.probe {
        let paths: Vec<String> = ports()?
            .iter()
            .map(|p| p.path.display().to_string())
            .collect();
        probe::probe_all(&paths, configs, out)?;
    }
    Ok(())
}

fn list_ports(out: &mut dyn Write) -> io::Result<()> {
    let ports = ports()?;
    if ports.is_empty() {
        eprintln!("no serial ports found (USB adapters appear as /dev/ttyUSB* or /dev/ttyACM*)");
        return Ok(());
    }
    let rows: Vec<[String; 5]> = ports
        .iter()
        .map(|port| {
            let path = port.path.display().to_string();
            match &port.kind {
                Kind::Usb(usb) => {
                    let product = match (&usb.product, &usb.manufacturer) {
                        (Some(p), Some(m)) if !p.contains(m.as_str()) => format!("{p} ({m})"),
                        (Some(p), _) => p.clone(),
                        (None, Some(m)) => m.clone(),
                        (None, None) => String::new(),
                    };
                    [
                        path,
                        "USB".into(),
                        format!("{:04x}:{:04x}", usb.vid, usb.pid),
                        usb.serial.clone().unwrap_or_else(|| "-".into()),
                        product,
                    ]
                }
                kind => {
                    let kind = match kind {
                        Kind::Pci => "PCI",
                        Kind::Bluetooth => "Bluetooth",
                        _ => "other",
                    };
                    [path, kind.into(), "-".into(), "-".into(), String::new()]
                }
            }
        })
        .collect();
    let header = ["PORT", "TYPE", "VID:PID", "SERIAL", "PRODUCT"].map(String::from);
    let widths: Vec<usize> = (0..4)
        .map(|i| {
            rows.iter()
                .chain([&header])
                .map(|r| r[i].len())
                .max()
                .unwrap_or(0)
        })
        .collect();
    for row in [&header].into_iter().chain(&rows) {
        let mut line = String::new();
        for (cell, width) in row.iter().zip(&widths) {
            line.push_str(&format!("{cell:<width$}  "));
        }
        line.push_str(&row[4]);
        writeln!(out, "{}", crate::escape::escape_control(line.trim_end()))?;
    }
    if let Some(named) = ports.iter().find_map(|p| match &p.kind {
        Kind::Usb(usb) => Some(format!(
            "usb:{:04x}:{:04x}{}",
            usb.vid,
            usb.pid,
            usb.serial
                .as_ref()
                .map(|s| format!(":{s}"))
                .unwrap_or_default()
        )),
        _ => None,
    }) {
        writeln!(
            out,
            "\n--port {named} names an adapter whatever device file it gets (its serial number may be left out)"
        )?;
    }
    Ok(())
}

/// Whether the port `--port` names is there now: a device file that exists, or a `usb:` name
/// that resolves to exactly one adapter. `Err` for a `usb:` name that is malformed or matches
/// several adapters (those do not get better by waiting).
pub(super) fn present(port: &str) -> Result<bool, String> {
    match usb::UsbSpec::parse(port) {
        None => Ok(Path::new(port).exists()),
        Some(spec) => match usb::find(&spec?) {
            usb::Found::One(_) => Ok(true),
            usb::Found::None(_) => Ok(false),
            usb::Found::Several(why) => Err(why),
        },
    }
}
