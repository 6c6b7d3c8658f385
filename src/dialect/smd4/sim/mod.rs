//! A simulated AML SMD4 drive: a pure state machine behind [`crate::sim::Device`] — bytes in,
//! bytes out, time as an input; no threads, clocks or I/O inside, except that STORE writes the
//! state file it was given (through a [`Store`]).
//!
//! It answers every command of `data/smd4.toml` as the document describes: rounding of currents,
//! the run/acceleration current and start/stop frequency couplings, standby gating, latching error
//! flags, limits, an analytic trapezoid motion model, bake, the three configuration sets and the
//! addressing state machine. Each point where the document contradicts itself is an option
//! ([`Smd4SimOptions`]), so clients can be tested against every reading.
//!
//! Addressing (document §"Addressing"): until the first well-formed packet with an `@N` prefix
//! arrives, un-prefixed packets are executed and answered (malformed ones with −104). From then
//! on, until restart, only `@own` packets are answered; `@0` is executed silently; everything
//! else — other addresses, packets without prefix, malformed packets — is ignored silently.

pub mod config;
mod control;
mod exec;
#[cfg(feature = "cli")]
pub mod flags;
pub mod motion;
pub mod options;
mod reply;
#[cfg(test)]
mod tests;

use std::time::Duration;

use crate::dialect::smd4::protocol::{Eflags, Request, Sflags, Smd4Spec};

use crate::sim::error::ConsoleError;
use crate::sim::store::{FileStore, MemoryStore, Store};
use crate::sim::{Device, LogSink};
pub use config::{Setting, Settings};
pub(crate) use control::CONSOLE;
pub use motion::MotorState;
use motion::{Goal, Motion, Ramp};
pub use options::{PositionFormat, PrefixAcceptance, Smd4SimOptions};

/// Longest line accepted; longer ones are malformed packets (the document gives no limit).
pub const MAX_LINE: usize = 1024;

/// A limit input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limit {
    /// Limit 1, reached while the step counter increases.
    Positive,
    /// Limit 2, reached while the step counter decreases.
    Negative,
}

impl Limit {
    fn of_direction(direction: f64) -> Option<Limit> {
        if direction > 0.0 {
            Some(Limit::Positive)
        } else if direction < 0.0 {
            Some(Limit::Negative)
        } else {
            None
        }
    }

    fn suffix(self) -> char {
        match self {
            Limit::Positive => '+',
            Limit::Negative => '-',
        }
    }
}

/// Electrical state of the drive's inputs, set by tests and adapters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Inputs {
    limit_positive_high: bool,
    limit_negative_high: bool,
    external_enable: bool,
    joystick: bool,
}

/// A simulated SMD4.
pub struct Smd4Sim {
    spec: &'static Smd4Spec,
    options: Smd4SimOptions,
    store: Box<dyn Store>,
    factory: Settings,
    stored: Settings,
    working: Settings,
    config_damaged: bool,
    boot: f64,
    input: Vec<u8>,
    output: Vec<u8>,
    addressed: bool,
    silent: bool,
    eflags: Eflags,
    motion: Motion,
    prel_offset: f64,
    homing: Option<f64>,
    inputs: Inputs,
    bake_started: Option<f64>,
    bake_elapsed: f64,
    flash_fails: bool,
    log: Option<LogSink>,
}

impl Smd4Sim {
    /// A drive powered up at time zero, its stored configuration in `options.state_file` (or in
    /// memory). A missing file means factory settings; a damaged one latches the configuration
    /// error flag (EFLAGS bit 6) and uses what it can.
    pub fn new(options: Smd4SimOptions) -> Smd4Sim {
        let store: Box<dyn Store> = match &options.state_file {
            Some(path) => Box::new(FileStore::new(path)),
            None => Box::new(MemoryStore::default()),
        };
        Smd4Sim::with_store(options, store)
    }

    /// A drive whose stored configuration lives in `store`.
    pub fn with_store(options: Smd4SimOptions, store: Box<dyn Store>) -> Smd4Sim {
        let spec = Smd4Spec::builtin();
        let factory = config::factory(&spec.commands);
        let (stored, config_damaged) = match store.load() {
            Ok(None) => (factory.clone(), false),
            Ok(Some(text)) => match config::from_text(&spec.commands, &factory, &text) {
                Ok(settings) => (settings, false),
                Err(usable) => (usable, true),
            },
            Err(_) => (factory.clone(), true),
        };
        let mut sim = Smd4Sim {
            spec,
            options,
            store,
            working: stored.clone(),
            factory,
            stored,
            config_damaged,
            boot: 0.0,
            input: Vec::new(),
            output: Vec::new(),
            addressed: false,
            silent: false,
            eflags: Eflags::default(),
            motion: Motion::at_rest(0.0),
            prel_offset: 0.0,
            homing: None,
            inputs: Inputs {
                limit_positive_high: false,
                limit_negative_high: false,
                external_enable: spec.sim.external_enable_input,
                joystick: false,
            },
            bake_started: None,
            bake_elapsed: 0.0,
            flash_fails: false,
            log: None,
        };
        sim.power_up(0.0);
        sim
    }

