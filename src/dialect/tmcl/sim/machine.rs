//! One simulated module behind its serial interface: parameters, motor, I/O, coordinates, program
//! memory and the program runner, driven by time. [`super::module`] feeds it decoded commands;
//! [`super::exec`] and [`super::control`] implement the commands.

use std::sync::Arc;

use crate::dialect::tmcl::profile::Profile;

use super::io::Io;
use super::motion::{Axis, Happened, Limits, Switch, Switches, encoder_position};
use super::params::{Params, Slot};
use super::program::Program;
use super::state::ModuleImage;
use super::vm::Vm;

/// Magic value of GP 64: any other value at power-up restores factory settings.
pub(crate) const EEPROM_MAGIC: i32 = 228;

/// A pending "target position reached" event request (command 138).
#[derive(Debug, Clone, Copy)]
struct EventRequest {
    mask: i32,
    every_move: bool,
}

/// A module's state.
pub(crate) struct Machine {
    pub profile: Arc<Profile>,
    /// The module's factory address (its place on the bus).
    pub slot: u8,
    pub params: Params,
    pub axis: Axis,
    pub io: Io,
    pub coords: Vec<i32>,
    pub program: Program,
    pub vm: Vm,
    /// Seconds since the bus started, up to which events are handled.
    pub t: f64,
    booted_at: f64,
    tick_offset: i64,
    rng: u64,
    event: Option<EventRequest>,
    /// Second replies of 138 that came due: (time, motor mask).
    pub due_events: Vec<(f64, i32)>,
    /// The EEPROM changed and should be saved.
    pub eeprom_changed: bool,
}

impl Machine {
    /// A factory-fresh module at `slot`, powered up at time 0.
    pub fn new(profile: Arc<Profile>, slot: u8, switches: Switches) -> Machine {
        let mut machine = Machine {
            params: Params::new(profile.clone(), slot),
            axis: Axis::new(switches),
            io: Io::new(&profile.sim),
            coords: vec![0; profile.coordinates.into()],
            program: Program::new(profile.program_memory),
            vm: Vm::new(),
            profile,
            slot,
            t: 0.0,
            booted_at: 0.0,
            tick_offset: 0,
            rng: 0x2545_F491_4F6C_DD1D ^ u64::from(slot),
            event: None,
            due_events: Vec::new(),
            eeprom_changed: false,
        };
        machine.boot(0.0);
        machine
    }

    /// Power-up at `t`: RAM from EEPROM (factory settings first if GP 64 lost its magic), motor
    /// standing at 0, outputs off, program stopped at 0 (or started, with GP 77).
    pub fn boot(&mut self, t: f64) {
        if self.params.stored(Slot::Global(0, 64)) != EEPROM_MAGIC {
            self.params.factory();
            self.eeprom_changed = true;
        }
        self.params.power_up();
        self.axis.power_up(t);
        self.io.reset_outputs();
        self.coords.fill(0);
        self.vm = Vm::new();
        self.program.quit_download();
        self.t = t;
        self.booted_at = t;
        self.tick_offset = 0;
        self.event = None;
        self.due_events.clear();
        if self.params.get(Slot::Global(0, 77)) == 1 && !self.program.is_empty() {
            self.vm.start(t, 0);
        }
    }

    /// Loads the EEPROM from a state-file image and powers up.
    pub fn load(&mut self, image: &ModuleImage) {
        for &(number, value) in &image.axis {
            self.params.set_stored(Slot::Axis(number), value);
        }
        for &(bank, number, value) in &image.global {
            if (bank as usize) < super::params::BANKS {
                self.params.set_stored(Slot::Global(bank, number), value);
            }
        }
        self.program.load(&image.program);
        self.eeprom_changed = false;
        self.boot(self.t);
        if self.params.get(Slot::Global(0, 84)) == 1 {
            for (slot, &value) in self.coords.iter_mut().zip(&image.coordinates) {
                *slot = value;
            }
        }
    }

    /// The EEPROM as a state-file image.
    pub fn image(&self) -> ModuleImage {
        let mut axis = Vec::new();
        let mut global = Vec::new();
        for (slot, value) in self.params.stored_values() {
            match slot {
                Slot::Axis(n) => axis.push((n, value)),
                Slot::Global(bank, n) => global.push((bank, n, value)),
            }
        }
        let coordinates = if self.params.get(Slot::Global(0, 84)) == 1 {
            self.coords.clone()
        } else {
            Vec::new()
        };
        ModuleImage {
            slot: self.slot,
            axis,
            global,
            coordinates,
            program: self.program.image(),
        }
    }

    /// The serial address the module answers to (GP 66).
    pub fn address(&self) -> u8 {
        self.params.get(Slot::Global(0, 66)) as u8
    }

    /// The host address put into replies (GP 76).
    pub fn host(&self) -> u8 {
        self.params.get(Slot::Global(0, 76)) as u8
    }

    /// GP 67: ASCII start-up (bit 0) and echo mode (bits 4, 5).
    pub fn ascii_config(&self) -> i32 {
        self.params.get(Slot::Global(0, 67))
    }

    fn limits(&self) -> Limits {
        Limits {
            right: self.params.get(Slot::Axis(12)) == 0,
            left: self.params.get(Slot::Axis(13)) == 0,
        }
    }

