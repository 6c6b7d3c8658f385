//! Defaults that stick: a user file (`$XDG_CONFIG_HOME/tmclsh/config.toml`, else
//! `~/.config/tmclsh/config.toml`) and a project file (`tmclsh.toml` in the working directory or
//! the nearest one above it) give the link (port, tcp, or sim), baud, protocol, profile, module,
//! timeout, echo, a log directory and the serial line's settings (dtr, rts, rs485, rs485_delay,
//! keep_latency). Precedence: command line > environment > project > user > built-in; a project
//! file that names a link replaces the user's link whole.
//!
//! A broken file cannot lock anyone out: `--help`, `--version`, `completions`, `man` run
//! whatever it holds, and `tmclsh config` shows what it could read with the errors; every other
//! command is refused (exit 2).
//!
//! A file's values become the defaults of the options (clap then ranks them below the command
//! line and the environment by itself), so they count wherever the option does and, like
//! environment values, are never refused where the option has no use (`cli::relevance` refuses
//! only what was written on the command line): a configured port does not bother `tmclsh asm`.
//! `tmclsh config` shows every value and where it came from.

mod env;
mod file;
mod json;

use std::io::{self, Write};
use std::path::PathBuf;

use clap::parser::ValueSource;
use clap::{ArgMatches, Command};

use crate::dialect::Dialect;
use crate::exit::Exit;

pub use file::Scope;
use file::{Entry, Parsed, Read, project_file, user_file};

pub(super) use env::apply as apply_environment;
pub(super) use env::unknown as unknown_variables;

use super::connection::ModuleArgs;
use super::link_kinds;
use super::position::leaf_matches;

/// What a key's value is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Text, as the option takes it.
    Text,
    /// A whole number.
    Integer,
    /// A file (relative to the configuration file's directory).
    Path,
    /// A built-in name, kept as written, or — with a directory part or a `.toml` ending — a file
    /// as for [`Kind::Path`] (`profile = "tmcm-6110"`, `profile = "rig/my.toml"`).
    NameOrPath,
    /// A directory (relative to the configuration file's directory).
    Dir,
    /// `true` or `false`, for a flag (`rs485 = true` is `--rs485`).
    Bool,
}

/// A key of the configuration files and the option it sets.
#[derive(Debug)]
pub struct Key {
    /// The key in the file.
    pub name: &'static str,
    /// The id of the option it sets.
    pub id: &'static str,
    /// What its value is.
    pub kind: Kind,
    /// An example, for messages.
    pub example: &'static str,
    /// What it means when nothing sets it.
    pub unset: &'static str,
}

/// A key that sets the option of its own name.
const fn key(name: &'static str, kind: Kind, example: &'static str, unset: &'static str) -> Key {
    Key {
        name,
        id: name,
        kind,
        example,
        unset,
    }
}

/// Every key, in the order `tmclsh config` shows them.
pub const KEYS: &[Key] = &[
    key(
        "port",
        Kind::Text,
        "port = \"/dev/ttyUSB0\" or \"usb:0403:6001\"",
        "no serial port",
    ),
    key(
        "tcp",
        Kind::Text,
        "tcp = \"192.168.1.20:4001\"",
        "no TCP link",
    ),
    key(
        "can",
        Kind::Text,
        "can = \"slcan:/dev/ttyACM0\" or \"socketcan:can0\"",
        "no CAN link",
    ),
    key("sim", Kind::Bool, "sim = true", ""),
    key("baud", Kind::Integer, "baud = 115200", ""),
    key("protocol", Kind::Text, "protocol = \"smd4\"", ""),
    key(
        "profile",
        Kind::NameOrPath,
        "profile = \"tmcm-1140\" or \"profiles/my-module.toml\"",
        "the built-in TMCM-142 tables",
    ),
    key("module", Kind::Integer, "module = 2", ""),
    key("timeout", Kind::Integer, "milliseconds, timeout = 500", ""),
    key(
        "reconnect",
        Kind::Text,
        "reconnect = \"30s\"",
        "a lost link ends a run that is not interactive (exit 3)",
    ),
    key(
        "echo",
        Kind::Text,
        "echo = \"line\"",
        "each module's echo as found",
    ),
    key(
        "local_echo",
        Kind::Text,
        "local_echo = \"on\" (or \"off\", \"auto\")",
        "",
    ),
    Key {
        name: "log_dir",
        id: "log",
        kind: Kind::Dir,
        example: "log_dir = \"logs\"",
        unset: "no transcript",
    },
    key(
        "dtr",
        Kind::Text,
        "dtr = \"off\" (on, off or keep)",
        "as opening the port sets it",
    ),
    key(
        "rts",
        Kind::Text,
        "rts = \"keep\" (on, off or keep)",
        "as opening the port sets it",
    ),
    key("rs485", Kind::Bool, "rs485 = true", ""),
    key(
        "rs485_delay",
        Kind::Text,
        "milliseconds, rs485_delay = \"1\" or \"1,2\"",
        "no delays (RS-485 only when rs485 = true)",
    ),
    key("keep_latency", Kind::Bool, "keep_latency = true", ""),
];

