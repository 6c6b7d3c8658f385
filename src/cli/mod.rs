//! The command-line surface (clap derive): one file per subcommand, errors mapped to exit codes.
//! Options may be written before or after the subcommand (`position`); options that would change
//! nothing are refused (`relevance`).

pub mod can;
mod completions;
pub mod config;
pub mod connection;
mod diagnose;
mod install;
mod link_kinds;
pub mod man;
pub(crate) mod params;
mod ports;
mod position;
pub mod profile_option;
mod progress;
mod relevance;
pub mod run;
mod scan;
pub mod shell;
mod sim;
mod snapshot;
mod target;
mod transcript;
pub mod value;

pub(crate) use diagnose::diagnose;

use std::borrow::Cow;
use std::ffi::OsString;
use std::io::Write;
use std::path::PathBuf;

use clap::{FromArgMatches, Parser, Subcommand};

use crate::dialect::Configured;
use crate::dialect::tmcl::{
    self,
    cli::{asm, disasm, download, profiles, upload},
};
use crate::escape::escape_control;
use crate::exit::{Exit, Failure};

/// Terminal and scripting shell for TMCL and SMD4 stepper-motor modules.
#[derive(Debug, Parser)]
#[command(name = "tmclsh", version, about, long_about = None, max_term_width = 100)]
pub struct Cli {
    /// The module profile given to the command that runs (`--profile`, declared by each command
    /// that reads module tables), filled in after parsing.
    #[arg(skip)]
    pub profile: Option<PathBuf>,

    #[command(flatten)]
    shell: shell::ShellArgs,

    #[command(subcommand)]
    command: Option<Command>,

    /// Where `profile` came from when not from the command line, for messages about it.
    #[arg(skip)]
    profile_origin: Option<String>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Print the module's axis and global parameters (those matching FILTER).
    Params(params::ParamsArgs),
    /// List the built-in TMCL module profiles with their sources, or show one in full.
    Profiles(profiles::ProfilesArgs),
    /// List the serial ports of this machine (--probe: and what module answers on each).
    Ports(ports::PortsArgs),
    /// Print a shell completion script.
    Completions(completions::CompletionsArgs),
    /// Print the manual page (roff; man/tmclsh.1 in the source).
    Man(install::ManArgs),
    /// Run a Rhai script against the module (exit code: 0 passed, 1 failed, 2 refused, 3 link).
    Run(run::RunArgs),
    /// Assemble a stand-alone TMCL program (check it, list it, write FILE.bin).
    Asm(asm::AsmArgs),
    /// Turn a program file back into TMCL source.
    Disasm(disasm::DisasmArgs),
    /// Store a program (source or program file) in the module, verify it, optionally run it.
    Download(download::DownloadArgs),
    /// Read the stored program back and print it as source (or write FILE.tmc / FILE.bin).
    Upload(upload::UploadArgs),
    /// Save the module's parameters to a TOML file, compare with one, or write one back.
    Snapshot(snapshot::SnapshotArgs),
    /// Find the modules on the bus, with firmware versions and echo settings.
    Scan(scan::ScanArgs),
    /// Turn a --log transcript into a replayable Rhai script.
    Transcript(transcript::TranscriptArgs),
    /// Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin.
    Sim(sim::SimArgs),
    /// Show the settings in effect (port, baud, protocol, …) and where each comes from: the
    /// command line, the environment, tmclsh.toml, the user's config.toml, or built in.
    Config(config::ConfigArgs),
}

