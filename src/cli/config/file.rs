//! The configuration files: where they are, and each checked whole — a value the option would
//! refuse is an error naming the file and the line, never ignored; an unknown key is a warning
//! with the nearest known one (a newer tmclsh's key does not stop an older one).

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use clap::Command;
use clap::error::{ContextKind, ContextValue};
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::super::ports::usb::UsbSpec;
use super::{KEYS, Key, Kind};

/// Which file a value comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scope {
    /// `tmclsh.toml` in the working directory or above it.
    Project,
    /// `$XDG_CONFIG_HOME/tmclsh/config.toml` (or `~/.config/tmclsh/config.toml`).
    User,
}

impl Scope {
    /// The word `tmclsh config` shows.
    pub fn name(self) -> &'static str {
        match self {
            Scope::Project => "project",
            Scope::User => "user",
        }
    }
}

/// One value read from a file, checked, in the form the option takes it.
#[derive(Debug, Clone)]
pub(super) struct Entry {
    /// The key.
    pub key: &'static Key,
    /// The option's value (paths resolved against the file's directory).
    pub value: String,
    /// The file.
    pub file: PathBuf,
    /// The line of the key.
    pub line: usize,
    /// Which file it is.
    pub scope: Scope,
}

/// The user's configuration file, whether or not it exists.
pub(super) fn user_file() -> Option<PathBuf> {
    let base = std::env::var_os("XDG_CONFIG_HOME")
        .map(PathBuf::from)
        .filter(|p| p.is_absolute())
        .or_else(|| dirs::home_dir().map(|home| home.join(".config")))?;
    Some(base.join("tmclsh").join("config.toml"))
}

/// The project's configuration file: `tmclsh.toml` in `from` or the nearest directory above it.
/// Anything there counts, so a broken file (a directory, a FIFO, a symlink loop, unreadable) is
/// an error naming it rather than skipped for one further up.
pub(super) fn project_file(from: &Path) -> Option<PathBuf> {
    from.ancestors()
        .map(|dir| dir.join("tmclsh.toml"))
        .find(|file| file.symlink_metadata().is_ok())
}

/// A file's checked values, and what was wrong with the rest of it.
#[derive(Debug, Default)]
pub(super) struct Parsed {
    /// The values that checked out.
    pub entries: Vec<Entry>,
    /// Unknown keys, each named with the file, line and the nearest known key.
    pub warnings: Vec<String>,
    /// Values refused, each with the file and line.
    pub errors: Vec<String>,
}

/// What reading a configuration file gave.
pub(super) enum Read {
    /// Its values, checked.
    Entries(Parsed),
    /// Not used, and why: a project file another user could have written.
    Ignored(String),
}