/// The values of the configuration files that apply, the project's over the user's.
#[derive(Debug, Default, Clone)]
pub struct Defaults {
    entries: Vec<Entry>,
    /// The user's file (whether or not it exists).
    user: Option<PathBuf>,
    /// The project's file, if one was found.
    project: Option<PathBuf>,
    /// Where the project file was looked for.
    searched_from: Option<PathBuf>,
    /// The project file found and not used, and why.
    ignored: Option<(PathBuf, String)>,
    /// Unknown keys, named with the nearest known one.
    warnings: Vec<String>,
    /// What could not be read or was refused, with file and line: only `--help`, `--version`,
    /// `completions`, `man` and `config` run while there is any.
    errors: Vec<String>,
}

impl Defaults {
    /// No configuration files (the built-in defaults only).
    pub fn none() -> Defaults {
        Defaults::default()
    }

    /// Reads the user's and the project's files, keeping what checks out: an unknown key is a
    /// warning, a bad value or a file that cannot be read an error naming the file (and line).
    /// A project file that is not trusted (another user's, or writable by others) is ignored
    /// with a note on stderr.
    pub fn load() -> Defaults {
        let cwd = std::env::current_dir().ok();
        let user = user_file();
        let mut project = cwd.as_deref().and_then(project_file);
        let cmd = super::command();
        let mut entries = Vec::new();
        let mut ignored = None;
        let mut warnings = Vec::new();
        let mut errors = Vec::new();
        let mut take = |parsed: Parsed, entries: &mut Vec<Entry>| {
            warnings.extend(parsed.warnings);
            errors.extend(parsed.errors);
            let overridden = |e: &Entry| {
                entries.iter().any(|p: &Entry| {
                    p.key.name == e.key.name
                        || (link_kinds::is_link_key(p.key.name)
                            && link_kinds::is_link_key(e.key.name))
                })
            };
            let kept: Vec<Entry> = parsed
                .entries
                .into_iter()
                .filter(|e| !overridden(e))
                .collect();
            entries.extend(kept);
        };
        if let Some(path) = project.clone() {
            match file::read(&path, Scope::Project, &cmd) {
                Ok(Read::Entries(parsed)) => take(parsed, &mut entries),
                Ok(Read::Ignored(why)) => {
                    super::diagnose(&format!(
                        "ignored {}: {why}; a tmclsh.toml must be yours and writable only \
                         by you (chown it, or chmod go-w)",
                        path.display()
                    ));
                    ignored = Some((path, why));
                    project = None;
                }
                Err(why) => take(unreadable(why), &mut entries),
            }
        }
        // Anything at the user's path is read, so a directory or a FIFO there is named.
        if let Some(path) = user.as_deref().filter(|p| p.symlink_metadata().is_ok()) {
            match file::read(path, Scope::User, &cmd) {
                Ok(Read::Entries(parsed)) => take(parsed, &mut entries),
                Ok(Read::Ignored(_)) => unreachable!("only project files are ignored"),
                Err(why) => take(unreadable(why), &mut entries),
            }
        }
        Defaults {
            entries,
            user,
            project,
            searched_from: cwd,
            ignored,
            warnings,
            errors,
        }
    }

    /// The unknown keys, each named with the nearest known one.
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// What was refused, with file and line; empty when the files are sound.
    pub fn errors(&self) -> &[String] {
        &self.errors
    }

