//! `tmclsh ports`: the serial ports of this machine, with what USB adapters say about themselves
//! (vendor and product id, serial number, interface, product), an FTDI adapter's latency timer,
//! the stable names udev gives them, and the `usb:VID:PID[:SERIAL][:IF]` names that `--port`
//! resolves to them; placeholder `ttyS` ports only with `--all`; with `--probe`, what module
//! answers on each USB port or on the ports named (`probe.rs`).

mod can;
mod list;
mod probe;
pub(super) mod usb;

use std::io::{self, Write};
use std::path::Path;

use crate::dialect::Configured;
use crate::json::{Value, json};

use super::connection::DialectArgs;

use list::{Kind, Port, ports};

/// Arguments of `ports`.
#[derive(Debug, Clone, clap::Args)]
pub(super) struct PortsArgs {
    /// Ask each USB port (or each PORT named) which module is there: address --module at --baud
    /// in --protocol (TMCL: command 136 to address 1 at 9600 baud by default), each reply
    /// awaited 100 ms (a port in use by another program is reported, not waited for). Built-in
    /// ports are probed only when named: what is wired to them may not expect the bytes.
    #[arg(long)]
    pub probe: bool,
    /// With --probe: the bit rate to probe at (8N1).
    #[arg(long, value_name = "N", env = "TMCLSH_BAUD", default_value_t = 9600, value_parser = super::connection::parse_baud)]
    pub baud: u32,
    /// With --probe: the protocol to ask in.
    #[command(flatten)]
    pub dialect: DialectArgs,
    /// With --probe: the address to ask (TMCL: 1 = address character A; SMD4: @N).
    #[arg(long, short = 'm', value_name = "N", env = "TMCLSH_MODULE", default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..))]
    pub module: u8,
    /// List the placeholder ttyS ports too (reserved by the kernel, with no UART behind them).
    #[arg(long)]
    pub all: bool,
    /// Print one JSON document instead (fields in docs/machine-output.md).
    #[arg(long)]
    pub json: bool,
    /// The ports to probe (with --probe).
    #[arg(value_name = "PORT", requires = "probe", value_hint = clap::ValueHint::FilePath)]
    pub named: Vec<String>,
}

/// Prints one row per port: device file, kind, VID:PID, serial number, interface, latency timer,
/// product (manufacturer), and its stable names under it; with `--probe`, then what answers.
pub(super) fn run(args: &PortsArgs, configs: &Configured, out: &mut dyn Write) -> io::Result<()> {
    let all = ports()?;
    if !args.json {
        list_ports(&all, args.all, out)?;
    }
    let paths: Vec<String> = match (args.probe, args.named.is_empty()) {
        (false, _) => Vec::new(),
        (true, true) => all
            .iter()
            .filter(|p| matches!(p.kind, Kind::Usb(_)))
            .map(|p| p.path.display().to_string())
            .collect(),
        (true, false) => args.named.clone(),
    };
    let probe = probe::Probe {
        baud: args.baud,
        dialect: args.dialect.protocol,
        address: args.module,
    };
    if !args.json {
        return probe::probe_all(&paths, configs, &probe, out);
    }
    let listed: Vec<Value> = all
        .iter()
        .filter(|p| args.all || !p.placeholder)
        .map(|p| port_json(p, &all))
        .collect();
    let mut document = json!({ "ports": listed });
    if args.probe {
        let probes: Vec<Value> = paths
            .iter()
            .map(|path| json!({ "port": path, "answer": probe::probe(path, configs, &probe) }))
            .collect();
        document["probes"] = json!(probes);
    }
    crate::json::write(&document, out)
}

/// A port as a JSON object (`ports --json`).
fn port_json(port: &Port, all: &[Port]) -> Value {
    let usb = match &port.kind {
        Kind::Usb(usb) => Some(usb),
        _ => None,
    };
    let kind = match &port.kind {
        Kind::Usb(_) => "usb",
        Kind::Pci => "pci",
        Kind::Bluetooth => "bluetooth",
        Kind::Other if port.placeholder => "none",
        Kind::Other => "other",
    };
    json!({
        "path": port.path.display().to_string(),
        "type": kind,
        "vid": usb.map(|u| format!("{:04x}", u.vid)),
        "pid": usb.map(|u| format!("{:04x}", u.pid)),
        "serial": usb.and_then(|u| u.serial.clone()),
        "interface": usb.and_then(|u| u.interface),
        "manufacturer": usb.and_then(|u| u.manufacturer.clone()),
        "product": usb.and_then(|u| u.product.clone()),
        "latency_ms": port.latency.map(|t| t.as_millis() as u64),
        "placeholder": port.placeholder,
        "links": port.links.iter().map(|l| l.display().to_string()).collect::<Vec<_>>(),
        "usb_name": usb_name(port, all),
    })
}