/// Parses the process arguments and runs; returns the exit code.
pub fn main() -> Exit {
    crate::progress::install(Box::new(progress::TerminalProgress));
    // What a broken file holds is left out; `--help` and `--version` (clap's errors here) need
    // none of it.
    let defaults = config::Defaults::load();
    let cli = match parse_with(std::env::args_os().collect(), &defaults) {
        Ok(cli) => cli,
        Err(e) => {
            let use_stderr = e.use_stderr();
            if use_stderr {
                for error in defaults.errors() {
                    diagnose(&format!("configuration refused: {error}"));
                }
            }
            print_usage_error(e);
            return if use_stderr {
                Exit::Refused
            } else {
                Exit::Success
            };
        }
    };
    if !cli.describes_itself() {
        let unknown = config::unknown_variables(&command());
        let said_by_config = matches!(cli.command, Some(Command::Config(_)));
        let warnings = defaults.warnings().iter().filter(|_| !said_by_config);
        for warning in unknown.iter().chain(warnings) {
            diagnose(&format!("warning: {warning}"));
        }
        for error in defaults.errors() {
            diagnose(&format!("configuration refused: {error}"));
        }
        // `config` goes on to show what it could read, and fails after.
        if !said_by_config && !defaults.errors().is_empty() {
            return Exit::Refused;
        }
    }
    let result = run(cli, &mut crate::stdout::Stdout);
    if crate::stdout::closed() {
        // The reader of stdout went away (`| head`): the run ended at that write, quietly, as a
        // Unix tool does; whatever failed on the way out followed from it.
        return crate::stdout::EXIT;
    }
    let exit = match result {
        Ok(exit) => exit,
        Err(failure) => {
            diagnose(&failure.message);
            failure.exit
        }
    };
    signalled(exit)
}

impl Cli {
    /// Whether the command only describes tmclsh itself (completions, the manual page), so
    /// neither the configuration nor the environment is any business of it.
    fn describes_itself(&self) -> bool {
        matches!(
            self.command,
            Some(Command::Completions(_) | Command::Man(_))
        )
    }
}

/// A run SIGTERM or SIGHUP ended (its waits end as for Ctrl-C, its motors stopped on the way)
/// exits 128 + the signal's number, as the shell expects of a process a signal ended.
fn signalled(exit: Exit) -> Exit {
    match (exit, crate::session::interrupt::terminated()) {
        (Exit::Interrupted | Exit::Success, Some(signal)) => {
            // Not `eprintln!`, which panics when a hung-up terminal refuses the line.
            let _ = writeln!(std::io::stderr(), "tmclsh: ended by {}", signal.name());
            Exit::Terminated(signal.number() as u8)
        }
        _ => exit,
    }
}

/// Prints clap's message (an error, or `--help` and `--version`). It quotes arguments and, in
/// help, environment values; when one of those carries a control character, the quoted values are
/// escaped (`\x1B[2J`, visible) and the message is printed without clap's colours, with anything
/// else escaped too, so nothing typed or inherited can act on the terminal.
fn print_usage_error(mut error: clap::Error) {
    use clap::error::ContextValue;
    let hostile = |text: &str| matches!(escape_control(text), Cow::Owned(_));
    let ours = |(name, _): &(OsString, OsString)| name.to_string_lossy().starts_with("TMCLSH_");
    let mut given = std::env::args_os().chain(std::env::vars_os().filter(ours).map(|(_, v)| v));
    // Clap's own styles are SGR sequences; anything else (a configured default shown in help)
    // came from outside.
    let styled = error.render().ansi().to_string();
    if !given.any(|text| hostile(&text.to_string_lossy())) && !hostile(&without_sgr(&styled)) {
        let _ = error.print();
        return;
    }
    let escape = |text: &String| escape_control(text).into_owned();
    let escaped: Vec<_> = error
        .context()
        .filter_map(|(kind, value)| match value {
            ContextValue::String(text) if hostile(text) => {
                Some((kind, ContextValue::String(escape(text))))
            }
            ContextValue::Strings(texts) if texts.iter().any(|t| hostile(t)) => Some((
                kind,
                ContextValue::Strings(texts.iter().map(escape).collect()),
            )),
            _ => None,
        })
        .collect();
    for (kind, value) in escaped {
        error.insert(kind, value);
    }
    // Rendered plain: clap's styles (and any sequence left in a message) stripped, then escaped.
    let text = escape_control(&error.render().to_string()).into_owned();
    let _ = if error.use_stderr() {
        std::io::stderr().write_all(text.as_bytes())
    } else {
        std::io::stdout().write_all(text.as_bytes())
    };
}

