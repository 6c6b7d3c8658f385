//! One module's serial interface: binary frames in binary mode, address-character lines in ASCII
//! mode, and the replies to both. Lines are read with tmclsh's own command grammar, so client
//! and simulator agree on one syntax.

use crate::dialect::tmcl::protocol::frame::{ChecksumError, encode_version_string, hex};
use crate::dialect::tmcl::protocol::line::{address_char, resolve};
use crate::dialect::tmcl::protocol::syntax::parse_line;
use crate::dialect::tmcl::protocol::{
    AsciiReply, AsciiWord, CommandFrame, FrameDecoder, InputError, Instruction, Op, Opcode,
    ReplyFrame, Status, format_instruction, host_char,
};

use super::ascii::{Context, Echo, LineInput};
use super::machine::Machine;
use super::options::Quirks;
use super::outcome::{Effect, Outcome, Reply, Source};

/// Where a module's replies and log lines go.
pub(crate) struct Sink<'a> {
    pub out: &'a mut Vec<u8>,
    pub quirks: &'a Quirks,
    pub log: Option<&'a mut (dyn FnMut(&str) + Send + 'static)>,
    /// The time, for log lines.
    pub t: f64,
}

impl Sink<'_> {
    fn log(&mut self, line: impl FnOnce() -> String) {
        if let Some(log) = self.log.as_mut() {
            log(&format!("{:12.6} {}", self.t, line()));
        }
    }
}

/// What the ASCII line input reads of the module's settings.
#[derive(Debug, Clone, Copy)]
struct LineSettings {
    address: Option<u8>,
    echo: Echo,
    max: usize,
}

/// A module on the bus.
pub(crate) struct Module {
    pub machine: Machine,
    /// The boot loader runs instead of the firmware: 136 answers with `B` for `V`, every other
    /// command with invalid command, and nothing starts ASCII mode.
    pub boot_loader: bool,
    ascii: bool,
    decoder: FrameDecoder,
    last_byte: f64,
    line: LineInput,
    /// The completed line being executed, kept to be filled again by the next one.
    text: String,
    /// The last line read and what it asked for (see [`Module::read_line`]).
    last_line: Option<(String, Result<Op, Status>)>,
    /// The last reply line sent, as written (see [`Module::send_line`]).
    last_reply: Option<(AsciiReply, Vec<u8>)>,
}

impl Module {
    pub(super) fn new(machine: Machine) -> Module {
        let mut module = Module {
            machine,
            boot_loader: false,
            ascii: false,
            decoder: FrameDecoder::new(),
            last_byte: 0.0,
            line: LineInput::new(),
            text: String::new(),
            last_line: None,
            last_reply: None,
        };
        module.power_up();
        module
    }

    /// The interface after power-up: ASCII when GP 67 bit 0 says so.
    pub(super) fn power_up(&mut self) {
        self.ascii = self.machine.ascii_config() & 1 != 0;
        self.decoder.clear();
        self.line.clear();
    }

    /// Whether the module is in ASCII mode.
    pub(super) fn is_ascii(&self) -> bool {
        self.ascii
    }

    /// Bytes from the line at `t` (the machine has been advanced to `t`), each taking
    /// `byte_time` seconds on a paced line. A partial binary frame followed by the profile's
    /// frame time-out of quiet is dropped, as the firmware's UART does.
    pub(super) fn receive(&mut self, t: f64, byte_time: f64, bytes: &[u8], sink: &mut Sink) {
        let timeout = f64::from(self.machine.profile.sim.frame_timeout_ms) / 1000.0;
        if self.decoder.pending() > 0 && t - self.last_byte - byte_time > timeout {
            self.decoder.clear();
        }
        self.last_byte = t;
        // What the line input needs of the module's settings, read again after each line (a
        // line may change them: SGP 66, SGP 67).
        let mut settings = None;
        for &byte in bytes {
            if self.ascii {
                let line = *settings.get_or_insert_with(|| self.line_settings());
                if self.ascii_byte(t, byte, line, sink) {
                    settings = None;
                }
            } else {
                self.decoder.push(&[byte]);
                match self.decoder.next_frame() {
                    None => {}
                    Some(Ok(frame)) => self.frame(t, &frame, sink),
                    Some(Err(error)) => self.bad_frame(&error, sink),
                }
            }
        }
    }

    fn bad_frame(&mut self, error: &ChecksumError, sink: &mut Sink) {
        if error.bytes[0] != self.machine.address() {
            return;
        }
        sink.log(|| {
            format!(
                "module {} <- {}  bad checksum",
                self.machine.slot,
                hex(&error.bytes)
            )
        });
        // Trinamic's firmware answers status 1 with command 0 and value 0.
        self.send_frame(Status::WrongChecksum, Opcode::Other(0), 0, sink);
    }

