//! One simulated module's state behind its serial interface: parameters, one motor per axis, I/O,
//! coordinates, program memory and the program runner's registers, with power-up and the EEPROM
//! image. It calls nothing of the files that build on it: [`super::module`] feeds it decoded
//! commands, [`super::exec`] and [`super::control`] implement them, [`super::live`] what the motors
//! read and their units, [`super::runner`] runs the program and [`super::events`] drives it all by
//! time.

use std::sync::Arc;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::sim_roles::AxisRoles;

use super::io::Io;
use super::motion::{Axis, Switches};
use super::params::{Params, Slot};
use super::program::Program;
use super::state::ModuleImage;
use super::vm::Vm;

/// Magic value of GP 64: any other value at power-up restores factory settings.
pub(crate) const EEPROM_MAGIC: i32 = 228;

/// A pending "target position reached" event request (command 138): the second reply comes
/// when every motor of the mask has arrived.
#[derive(Debug, Clone, Copy)]
pub(super) struct EventRequest {
    pub mask: i32,
    pub every_move: bool,
}

/// The roles of a profile's axis parameters; a profile file without the table gets the
/// TMCM-142's, whose numbering the simulator always had.
fn roles_of(profile: &Profile) -> AxisRoles {
    if profile.sim.axis_roles.is_empty() {
        Profile::builtin().sim.axis_roles.clone()
    } else {
        profile.sim.axis_roles.clone()
    }
}

/// A module's state.
pub(crate) struct Machine {
    pub profile: Arc<Profile>,
    /// The module's factory address (its place on the bus).
    pub slot: u8,
    pub params: Params,
    /// One motor per axis of the profile, each with its own switches.
    pub axes: Vec<Axis>,
    /// Which axis parameter is which part of the motion.
    pub roles: AxisRoles,
    pub io: Io,
    /// Coordinates of each motor (SCO/GCO/CCO/ACO, MVP COORD).
    pub coords: Vec<Vec<i32>>,
    pub program: Program,
    pub vm: Vm,
    /// Seconds since the bus started, up to which events are handled.
    pub t: f64,
    booted_at: f64,
    tick_offset: i64,
    rng: u64,
    pub(super) event: Option<EventRequest>,
    /// Second replies of 138 that came due: (time, motor mask).
    pub due_events: Vec<(f64, i32)>,
    /// The EEPROM changed and should be saved.
    pub eeprom_changed: bool,
}

impl Machine {
    /// A factory-fresh module at `slot`, powered up at time 0; `switches` gives each motor's
    /// switches (a motor past its end has none).
    pub(super) fn new(profile: Arc<Profile>, slot: u8, switches: &[Switches]) -> Machine {
        let axes = (0..profile.axes.max(1))
            .map(|m| Axis::new(switches.get(usize::from(m)).copied().unwrap_or_default()))
            .collect();
        let mut machine = Machine {
            params: Params::new(profile.clone(), slot),
            axes,
            roles: roles_of(&profile),
            io: Io::new(&profile.sim),
            coords: vec![vec![0; profile.coordinates.into()]; usize::from(profile.axes.max(1))],
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
    pub(super) fn boot(&mut self, t: f64) {
        if self.params.stored(Slot::Global(0, 64)) != EEPROM_MAGIC {
            self.params.factory();
            self.eeprom_changed = true;
        }
        self.params.power_up();
        for axis in &mut self.axes {
            axis.power_up(t);
        }
        self.io.reset_outputs();
        for coords in &mut self.coords {
            coords.fill(0);
        }
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
    pub(super) fn load(&mut self, image: &ModuleImage) {
        for &(number, value) in &image.axis {
            self.params.set_stored(Slot::Axis(0, number), value);
        }
        for &(motor, number, value) in &image.motors {
            self.params.set_stored(Slot::Axis(motor, number), value);
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
            let first = std::iter::once((0, &image.coordinates));
            let others = image.motor_coordinates.iter().map(|(m, c)| (*m, c));
            for (motor, stored) in first.chain(others) {
                let Some(coords) = self.coords.get_mut(usize::from(motor)) else {
                    continue;
                };
                for (slot, &value) in coords.iter_mut().zip(stored) {
                    *slot = value;
                }
            }
        }
    }

    /// The EEPROM as a state-file image.
    pub(super) fn image(&self) -> ModuleImage {
        let mut axis = Vec::new();
        let mut motors = Vec::new();
        let mut global = Vec::new();
        for (slot, value) in self.params.stored_values() {
            match slot {
                Slot::Axis(0, n) => axis.push((n, value)),
                Slot::Axis(m, n) => motors.push((m, n, value)),
                Slot::Global(bank, n) => global.push((bank, n, value)),
            }
        }
        let stored = self.params.get(Slot::Global(0, 84)) == 1;
        let coordinates = if stored {
            self.coords[0].clone()
        } else {
            Vec::new()
        };
        let motor_coordinates = if stored {
            (1..self.coords.len())
                .map(|m| (m as u8, self.coords[m].clone()))
                .collect()
        } else {
            Vec::new()
        };
        ModuleImage {
            slot: self.slot,
            axis,
            motors,
            global,
            coordinates,
            motor_coordinates,
            program: self.program.image(),
        }
    }

    /// The serial address the module answers to (GP 66).
    pub(super) fn address(&self) -> u8 {
        self.params.get(Slot::Global(0, 66)) as u8
    }

    /// The host address put into replies (GP 76).
    pub(super) fn host(&self) -> u8 {
        self.params.get(Slot::Global(0, 76)) as u8
    }

    /// GP 67: ASCII start-up (bit 0) and echo mode (bits 4, 5).
    pub(super) fn ascii_config(&self) -> i32 {
        self.params.get(Slot::Global(0, 67))
    }

    /// Requests the second reply of 138 for the next move's arrival (or every move's).
    pub(super) fn request_event(&mut self, mask: i32, every_move: bool) {
        self.event = Some(EventRequest { mask, every_move });
    }

    /// The value GGP reads at `t`.
    pub(super) fn global_value(&mut self, bank: u8, number: u8, t: f64) -> i32 {
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
    pub(super) fn ticks(&self, t: f64) -> i32 {
        let ms = ((t - self.booted_at) * 1000.0).floor() as i64;
        ms.wrapping_add(self.tick_offset) as i32
    }

    /// Sets the tick timer (SGP 132).
    pub(super) fn set_ticks(&mut self, t: f64, value: i32) {
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
