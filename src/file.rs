//! Files a user names — on the command line, in a REPL helper, in a configuration file or a
//! script: the one policy of how tmclsh opens them, which the script sandbox builds on.
//!
//! - Opened without blocking (`O_NONBLOCK`), so a named pipe never holds up `open()`; what was
//!   opened is checked on the descriptor itself (`fstat`), so nothing swapped in between
//!   counts. The path is looked at before opening too, so a device is not even opened.
//! - Only regular files: a FIFO, a device, a socket or a directory is refused, and the message
//!   says what it is.
//! - Reads are bounded ([`READ_LIMIT`] unless a kind of file needs more), so no file streams
//!   for ever and a read ends quickly, with Ctrl-C and signals working around it.
//! - A symlink the user names is followed to a regular file; the sandbox and files tmclsh names
//!   itself (`--log DIR/`) never follow one ([`Follow::No`], [`Mode::CreateNew`]).

use std::fs::{File, Metadata, OpenOptions};
use std::io::Read;
use std::path::Path;

/// The largest file read whole (snapshots, profiles, programs, scripts, configuration, state).
pub const READ_LIMIT: u64 = 4 << 20;

/// Why a file cannot be used: the path and what is wrong, never the file's contents.
#[derive(Debug, thiserror::Error)]
#[error("{path}: {reason}")]
pub struct FileError {
    /// The path as given.
    pub path: String,
    /// What is wrong, in words ("a named pipe (FIFO), not a regular file").
    pub reason: String,
    missing: bool,
}

impl FileError {
    /// Whether nothing is at the path (a store or configuration may treat that as empty).
    pub fn is_missing(&self) -> bool {
        self.missing
    }

    fn new(path: &Path, reason: String) -> FileError {
        FileError {
            path: path.display().to_string(),
            reason,
            missing: false,
        }
    }

    /// The error of `doing` ("read", "write") the file at `path`.
    pub fn io(path: &Path, doing: &str, error: &std::io::Error) -> FileError {
        FileError {
            missing: error.kind() == std::io::ErrorKind::NotFound,
            ..FileError::new(path, format!("cannot {doing} it: {}", io_reason(error)))
        }
    }
}

/// What a file is opened for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Reading.
    Read,
    /// Reading and writing, created if missing, not truncated (the caller decides).
    Write,
    /// Appending, created if missing.
    Append,
    /// Writing a file that must not exist yet (never follows a symlink in its place).
    CreateNew,
}

/// Whether a symlink in the last place of the path is followed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Follow {
    /// Followed (a path the user gave).
    Yes,
    /// Refused (the sandbox, which resolved its paths itself).
    No,
}

/// Opens the regular file at `path` for `mode` without blocking; refuses anything else, saying
/// what it is. The file returned is in blocking mode again.
pub fn open(path: &Path, mode: Mode, follow: Follow) -> Result<File, FileError> {
    let look = || match follow {
        Follow::Yes => std::fs::metadata(path),
        Follow::No => std::fs::symlink_metadata(path),
    };
    match look() {
        Ok(meta) if !meta.is_file() => return Err(not_regular(path, &meta)),
        Err(e) if mode == Mode::Read => return Err(FileError::io(path, "read", &e)),
        _ => {}
    }
    let doing = if mode == Mode::Read { "read" } else { "write" };
    let file = options(mode, follow).open(path).map_err(|e| {
        // A FIFO put in place after the look (ENXIO when no one reads it), or a symlink not
        // followed.
        match look() {
            Ok(meta) if !meta.is_file() && mode != Mode::CreateNew => not_regular(path, &meta),
            Ok(_) if mode == Mode::CreateNew && e.kind() == std::io::ErrorKind::AlreadyExists => {
                FileError::new(path, "exists already; not replaced".into())
            }
            _ => FileError::io(path, doing, &e),
        }
    })?;
    let meta = file
        .metadata()
        .map_err(|e| FileError::io(path, doing, &e))?;
    if !meta.is_file() {
        return Err(not_regular(path, &meta));
    }
    blocking(&file).map_err(|e| FileError::io(path, doing, &e))?;
    Ok(file)
}

/// Reads the regular file at `path` (a symlink followed), at most `limit` bytes.
pub fn read(path: &Path, limit: u64) -> Result<Vec<u8>, FileError> {
    let file = open(path, Mode::Read, Follow::Yes)?;
    read_opened(&file, path, limit)
}

/// Reads the regular file at `path` as UTF-8 text, at most `limit` bytes.
pub fn read_text(path: &Path, limit: u64) -> Result<String, FileError> {
    let bytes = read(path, limit)?;
    String::from_utf8(bytes).map_err(|e| {
        FileError::new(
            path,
            format!(
                "not UTF-8 text (an invalid byte at offset {})",
                e.utf8_error().valid_up_to()
            ),
        )
    })
}

/// [`read_text`], with `None` when nothing is at `path`.
pub fn read_text_if_any(path: &Path, limit: u64) -> Result<Option<String>, FileError> {
    match read_text(path, limit) {
        Ok(text) => Ok(Some(text)),
        Err(e) if e.is_missing() => Ok(None),
        Err(e) => Err(e),
    }
}

