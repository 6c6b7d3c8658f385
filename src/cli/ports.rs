//! `tmclsh ports`: the serial ports of this machine.

use std::io::{self, Write};

pub fn run(out: &mut dyn Write) -> io::Result<()> {
    let ports = serialport::available_ports().map_err(io::Error::other)?;
    if ports.is_empty() {
        eprintln!("no serial ports found (USB adapters appear as /dev/ttyUSB* or /dev/ttyACM*)");
    }
    for port in ports {
        let kind = match port.port_type {
            serialport::SerialPortType::UsbPort(usb) => format!(
                "USB {:04x}:{:04x}{}",
                usb.vid,
                usb.pid,
                usb.product.map(|p| format!(" {p}")).unwrap_or_default()
            ),
            serialport::SerialPortType::PciPort => "PCI".into(),
            serialport::SerialPortType::BluetoothPort => "Bluetooth".into(),
            serialport::SerialPortType::Unknown => "unknown".into(),
        };
        writeln!(out, "{}\t{kind}", port.port_name)?;
    }
    Ok(())
}
