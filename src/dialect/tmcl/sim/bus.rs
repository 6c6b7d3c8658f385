//! Several simulated modules on one RS-485 line, each of its own profile (a TMCM-142 beside a
//! TMCM-6110): every byte reaches every module, each answers only its own address, in binary and
//! in ASCII mode. On a shared line (`tmclsh sim --shared-line`) the modules also hear each other's
//! replies, so a module whose address is the host address misbehaves as on a real bus. The bus is
//! the [`Device`] that adapters serve.

use std::sync::Arc;
use std::time::Duration;

use crate::dialect::tmcl::profile::Profile;
use crate::sim::error::ConsoleError;
use crate::sim::{Device, LogSink};

use super::control_cmd::{self, Controlled};
use super::machine::Machine;
use super::module::{Module, Sink};
use super::motion::{MotorState, Switch, Switches};
use super::options::Quirks;
use super::state::{BusImage, Eeprom};

/// How to build a bus.
pub struct BusOptions {
    /// Factory addresses of the modules, in bus order. Default: one module at address 1.
    pub addresses: Vec<u8>,
    /// The modules that are not of the bus's profile, by factory address.
    pub profiles: Vec<(u8, Arc<Profile>)>,
    /// Behaviour the manual leaves open.
    pub quirks: Quirks,
    /// Where every motor's virtual switches are (the same for every motor of every module)…
    pub switches: Switches,
    /// …but for these: a motor number, one of its switches and where that one is.
    pub motor_switches: Vec<(u8, Switch, i64)>,
    /// The EEPROM kept between runs; `None` starts from factory settings every time.
    pub eeprom: Option<Eeprom>,
    /// The modules, by factory address, that run their boot loader instead of their firmware.
    pub boot_loader: Vec<u8>,
    /// Where to log decoded traffic; `None` logs nothing (and costs nothing).
    pub log: Option<LogSink>,
    /// The modules hear each other's replies and echoes, as on a real RS-485 line: a module whose
    /// address equals the host address then takes the others' replies for commands.
    pub shared_line: bool,
}

impl Default for BusOptions {
    fn default() -> Self {
        BusOptions {
            addresses: vec![1],
            profiles: Vec::new(),
            quirks: Quirks::default(),
            switches: Switches::default(),
            motor_switches: Vec::new(),
            eeprom: None,
            boot_loader: Vec::new(),
            log: None,
            shared_line: false,
        }
    }
}

/// Simulated modules sharing one serial line.
pub struct Bus {
    modules: Vec<Module>,
    out: Vec<u8>,
    quirks: Quirks,
    eeprom: Option<Eeprom>,
    log: Option<LogSink>,
    shared_line: bool,
    /// Seconds a byte takes on a paced line (0 when the line is not paced).
    byte_time: f64,
}

/// How many times on a shared line the modules may answer what other modules sent, after one
/// write of the host: two modules that take each other's replies for commands would otherwise
/// talk for ever.
const ANSWERS_TO_ANSWERS: usize = 16;

/// Batches of bytes still to reach the modules on a shared line, each with its sender, and how
/// many answers to answers there were.
#[derive(Default)]
struct Relay {
    queue: std::collections::VecDeque<(Option<usize>, Vec<u8>)>,
    answers: usize,
}

fn secs(now: Duration) -> f64 {
    now.as_secs_f64()
}

impl BusOptions {
    /// The switches of each motor of a module with `axes` motors.
    fn switches_of(&self, axes: u8) -> Vec<Switches> {
        (0..axes.max(1))
            .map(|motor| {
                let mut switches = self.switches;
                for &(m, which, position) in &self.motor_switches {
                    if m == motor {
                        switches.set(which, Some(position));
                    }
                }
                switches
            })
            .collect()
    }
}

impl Bus {
    /// Modules as `options` say (of `profile` unless `options.profiles` names another), with
    /// their EEPROM from the store, powered up at time 0.
    pub fn new(profile: Arc<Profile>, options: BusOptions) -> Bus {
        let image = options.eeprom.as_ref().and_then(Eeprom::loaded);
        let modules = options
            .addresses
            .iter()
            .map(|&slot| {
                let profile = options
                    .profiles
                    .iter()
                    .find(|(a, _)| *a == slot)
                    .map_or_else(|| profile.clone(), |(_, p)| p.clone());
                let switches = options.switches_of(profile.axes);
                let mut machine = Machine::new(profile, slot, &switches);
                if let Some(stored) = image.and_then(|i| i.module(slot)) {
                    machine.load(stored);
                }
                let mut module = Module::new(machine);
                module.boot_loader = options.boot_loader.contains(&slot);
                module
            })
            .collect();
        let mut bus = Bus {
            modules,
            out: Vec::new(),
            quirks: options.quirks,
            eeprom: options.eeprom,
            log: options.log,
            shared_line: options.shared_line,
            byte_time: 0.0,
        };
        bus.save_if_changed(true);
        bus
    }