/// Why a configuration file could not be read at all: listed with the other errors, its keys
/// unread.
#[derive(Debug, thiserror::Error)]
pub(super) enum Unreadable {
    /// Not a regular file, missing, too large, not allowed.
    #[error(transparent)]
    File(#[from] crate::file::FileError),
    /// Its owner and mode could not be read.
    #[error("{}: {source}", path.display())]
    Metadata {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
    /// Bytes that are not UTF-8.
    #[error("{}: not UTF-8 text", path.display())]
    NotText { path: std::path::PathBuf },
    /// Text that is not TOML, at `place` (`file:line`).
    #[error("{place}: {message}")]
    NotToml { place: String, message: String },
}

/// Reads and checks one file against the options of `cmd`; a project file is used only when it
/// is trusted (see [`distrust`]).
pub(super) fn read(path: &Path, scope: Scope, cmd: &Command) -> Result<Read, Unreadable> {
    use crate::file::{Follow, Mode};
    let file = crate::file::open(path, Mode::Read, Follow::Yes)?;
    if scope == Scope::Project {
        let opened = file.metadata().map_err(|source| Unreadable::Metadata {
            path: path.to_path_buf(),
            source,
        })?;
        let link = path.symlink_metadata().ok();
        if let Some(why) = distrust(&opened).or_else(|| link.as_ref().and_then(distrust_link)) {
            return Ok(Read::Ignored(why));
        }
    }
    let bytes = crate::file::read_opened(&file, path, crate::file::READ_LIMIT)?;
    let text = String::from_utf8(bytes).map_err(|_| Unreadable::NotText {
        path: path.to_path_buf(),
    })?;
    parse(path, &text, scope, cmd).map(Read::Entries)
}

/// Why a project file may not be trusted, as git's `safe.directory` reasons: one owned by
/// another user (root aside), or one others may write, may have been planted — in a shared
/// directory such as the system's temporary one — to redirect everyone's port and logs. A file
/// writable by its group is trusted only when that group is the user's own (the user-private
/// groups of a umask of 002).
#[cfg(unix)]
fn distrust(meta: &std::fs::Metadata) -> Option<String> {
    use std::os::unix::fs::MetadataExt;
    let me = nix::unistd::geteuid().as_raw();
    let mode = meta.mode() & 0o777;
    if meta.uid() != me && meta.uid() != 0 {
        return Some(format!(
            "owned by uid {}, not by you (uid {me}) or root",
            meta.uid()
        ));
    }
    if mode & 0o002 != 0 {
        return Some(format!("writable by everyone (mode {mode:03o})"));
    }
    if mode & 0o020 != 0 && meta.gid() != nix::unistd::getegid().as_raw() {
        return Some(format!(
            "writable by group {} (mode {mode:03o})",
            meta.gid()
        ));
    }
    None
}

/// A symlink in the project file's place is trusted only when its owner is.
#[cfg(unix)]
fn distrust_link(meta: &std::fs::Metadata) -> Option<String> {
    use std::os::unix::fs::MetadataExt;
    let me = nix::unistd::geteuid().as_raw();
    (meta.file_type().is_symlink() && meta.uid() != me && meta.uid() != 0).then(|| {
        format!(
            "a symlink owned by uid {}, not by you (uid {me}) or root",
            meta.uid()
        )
    })
}

#[cfg(not(unix))]
fn distrust(_meta: &std::fs::Metadata) -> Option<String> {
    None
}

#[cfg(not(unix))]
fn distrust_link(_meta: &std::fs::Metadata) -> Option<String> {
    None
}

/// Checks one file's text against the options of `cmd`: an error for text that is not TOML,
/// else every key checked on its own.
fn parse(path: &Path, text: &str, scope: Scope, cmd: &Command) -> Result<Parsed, Unreadable> {
    let at = |offset: usize| format!("{}:{}", path.display(), line_at(text, offset));
    let root = DeTable::parse(text).map_err(|e| Unreadable::NotToml {
        place: e
            .span()
            .map_or_else(|| path.display().to_string(), |s| at(s.start)),
        message: e.message().trim_end().to_string(),
    })?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut parsed = Parsed::default();
    for (name, value) in root.get_ref().iter() {
        let Some(key) = KEYS.iter().find(|k| k.name == name.get_ref().as_ref()) else {
            let known: Vec<&str> = KEYS.iter().map(|k| k.name).collect();
            let nearest = crate::suggest::nearest(name.get_ref(), known.iter().copied());
            parsed.warnings.push(format!(
                "{}: unknown key `{}`, ignored (the keys are {}){}",
                at(name.span().start),
                name.get_ref(),
                known.join(", "),
                crate::suggest::did_you_mean(&nearest.map(|n| format!("`{n}`")))
            ));
            continue;
        };
        let value = match checked(key, value, dir, cmd) {
            Ok(value) => value,
            Err(why) => {
                parsed
                    .errors
                    .push(format!("{}: {why}", at(value.span().start)));
                continue;
            }
        };
        let line = line_at(text, name.span().start);
        let names_link =
            |e: &Entry| super::super::link_kinds::is_link_key(e.key.name) && e.value != "false";
        let entry = Entry {
            key,
            value,
            file: path.to_path_buf(),
            line,
            scope,
        };
        if names_link(&entry) {
            if let Some(other) = parsed.entries.iter().find(|e| names_link(e)) {
                parsed.errors.push(format!(
                    "{}: `{}` and `{}` (line {}) name different links; keep one",
                    at(name.span().start),
                    key.name,
                    other.key.name,
                    other.line
                ));
                continue;
            }
        }
        parsed.entries.push(entry);
    }
    Ok(parsed)
}

/// The value of `key` as its option takes it, or why it cannot be.
fn checked(
    key: &Key,
    value: &Spanned<DeValue<'_>>,
    dir: &Path,
    cmd: &Command,
) -> Result<String, String> {
    let name = key.name;
    let text = match (key.kind, value.get_ref()) {
        (Kind::Integer, DeValue::Integer(n)) => i64::from_str_radix(n.as_str(), n.radix())
            .map(|n| n.to_string())
            .map_err(|_| format!("{name} is out of range"))?,
        (Kind::Integer, other) => {
            return Err(format!(
                "{name} must be a number ({}), not {}",
                key.example,
                describe(other)
            ));
        }
        (Kind::Bool, DeValue::Boolean(b)) => {
            // A flag has no value to check: `true` turns it on.
            return Ok(b.to_string());
        }
        (Kind::Bool, other) => {
            return Err(format!(
                "{name} must be true or false ({}), not {}",
                key.example,
                describe(other)
            ));
        }
        (_, DeValue::String(s)) if s.is_empty() => {
            return Err(format!("{name} is empty ({})", key.example));
        }
        (Kind::Text, DeValue::String(s)) => {
            if let Some(Err(why)) = UsbSpec::parse(s) {
                return Err(why.to_string());
            }
            s.to_string()
        }
        (Kind::NameOrPath, DeValue::String(s)) if !names_a_file(s) => s.to_string(),
        (Kind::Path | Kind::Dir | Kind::NameOrPath, DeValue::String(s)) => {
            let path = dir.join(expand_home(s));
            match key.kind {
                Kind::Path | Kind::NameOrPath if !path.is_file() => {
                    return Err(format!("{name}: no such file {}", path.display()));
                }
                Kind::Dir if path.exists() && !path.is_dir() => {
                    return Err(format!("{name}: {} is not a directory", path.display()));
                }
                _ => {}
            }
            let mut text = path.to_string_lossy().into_owned();
            if key.kind == Kind::Dir && !text.ends_with(std::path::MAIN_SEPARATOR) {
                // The trailing separator is what makes `--log` take it as a directory.
                text.push(std::path::MAIN_SEPARATOR);
            }
            text
        }
        (_, other) => {
            return Err(format!(
                "{name} must be a string in quotes ({}), not {}",
                key.example,
                describe(other)
            ));
        }
    };
    option_accepts(cmd, key.id, &text).map_err(|why| format!("{name}: {why}"))?;
    Ok(text)
}

/// Whether a name-or-file value is a file: it has a directory part or a `.toml` ending.
fn names_a_file(text: &str) -> bool {
    text.contains('/') || text.contains(std::path::MAIN_SEPARATOR) || text.ends_with(".toml")
}

/// `~/…` in a configuration file means the home directory.
fn expand_home(path: &str) -> Cow<'_, Path> {
    match (path.strip_prefix("~/"), dirs::home_dir()) {
        (Some(rest), Some(home)) => Cow::Owned(home.join(rest)),
        _ => Cow::Borrowed(Path::new(path)),
    }
}

/// Whether the option `id` of `cmd` takes `value`, by the option's own value parser (so a file
/// can never hold what the command line would refuse), and if not, why.
pub(super) fn option_accepts(cmd: &Command, id: &str, value: &str) -> Result<(), String> {
    let arg = cmd
        .get_arguments()
        .find(|a| a.get_id() == id)
        .expect("every configuration key is an option of the shell");
    let long = arg
        .get_long()
        .expect("every configuration key sets a long option");
    let alone = Command::new("tmclsh")
        .no_binary_name(true)
        .arg(arg.clone().required(false).env(None::<&str>));
    let error = match alone.try_get_matches_from([format!("--{long}={value}")]) {
        Ok(_) => return Ok(()),
        Err(error) => error,
    };
    if let Some(source) = std::error::Error::source(&error) {
        return Err(format!("invalid value '{value}': {source}"));
    }
    if let Some(ContextValue::Strings(valid)) = error.get(ContextKind::ValidValue) {
        return Err(format!(
            "invalid value '{value}' (possible values: {})",
            valid.join(", ")
        ));
    }
    Err(format!("invalid value '{value}'"))
}

/// A TOML value's kind in words.
fn describe(value: &DeValue<'_>) -> &'static str {
    match value {
        DeValue::String(_) => "a string",
        DeValue::Integer(_) => "a number",
        DeValue::Float(_) => "a fractional number",
        DeValue::Boolean(_) => "true or false",
        DeValue::Datetime(_) => "a date",
        DeValue::Array(_) => "a list",
        DeValue::Table(_) => "a table",
    }
}

fn line_at(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}
