//! A simulated bus served as an slcan adapter (`tmclsh sim --slcan`): the host's `C`, `Sn`, `O`
//! answered as a CANable answers them, each transmitted frame acknowledged in the chosen style
//! (`z`, `Z`, a bare CR or nothing) and handed to the bus, the bus's frames sent back as `t…`
//! lines; optionally another node's frames on the bus too. The bus is a [`CanDevice`]: a
//! dialect's simulator seen through its CAN framing.

use std::time::Duration;

use crate::link::can::CanFrame;
use crate::link::can::slcan::{self, AckStyle, Decoder, Event};

use super::Device;
use super::error::ConsoleError;

/// A simulated CAN bus: frames in, frames out, time as an input (see [`Device`]).
pub trait CanDevice: Send {
    /// A frame from the host arrives at `now`.
    fn receive_frame(&mut self, now: Duration, frame: &CanFrame);

    /// Appends the frames the bus has sent by `now`.
    fn poll_frames(&mut self, now: Duration, out: &mut Vec<CanFrame>);

    /// When the bus next has a frame or an event due.
    fn next_due(&self, now: Duration) -> Option<Duration>;

    /// Whether the bus hung up (fault injection).
    fn hung_up(&self) -> bool {
        false
    }

    /// A new connection replaces one that hung up.
    fn reconnect(&mut self) {}

    /// A console command for the simulated modules.
    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        let _ = (now, command);
        None
    }
}

/// Another node's frame put on the bus before each reply when foreign frames are asked for: a
/// CANopen heartbeat of node 5 (ID 0x705, state operational).
const HEARTBEAT: (u16, [u8; 1]) = (0x705, [0x05]);

/// What the simulated adapter says of itself (`V`, `N`).
const VERSION: &str = "V1013";
const SERIAL: &str = "NSIM1";

/// How the simulated adapter behaves.
#[derive(Debug, Clone, Copy, Default)]
pub struct SlcanOptions {
    /// The acknowledgement of a transmitted frame.
    pub ack: AckStyle,
    /// Put another node's frame on the bus before each frame of the simulated modules.
    pub foreign: bool,
}

/// The slcan adapter in front of a simulated bus.
pub struct SlcanAdapter {
    bus: Box<dyn CanDevice>,
    options: SlcanOptions,
    decoder: Decoder,
    open: bool,
    rate: Option<u8>,
    timestamps: bool,
    out: Vec<u8>,
}

impl SlcanAdapter {
    /// An adapter, closed, in front of `bus`.
    pub fn new(bus: Box<dyn CanDevice>, options: SlcanOptions) -> SlcanAdapter {
        SlcanAdapter {
            bus,
            options,
            decoder: Decoder::default(),
            open: false,
            rate: None,
            timestamps: false,
            out: Vec::new(),
        }
    }

    /// Answers one command line of the host (without its CR).
    fn command(&mut self, line: &str) -> Result<&'static [u8], ()> {
        match line.as_bytes() {
            b"" => Ok(b"\r"),
            b"O" if !self.open => {
                self.open = true;
                Ok(b"\r")
            }
            b"C" if self.open => {
                self.open = false;
                Ok(b"\r")
            }
            [b'S', code] if !self.open => {
                let code = code
                    .checked_sub(b'0')
                    .filter(|c| slcan::bitrate_of(*c).is_some());
                self.rate = Some(code.ok_or(())?);
                Ok(b"\r")
            }
            [b'Z', b'0' | b'1'] => {
                self.timestamps = line.ends_with('1');
                Ok(b"\r")
            }
            b"V" | b"v" => {
                self.out.extend_from_slice(VERSION.as_bytes());
                Ok(b"\r")
            }
            b"N" => {
                self.out.extend_from_slice(SERIAL.as_bytes());
                Ok(b"\r")
            }
            b"F" => {
                self.out.extend_from_slice(b"F00");
                Ok(b"\r")
            }
            _ => Err(()),
        }
    }

    /// A frame as the adapter hands it to the host, with the timestamp `Z1` asks for
    /// (milliseconds, wrapping at 60 000 as the Lawicel manual says).
    fn emit(&mut self, now: Duration, frame: &CanFrame) {
        let mut line = slcan::encode(frame);
        if self.timestamps {
            line.pop();
            line.push_str(&format!("{:04X}\r", now.as_millis() % 60_000));
        }
        self.out.extend_from_slice(line.as_bytes());
    }
}