    /// Logs traffic to `log` (lines received, replies sent, lines ignored and why).
    pub fn with_log(mut self, log: LogSink) -> Smd4Sim {
        self.log = Some(log);
        self
    }

    fn log(&mut self, t: f64, line: impl FnOnce() -> String) {
        if let Some(log) = self.log.as_mut() {
            log(&format!("{t:12.6} smd4 {}", line()));
        }
    }

    /// Power cycle at `now`: settings from the stored set, counters zero, errors cleared (the
    /// configuration error comes back if the stored set was damaged), addressing mode and
    /// programming mode left.
    pub fn power_cycle(&mut self, now: Duration) {
        self.power_up(now.as_secs_f64());
    }

    fn power_up(&mut self, t: f64) {
        self.working = self.factory.clone();
        self.working.extend(self.stored.clone());
        self.boot = t;
        self.input.clear();
        self.addressed = false;
        self.silent = false;
        self.eflags = Eflags::default();
        if self.config_damaged {
            self.eflags.latch(Eflags::CONFIG_ERROR);
        }
        self.motion = Motion::at_rest(0.0);
        self.prel_offset = 0.0;
        self.homing = None;
        self.bake_started = None;
        self.bake_elapsed = 0.0;
        self.update(t);
    }

    /// Sets the electrical level of a limit input (whether it counts as active depends on its
    /// polarity). An enabled limit that becomes active stops a motion towards it.
    pub fn set_limit_input(&mut self, now: Duration, side: Limit, high: bool) {
        match side {
            Limit::Positive => self.inputs.limit_positive_high = high,
            Limit::Negative => self.inputs.limit_negative_high = high,
        }
        self.update(now.as_secs_f64());
    }

    /// Sets the external enable input. With SYS:EXTEN = 1, an inactive input latches EFLAGS bit 4
    /// and disables the motor.
    pub fn set_external_enable(&mut self, now: Duration, active: bool) {
        self.inputs.external_enable = active;
        self.update(now.as_secs_f64());
    }

    /// Plugs a joystick in or out. With SYS:AUTOJS = 1 a drive in standby switches to joystick
    /// mode when one is plugged in. (Joystick buttons are not simulated.)
    pub fn set_joystick(&mut self, now: Duration, connected: bool) {
        let t = now.as_secs_f64();
        let plugged_in = connected && !self.inputs.joystick;
        self.inputs.joystick = connected;
        if plugged_in && self.number("SYS:AUTOJS") == 1.0 && self.motion.at(t).standby {
            self.working.insert("SYS:MODE".into(), Setting::Int(2));
            self.end_bake(t);
        }
        self.update(t);
    }

    /// Latches an error flag as a fault would (e.g. [`Eflags::TEMP_OPEN`]); the motor stops.
    pub fn inject_fault(&mut self, now: Duration, bit: u8) {
        self.eflags.latch(bit);
        self.update(now.as_secs_f64());
    }

    /// Makes STORE fail with −5 as with worn-out flash.
    pub fn set_flash_failure(&mut self, fails: bool) {
        self.flash_fails = fails;
    }

    /// The motor at `now`.
    pub fn motion_state(&self, now: Duration) -> MotorState {
        self.motion.at(now.as_secs_f64())
    }

    /// The status word at `now`.
    pub fn sflags(&self, now: Duration) -> Sflags {
        self.status(now.as_secs_f64())
    }

    /// The latched error word.
    pub fn eflags(&self) -> Eflags {
        self.eflags
    }

    /// Whether the drive is in addressing mode.
    pub fn addressing_mode(&self) -> bool {
        self.addressed
    }

    /// A working setting by mnemonic (`MOTOR:IA`).
    pub fn setting(&self, mnemonic: &str) -> Option<&Setting> {
        self.working.get(&mnemonic.to_ascii_uppercase())
    }

    fn number(&self, mnemonic: &str) -> f64 {
        self.working.get(mnemonic).map_or(0.0, Setting::number)
    }

    fn profile(&self) -> Ramp {
        Ramp {
            vstart: self.number("MOTOR:VSTART"),
            vstop: self.number("MOTOR:VSTOP"),
            vmax: self.number("MOTOR:VMAX"),
            amax: self.number("MOTOR:AMAX"),
            dmax: self.number("MOTOR:DMAX"),
            tzw: self.number("MOTOR:TZW"),
        }
    }

    fn mode(&self) -> u8 {
        self.number("SYS:MODE") as u8
    }

    /// Whether a limit input is active after its polarity (1 = active low).
    fn limit_active(&self, side: Limit) -> bool {
        let high = match side {
            Limit::Positive => self.inputs.limit_positive_high,
            Limit::Negative => self.inputs.limit_negative_high,
        };
        let active_low = self.number(&format!("LIMIT:POL{}", side.suffix())) == 1.0;
        high != active_low
    }

