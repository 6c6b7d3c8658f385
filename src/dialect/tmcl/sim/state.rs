//! The simulated EEPROM of a bus, kept in a state file (`tmclsh sim --state FILE`) so that a
//! restarted simulator keeps stored parameters, coordinates and programs like a power-cycled
//! module. The core only sees the [`StateStore`] trait; the file is written at once whenever a
//! stored value changes, so killing the simulator loses nothing.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use serde::{Deserialize, Serialize};

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
    /// EEPROM-backed axis parameters as `[number, value]`.
    #[serde(default)]
    pub axis: Vec<(u8, i32)>,
    /// EEPROM-backed global parameters as `[bank, number, value]`.
    #[serde(default)]
    pub global: Vec<(u8, u8, i32)>,
    /// Coordinates stored while GP 84 (coordinate storage) was 1, from coordinate 0 on.
    #[serde(default)]
    pub coordinates: Vec<i32>,
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

/// Where the EEPROM image lives between runs.
pub trait StateStore: Send {
    /// The image saved last, if any.
    fn load(&self) -> Option<BusImage>;

    /// Saves the image (called whenever it changes).
    fn save(&mut self, image: &BusImage);
}

/// Why a state file could not be used.
#[derive(Debug, thiserror::Error)]
pub enum StateError {
    /// The file exists but cannot be read.
    #[error("cannot read state file {path}: {source}")]
    Read {
        /// The file.
        path: String,
        /// What the OS said.
        source: std::io::Error,
    },
    /// The file is not a state file.
    #[error("state file {path} is damaged ({message}); delete it to start from factory settings")]
    Parse {
        /// The file.
        path: String,
        /// What is wrong.
        message: String,
    },
}

/// A state file on disk, replaced atomically (write aside, then rename) on every save.
#[derive(Debug)]
pub struct FileStore {
    path: PathBuf,
    loaded: Option<BusImage>,
}

impl FileStore {
    /// Opens `path`; a missing file means factory state and is created on the first save.
    pub fn open(path: &Path) -> Result<FileStore, StateError> {
        let shown = path.display().to_string();
        let loaded = match std::fs::read_to_string(path) {
            Ok(text) => Some(toml::from_str(&text).map_err(|e| StateError::Parse {
                path: shown,
                message: e.message().to_string(),
            })?),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
            Err(source) => {
                return Err(StateError::Read {
                    path: shown,
                    source,
                });
            }
        };
        Ok(FileStore {
            path: path.to_path_buf(),
            loaded,
        })
    }

    fn write(&self, image: &BusImage) -> std::io::Result<()> {
        let body = toml::to_string_pretty(image).map_err(std::io::Error::other)?;
        let text = format!(
            "# Simulated TMCL module EEPROM (tmclsh sim --state). Delete for factory settings.\n{body}"
        );
        let mut aside = self.path.clone().into_os_string();
        aside.push(".tmp");
        std::fs::write(&aside, text)?;
        std::fs::rename(&aside, &self.path)
    }
}

impl StateStore for FileStore {
    fn load(&self) -> Option<BusImage> {
        self.loaded.clone()
    }

    fn save(&mut self, image: &BusImage) {
        if let Err(e) = self.write(image) {
            // The simulator keeps running; the user learns that persistence failed.
            eprintln!(
                "tmclsh sim: cannot write state file {}: {e}",
                self.path.display()
            );
        }
    }
}

/// A state store in memory, shared between clones: "restart" a simulator in a test by building
/// a new bus on a clone.
#[derive(Debug, Clone, Default)]
pub struct MemoryStore {
    image: Arc<Mutex<Option<BusImage>>>,
    saves: Arc<Mutex<usize>>,
}

impl MemoryStore {
    /// An empty store (factory state).
    pub fn new() -> Self {
        Self::default()
    }

    /// The image saved last.
    pub fn image(&self) -> Option<BusImage> {
        self.image.lock().expect("store lock").clone()
    }

    /// How many times the image was saved.
    pub fn saves(&self) -> usize {
        *self.saves.lock().expect("store lock")
    }
}

impl StateStore for MemoryStore {
    fn load(&self) -> Option<BusImage> {
        self.image()
    }

    fn save(&mut self, image: &BusImage) {
        *self.image.lock().expect("store lock") = Some(image.clone());
        *self.saves.lock().expect("store lock") += 1;
    }
}