/// `text` without its SGR sequences (`ESC [ digits and semicolons m`), the only ones clap writes.
fn without_sgr(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find("\x1b[") {
        out.push_str(&rest[..at]);
        let after = &rest[at + 2..];
        let end = after.find(|c: char| !(c.is_ascii_digit() || c == ';'));
        match end {
            Some(end) if after[end..].starts_with('m') => rest = &after[end + 1..],
            _ => {
                out.push('\x1b');
                rest = &rest[at + 1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// Parses a command line (program name first) without configuration files.
pub fn parse(argv: Vec<OsString>) -> Result<Cli, clap::Error> {
    parse_with(argv, &config::Defaults::none())
}

/// Parses a command line (program name first) over the defaults of the configuration files:
/// options written before the subcommand are handed to it, and options given on the command line
/// that it has no use for are refused.
pub fn parse_with(argv: Vec<OsString>, defaults: &config::Defaults) -> Result<Cli, clap::Error> {
    let mut cmd = config::apply_environment(defaults.apply(command()))?;
    let first = cmd.try_get_matches_from_mut(argv.clone())?;
    let argv = position::behind_subcommand(&mut cmd, &first, argv)?;
    let matches = cmd.try_get_matches_from_mut(argv)?;
    relevance::check(&mut cmd, &matches)?;
    let mut cli = Cli::from_arg_matches(&matches)?;
    cli.profile = profile_option::given(position::leaf_matches(&matches));
    cli.profile_origin = config::origin_of(&matches, "profile", defaults);
    if let Some(Command::Config(args)) = &mut cli.command {
        config::explain(args, &matches, defaults);
    }
    Ok(cli)
}

/// Runs a parsed command line, printing results to `out`.
pub fn run(cli: Cli, out: &mut dyn Write) -> Result<Exit, Failure> {
    if let Some(Command::Profiles(args)) = &cli.command {
        return profiles::run(args, out); // the built-in catalogue: no profile to load
    }
    let configs = Configured::load(cli.profile.as_deref()).map_err(|message| {
        let message = match &cli.profile_origin {
            Some(origin) => format!("{origin}: {message}"),
            None => message.to_string(),
        };
        Failure::new(Exit::Refused, message)
    })?;
    let result = match cli.command {
        Some(Command::Params(args)) if args.values => {
            return params::read_values(&args, &configs, out);
        }
        Some(Command::Params(args)) => return Ok(params::run(&args, &configs, out)?),
        Some(Command::Ports(args)) => ports::run(&args, &configs, out),
        Some(Command::Profiles(_)) => unreachable!("listed before the profile is loaded"),
        Some(Command::Completions(args)) if args.install => {
            return install::completions(args.shell, out);
        }
        Some(Command::Completions(args)) => completions::run(&args, out),
        Some(Command::Man(args)) => return install::man(&args, out),
        Some(Command::Run(args)) => return run::run(args, &configs),
        Some(Command::Asm(args)) => return asm::run(&args, tmcl::cli::profile(&configs), out),
        Some(Command::Disasm(args)) => {
            return disasm::run(&args, tmcl::cli::profile(&configs), out);
        }
        Some(Command::Download(args)) => return download::run(args, &configs, out),
        Some(Command::Upload(args)) => return upload::run(args, &configs, out),
        Some(Command::Snapshot(args)) => return snapshot::run(args, &configs, out),
        Some(Command::Scan(args)) => return scan::run(args, &configs, out),
        Some(Command::Transcript(args)) => return transcript::run(args, &configs, out),
        Some(Command::Sim(args)) => return sim::run(&args, &configs, out),
        Some(Command::Config(args)) => return Ok(config::run(&args, out)?),
        None => return shell::run(cli.shell, &configs),
    };
    result?;
    Ok(Exit::Success)
}

/// The clap command, for completions and docs.
pub fn command() -> clap::Command {
    relevance::hide_unused(<Cli as clap::CommandFactory>::command())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_sgr_sequences_are_taken_for_clap_s_own() {
        assert_eq!(without_sgr("\x1b[1m\x1b[31merror:\x1b[0m x"), "error: x");
        assert_eq!(without_sgr("a\x1b]0;t\x07b"), "a\x1b]0;t\x07b");
        assert_eq!(without_sgr("a\x1b[2Jb\x1b["), "a\x1b[2Jb\x1b[");
    }
}