    fn limit_enabled(&self, side: Limit) -> bool {
        self.number("LIMIT:EN") == 1.0 && self.number(&format!("LIMIT:EN{}", side.suffix())) == 1.0
    }

    fn status(&self, t: f64) -> Sflags {
        let now = self.motion.at(t);
        let mut s = Sflags::default();
        s.set(Sflags::JOYSTICK, self.inputs.joystick);
        s.set(Sflags::LIMIT_NEGATIVE, self.limit_active(Limit::Negative));
        s.set(Sflags::LIMIT_POSITIVE, self.limit_active(Limit::Positive));
        s.set(Sflags::EXTERNAL_ENABLE, self.inputs.external_enable);
        s.set(Sflags::IDENT, self.number("SYS:IDENT") == 1.0);
        s.set(Sflags::STANDBY, now.standby);
        s.set(Sflags::BAKING, self.bake_started.is_some());
        s.set(Sflags::AT_TARGET_VELOCITY, now.at_target_velocity);
        s.set(Sflags::BOOST_OPERATIONAL, self.number("BOOST:EN") == 1.0);
        s
    }

    /// Applies the inputs at `t`: the external enable, disabling on errors, limits, homing.
    fn update(&mut self, t: f64) {
        if self.number("SYS:EXTEN") == 1.0 && !self.inputs.external_enable {
            self.eflags.latch(Eflags::EXTERNAL_DISABLE);
        }
        let now = self.motion.at(t);
        if now.standby {
            return;
        }
        if self.eflags.any() {
            self.motion.halt(t);
            return;
        }
        let Some(side) = Limit::of_direction(self.motion.direction(t)) else {
            return;
        };
        let homed = self
            .homing
            .is_some_and(|d| Limit::of_direction(d) == Some(side));
        let blocked = self.limit_active(side) && (homed || self.limit_enabled(side));
        if !blocked {
            return;
        }
        self.homing = None;
        let soft = self.number("LIMIT:STOPMODE") == 1.0;
        match self.motion.goal(t) {
            Goal::Stop(_) if soft => {}
            _ if soft => self.motion.plan(t, Goal::Stop(None), &self.profile()),
            _ => self.motion.halt(t),
        }
    }

    fn end_bake(&mut self, t: f64) {
        if let Some(start) = self.bake_started.take() {
            self.bake_elapsed = t - start;
        }
    }

    /// Handles one received line at time `t`.
    fn line(&mut self, t: f64, line: &[u8]) {
        let text = String::from_utf8_lossy(line).into_owned();
        self.log(t, || format!("<- {text:?}"));
        if self.silent {
            self.log(t, || "ignored: programming mode (SYS:PROG)".into());
            return;
        }
        self.update(t);
        let parsed = if line.len() > MAX_LINE {
            None
        } else {
            Request::parse_styled(&text).ok()
        };
        let (request, address) = match parsed {
            Some((request, Some(style))) if self.options.prefix.accepts(style) => {
                self.addressed = true;
                let address = request.address;
                (request, address)
            }
            Some((request, None)) if !self.addressed => (request, None),
            _ if self.addressed => {
                self.log(t, || {
                    "ignored: addressing mode answers only well-formed @own packets".into()
                });
                return;
            }
            _ => {
                let reply = self.failure(
                    t,
                    None,
                    crate::dialect::smd4::protocol::ErrorCode::PacketError,
                );
                self.emit(t, reply);
                return;
            }
        };
        let own = self.number("COMS:SERIAL:SLAVEADDR") as u32;
        let answer = match address {
            None => true,
            Some(0) => false,
            Some(a) if a == own => true,
            Some(a) => {
                self.log(t, || format!("ignored: for drive @{a}, this is @{own}"));
                return;
            }
        };
        let outcome = self.execute(t, &request);
        if answer {
            let reply = self.render(t, address, outcome);
            self.emit(t, reply);
        } else {
            self.log(t, || "executed without reply (broadcast)".into());
        }
    }

    /// Queues a reply for the host (and logs it).
    fn emit(&mut self, t: f64, reply: Vec<u8>) {
        if !reply.is_empty() {
            self.log(t, || {
                format!("-> {:?}", String::from_utf8_lossy(&reply).trim_end())
            });
        }
        self.output.extend(reply);
    }
}

impl Device for Smd4Sim {
    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        let t = now.as_secs_f64();
        for &byte in bytes {
            if byte != b'\n' {
                // Past MAX_LINE the line is malformed whatever follows; keep memory bounded.
                if self.input.len() <= MAX_LINE {
                    self.input.push(byte);
                }
                continue;
            }
            let mut line = std::mem::take(&mut self.input);
            if line.last() == Some(&b'\r') {
                line.pop();
            }
            self.line(t, &line);
        }
    }

    fn poll_output(&mut self, _now: Duration, out: &mut Vec<u8>) {
        out.append(&mut self.output);
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        (!self.output.is_empty()).then_some(now)
    }

    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        control::run(self, now, command)
    }
}
