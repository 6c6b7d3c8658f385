//! An slcan adapter on a serial line as a [`CanBus`]: the open sequence (`C`, `Sn`, `O`), each
//! answered by the adapter or named as the problem; frames out as `t…` commands; frames in with
//! the adapter's acknowledgements (whichever style, or none) set aside and BEL reported as the
//! adapter's error.

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use super::CanBus;
use super::frame::CanFrame;
use super::slcan::{self, Decoder, Event};
use crate::link::{Link, LinkError};

/// An slcan adapter, open on the bus.
pub struct SlcanLink {
    serial: Box<dyn Link>,
    name: String,
    bitrate: u32,
    timeout: Duration,
    decoder: Decoder,
    events: VecDeque<Event>,
    acks: u64,
    other_lines: u64,
    /// The last read of the line filled its buffer: more may have arrived than it took.
    read_full: bool,
}

impl SlcanLink {
    /// Opens the adapter on `serial` (named `name` in messages) at `bitrate`; each command of the
    /// open sequence must be answered within `timeout`.
    pub fn open(
        serial: Box<dyn Link>,
        name: &str,
        bitrate: u32,
        timeout: Duration,
    ) -> Result<SlcanLink, LinkError> {
        let mut link = SlcanLink {
            serial,
            name: name.to_string(),
            bitrate,
            timeout,
            decoder: Decoder::default(),
            events: VecDeque::new(),
            acks: 0,
            other_lines: 0,
            read_full: false,
        };
        link.start()?;
        Ok(link)
    }

    /// The open sequence: close whatever was open (an adapter already closed may refuse that),
    /// set the bit rate, open.
    fn start(&mut self) -> Result<(), LinkError> {
        let rate = slcan::bitrate_command(self.bitrate).ok_or_else(|| {
            LinkError::Open(format!(
                "slcan has no code for {} bit/s; its rates are {}",
                self.bitrate,
                slcan::BITRATES.map(|r| r.to_string()).join(", ")
            ))
        })?;
        self.decoder = Decoder::default();
        self.events.clear();
        self.drain_stale()?;
        self.command(slcan::CLOSE, true)?;
        self.command(&rate, false)?;
        self.command(slcan::OPEN, false)
    }

    /// Drops what the adapter said before this open (an earlier program's unread answers and
    /// frames), so no stale CR is taken for the answer to `C`: what has arrived is read without
    /// waiting, up to a bound, since an adapter left open may stream a busy bus's frames.
    fn drain_stale(&mut self) -> Result<(), LinkError> {
        let mut buf = [0u8; 256];
        for _ in 0..256 {
            match self.serial.recv(&mut buf, Instant::now()) {
                Ok(_) => {}
                Err(LinkError::Timeout) => return Ok(()),
                Err(e) => return Err(e),
            }
        }
        Ok(())
    }

    /// Sends one command and waits for its CR (or BEL, taken when `bell_ok`).
    fn command(&mut self, command: &str, bell_ok: bool) -> Result<(), LinkError> {
        self.serial.send(command.as_bytes())?;
        let shown = command.trim_end_matches('\r');
        let deadline = Instant::now() + self.timeout;
        loop {
            let event = match self.next_event(deadline) {
                Ok(event) => event,
                Err(LinkError::Timeout) => {
                    return Err(LinkError::Open(format!(
                        "the CAN adapter on {} did not answer the slcan command `{shown}` within \
                         {} ms: is it an slcan adapter (CANable or candleLight with slcan \
                         firmware, USBtin, CANUSB), powered and not held by another program?",
                        self.name,
                        self.timeout.as_millis()
                    )));
                }
                Err(e) => return Err(e),
            };
            match event {
                Event::Ack(_) => return Ok(()),
                Event::Bell if bell_ok => return Ok(()),
                Event::Bell => {
                    return Err(LinkError::Adapter(format!(
                        "the slcan adapter on {} refused `{shown}` (BEL)",
                        self.name
                    )));
                }
                Event::Frame(_) | Event::Line(_) => {}
            }
        }
    }

    /// The next event from the adapter, reading the line until `deadline`.
    fn next_event(&mut self, deadline: Instant) -> Result<Event, LinkError> {
        loop {
            if let Some(event) = self.events.pop_front() {
                return Ok(event);
            }
            self.read(deadline)?;
        }
    }

    /// Reads the line until `deadline` and decodes what came.
    fn read(&mut self, deadline: Instant) -> Result<(), LinkError> {
        let mut buf = [0u8; 256];
        let n = self.serial.recv(&mut buf, deadline)?;
        self.read_full = n == buf.len();
        let mut events = Vec::new();
        self.decoder.push(&buf[..n], &mut events);
        self.events.extend(events);
        Ok(())
    }

    /// Counts an event that is no frame, or names the adapter's error.
    fn not_a_frame(&mut self, event: Event) -> Result<(), LinkError> {
        match event {
            Event::Frame(_) => {}
            Event::Ack(_) => self.acks += 1,
            Event::Line(_) => self.other_lines += 1,
            Event::Bell => {
                return Err(LinkError::Adapter(format!(
                    "the slcan adapter on {} reported an error (BEL): a frame it could not \
                     send, or its bus is off (no other node acknowledging, wrong bit rate, \
                     missing termination)",
                    self.name
                )));
            }
        }
        Ok(())
    }
}

impl CanBus for SlcanLink {
    fn send_frame(&mut self, frame: &CanFrame) -> Result<(), LinkError> {
        self.serial.send(slcan::encode(frame).as_bytes())
    }

    fn recv_frame(&mut self, deadline: Instant) -> Result<CanFrame, LinkError> {
        loop {
            match self.next_event(deadline)? {
                Event::Frame(frame) => return Ok(frame),
                event => self.not_a_frame(event)?,
            }
        }
    }

    fn reads_all(&self) -> bool {
        self.serial.reads_all()
    }

    fn frame_at_hand(&mut self) -> Result<Option<CanFrame>, LinkError> {
        loop {
            match self.events.pop_front() {
                Some(Event::Frame(frame)) => return Ok(Some(frame)),
                Some(Event::Bell) => {
                    self.events.push_front(Event::Bell);
                    return Ok(None);
                }
                Some(event) => self.not_a_frame(event)?,
                // Only a read that filled its buffer can have left bytes on the line.
                None if !self.read_full => return Ok(None),
                None => match self.read(Instant::now()) {
                    Ok(()) => {}
                    Err(LinkError::Timeout) => return Ok(None),
                    Err(e) => return Err(e),
                },
            }
        }
    }

    fn describe(&self) -> String {
        format!("slcan {} at {} bit/s", self.name, self.bitrate)
    }

    fn reopen(&mut self) -> Result<(), LinkError> {
        self.serial.reopen()?;
        self.start()
    }

    fn close(&mut self) {
        self.serial.close()
    }

    #[cfg(unix)]
    fn watch(&self) -> Option<std::os::fd::OwnedFd> {
        self.serial.watch()
    }

    fn notes(&self) -> Vec<String> {
        vec![format!(
            "slcan: {} acknowledgements, {} other lines (extended or remote frames, answers) \
             ignored",
            self.acks, self.other_lines
        )]
    }
}
