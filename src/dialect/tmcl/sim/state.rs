//! The simulated EEPROM of a bus, kept in a state file (`tmclsh sim --state FILE`) so that a
//! restarted simulator keeps stored parameters, coordinates and programs like a power-cycled
//! module. The image lives in a [`Store`] (a file, or memory in tests) and is written at once
//! whenever a stored value changes, so killing the simulator loses nothing.

use serde::{Deserialize, Serialize};

use crate::sim::error::SimStartError;
use crate::sim::store::Store;

/// The EEPROM contents of every module on a bus.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct BusImage {
    /// One entry per module, by factory address.
    #[serde(default, rename = "module")]
    pub modules: Vec<ModuleImage>,
}

/// The EEPROM contents of one module.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ModuleImage {
    /// The module's factory address (its entry in `--modules`); GP 66 may since have changed.
    pub slot: u8,
    /// EEPROM-backed axis parameters of motor 0 as `[number, value]`.
    #[serde(default)]
    pub axis: Vec<(u8, i32)>,
    /// EEPROM-backed axis parameters of the other motors as `[motor, number, value]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub motors: Vec<(u8, u8, i32)>,
    /// EEPROM-backed global parameters as `[bank, number, value]`.
    #[serde(default)]
    pub global: Vec<(u8, u8, i32)>,
    /// Coordinates of motor 0 stored while GP 84 (coordinate storage) was 1, from coordinate 0
    /// on.
    #[serde(default)]
    pub coordinates: Vec<i32>,
    /// The same for the other motors, as `[motor, [coordinates]]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub motor_coordinates: Vec<(u8, Vec<i32>)>,
    /// Program memory from address 0 to the last used one, as `[command, type, motor, value]`.
    #[serde(default)]
    pub program: Vec<(u8, u8, u8, i32)>,
}

impl BusImage {
    /// The entry of the module with factory address `slot`.
    pub fn module(&self, slot: u8) -> Option<&ModuleImage> {
        self.modules.iter().find(|m| m.slot == slot)
    }
}

/// The EEPROM image of a bus in its [`Store`]: read once when the simulator starts (a damaged file
/// is refused then, before anything runs), written whenever a stored value changes.
pub struct Eeprom {
    store: Box<dyn Store>,
    loaded: Option<BusImage>,
}

impl Eeprom {
    /// Reads the image in `store`; an empty store means factory state.
    pub fn open(store: Box<dyn Store>) -> Result<Eeprom, SimStartError> {
        let loaded = match store.load()? {
            Some(text) => Some(toml::from_str(&text).map_err(|e| SimStartError::Damaged {
                path: store.name(),
                message: e.message().to_string(),
            })?),
            None => None,
        };
        Ok(Eeprom { store, loaded })
    }

    /// The image the store held when the simulator started.
    pub fn loaded(&self) -> Option<&BusImage> {
        self.loaded.as_ref()
    }

    /// Writes `image`. A failure is told on stderr and the simulator keeps running: the user
    /// learns that persistence failed, the session on the other end sees a module that works.
    pub fn save(&mut self, image: &BusImage) {
        let written = toml::to_string_pretty(image)
            .map_err(|e| e.to_string())
            .and_then(|body| {
                let text = format!("{HEADER}\n{body}");
                self.store.save(&text).map_err(|e| e.to_string())
            });
        if let Err(e) = written {
            eprintln!("tmclsh sim: {e}");
        }
    }
}

/// The first line of a state file.
const HEADER: &str =
    "# Simulated TMCL module EEPROM (tmclsh sim --state). Delete for factory settings.";