    /// One factory-fresh module at address 1 with the built-in TMCM-142 profile.
    pub fn builtin() -> Bus {
        Bus::new(Profile::builtin(), BusOptions::default())
    }

    fn module(&mut self, slot: u8) -> Result<&mut Module, ConsoleError> {
        let on_bus = self.slots();
        self.modules
            .iter_mut()
            .find(|m| m.machine.slot == slot)
            .ok_or(ConsoleError::NoModule { slot, on_bus })
    }

    /// Handles events due by `now` and sends what they produce.
    fn advance(&mut self, now: Duration) {
        let t = secs(now);
        let mut sent = Vec::new();
        for (i, module) in self.modules.iter_mut().enumerate() {
            module.machine.advance(t);
            if !module.machine.due_events.is_empty() {
                let mut out = Vec::new();
                let mut sink = Sink {
                    out: &mut out,
                    quirks: &self.quirks,
                    log: self.log.as_deref_mut(),
                    t,
                };
                module.send_events(&mut sink);
                self.out.extend_from_slice(&out);
                sent.push((Some(i), out));
            }
        }
        if self.shared_line {
            let queue = sent.into();
            self.deliver(t, Relay { queue, answers: 0 });
        }
    }

    /// Bytes on the line at `t` from the module `from` (`None`: the host) reach every other
    /// module, each answer straight into the bus's output; on a shared line what they send back
    /// is queued to reach the others in turn (at most [`ANSWERS_TO_ANSWERS`] times in all).
    fn hear(&mut self, t: f64, from: Option<usize>, bytes: &[u8], relay: &mut Relay) {
        for (i, module) in self.modules.iter_mut().enumerate() {
            if from == Some(i) {
                continue;
            }
            let start = self.out.len();
            let mut sink = Sink {
                out: &mut self.out,
                quirks: &self.quirks,
                log: self.log.as_deref_mut(),
                t,
            };
            module.receive(t, self.byte_time, bytes, &mut sink);
            let heard = self.shared_line && relay.answers < ANSWERS_TO_ANSWERS;
            if heard && self.out.len() > start {
                relay.answers += 1;
                relay.queue.push_back((Some(i), self.out[start..].to_vec()));
            }
        }
    }

    /// Delivers what `relay` holds, and the answers to it, in order.
    fn deliver(&mut self, t: f64, mut relay: Relay) {
        while let Some((from, bytes)) = relay.queue.pop_front() {
            self.hear(t, from, &bytes, &mut relay);
        }
    }

    /// Saves the EEPROM image when a module's EEPROM changed (or when `force`d at start).
    fn save_if_changed(&mut self, force: bool) {
        let changed = self.modules.iter().any(|m| m.machine.eeprom_changed);
        let Some(eeprom) = self.eeprom.as_mut() else {
            return;
        };
        if !changed && !force {
            return;
        }
        if !changed && eeprom.loaded().is_some() {
            return;
        }
        let image = BusImage {
            modules: self.modules.iter().map(|m| m.machine.image()).collect(),
        };
        eeprom.save(&image);
        for module in &mut self.modules {
            module.machine.eeprom_changed = false;
        }
    }
}

impl Device for Bus {
    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        self.advance(now);
        // The host's bytes are heard where they lie: only answers on a shared line are copied.
        let mut relay = Relay::default();
        self.hear(secs(now), None, bytes, &mut relay);
        self.deliver(secs(now), relay);
        self.save_if_changed(false);
    }

    fn byte_time(&mut self, time: Duration) {
        self.byte_time = time.as_secs_f64();
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        self.advance(now);
        out.append(&mut self.out);
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        if !self.out.is_empty() {
            return Some(now);
        }
        self.modules
            .iter()
            .filter_map(|m| m.machine.next_output())
            .min_by(f64::total_cmp)
            .map(|t| Duration::from_nanos((t.max(0.0) * 1e9).ceil() as u64))
    }

    fn control(&mut self, now: Duration, command: &str) -> Option<Result<String, ConsoleError>> {
        control_cmd::run(self, now, command)
    }
}

