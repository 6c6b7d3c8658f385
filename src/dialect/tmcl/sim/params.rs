//! Parameter memory of one simulated module: RAM values and their EEPROM copies, with the access
//! rules, ranges and factory defaults of the profile. Parameters whose value is live (positions,
//! switches, program status) are computed elsewhere; this is plain storage plus the rules.

use std::sync::Arc;

use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::profile::{Param, Profile};
use crate::dialect::tmcl::protocol::Status;

/// Global parameter banks the module has (0 module settings, 1 reserved, 2 user variables,
/// 3 interrupt configuration).
pub(crate) const BANKS: usize = 4;

/// Which parameter: a motor and axis parameter number, or a bank and number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Slot {
    /// SAP/GAP parameter of a motor.
    Axis(u8, u8),
    /// SGP/GGP parameter in a bank.
    Global(u8, u8),
}

/// The bank-0 global parameters that live in EEPROM only: SGP writes them through at once
/// (generic TMCL reference, chapter 8).
pub(crate) fn eeprom_only(slot: Slot) -> bool {
    matches!(slot, Slot::Global(0, 64..=127))
}

/// Values of every motor's axis parameters and of every bank. A motor the module does not have
/// reads 0 and keeps nothing (the commands refuse it before they get here).
#[derive(Clone)]
struct Values {
    axis: Vec<[i32; 256]>,
    global: [[i32; 256]; BANKS],
}

impl Values {
    fn zero(axes: u8) -> Box<Values> {
        Box::new(Values {
            axis: vec![[0; 256]; usize::from(axes.max(1))],
            global: [[0; 256]; BANKS],
        })
    }

    fn get(&self, slot: Slot) -> i32 {
        match slot {
            Slot::Axis(m, n) => self.axis.get(m as usize).map_or(0, |a| a[n as usize]),
            Slot::Global(bank, n) => self.global[bank as usize][n as usize],
        }
    }

    fn set(&mut self, slot: Slot, value: i32) {
        match slot {
            Slot::Axis(m, n) => {
                if let Some(axis) = self.axis.get_mut(m as usize) {
                    axis[n as usize] = value;
                }
            }
            Slot::Global(bank, n) => self.global[bank as usize][n as usize] = value,
        }
    }
}

/// GP 67: ASCII start-up and echo.
const ASCII_MODE: u8 = 67;

/// The profile, with the bank-0 interface settings (GP 64..127: address, host address, ASCII
/// mode, EEPROM magic …) the simulated firmware works by (GP 67 only where the module has an
/// ASCII interface). A custom profile that leaves them out
/// gets the built-in profile's rows: without them the module would answer to no address at all.
///
/// The generic profile has no parameter rows at all: its simulated module takes every row of the
/// built-in profile (the numbering its motion roles follow, with defaults a motor can move by).
fn with_interface_settings(profile: Arc<Profile>) -> Arc<Profile> {
    let builtin = Profile::builtin();
    // A binary-only module has no ASCII start-up setting to be locked out by.
    let binary_only = profile.identity.ascii_interface() == AsciiInterface::No;
    let wanted = |p: &&Param| {
        (profile.generic || eeprom_only(Slot::Global(p.bank(), p.number)))
            && !(binary_only && (p.bank(), p.number) == (0, ASCII_MODE))
    };
    let missing: Vec<Param> = builtin
        .global
        .iter()
        .filter(wanted)
        .filter(|p| profile.global_param(p.bank(), p.number).is_none())
        .cloned()
        .collect();
    let axis: Vec<Param> = if profile.generic && profile.axis.is_empty() {
        builtin.axis.clone()
    } else {
        Vec::new()
    };
    if missing.is_empty() && axis.is_empty() {
        return profile;
    }
    let mut profile = Profile::clone(&profile);
    profile.global.extend(missing);
    profile.global.sort_by_key(|p| (p.bank(), p.number));
    profile.axis.extend(axis);
    Arc::new(profile)
}

/// RAM and EEPROM values of every parameter of the profile.
pub(crate) struct Params {
    profile: Arc<Profile>,
    axis_index: Box<[Option<u16>; 256]>,
    global_index: Box<[[Option<u16>; 256]; BANKS]>,
    ram: Box<Values>,
    rom: Box<Values>,
    factory_address: u8,
}

impl Params {
    /// Factory state of a module whose serial address is `address`.
    pub(super) fn new(profile: Arc<Profile>, address: u8) -> Params {
        let profile = with_interface_settings(profile);
        let mut axis_index = Box::new([None; 256]);
        for (i, p) in profile.axis.iter().enumerate() {
            axis_index[p.number as usize] = Some(i as u16);
        }
        let mut global_index = Box::new([[None; 256]; BANKS]);
        for (i, p) in profile.global.iter().enumerate() {
            if let Some(bank) = global_index.get_mut(p.bank() as usize) {
                bank[p.number as usize] = Some(i as u16);
            }
        }
        let ram = Values::zero(profile.axes);
        let rom = Values::zero(profile.axes);
        let mut params = Params {
            profile,
            axis_index,
            global_index,
            ram,
            rom,
            factory_address: address,
        };
        params.factory();
        params.power_up();
        params
    }

