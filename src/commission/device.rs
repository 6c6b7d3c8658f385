//! The seam between the commissioning tools and a module dialect: list the parameters, read,
//! write and store one. Snapshots, watches and recordings only use this trait, so a dialect that
//! implements it (TMCL here, SMD4 later) gets them all.

use crate::profile::{Access, SnapshotRole};
use crate::session::SessionError;

/// Where a parameter lives: an axis parameter of a motor, or a global parameter of a bank.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Scope {
    /// An axis parameter of this motor.
    Axis {
        /// Motor number.
        motor: u8,
    },
    /// A global parameter of this bank.
    Global {
        /// Bank number.
        bank: u8,
    },
}

impl Scope {
    /// The section of a snapshot file (`axis.0`, `global.2`).
    pub fn section(self) -> String {
        match self {
            Scope::Axis { motor } => format!("axis.{motor}"),
            Scope::Global { bank } => format!("global.{bank}"),
        }
    }
}

/// A parameter as the commissioning tools see it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParamRef {
    /// Where it lives.
    pub scope: Scope,
    /// The identifier users type, unique within its scope (`max_current`).
    pub name: String,
    /// Its number in the dialect (TMCL: the type byte).
    pub number: u32,
    /// Unit as printed in the manual (may be empty).
    pub unit: String,
    /// Read, write and store rules.
    pub access: Access,
    /// What a snapshot does with it.
    pub role: SnapshotRole,
    /// Restore order: lower ranks are written first; equal ranks keep the list order.
    pub rank: usize,
}

impl ParamRef {
    /// "axis 6" / "global 0/65": where to find it in the manual's tables.
    pub fn place(&self) -> String {
        match self.scope {
            Scope::Axis { motor: 0 } => format!("axis {}", self.number),
            Scope::Axis { motor } => format!("axis {} motor {motor}", self.number),
            Scope::Global { bank } => format!("global {bank}/{}", self.number),
        }
    }
}

/// A module whose parameters can be listed, read, written and stored — implemented by each
/// dialect's session for the module it targets.
pub trait ParamDevice {
    /// The module type, as its profile names it ("TMCM-142").
    fn module_name(&self) -> String;

    /// The bus address of the module talked to.
    fn address(&self) -> u8;

    /// The firmware version, where the module tells it (`None` when it cannot).
    fn firmware(&mut self) -> Option<String>;

    /// Every parameter of the module's profile, in table order.
    fn params(&self) -> Vec<ParamRef>;

    /// The parameter a user means by `name` (an identifier or a unique prefix of one).
    fn find(&self, name: &str) -> Result<ParamRef, String>;

    /// Reads one parameter; a refusal by the module is [`SessionError::Device`].
    fn read(&mut self, param: &ParamRef) -> Result<i64, SessionError>;

    /// Writes one parameter (in RAM).
    fn write(&mut self, param: &ParamRef, value: i64) -> Result<(), SessionError>;

    /// Stores one parameter to the module's EEPROM.
    fn store(&mut self, param: &ParamRef) -> Result<(), SessionError>;

    /// The line [`ParamDevice::write`] sends, for dry runs and hints.
    fn write_line(&self, param: &ParamRef, value: i64) -> String;

    /// The line [`ParamDevice::store`] sends.
    fn store_line(&self, param: &ParamRef) -> String;
}