    /// Runs motor events and the program up to `t`, in time order.
    pub fn advance(&mut self, t: f64) {
        loop {
            let limits = self.limits();
            let axis_next = self.axis.next_event(limits);
            let vm_next = self.program_due();
            let next = match (axis_next, vm_next) {
                (Some(a), Some(v)) => a.min(v),
                (a, v) => match a.or(v) {
                    Some(n) => n,
                    None => break,
                },
            };
            if next > t + 1e-9 {
                break;
            }
            let at = next.max(self.t);
            if axis_next.is_some_and(|a| a <= next) {
                if let Some(happened) = self.axis.handle_event(at, limits) {
                    self.on_axis(at, happened);
                }
            } else {
                self.t = at;
                self.run_program(at);
            }
            self.t = self.t.max(at);
        }
        self.t = self.t.max(t);
        // Everything up to now is handled: a switch or limit setting changed from now on must
        // not act in the past.
        self.axis.settle(self.t);
    }

    fn on_axis(&mut self, at: f64, happened: Happened) {
        match happened {
            Happened::Arrived => {
                if let Some(request) = self.event {
                    self.due_events.push((at, request.mask));
                    if !request.every_move {
                        self.event = None;
                    }
                }
            }
            Happened::SearchDone => self.params.set(Slot::Axis(0), 0),
            Happened::LimitStop | Happened::SearchLeg => {}
        }
    }

    /// Requests the second reply of 138 for the next move's arrival (or every move's).
    pub fn request_event(&mut self, mask: i32, every_move: bool) {
        self.event = Some(EventRequest { mask, every_move });
    }

    /// When output (a 138 second reply) may next be due, as seconds.
    pub fn next_output(&self) -> Option<f64> {
        self.event?;
        let arrival = self.axis.arrival();
        match (arrival, self.program_due()) {
            (Some(a), Some(v)) => Some(a.min(v)),
            (a, v) => a.or(v),
        }
    }

    // ---- units -----------------------------------------------------------------------------

    fn pps_mode(&self) -> bool {
        self.params.get(Slot::Axis(255)) == 1
    }

    /// A velocity in the user's unit (AP 255) as microsteps per second.
    pub fn pps(&self, value: i32) -> f64 {
        let factor = if self.pps_mode() {
            1.0
        } else {
            self.profile.sim.velocity_pps_per_unit
        };
        f64::from(value) * factor
    }

    /// An acceleration in the user's unit as microsteps per second².
    pub fn pps2(&self, value: i32) -> f64 {
        let factor = if self.pps_mode() {
            1.0
        } else {
            self.profile.sim.acceleration_pps2_per_unit
        };
        f64::from(value) * factor
    }

    fn velocity_units(&self, pps: f64) -> i32 {
        let factor = if self.pps_mode() {
            1.0
        } else {
            self.profile.sim.velocity_pps_per_unit
        };
        let units = (pps / factor).round();
        units.clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32
    }

    /// Maximum positioning speed (AP 4) and acceleration (AP 5) in pps, pps².
    pub fn move_limits(&self) -> (f64, f64) {
        (
            self.pps(self.params.get(Slot::Axis(4))),
            self.pps2(self.params.get(Slot::Axis(5))),
        )
    }

    // ---- live values -----------------------------------------------------------------------

    /// The value GAP reads at `t` (parameters with live values computed, others from RAM).
    pub fn axis_value(&self, number: u8, t: f64) -> i32 {
        let state = self.axis.state(t);
        let counter = self.axis.counter(t);
        let ram = |n| self.params.get(Slot::Axis(n));
        match number {
            1 => counter,
            3 | 39 => self.velocity_units(state.v),
            8 => i32::from(self.target_reached(t)),
            9 => i32::from(self.axis.switch_active(t, Switch::Home)),
            10 => i32::from(self.axis.switch_active(t, Switch::Right)),
            11 => i32::from(self.axis.switch_active(t, Switch::Left)),
            38 => (self.encoder(t) as i64 - counter as i64).clamp(-(1 << 23), 1 << 23) as i32,
            41 => self.encoder(t),
            129 => {
                i32::from(self.target_reached(t))
                    | i32::from(state.a == 0.0) << 1
                    | i32::from(state.v == 0.0) << 2
            }
            130 => i32::from(state.a == 0.0),
            196 => self.axis.end_distance(),
            n => ram(n),
        }
    }

    fn target_reached(&self, t: f64) -> bool {
        self.axis.state(t).v == 0.0 && self.axis.counter(t) == self.params.get(Slot::Axis(0))
    }

    fn encoder(&self, t: f64) -> i32 {
        encoder_position(
            self.axis.counter(t),
            self.params.get(Slot::Axis(42)),
            self.params.get(Slot::Axis(43)),
            self.profile.sim.encoder_usteps_per_count,
        )
    }

    /// The value GGP reads at `t`.
    pub fn global_value(&mut self, bank: u8, number: u8, t: f64) -> i32 {
        match (bank, number) {
            (0, 128) => self.vm.status_code(),
            (0, 129) => i32::from(self.program.downloading()),
            (0, 130) => self.vm.pc(),
            (0, 132) => self.ticks(t),
            (0, 133) => self.random(),
            _ => self.params.get(Slot::Global(bank, number)),
        }
    }

    /// The 1 ms tick timer (GP 132).
    pub fn ticks(&self, t: f64) -> i32 {
        let ms = ((t - self.booted_at) * 1000.0).floor() as i64;
        ms.wrapping_add(self.tick_offset) as i32
    }

    /// Sets the tick timer (SGP 132).
    pub fn set_ticks(&mut self, t: f64, value: i32) {
        let ms = ((t - self.booted_at) * 1000.0).floor() as i64;
        self.tick_offset = i64::from(value) - ms;
    }

    fn random(&mut self) -> i32 {
        // xorshift64: deterministic, so runs are reproducible.
        self.rng ^= self.rng << 13;
        self.rng ^= self.rng >> 7;
        self.rng ^= self.rng << 17;
        (self.rng >> 33) as i32
    }
}