/// The `usb:` name of `port`, with its interface when its adapter has several ports.
fn usb_name(port: &Port, all: &[Port]) -> Option<String> {
    let Kind::Usb(usb) = &port.kind else {
        return None;
    };
    let siblings = all
        .iter()
        .filter(|p| match &p.kind {
            Kind::Usb(other) => {
                (other.vid, other.pid, &other.serial) == (usb.vid, usb.pid, &usb.serial)
            }
            _ => false,
        })
        .count();
    let mut name = format!("usb:{:04x}:{:04x}", usb.vid, usb.pid);
    match (&usb.serial, usb.interface) {
        (Some(serial), Some(i)) if siblings > 1 => name.push_str(&format!(":{serial}:{i}")),
        (None, Some(i)) if siblings > 1 => name.push_str(&format!("::{i}")),
        (Some(serial), _) => name.push_str(&format!(":{serial}")),
        (None, _) => {}
    }
    Some(name)
}

fn list_ports(all: &[Port], placeholders: bool, out: &mut dyn Write) -> io::Result<()> {
    let shown: Vec<&Port> = all
        .iter()
        .filter(|p| placeholders || !p.placeholder)
        .collect();
    let hidden = all.len() - shown.len();
    if shown.is_empty() {
        eprintln!("no serial ports found (USB adapters appear as /dev/ttyUSB* or /dev/ttyACM*)");
    }
    let dash = || "-".to_string();
    let rows: Vec<[String; 7]> = shown
        .iter()
        .map(|port| {
            let path = port.path.display().to_string();
            let latency = port
                .latency
                .map(|t| format!("{} ms", t.as_millis()))
                .unwrap_or_else(dash);
            match &port.kind {
                Kind::Usb(usb) => {
                    let product = match (&usb.product, &usb.manufacturer) {
                        (Some(p), Some(m)) if !p.contains(m.as_str()) => format!("{p} ({m})"),
                        (Some(p), _) => p.clone(),
                        (None, Some(m)) => m.clone(),
                        (None, None) => String::new(),
                    };
                    let (kind, product) = match can::slcan_adapter(usb.vid, usb.pid) {
                        Some(name) => ("CAN", format!("{name}: --can slcan:{path}")),
                        None => ("USB", product),
                    };
                    [
                        path,
                        kind.into(),
                        format!("{:04x}:{:04x}", usb.vid, usb.pid),
                        usb.serial.clone().unwrap_or_else(dash),
                        usb.interface.map(|i| i.to_string()).unwrap_or_else(dash),
                        latency,
                        product,
                    ]
                }
                kind => {
                    let kind = match kind {
                        Kind::Pci => "PCI",
                        Kind::Bluetooth => "Bluetooth",
                        _ if port.placeholder => "none",
                        _ => "other",
                    };
                    let product = if port.placeholder {
                        "placeholder: no UART behind it".to_string()
                    } else {
                        String::new()
                    };
                    [path, kind.into(), dash(), dash(), dash(), latency, product]
                }
            }
        })
        .collect();
    if !rows.is_empty() {
        let header = [
            "PORT", "TYPE", "VID:PID", "SERIAL", "IF", "LATENCY", "PRODUCT",
        ]
        .map(String::from);
        let widths: Vec<usize> = (0..6)
            .map(|i| {
                rows.iter()
                    .chain([&header])
                    .map(|r| r[i].chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let lines = std::iter::once((&header, None))
            .chain(rows.iter().zip(&shown).map(|(r, p)| (r, Some(*p))));
        for (row, port) in lines {
            let mut line = String::new();
            for (cell, width) in row.iter().zip(&widths) {
                line.push_str(&format!("{cell:<width$}  "));
            }
            line.push_str(&row[6]);
            writeln!(out, "{}", crate::escape::escape_control(line.trim_end()))?;
            for link in port.map(|p| p.links.as_slice()).unwrap_or_default() {
                let line = format!("  also {}", link.display());
                writeln!(out, "{}", crate::escape::escape_control(&line))?;
            }
        }
    }
    if hidden > 0 {
        writeln!(
            out,
            "({} hidden: ttyS ports the kernel reserves with no UART behind them; --all lists them)",
            crate::count::counted(hidden, "placeholder port")
        )?;
    }
    if let Some(named) = shown.iter().find_map(|p| usb_name(p, all)) {
        writeln!(
            out,
            "\n--port {named} names an adapter whatever device file it gets (its serial number may be left out)"
        )?;
    }
    if shown.iter().any(|p| {
        p.latency
            .is_some_and(|t| t > crate::link::line::latency::LOW)
    }) {
        writeln!(
            out,
            "an FTDI latency timer above 2 ms delays every reply by up to that much; tmclsh lowers \
             it on opening where the driver lets it (docs/real-line.md has the fix)"
        )?;
    }
    Ok(())
}

/// Whether the port `--port` names is there now: a device file that exists, or a `usb:` name
/// that resolves to exactly one adapter. `Err` for a `usb:` name that is malformed or matches
/// several adapters (those do not get better by waiting).
pub(super) fn present(port: &str) -> Result<bool, usb::UsbError> {
    match usb::UsbSpec::parse(port) {
        None => Ok(Path::new(port).exists()),
        Some(spec) => match usb::find(&spec?) {
            Ok(_) => Ok(true),
            Err(usb::UsbError::Absent(_)) => Ok(false),
            Err(several) => Err(several),
        },
    }
}
