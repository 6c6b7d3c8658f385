//! A Linux SocketCAN interface as a [`CanBus`] (PEAK, Kvaser, gs_usb, MCP2515 … all appear as
//! `can0`; `vcan0` is a virtual bus), through the `socketcan` crate. The bit rate is the
//! interface's, set with `ip link`, not tmclsh's.

use std::io;
use std::time::Instant;

use socketcan::{CanSocket, EmbeddedFrame, Id, Socket, StandardId};

use super::CanBus;
use super::frame::CanFrame;
use crate::link::LinkError;

/// An open SocketCAN interface.
pub struct SocketCanLink {
    socket: CanSocket,
    iface: String,
    other: u64,
}

impl SocketCanLink {
    /// Opens the raw CAN socket on `iface`; the error says what is missing (the kernel's CAN
    /// support, the interface, its being up).
    pub fn open(iface: &str) -> Result<SocketCanLink, LinkError> {
        let socket = CanSocket::open(iface).map_err(|e| LinkError::Open(refusal(iface, &e)))?;
        Ok(SocketCanLink {
            socket,
            iface: iface.to_string(),
            other: 0,
        })
    }
}

/// Why `iface` could not be opened, and what to do.
fn refusal(iface: &str, error: &io::Error) -> String {
    match error.raw_os_error() {
        Some(libc::EAFNOSUPPORT) | Some(libc::EPROTONOSUPPORT) => format!(
            "socketcan:{iface}: this kernel has no SocketCAN support ({error}); load it with \
             `modprobe can-raw`, or use an slcan adapter (--can slcan:PATH)"
        ),
        Some(libc::ENODEV) | Some(libc::ENXIO) => format!(
            "socketcan:{iface}: no such CAN interface ({error}); `ip -details link show type can` \
             lists them, and a virtual bus is `ip link add dev vcan0 type vcan && ip link set \
             up vcan0`"
        ),
        _ => format!("socketcan:{iface}: {error}"),
    }
}

/// The socket's frame for one of ours.
pub fn to_socketcan(frame: &CanFrame) -> socketcan::CanFrame {
    let id = StandardId::new(frame.id()).expect("an 11-bit identifier");
    socketcan::CanFrame::new(id, frame.data()).expect("at most 8 bytes")
}

/// Ours for a standard data frame; `None` for extended, remote and error frames.
pub fn from_socketcan(frame: &socketcan::CanFrame) -> Option<CanFrame> {
    let socketcan::CanFrame::Data(data) = frame else {
        return None;
    };
    match data.id() {
        Id::Standard(id) => CanFrame::new(id.as_raw(), data.data()).ok(),
        Id::Extended(_) => None,
    }
}

impl CanBus for SocketCanLink {
    fn send_frame(&mut self, frame: &CanFrame) -> Result<(), LinkError> {
        self.socket
            .write_frame(&to_socketcan(frame))
            .map_err(|e| match e.raw_os_error() {
                Some(libc::ENETDOWN) => LinkError::Adapter(format!(
                    "socketcan:{}: the interface is down (`ip link set up {}`)",
                    self.iface, self.iface
                )),
                Some(libc::ENOBUFS) => LinkError::Adapter(format!(
                    "socketcan:{}: the transmit queue is full: no other node acknowledges \
                     frames (bus off, wrong bit rate, missing termination)",
                    self.iface
                )),
                _ => LinkError::from_io(e),
            })
    }

    fn recv_frame(&mut self, deadline: Instant) -> Result<CanFrame, LinkError> {
        loop {
            let wait = deadline.saturating_duration_since(Instant::now());
            let frame = self
                .socket
                .read_frame_timeout(wait)
                .map_err(LinkError::from_io)?;
            match from_socketcan(&frame) {
                Some(frame) => return Ok(frame),
                None => self.other += 1,
            }
        }
    }

    fn describe(&self) -> String {
        format!("SocketCAN {}", self.iface)
    }

    fn notes(&self) -> Vec<String> {
        vec![format!(
            "SocketCAN {}: {} extended, remote or error frames ignored; the bit rate is the \
             interface's (ip -details link show {})",
            self.iface, self.other, self.iface
        )]
    }
}

#[cfg(test)]
mod tests {
    use socketcan::{CanRemoteFrame, ExtendedId};

    use super::*;

    #[test]
    fn standard_data_frames_cross_both_ways() {
        let ours = CanFrame::new(0x123, &[1, 100, 6, 0, 0, 0, 9]).unwrap();
        let theirs = to_socketcan(&ours);
        assert!(!theirs.is_extended());
        assert_eq!(theirs.data(), ours.data());
        assert_eq!(from_socketcan(&theirs), Some(ours));
        let empty = CanFrame::new(0x7FF, &[]).unwrap();
        assert_eq!(from_socketcan(&to_socketcan(&empty)), Some(empty));
    }

    #[test]
    fn extended_and_remote_frames_are_not_ours() {
        let extended = socketcan::CanFrame::new(ExtendedId::new(0x1234).unwrap(), &[1]).unwrap();
        assert_eq!(from_socketcan(&extended), None);
        let remote = socketcan::CanFrame::Remote(
            CanRemoteFrame::new_remote(StandardId::new(1).unwrap(), 0).unwrap(),
        );
        assert_eq!(from_socketcan(&remote), None);
    }

    #[test]
    fn a_missing_interface_is_named() {
        match SocketCanLink::open("tmclsh-none0") {
            Err(LinkError::Open(why)) => assert!(why.contains("socketcan:tmclsh-none0"), "{why}"),
            Ok(_) => panic!("an interface that cannot exist opened"),
            Err(e) => panic!("{e}"),
        }
    }
}
