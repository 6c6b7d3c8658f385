//! Where a script's file functions may reach — the one path policy every file function goes
//! through (`snapshot_save`, `snapshot_diff`, `snapshot_restore`, `record_csv`, `download`).
//!
//! - Only inside the sandbox's directories: the script's directory, the working directory and
//!   those given with `--allow-dir`. Paths are canonicalised (`..` and symlinks resolved) before
//!   the check, and the file actually opened is checked again (Linux: through `/proc/self/fd`),
//!   so a symlink or a directory swapped in between cannot lead outside.
//! - Only regular files, opened without following a last symlink, and reads capped in size:
//!   the policy of every file a user names (`crate::file`), so a FIFO or a device never blocks
//!   or streams forever.
//! - An existing file is replaced only when it is a tmclsh file of the same kind (a snapshot, a
//!   recording), unless the sandbox allows overwriting (`--overwrite`).
//! - Messages name the path and what is wrong, never what the file contains.

use crate::file::{self, FileError, Follow, Mode, io_reason};
use std::fs::{File, Metadata};
use std::io::{Read, Seek, SeekFrom};
use std::path::{Component, Path, PathBuf};

/// The largest file a script may read (snapshots, program sources): the policy's.
pub const READ_LIMIT: u64 = file::READ_LIMIT;

/// What a file function writes, and how to recognise a file of that kind it may replace.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A parameter snapshot (`.toml`).
    Snapshot,
    /// A CSV recording (`.csv`).
    Recording,
}

impl Kind {
    fn extension(self) -> &'static str {
        match self {
            Kind::Snapshot => "toml",
            Kind::Recording => "csv",
        }
    }

    fn name(self) -> &'static str {
        match self {
            Kind::Snapshot => "snapshot",
            Kind::Recording => "recording",
        }
    }

    /// Whether `head`, the start of an existing file, is one tmclsh wrote.
    fn written_by_us(self, head: &[u8]) -> bool {
        match self {
            Kind::Snapshot => head.starts_with(crate::commission::snapshot::HEADER.as_bytes()),
            Kind::Recording => {
                let time = crate::commission::record::CSV_TIME.as_bytes();
                head.starts_with(time) && head.get(time.len()) == Some(&b',')
            }
        }
    }
}

/// The directories a script's file functions may reach.
#[derive(Debug, Clone)]
pub struct Sandbox {
    roots: Vec<PathBuf>,
    overwrite: bool,
}

/// Why a file function may not use a path (the message names the path, never the contents).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{path}: {reason}")]
pub struct PathRefusal {
    /// The path as the script gave it.
    pub path: String,
    /// What is wrong with it.
    pub reason: String,
}

/// A path a script may not use is refused: nothing was read or written.
impl crate::exit::ExitStatus for PathRefusal {
    fn exit(&self) -> crate::exit::Exit {
        crate::exit::Exit::Refused
    }
}

impl Sandbox {
    /// A sandbox of the script's directory, the working directory and `allowed`; `overwrite`
    /// lets file functions replace files tmclsh did not write.
    pub fn for_script(script: &Path, allowed: &[PathBuf], overwrite: bool) -> Sandbox {
        let script_dir = script
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let dirs = [script_dir, Path::new(".")]
            .into_iter()
            .chain(allowed.iter().map(PathBuf::as_path));
        Sandbox::new(dirs, overwrite)
    }