    /// The value `key` gets from a file, if any.
    fn entry(&self, key: &Key) -> Option<&Entry> {
        self.entries.iter().find(|e| e.key.name == key.name)
    }

    /// Makes the files' values the defaults of the options of `cmd` and its subcommands, except
    /// `sim`, whose options of the same names are the simulator's own (`--profile` reaches it too).
    pub fn apply(&self, cmd: Command) -> Command {
        let mut cmd = cmd;
        for entry in &self.entries {
            cmd = set_default(cmd, entry.key.id, &entry.value);
        }
        cmd
    }
}

/// A file that could not be read at all.
fn unreadable(why: file::Unreadable) -> Parsed {
    Parsed {
        errors: vec![why.to_string()],
        ..Parsed::default()
    }
}

fn set_default(cmd: Command, id: &'static str, value: &str) -> Command {
    let has = cmd.get_arguments().any(|a| a.get_id() == id);
    let cmd = if has {
        let value = value.to_string();
        cmd.mut_arg(id, |a| a.default_value(value))
    } else {
        cmd
    };
    cmd.mut_subcommands(|sub| {
        // `--profile` means the same to the simulator: the modules it simulates.
        if sub.get_name() == "sim" && id != super::profile_option::ID {
            sub
        } else {
            set_default(sub, id, value)
        }
    })
}

/// Arguments of `config`: the options whose values it shows, so that `tmclsh config --port X`
/// shows what `--port X` would do to the rest.
#[derive(Debug, Clone, clap::Args)]
pub struct ConfigArgs {
    // Parsed so that every option is accepted here; the report reads their values and sources
    // from the matches, which know where each came from.
    #[allow(dead_code)]
    #[command(flatten)]
    module: ModuleArgs,
    /// Print one JSON document instead (fields in docs/machine-output.md).
    #[arg(long)]
    json: bool,
    /// Filled in after parsing: every value and where it came from.
    #[arg(skip)]
    report: Vec<Line>,
    /// Filled in after parsing: the files read.
    #[arg(skip)]
    defaults: Option<Defaults>,
    /// Filled in after parsing: where the link goes, and by which setting.
    #[arg(skip)]
    link: String,
}

/// One line of `tmclsh config`.
#[derive(Debug, Clone)]
struct Line {
    key: &'static Key,
    /// The value in TOML, if any.
    value: Option<String>,
    /// Where it came from.
    origin: String,
    /// Why it has no effect, if it has none: another setting wins (`--tcp` over a port), or the
    /// option belongs to the other dialect (a TMCL `profile` under `--protocol smd4`).
    unused: Option<String>,
}

/// Where the value of `key` in `leaf` came from: "command line", "environment TMCLSH_PORT",
/// "project /home/me/rig/tmclsh.toml:1", "built-in".
fn origin(leaf: &ArgMatches, key: &Key, defaults: &Defaults) -> String {
    match leaf.value_source(key.id) {
        Some(ValueSource::CommandLine) => "command line".to_string(),
        Some(ValueSource::EnvVariable) => {
            let cmd = super::command();
            let var = cmd
                .get_arguments()
                .find(|a| a.get_id() == key.id)
                .and_then(|a| a.get_env())
                .map(|v| v.to_string_lossy().into_owned())
                .unwrap_or_default();
            format!("environment {var}")
        }
        Some(ValueSource::DefaultValue) => match defaults.entry(key) {
            Some(e) => format!("{} {}:{}", e.scope.name(), e.file.display(), e.line),
            None => "built-in".to_string(),
        },
        _ => "built-in".to_string(),
    }
}

/// Where the value of the option `id` came from when not from the command line (so a message
/// about it can say: `environment TMCLSH_PROFILE`, `project FILE:LINE`), else `None`.
pub fn origin_of(matches: &ArgMatches, id: &str, defaults: &Defaults) -> Option<String> {
    let key = KEYS.iter().find(|k| k.id == id)?;
    let leaf = leaf_matches(matches);
    let leaf = if leaf.try_contains_id(id).unwrap_or(false) {
        leaf
    } else {
        matches
    };
    match origin(leaf, key, defaults).as_str() {
        "command line" | "built-in" => None,
        other => Some(other.to_string()),
    }
}

