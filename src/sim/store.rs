//! Where a simulated device keeps what survives a power cycle — a TMCL module's EEPROM, an SMD4's
//! stored configuration — between runs: a state file (`tmclsh sim --state FILE`), or memory
//! shared between clones so a test can "restart" a simulator by building a new one on a clone.
//!
//! A store holds text; each simulator writes and reads its own format and decides what a damaged
//! text means. Saves replace the file atomically (written aside, then renamed), so killing the
//! simulator at any moment leaves the old contents or the new, never half of them.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// Non-volatile memory between runs.
pub trait Store: Send {
    /// The text saved last; `None` when nothing was ever saved (factory state).
    fn load(&self) -> Result<Option<String>, StoreError>;

    /// Replaces the saved text.
    fn save(&mut self, text: &str) -> Result<(), StoreError>;

    /// The store as messages name it: the file's path.
    fn name(&self) -> String;
}

/// Why a store could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    /// The file exists but cannot be read (or is no regular file, or too large).
    #[error("cannot read state file {0}")]
    Read(crate::file::FileError),
    /// The file cannot be written.
    #[error("cannot write state file {0}")]
    Write(crate::file::FileError),
}

/// A state file on disk; a missing file means factory state and is created by the first save.
#[derive(Debug, Clone)]
pub struct FileStore {
    path: PathBuf,
}

impl FileStore {
    /// A store at `path` (its directory must exist by the first save).
    pub fn new(path: &Path) -> FileStore {
        FileStore {
            path: path.to_path_buf(),
        }
    }
}

impl Store for FileStore {
    fn load(&self) -> Result<Option<String>, StoreError> {
        crate::file::read_text_if_any(&self.path, crate::file::READ_LIMIT).map_err(StoreError::Read)
    }

    fn save(&mut self, text: &str) -> Result<(), StoreError> {
        let mut aside = self.path.clone().into_os_string();
        aside.push(".tmp");
        let aside = PathBuf::from(aside);
        crate::file::check_writable(&self.path).map_err(StoreError::Write)?;
        crate::file::write(&aside, text.as_bytes()).map_err(StoreError::Write)?;
        std::fs::rename(&aside, &self.path)
            .map_err(|e| StoreError::Write(crate::file::FileError::io(&self.path, "write", &e)))
    }

    fn name(&self) -> String {
        self.path.display().to_string()
    }
}

/// A store in memory; clones share it, so a re-created simulator finds what the last one saved.
#[derive(Debug, Clone, Default)]
pub struct MemoryStore {
    text: Arc<Mutex<Option<String>>>,
    saves: Arc<AtomicUsize>,
}

impl MemoryStore {
    /// An empty store (factory state).
    pub fn new() -> Self {
        Self::default()
    }

    /// The text saved last.
    pub fn text(&self) -> Option<String> {
        self.text.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// How many times text was saved.
    pub fn saves(&self) -> usize {
        self.saves.load(Ordering::SeqCst)
    }
}

impl Store for MemoryStore {
    fn load(&self) -> Result<Option<String>, StoreError> {
        Ok(self.text())
    }

    fn save(&mut self, text: &str) -> Result<(), StoreError> {
        *self.text.lock().unwrap_or_else(|e| e.into_inner()) = Some(text.to_string());
        self.saves.fetch_add(1, Ordering::SeqCst);
        Ok(())
    }

    fn name(&self) -> String {
        "memory".into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("tmclsh-store-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn a_file_store_starts_empty_and_keeps_the_last_save_only() {
        let dir = scratch("file");
        let path = dir.join("state.toml");
        let mut store = FileStore::new(&path);
        assert!(store.load().unwrap().is_none());
        store.save("first").unwrap();
        store.save("second").unwrap();
        assert_eq!(
            FileStore::new(&path).load().unwrap().as_deref(),
            Some("second")
        );
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left, ["state.toml"], "nothing is left aside");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_file_that_cannot_be_read_or_written_says_which_and_why() {
        let dir = scratch("unusable");
        // A directory where the file should be: reading and renaming onto it both fail.
        let path = dir.join("state.toml");
        std::fs::create_dir(&path).unwrap();
        let mut store = FileStore::new(&path);
        let read = store.load().unwrap_err().to_string();
        assert!(
            read.starts_with(&format!("cannot read state file {}: ", path.display())),
            "{read}"
        );
        let write = store.save("x").unwrap_err().to_string();
        assert!(
            write.starts_with(&format!("cannot write state file {}: ", path.display())),
            "{write}"
        );
        let missing = FileStore::new(&dir.join("no/such/dir/state.toml")).save("x");
        assert!(matches!(missing, Err(StoreError::Write { .. })));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn clones_of_a_memory_store_share_it() {
        let store = MemoryStore::new();
        assert!(store.load().unwrap().is_none());
        let mut writer = store.clone();
        writer.save("kept").unwrap();
        assert_eq!(store.load().unwrap().as_deref(), Some("kept"));
        assert_eq!(store.saves(), 1);
    }
}