    fn frame(&mut self, t: f64, bytes: &[u8; 9], sink: &mut Sink) {
        let Ok(frame) = CommandFrame::decode(bytes) else {
            return;
        };
        if frame.address != self.machine.address() {
            return;
        }
        let instruction = frame.instruction;
        sink.log(|| {
            format!(
                "module {} <- {}  {}",
                self.machine.slot,
                hex(bytes),
                format_instruction(&instruction, &self.machine.profile)
            )
        });
        if self.boot_loader {
            return self.boot_loader_frame(&instruction, sink);
        }
        if instruction.command == Opcode::EnterAscii && !sink.quirks.ascii {
            let value = instruction.value;
            return self.send_frame(Status::InvalidCommand, instruction.command, value, sink);
        }
        let outcome = self.machine.execute(t, &instruction, Source::Direct);
        match outcome.reply {
            Reply::Normal(status, value) => {
                let quiet = outcome.effect == Effect::EnterAscii && !sink.quirks.reply_to_139;
                if !quiet {
                    self.send_frame(status, instruction.command, value, sink);
                }
            }
            Reply::Version => {
                let reply = encode_version_string(
                    self.machine.host(),
                    &self.machine.profile.sim.version_string,
                );
                sink.log(|| format!("module {} -> {}", self.machine.slot, hex(&reply)));
                sink.out.extend_from_slice(&reply);
            }
            Reply::Silent => {}
        }
        self.apply(outcome.effect);
    }

    /// What the boot loader answers: its version string (`6110B131`), the binary version, and
    /// invalid command to everything else.
    fn boot_loader_frame(&mut self, i: &Instruction, sink: &mut Sink) {
        match (i.command, i.type_) {
            (Opcode::FirmwareVersion, 0) => {
                let text = boot_loader_version(&self.machine.profile.sim.version_string);
                let reply = encode_version_string(self.machine.host(), &text);
                sink.log(|| format!("module {} -> {}", self.machine.slot, hex(&reply)));
                sink.out.extend_from_slice(&reply);
            }
            (Opcode::FirmwareVersion, 1) => {
                let value = self.machine.profile.sim.version_binary as i32;
                self.send_frame(Status::Ok, i.command, value, sink);
            }
            _ => self.send_frame(Status::InvalidCommand, i.command, i.value, sink),
        }
    }

    fn apply(&mut self, effect: Effect) {
        match effect {
            Effect::None => {}
            Effect::EnterAscii => {
                self.ascii = true;
                self.line.clear();
            }
            Effect::Rebooted => self.power_up(),
        }
    }

    fn send_frame(&mut self, status: Status, command: Opcode, value: i32, sink: &mut Sink) {
        let reply = ReplyFrame {
            host: self.machine.host(),
            module: self.machine.address(),
            status,
            command,
            value,
        }
        .encode();
        sink.log(|| {
            format!(
                "module {} -> {}  status {} value {value}",
                self.machine.slot,
                hex(&reply),
                status.code()
            )
        });
        sink.out.extend_from_slice(&reply);
    }

    /// The module's address character, echo mode and longest line, as its settings are now.
    fn line_settings(&self) -> LineSettings {
        LineSettings {
            address: address_char(self.machine.address()).map(|c| c as u8),
            echo: Echo::from_config(self.machine.ascii_config()),
            max: self.machine.profile.sim.ascii_line_max,
        }
    }

    /// One byte in ASCII mode; true when it completed a line for this module (executed).
    fn ascii_byte(&mut self, t: f64, byte: u8, settings: LineSettings, sink: &mut Sink) -> bool {
        let cx = Context {
            address: settings.address,
            echo: settings.echo,
            quirks: sink.quirks,
            max: settings.max,
        };
        if !self.line.feed(byte, &cx, sink.out) {
            return false;
        }
        let mut text = std::mem::take(&mut self.text);
        text.clear();
        text.push_str(self.line.line().unwrap_or("\u{FFFD}"));
        sink.log(|| format!("module {} <- {text:?}", self.machine.slot));
        let (outcome, binary_after) = self.ascii_line(t, &text);
        self.text = text;
        let reply_wanted = !binary_after || sink.quirks.reply_to_bin;
        if let (Reply::Normal(status, value), true) = (outcome.reply, reply_wanted) {
            self.send_line(status, value, sink);
        }
        if binary_after {
            self.ascii = false;
            self.decoder.clear();
        }
        self.apply(outcome.effect);
        true
    }