/// Reads an opened file, at most `limit` bytes: its size is checked first and again while
/// reading (a file that grows meanwhile).
pub fn read_opened(file: &File, path: &Path, limit: u64) -> Result<Vec<u8>, FileError> {
    let too_large = || {
        FileError::new(
            path,
            format!(
                "larger than {}, more than such a file can be",
                size_in_words(limit)
            ),
        )
    };
    let len = file
        .metadata()
        .map_err(|e| FileError::io(path, "read", &e))?
        .len();
    if len > limit {
        return Err(too_large());
    }
    let mut bytes = Vec::with_capacity(len as usize);
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| FileError::io(path, "read", &e))?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    Ok(bytes)
}

/// Opens the regular file at `path` (a symlink followed) for writing, emptied.
pub fn create(path: &Path) -> Result<File, FileError> {
    let file = open(path, Mode::Write, Follow::Yes)?;
    file.set_len(0)
        .map_err(|e| FileError::io(path, "write", &e))?;
    Ok(file)
}

/// Writes `bytes` to the regular file at `path` (a symlink followed), replacing what it held.
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), FileError> {
    use std::io::Write;
    let mut file = create(path)?;
    file.write_all(bytes)
        .and_then(|()| file.flush())
        .map_err(|e| FileError::io(path, "write", &e))
}

/// Refuses an existing `path` that is not a regular file (a symlink followed), before any long
/// work whose result would go there, or before handing the path to a library that opens it
/// itself (the line editor's history).
pub fn check_writable(path: &Path) -> Result<(), FileError> {
    match std::fs::metadata(path) {
        Ok(meta) if !meta.is_file() => Err(not_regular(path, &meta)),
        _ => Ok(()),
    }
}

/// "a named pipe (FIFO), not a regular file", for the file at `path`.
fn not_regular(path: &Path, meta: &Metadata) -> FileError {
    FileError::new(path, format!("{}, not a regular file", describe_type(meta)))
}

/// What a file is, in words: "a directory", "a named pipe (FIFO)", "a character device" …
pub fn describe_type(meta: &Metadata) -> &'static str {
    let t = meta.file_type();
    if t.is_file() {
        return "a regular file";
    }
    if t.is_dir() {
        return "a directory";
    }
    if t.is_symlink() {
        return "a symlink";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a named pipe (FIFO)";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    "a special file"
}

/// What is at `path`, in words, for messages about a file expected there: "a named pipe
/// (FIFO)", "a symlink loop", "missing" …
pub fn describe_path(path: &Path) -> String {
    match std::fs::metadata(path) {
        Ok(meta) => describe_type(&meta).to_string(),
        Err(e) => match std::fs::symlink_metadata(path) {
            Ok(meta) if meta.file_type().is_symlink() => {
                if e.raw_os_error() == Some(40) {
                    "a symlink loop".into()
                } else {
                    "a symlink to nothing".into()
                }
            }
            Ok(meta) => describe_type(&meta).to_string(),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => "missing".into(),
            Err(e) => format!("not readable ({})", io_reason(&e)),
        },
    }
}

/// An I/O error in words, without the path (the message names it already).
pub fn io_reason(error: &std::io::Error) -> String {
    let text = error.to_string();
    match text.find(" (os error") {
        Some(i) => text[..i].to_lowercase(),
        None => text.to_lowercase(),
    }
}

fn size_in_words(bytes: u64) -> String {
    if bytes >= 1 << 20 && bytes % (1 << 20) == 0 {
        format!("{} MiB", bytes >> 20)
    } else {
        format!("{} KiB", bytes >> 10)
    }
}

fn options(mode: Mode, follow: Follow) -> OpenOptions {
    let mut options = OpenOptions::new();
    match mode {
        Mode::Read => options.read(true),
        Mode::Write => options.read(true).write(true).create(true).truncate(false),
        Mode::Append => options.append(true).create(true),
        Mode::CreateNew => options.write(true).create_new(true),
    };
    #[cfg(unix)]
    {
        use nix::fcntl::OFlag;
        use std::os::unix::fs::OpenOptionsExt;
        let mut flags = OFlag::O_NONBLOCK;
        if follow == Follow::No {
            flags |= OFlag::O_NOFOLLOW;
        }
        options.custom_flags(flags.bits());
    }
    #[cfg(not(unix))]
    let _ = follow;
    options
}

/// Puts an opened file back into blocking mode (it was opened non-blocking only so that
/// `open()` itself cannot block).
#[cfg(unix)]
fn blocking(file: &File) -> std::io::Result<()> {
    use nix::fcntl::{FcntlArg, OFlag, fcntl};
    let flags = fcntl(file, FcntlArg::F_GETFL)?;
    let flags = OFlag::from_bits_truncate(flags) - OFlag::O_NONBLOCK;
    fcntl(file, FcntlArg::F_SETFL(flags))?;
    Ok(())
}

#[cfg(not(unix))]
fn blocking(_file: &File) -> std::io::Result<()> {
    Ok(())
}

#[cfg(test)]
mod tests;