    /// The profile row of a parameter, if the module has it.
    pub(super) fn spec(&self, slot: Slot) -> Option<&Param> {
        let index = match slot {
            Slot::Axis(_, n) => self.axis_index[n as usize],
            Slot::Global(bank, n) => self.global_index.get(bank as usize)?[n as usize],
        }?;
        Some(match slot {
            Slot::Axis(..) => &self.profile.axis[index as usize],
            Slot::Global(..) => &self.profile.global[index as usize],
        })
    }

    /// Checks that GAP/GGP may read the parameter: unknown or unreadable answers wrong type.
    /// A module of the generic profile has every number, as plain memory where the built-in
    /// table has no row.
    pub(super) fn check_read(&self, slot: Slot) -> Result<(), Status> {
        match self.spec(slot) {
            Some(p) if p.access.read => Ok(()),
            None if self.open(slot) => Ok(()),
            _ => Err(Status::WrongType),
        }
    }

    /// A parameter a module of the generic profile keeps in plain memory (any number the
    /// built-in table lacks, in the banks the module has).
    fn open(&self, slot: Slot) -> bool {
        self.profile.generic
            && match slot {
                Slot::Axis(m, _) => m < self.profile.axes.max(1),
                Slot::Global(bank, _) => usize::from(bank) < BANKS,
            }
    }

    /// Checks that SAP/SGP may write `value`: unknown or read-only answers wrong type (as
    /// Trinamic's firmware does), a value outside the range answers invalid value.
    pub(super) fn check_write(&self, slot: Slot, value: i32) -> Result<(), Status> {
        match self.spec(slot) {
            Some(p) if p.access.write => {
                if p.accepts(value.into()) {
                    Ok(())
                } else {
                    Err(Status::InvalidValue)
                }
            }
            None if self.open(slot) => Ok(()),
            _ => Err(Status::WrongType),
        }
    }

    /// Checks that STAP/RSAP/STGP/RSGP apply: the parameter must be EEPROM backed.
    pub(super) fn check_store(&self, slot: Slot) -> Result<(), Status> {
        match self.spec(slot) {
            Some(p) if p.access.store => Ok(()),
            None if self.open(slot) => Ok(()),
            _ => Err(Status::WrongType),
        }
    }

    /// The RAM value.
    pub(super) fn get(&self, slot: Slot) -> i32 {
        self.ram.get(slot)
    }

    /// Sets the RAM value (no checks).
    pub(super) fn set(&mut self, slot: Slot, value: i32) {
        self.ram.set(slot, value);
    }

    /// The EEPROM value.
    pub(super) fn stored(&self, slot: Slot) -> i32 {
        self.rom.get(slot)
    }

    /// Copies RAM to EEPROM; whether the EEPROM changed.
    pub(super) fn store(&mut self, slot: Slot) -> bool {
        let value = self.ram.get(slot);
        self.set_stored(slot, value)
    }

    /// Writes an EEPROM value; whether it changed.
    pub(super) fn set_stored(&mut self, slot: Slot, value: i32) -> bool {
        let changed = self.rom.get(slot) != value;
        self.rom.set(slot, value);
        changed
    }

    /// Copies EEPROM to RAM.
    pub(super) fn restore(&mut self, slot: Slot) {
        self.ram.set(slot, self.rom.get(slot));
    }

    /// Power-up: EEPROM-backed parameters from EEPROM, the others from their defaults.
    pub(super) fn power_up(&mut self) {
        for slot in self.slots() {
            let value = match self.spec(slot) {
                Some(p) if p.access.store => self.rom.get(slot),
                _ => self.factory_value(slot),
            };
            self.ram.set(slot, value);
        }
    }

    /// Resets the EEPROM to factory values (RAM is untouched until the next power-up).
    pub(super) fn factory(&mut self) {
        for slot in self.slots() {
            let value = self.factory_value(slot);
            self.rom.set(slot, value);
        }
    }

    /// The factory value: the profile default, the module's own address for GP 66.
    pub(super) fn factory_value(&self, slot: Slot) -> i32 {
        if slot == Slot::Global(0, 66) {
            return self.factory_address.into();
        }
        self.spec(slot)
            .and_then(|p| p.default)
            .and_then(|d| i32::try_from(d).ok())
            .unwrap_or(0)
    }

    /// Every parameter the profile defines, of every motor (in the banks the module has).
    pub(super) fn slots(&self) -> Vec<Slot> {
        let motors = 0..self.profile.axes.max(1);
        motors
            .flat_map(|m| {
                self.profile
                    .axis
                    .iter()
                    .map(move |p| Slot::Axis(m, p.number))
            })
            .chain(
                self.profile
                    .global
                    .iter()
                    .filter(|p| (p.bank() as usize) < BANKS)
                    .map(|p| Slot::Global(p.bank(), p.number)),
            )
            .collect()
    }

    /// EEPROM-backed parameters with their stored values, for the state file.
    pub(super) fn stored_values(&self) -> Vec<(Slot, i32)> {
        self.slots()
            .into_iter()
            .filter(|&s| self.spec(s).is_some_and(|p| p.access.store))
            .map(|s| (s, self.rom.get(s)))
            .collect()
    }
}