/// A setting as its source writes it, for saying which one wins: `--tcp 127.0.0.1:4001`,
/// `TMCLSH_TCP=127.0.0.1:4001`, `sim = true (project FILE:LINE)`.
fn setting(leaf: &ArgMatches, key: &Key, defaults: &Defaults) -> String {
    let value = leaf
        .get_raw(key.id)
        .and_then(|mut v| v.next())
        .map(|v| crate::escape::escape_control(&v.to_string_lossy()).into_owned())
        .unwrap_or_default();
    let flag = key.kind == Kind::Bool;
    match leaf.value_source(key.id) {
        Some(ValueSource::CommandLine) if flag => format!("--{}", key.name),
        Some(ValueSource::CommandLine) => format!("--{} {value}", key.name),
        Some(ValueSource::EnvVariable) => {
            let origin = origin(leaf, key, defaults);
            let var = origin.trim_start_matches("environment ");
            format!("{var}={value}")
        }
        _ if flag => format!("{} = {value} ({})", key.name, origin(leaf, key, defaults)),
        _ => format!(
            "{} = \"{value}\" ({})",
            key.name,
            origin(leaf, key, defaults)
        ),
    }
}

/// Fills in the report of a parsed `tmclsh config` from its matches.
pub fn explain(args: &mut ConfigArgs, matches: &ArgMatches, defaults: &Defaults) {
    let leaf = leaf_matches(matches);
    let chosen = link_kinds::chosen(leaf);
    let winner = chosen.as_ref().ok().copied().flatten();
    let dialect = leaf.get_one::<&'static Dialect>("protocol").copied();
    let winning = winner.and_then(|id| KEYS.iter().find(|k| k.id == id));
    let unused = |key: &Key| -> Option<String> {
        if let Some(win) = winning.filter(|w| w.id != key.id) {
            let setting = setting(leaf, win, defaults);
            if link_kinds::is_link_key(key.id) {
                return Some(format!("{setting} wins"));
            }
            if key.id == "baud" && win.id != "port" {
                return Some(format!("the link is not a serial port: {setting}"));
            }
        }
        let dialect = dialect?;
        let owner = crate::dialect::all()
            .iter()
            .find(|d| d.owned_options().iter().any(|id| id == key.id))?;
        (owner.name != dialect.name).then(|| {
            format!(
                "{} only; the protocol is {}",
                owner.name.to_uppercase(),
                dialect.name
            )
        })
    };
    args.link = match (&chosen, winning) {
        (Err(why), _) => format!("refused: {why}"),
        (Ok(_), Some(key)) => {
            let origin = origin(leaf, key, defaults);
            let value = |id: &str| {
                leaf.get_one::<String>(id)
                    .map(|v| crate::escape::escape_control(v).into_owned())
                    .unwrap_or_default()
            };
            match key.id {
                link_kinds::SIM => format!("the built-in simulator ({origin})"),
                "tcp" => format!("TCP {} ({origin})", value("tcp")),
                id => format!("{id} {} ({origin})", value(id)),
            }
        }
        (Ok(_), None) => "none: commands run without a terminal are refused; the interactive \
                          shell opens on the built-in simulator"
            .to_string(),
    };
    args.report = KEYS
        .iter()
        .map(|key| {
            let raw: Option<String> = leaf
                .try_get_raw(key.id)
                .ok()
                .flatten()
                .and_then(|mut values| values.next())
                .map(|v| v.to_string_lossy().into_owned());
            let origin = origin(leaf, key, defaults);
            let value = raw.map(|raw| match key.kind {
                Kind::Integer | Kind::Bool => raw,
                _ => toml::Value::String(raw).to_string(),
            });
            // `sim = false` is as good as unset: it never outranks a link.
            let set = value.as_deref().is_some_and(|v| v != "false");
            let unused = set.then(|| unused(key)).flatten();
            Line {
                key,
                value,
                origin,
                unused,
            }
        })
        .collect();
    args.defaults = Some(defaults.clone());
}