impl Device for SlcanAdapter {
    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        let mut events = Vec::new();
        self.decoder.push(bytes, &mut events);
        for event in events {
            match event {
                Event::Frame(frame) if self.open => {
                    self.out.extend_from_slice(self.options.ack.bytes());
                    self.bus.receive_frame(now, &frame);
                }
                Event::Frame(_) | Event::Ack(_) | Event::Bell => {
                    // A frame while closed, a stray acknowledgement: refused (an empty line,
                    // read as an acknowledgement, is the empty command).
                    if matches!(event, Event::Ack(slcan::Ack::Ok)) {
                        self.out.push(b'\r');
                    } else if !matches!(event, Event::Bell) {
                        self.out.push(slcan::BEL);
                    }
                }
                Event::Line(line) => match self.command(&line) {
                    Ok(answer) => self.out.extend_from_slice(answer),
                    Err(()) => self.out.push(slcan::BEL),
                },
            }
        }
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        let mut frames = Vec::new();
        self.bus.poll_frames(now, &mut frames);
        if self.open {
            for frame in frames {
                if self.options.foreign {
                    let (id, data) = HEARTBEAT;
                    let heartbeat = CanFrame::new(id, &data).expect("a standard frame");
                    self.emit(now, &heartbeat);
                }
                self.emit(now, &frame);
            }
        }
        out.append(&mut self.out);
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        if self.out.is_empty() {
            self.bus.next_due(now)
        } else {
            Some(now)
        }
    }

    fn reconnect(&mut self) {
        self.open = false;
        self.decoder = Decoder::default();
        self.bus.reconnect()
    }

    /// The bus behind hung up (the console's `hangup`, `--hangup-after`): the adapter goes with it.
    fn hung_up(&self) -> bool {
        self.bus.hung_up()
    }

    /// The console's commands are for the modules and faults behind the adapter.
    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        self.bus.control(now, command)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bus whose one node answers every frame to ID 1 with its data reversed, to ID 2.
    #[derive(Default)]
    struct Mirror(Vec<CanFrame>);

    impl CanDevice for Mirror {
        fn receive_frame(&mut self, _: Duration, frame: &CanFrame) {
            if frame.id() == 1 {
                let data: Vec<u8> = frame.data().iter().rev().copied().collect();
                self.0.push(CanFrame::new(2, &data).unwrap());
            }
        }

        fn poll_frames(&mut self, _: Duration, out: &mut Vec<CanFrame>) {
            out.append(&mut self.0);
        }

        fn next_due(&self, now: Duration) -> Option<Duration> {
            (!self.0.is_empty()).then_some(now)
        }
    }

    fn exchange(adapter: &mut SlcanAdapter, sent: &str) -> String {
        adapter.receive(Duration::ZERO, sent.as_bytes());
        let mut out = Vec::new();
        adapter.poll_output(Duration::ZERO, &mut out);
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn the_adapter_opens_acknowledges_and_relays() {
        for (ack, shown) in [
            (AckStyle::Lower, "z\r"),
            (AckStyle::Upper, "Z\r"),
            (AckStyle::Cr, "\r"),
            (AckStyle::None, ""),
        ] {
            let options = SlcanOptions {
                ack,
                foreign: false,
            };
            let mut adapter = SlcanAdapter::new(Box::new(Mirror::default()), options);
            assert_eq!(exchange(&mut adapter, "t0012AABB\r"), "\x07", "closed");
            assert_eq!(exchange(&mut adapter, "C\rS8\rO\r"), "\x07\r\r");
            assert_eq!(
                exchange(&mut adapter, "t0012AABB\r"),
                format!("{shown}t0022BBAA\r")
            );
            assert_eq!(exchange(&mut adapter, "S4\r"), "\x07", "open: no new rate");
        }
    }

    #[test]
    fn foreign_frames_and_timestamps_come_when_asked() {
        let options = SlcanOptions {
            ack: AckStyle::None,
            foreign: true,
        };
        let mut adapter = SlcanAdapter::new(Box::new(Mirror::default()), options);
        assert_eq!(exchange(&mut adapter, "S8\rO\rZ1\rV\r"), "\r\r\rV1013\r");
        adapter.receive(Duration::ZERO, b"t00110A\r");
        let mut out = Vec::new();
        adapter.poll_output(Duration::from_millis(0x1234), &mut out);
        assert_eq!(out, b"t7051051234\rt00210A1234\r".to_vec());
    }
}
