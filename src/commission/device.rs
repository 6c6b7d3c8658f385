//! The seam between the commissioning tools and a module dialect: list the parameters, read,
//! write and store them. Snapshots, watches and recordings only use this trait, so a dialect that
//! implements it (each dialect's `commission.rs`) gets them all.

use crate::exit::{Exit, ExitStatus};
use crate::session::SessionError;

use super::rules::SnapshotRole;
use super::value::{ParamValue, Reading, Tolerance};

/// Why a parameter named, or a value for one, is refused before anything is sent (exit 2). The
/// dialect words the message: the name's nearest match, the validator's reason.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ParamError {
    /// No parameter has that name, or more than one starts with it.
    #[error("{0}")]
    Unknown(String),
    /// The module's validator would refuse the value (its type, range or access).
    #[error("{0}")]
    Value(String),
}

impl ExitStatus for ParamError {
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}

/// Whether a parameter can be read, written and stored (TMCL: GAP/GGP, SAP/SGP, STAP/STGP and
/// RSAP/RSGP; SMD4: a read, a write, STORE).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Access {
    /// Readable.
    pub read: bool,
    /// Writable.
    pub write: bool,
    /// Storable to and restorable from non-volatile memory.
    pub store: bool,
}

impl Access {
    /// From the letters of the manual's tables (`RWE`, any case).
    pub fn from_letters(letters: &str) -> Self {
        let has = |c| letters.to_ascii_uppercase().contains(c);
        Access {
            read: has('R'),
            write: has('W'),
            store: has('E'),
        }
    }

    /// The letters as printed in the manual's tables (`RWE`).
    pub fn letters(&self) -> String {
        [(self.read, 'R'), (self.write, 'W'), (self.store, 'E')]
            .iter()
            .filter(|(on, _)| *on)
            .map(|(_, c)| *c)
            .collect()
    }
}

/// Where a parameter lives: an axis parameter of a motor, a global parameter of a bank, or a
/// setting of a drive that has one motor and no banks (SMD4).
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
    /// A setting or query of the drive, named by its mnemonic.
    Drive,
}

impl Scope {
    /// The section of a snapshot file (`axis.0`, `global.2`, `drive`).
    pub fn section(self) -> String {
        match self {
            Scope::Axis { motor } => format!("axis.{motor}"),
            Scope::Global { bank } => format!("global.{bank}"),
            Scope::Drive => "drive".into(),
        }
    }
}

/// A parameter as the commissioning tools see it.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamRef {
    /// Where it lives.
    pub scope: Scope,
    /// The identifier users type, unique within its scope (`max_current`, `MOTOR:IR`).
    pub name: String,
    /// Its number in the dialect (TMCL: the type byte); SMD4 settings have none.
    pub number: Option<u32>,
    /// Unit as printed in the manual (may be empty).
    pub unit: String,
    /// Read, write and store rules.
    pub access: Access,
    /// What a snapshot does with it.
    pub role: SnapshotRole,
    /// Restore order: lower ranks are written first; equal ranks keep the list order.
    pub rank: usize,
    /// How two of its values are compared.
    pub tolerance: Tolerance,
}

impl ParamRef {
    /// "axis 6" / "global 0/65": where to find it in the manual's tables (empty for a drive's
    /// settings, whose name says it all).
    pub fn place(&self) -> String {
        let number = self.number.unwrap_or_default();
        match self.scope {
            Scope::Axis { motor: 0 } => format!("axis {number}"),
            Scope::Axis { motor } => format!("axis {number} motor {motor}"),
            Scope::Global { bank } => format!("global {bank}/{number}"),
            Scope::Drive => String::new(),
        }
    }
}

/// One step that makes restored parameters survive a power cycle: one per parameter (TMCL
/// STAP/STGP) or one for the whole configuration (SMD4 STORE).
#[derive(Debug, Clone, PartialEq)]
pub struct StoreStep {
    /// The line it sends.
    pub line: String,
    /// The restored parameters it makes permanent.
    pub params: Vec<ParamRef>,
    /// Whether it stores the module's whole working configuration, not only `params`.
    pub whole: bool,
}

/// A module whose parameters can be listed, read, written and stored — implemented by each
/// dialect's session for the module it targets.
pub trait ParamDevice {
    /// The module type, as its profile names it ("TMCM-142", "SMD4").
    fn module_name(&self) -> String;

    /// The bus address of the module talked to, where requests carry one.
    fn address(&self) -> Option<u32>;

    /// The module talked to, for messages ("module 1", "drive @3").
    fn who(&self) -> String;

    /// What the module keeps its settings in over a power cycle, for messages ("EEPROM").
    fn memory(&self) -> &'static str;

    /// The firmware version, where the module tells it (`None` when it cannot).
    fn firmware(&mut self) -> Option<String>;

    /// Every parameter of the module's profile, in table order.
    fn params(&self) -> Vec<ParamRef>;

    /// The parameter a user means by `name` (an identifier or a unique abbreviation of one).
    fn find(&self, name: &str) -> Result<ParamRef, ParamError>;

    /// Reads one parameter; a refusal by the module is [`SessionError::Device`].
    fn read(&mut self, param: &ParamRef) -> Result<Reading, SessionError>;

    /// Writes one parameter (in RAM).
    fn write(&mut self, param: &ParamRef, value: &ParamValue) -> Result<(), SessionError>;

    /// Whether the module's validator lets [`ParamDevice::write`] send `value` to `param` (its
    /// type, range and access), without sending anything; the error says why not. Under
    /// `--no-validate` only what cannot be sent at all is refused.
    fn check_write(&self, param: &ParamRef, value: &ParamValue) -> Result<(), ParamError>;

    /// The line [`ParamDevice::write`] sends, for dry runs and hints.
    fn write_line(&self, param: &ParamRef, value: &ParamValue) -> String;

    /// How `params` (written by a restore) are made permanent, in order.
    fn store_steps(&self, params: &[&ParamRef]) -> Vec<StoreStep>;

    /// Runs one step of [`ParamDevice::store_steps`].
    fn store(&mut self, step: &StoreStep) -> Result<(), SessionError>;

    /// What `value` of `param` means, where the module's tables say (`9600 baud`); shown by
    /// `:params --values`.
    fn explain(&self, param: &ParamRef, value: &ParamValue) -> Option<String> {
        let _ = (param, value);
        None
    }

    /// Whether the module can take a restore now; the error says why not (an SMD4 drive must
    /// stand still).
    fn ready_to_restore(&mut self) -> Result<(), SessionError> {
        Ok(())
    }
}