impl Controlled for Bus {
    /// Factory addresses of the modules, in bus order.
    fn slots(&self) -> Vec<u8> {
        self.modules.iter().map(|m| m.machine.slot).collect()
    }
    /// Power-cycles the module at factory address `slot`, or every module: RAM back to the
    /// stored values, motors standing, program stopped, the interface in the mode GP 67 bit 0
    /// says (binary unless set otherwise).
    fn reset(&mut self, now: Duration, slot: Option<u8>) -> Result<String, ConsoleError> {
        self.advance(now);
        if let Some(slot) = slot {
            self.module(slot)?;
        }
        let t = secs(now);
        let mut told = Vec::new();
        for module in &mut self.modules {
            if slot.is_some_and(|s| s != module.machine.slot) {
                continue;
            }
            module.machine.boot(t);
            module.power_up();
            let mode = if module.is_ascii() { "ASCII" } else { "binary" };
            told.push(format!(
                "module {} restarted in {mode} mode",
                module.machine.slot
            ));
        }
        self.save_if_changed(false);
        Ok(told.join("; "))
    }
    /// Sets a digital input of a module.
    fn set_input(
        &mut self,
        now: Duration,
        slot: u8,
        port: u8,
        high: bool,
    ) -> Result<(), ConsoleError> {
        self.advance(now);
        self.module(slot)?.machine.set_input(port, high)
    }
    /// Sets an analog input of a module (0..adc_max).
    fn set_analog(
        &mut self,
        now: Duration,
        slot: u8,
        port: u8,
        value: i32,
    ) -> Result<(), ConsoleError> {
        self.advance(now);
        self.module(slot)?.machine.io.set_analog(port, value)
    }
    /// Moves (or with `None` disconnects) a virtual switch of a motor of a module, in physical
    /// microsteps.
    fn set_switch(
        &mut self,
        now: Duration,
        slot: u8,
        motor: u8,
        which: Switch,
        position: Option<i64>,
    ) -> Result<(), ConsoleError> {
        self.advance(now);
        let machine = &mut self.module(slot)?.machine;
        let (module, motors) = (machine.profile.module.clone(), machine.axes.len());
        let axis = machine
            .axes
            .get_mut(usize::from(motor))
            .ok_or(ConsoleError::NoMotor {
                module,
                motor,
                motors,
            })?;
        axis.switches.set(which, position);
        axis.settle(secs(now));
        Ok(())
    }
    /// The state of an output of a module at `now` (a running program may have set it).
    fn output(&mut self, now: Duration, slot: u8, port: u8) -> Option<bool> {
        self.advance(now);
        self.module(slot).ok()?.machine.io.output(port)
    }

    /// What a motor of a module is doing at `now` (`None`: no such module or motor).
    fn motor_of(&mut self, now: Duration, slot: u8, motor: u8) -> Option<MotorState> {
        self.advance(now);
        let t = secs(now);
        let machine = &self.module(slot).ok()?.machine;
        let axis = machine.axes.get(usize::from(motor))?;
        Some(MotorState {
            position: axis.counter(t),
            target: machine.role(motor, machine.roles.target_position),
            velocity: axis.state(t).v,
            target_reached: machine.target_reached(motor, t),
            searching: axis.search_status() != 0,
        })
    }
}

/// What only the tests look at.
#[cfg(test)]
impl Bus {
    /// What motor 0 of a module is doing at `now`.
    pub fn motor(&mut self, now: Duration, slot: u8) -> Option<MotorState> {
        self.motor_of(now, slot, 0)
    }

    /// The EEPROM image of each module, in bus order.
    pub fn images(&self) -> Vec<super::state::ModuleImage> {
        self.modules.iter().map(|m| m.machine.image()).collect()
    }

    /// The module name of each module, in bus order (`TMCM-6110`).
    pub fn modules(&self) -> Vec<(u8, String)> {
        self.modules
            .iter()
            .map(|m| (m.machine.slot, m.machine.profile.module.clone()))
            .collect()
    }

    /// Whether a module is in ASCII mode.
    pub fn is_ascii(&mut self, slot: u8) -> Option<bool> {
        Some(self.module(slot).ok()?.is_ascii())
    }
}