    /// A sandbox of these directories (those that do not exist are left out).
    pub fn new<'a>(dirs: impl IntoIterator<Item = &'a Path>, overwrite: bool) -> Sandbox {
        let mut roots: Vec<PathBuf> = Vec::new();
        for dir in dirs {
            if let Ok(root) = dir.canonicalize() {
                if root.is_dir() && !roots.contains(&root) {
                    roots.push(root);
                }
            }
        }
        Sandbox { roots, overwrite }
    }

    fn inside(&self, path: &Path) -> bool {
        self.roots.iter().any(|root| path.starts_with(root))
    }

    fn outside(&self, path: &str) -> PathRefusal {
        let roots: Vec<String> = self.roots.iter().map(|r| r.display().to_string()).collect();
        refusal(
            path,
            format!(
                "outside the directories scripts may use ({}); widen them with --allow-dir DIR",
                roots.join(", ")
            ),
        )
    }

    /// Reads the regular file at `path` inside the sandbox, at most `limit` bytes.
    pub fn read(&self, path: &str, limit: u64) -> Result<Vec<u8>, PathRefusal> {
        let real = Path::new(path)
            .canonicalize()
            .map_err(|e| refusal(path, format!("cannot read it: {}", io_reason(&e))))?;
        if !self.inside(&real) {
            return Err(self.outside(path));
        }
        let opened = file::open(&real, Mode::Read, Follow::No).map_err(|e| refused(path, e))?;
        self.check_opened(path, &opened)?;
        file::read_opened(&opened, &real, limit).map_err(|e| refused(path, e))
    }

    /// Checks that [`Sandbox::create`] would open `path` for a file of `kind`, without creating
    /// or changing anything (so a script learns of a refused path before a long capture).
    pub fn check_writable(&self, path: &str, kind: Kind) -> Result<(), PathRefusal> {
        let target = self.target(path, kind)?;
        match std::fs::symlink_metadata(&target) {
            Err(_) => Ok(()),
            Ok(meta) if !meta.is_file() => Err(refusal(path, not_regular(&meta))),
            Ok(meta) if meta.len() == 0 || self.overwrite => Ok(()),
            Ok(_) => {
                let file =
                    file::open(&target, Mode::Read, Follow::No).map_err(|e| refused(path, e))?;
                self.check_opened(path, &file)?;
                self.check_ours(path, &file, kind)
            }
        }
    }

    /// Opens `path` inside the sandbox for writing a file of `kind`, replacing an existing file
    /// only when tmclsh wrote it (or the sandbox allows overwriting). The file is empty when
    /// returned.
    pub fn create(&self, path: &str, kind: Kind) -> Result<File, PathRefusal> {
        let target = self.target(path, kind)?;
        if let Ok(meta) = std::fs::symlink_metadata(&target) {
            if !meta.is_file() {
                return Err(refusal(path, not_regular(&meta)));
            }
        }
        let file = file::open(&target, Mode::Write, Follow::No).map_err(|e| refused(path, e))?;
        self.check_opened(path, &file)?;
        let len = file
            .metadata()
            .map_err(|e| refusal(path, format!("cannot write it: {}", io_reason(&e))))?
            .len();
        if len > 0 && !self.overwrite {
            self.check_ours(path, &file, kind)?;
        }
        file.set_len(0)
            .map_err(|e| refusal(path, format!("cannot write it: {}", io_reason(&e))))?;
        Ok(file)
    }

    /// Refuses an opened existing file that tmclsh did not write as a `kind`.
    fn check_ours(&self, path: &str, file: &File, kind: Kind) -> Result<(), PathRefusal> {
        let mut head = [0u8; 64];
        let n = read_head(file, &mut head)
            .map_err(|e| refusal(path, format!("cannot read it: {}", io_reason(&e))))?;
        if kind.written_by_us(&head[..n]) {
            return Ok(());
        }
        Err(refusal(
            path,
            format!(
                "exists and is not a tmclsh {}; scripts replace only their own files \
                 (run with --overwrite to allow it)",
                kind.name()
            ),
        ))
    }

    /// The extension checked, and the real path a write of `kind` to `path` goes to.
    fn target(&self, path: &str, kind: Kind) -> Result<PathBuf, PathRefusal> {
        let extension_ok = Path::new(path)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case(kind.extension()));
        if !extension_ok {
            return Err(refusal(
                path,
                format!(
                    "a {} is written to a .{} file (scripts write only snapshots and recordings)",
                    kind.name(),
                    kind.extension()
                ),
            ));
        }
        self.resolve_for_writing(path)
    }

    /// The real path a write to `path` goes to: its directory canonicalised and inside the
    /// sandbox; a last component that is a symlink is followed only to a place inside.
    fn resolve_for_writing(&self, path: &str) -> Result<PathBuf, PathRefusal> {
        let given = Path::new(path);
        let Some(Component::Normal(name)) = given.components().next_back() else {
            return Err(refusal(path, "not a file name".into()));
        };
        let parent = match given.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let dir = parent.canonicalize().map_err(|e| {
            refusal(
                path,
                format!("its directory cannot be used: {}", io_reason(&e)),
            )
        })?;
        let target = dir.join(name);
        let real = match std::fs::symlink_metadata(&target) {
            Ok(meta) if meta.file_type().is_symlink() => target.canonicalize().map_err(|_| {
                refusal(
                    path,
                    "a symlink to nothing; scripts do not follow it".into(),
                )
            })?,
            _ => target,
        };
        if !self.inside(&real) {
            return Err(self.outside(path));
        }
        Ok(real)
    }

    /// Checks the file really opened (not only the path looked at before) is inside.
    fn check_opened(&self, path: &str, file: &File) -> Result<(), PathRefusal> {
        match opened_path(file) {
            Some(real) if !self.inside(&real) => Err(self.outside(path)),
            _ => Ok(()),
        }
    }
}

fn refusal(path: &str, reason: String) -> PathRefusal {
    PathRefusal {
        path: path.to_string(),
        reason,
    }
}

/// The policy's refusal as the sandbox says it: the script's path, with a hint for scripts.
fn refused(path: &str, error: FileError) -> PathRefusal {
    let reason = if error.reason.ends_with("not a regular file") {
        format!("{}; scripts use regular files only", error.reason)
    } else {
        error.reason
    };
    refusal(path, reason)
}

fn not_regular(meta: &Metadata) -> String {
    let kind = file::describe_type(meta);
    format!("{kind}, not a regular file; scripts use regular files only")
}

fn read_head(mut file: &File, buf: &mut [u8]) -> std::io::Result<usize> {
    file.seek(SeekFrom::Start(0))?;
    let mut filled = 0;
    while filled < buf.len() {
        match file.read(&mut buf[filled..])? {
            0 => break,
            n => filled += n,
        }
    }
    file.seek(SeekFrom::Start(0))?;
    Ok(filled)
}

/// The path of an opened file as the kernel sees it, where the system tells it.
#[cfg(target_os = "linux")]
fn opened_path(file: &File) -> Option<PathBuf> {
    use std::os::fd::AsRawFd;
    std::fs::read_link(format!("/proc/self/fd/{}", file.as_raw_fd())).ok()
}

#[cfg(not(target_os = "linux"))]
fn opened_path(_file: &File) -> Option<PathBuf> {
    None
}

#[cfg(test)]
mod tests;