/// Prints every value and where it came from, as TOML a file could hold.
pub fn run(args: &ConfigArgs, out: &mut dyn Write) -> io::Result<Exit> {
    let defaults = args.defaults.clone().unwrap_or_default();
    if args.json {
        return json::write(args, &defaults, out).map(|()| Exit::Success);
    }
    writeln!(
        out,
        "# precedence: command line > environment > project file > user file > built-in"
    )?;
    match (
        &defaults.project,
        &defaults.ignored,
        &defaults.searched_from,
    ) {
        (Some(path), _, _) => writeln!(out, "# project file: {}", path.display())?,
        (None, Some((path, why)), _) => writeln!(
            out,
            "# project file: none ({} ignored: {why})",
            path.display()
        )?,
        (None, None, Some(dir)) => writeln!(
            out,
            "# project file: none (no tmclsh.toml in {} or above)",
            dir.display()
        )?,
        (None, None, None) => writeln!(out, "# project file: none")?,
    }
    for error in &defaults.errors {
        writeln!(out, "# error: {error}")?;
    }
    for warning in &defaults.warnings {
        writeln!(out, "# warning: {warning}")?;
    }
    match &defaults.user {
        Some(path) if path.is_file() => writeln!(out, "# user file: {}", path.display())?,
        Some(path) => match crate::file::describe_path(path).as_str() {
            "missing" => writeln!(out, "# user file: none ({} does not exist)", path.display())?,
            what => writeln!(out, "# user file: none ({} is {what})", path.display())?,
        },
        None => writeln!(out, "# user file: none (no home directory)")?,
    }
    let width = args
        .report
        .iter()
        .filter_map(|l| l.value.as_ref().map(|v| l.key.name.len() + 3 + v.len()))
        .max()
        .unwrap_or(0);
    for line in &args.report {
        match &line.value {
            Some(value) => {
                let setting = format!("{} = {value}", line.key.name);
                match &line.unused {
                    None => writeln!(out, "{setting:<width$}  # {}", line.origin)?,
                    Some(why) => writeln!(out, "# {setting} ({}) is not used: {why}", line.origin)?,
                }
            }
            None => writeln!(out, "# {} is not set: {}", line.key.name, line.key.unset)?,
        }
    }
    writeln!(out, "# link: {}", args.link)?;
    // A broken file fails `config` too, so a script checking the set-up notices.
    Ok(if defaults.errors.is_empty() {
        Exit::Success
    } else {
        Exit::Refused
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_sets_a_long_option_of_the_shell() {
        let cmd = super::super::command();
        for key in KEYS {
            let arg = cmd
                .get_arguments()
                .find(|a| a.get_id() == key.id)
                .unwrap_or_else(|| panic!("{} sets no option", key.name));
            assert!(arg.get_long().is_some(), "{}", key.name);
            let flag = matches!(arg.get_action(), clap::ArgAction::SetTrue);
            assert_eq!(flag, key.kind == Kind::Bool, "{}", key.name);
            assert!(flag || arg.get_action().takes_values(), "{}", key.name);
        }
    }

    #[test]
    fn defaults_reach_nested_subcommands_but_not_the_simulator() {
        let place = std::env::temp_dir().join(format!("tmclsh-config-unit-{}", std::process::id()));
        std::fs::create_dir_all(&place).unwrap();
        let file = place.join("tmclsh.toml");
        std::fs::write(&file, "baud = 300\nprotocol = \"smd4\"\n").unwrap();
        let cmd = super::super::command();
        let Ok(file::Read::Entries(parsed)) = file::read(&file, Scope::Project, &cmd) else {
            panic!("the file is read");
        };
        let defaults = Defaults {
            entries: parsed.entries,
            ..Defaults::none()
        };
        let applied = defaults.apply(cmd);
        let default_of = |path: &[&str], id: &str| {
            let sub = path
                .iter()
                .try_fold(&applied, |c, name| c.find_subcommand(name))
                .unwrap();
            sub.get_arguments()
                .find(|a| a.get_id() == id)
                .map(|a| a.get_default_values().to_vec())
        };
        assert_eq!(default_of(&[], "baud").unwrap(), ["300"]);
        assert_eq!(default_of(&["snapshot", "save"], "baud").unwrap(), ["300"]);
        assert_eq!(default_of(&["params"], "protocol").unwrap(), ["smd4"]);
        assert_eq!(default_of(&["sim"], "protocol").unwrap(), ["tmcl"]);
        std::fs::remove_dir_all(&place).unwrap();
    }
}