    /// What a line after its address character asks for, or the status it is refused with. The
    /// answer depends only on the text and the module's profile, so the last line's is kept: a
    /// host repeating a request (a polling loop) is not parsed again.
    fn read_line(&mut self, text: &str) -> Result<Op, Status> {
        if let Some((last, read)) = &self.last_line {
            if last == text {
                return *read;
            }
        }
        let profile = &self.machine.profile;
        let read = parse_line(text, |w| profile.commands.is_word(w))
            .map_err(InputError::from)
            .and_then(|raw| match raw.address {
                // The address character was the line's first; another one is not a command.
                Some(_) => Err(InputError::UnknownCommand {
                    word: text.to_string(),
                    suggestion: None,
                }),
                None => resolve(&raw, profile),
            })
            .map(|line| line.op)
            .map_err(|error| ascii_status(&error));
        let mut last = self
            .last_line
            .take()
            .map(|(last, _)| last)
            .unwrap_or_default();
        last.clear();
        last.push_str(text);
        self.last_line = Some((last, read));
        read
    }

    /// Executes one ASCII line; the flag says the module goes back to binary mode (BIN).
    fn ascii_line(&mut self, t: f64, text: &str) -> (Outcome, bool) {
        let op = match self.read_line(text) {
            Ok(op) => op,
            Err(status) => return (Outcome::status(status, 0), false),
        };
        let profile = &self.machine.profile;
        match op {
            Op::Ascii(AsciiWord::Bin) => (Outcome::ok(0), true),
            Op::Ascii(AsciiWord::Run) => {
                let run = Instruction::new(Opcode::RunApplication, 1, 0, 0);
                (self.machine.control(t, &run), false)
            }
            Op::Ascii(AsciiWord::Stop) => {
                let stop = Instruction::new(Opcode::StopApplication, 0, 0, 0);
                (self.machine.control(t, &stop), false)
            }
            Op::Command(instruction) => {
                let allowed = profile
                    .commands
                    .by_number(instruction.command)
                    .is_some_and(|spec| spec.ascii_allowed);
                if !allowed {
                    return (Outcome::error(Status::InvalidCommand, &instruction), false);
                }
                (self.machine.execute(t, &instruction, Source::Direct), false)
            }
        }
    }

    fn send_line(&mut self, status: Status, value: i32, sink: &mut Sink) {
        // The host and module characters follow the manual's rule for address characters,
        // 0x40 + address, whatever the host address (GP 76, 0..255) is.
        let reply = AsciiReply {
            host: host_char(self.machine.host()),
            module: host_char(self.machine.address()),
            status,
            value,
        };
        sink.log(|| format!("module {} -> {:?}", self.machine.slot, reply.format()));
        // Written once for a polling host that gets the same reply again and again.
        match &mut self.last_reply {
            Some((last, written)) if *last == reply => sink.out.extend_from_slice(written),
            kept => {
                let (last, written) = kept.get_or_insert_with(|| (reply, Vec::new()));
                *last = reply;
                written.clear();
                reply.write_to(written);
                sink.out.extend_from_slice(written);
            }
        }
        sink.out.extend_from_slice(sink.quirks.reply_end.bytes());
    }

    /// Sends the second replies of 138 that have come due.
    pub(super) fn send_events(&mut self, sink: &mut Sink) {
        let events = std::mem::take(&mut self.machine.due_events);
        for (_, mask) in events {
            if self.ascii {
                self.send_line(Status::PositionReachedEvent, mask, sink);
            } else {
                self.send_frame(
                    Status::PositionReachedEvent,
                    Opcode::PositionEvent,
                    mask,
                    sink,
                );
            }
        }
    }
}

/// The boot loader's version string: the firmware's with `B` in place of its `V` (`142B1.06`,
/// `6110B131`), as PyTrinamic's firmware updater recognises it.
fn boot_loader_version(firmware: &str) -> String {
    match firmware.find('V') {
        Some(at) => format!("{}B{}", &firmware[..at], &firmware[at + 1..]),
        None => firmware.to_string(),
    }
}

/// The status a module answers to an ASCII line it cannot use: the one the same command would
/// get as a binary frame.
fn ascii_status(error: &InputError) -> Status {
    match error {
        InputError::Syntax(_)
        | InputError::UnknownCommand { .. }
        | InputError::UnknownCommandNumber { .. }
        | InputError::NotInMode { .. }
        | InputError::AbsentCommand { .. } => Status::InvalidCommand,
        // As in binary: an unknown parameter or port is the type byte's fault.
        InputError::Param(_) | InputError::BadPort { .. } | InputError::NoSuchPort { .. } => {
            Status::WrongType
        }
        _ => Status::InvalidValue,
    }
}
