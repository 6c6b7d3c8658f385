//! The flags of `tmclsh sim` for the simulated TMCL bus: which module addresses it has, where its
//! switches are, and the choices the manual leaves open.

use std::path::Path;
use std::sync::Arc;

use clap::{ArgMatches, Args, Command, FromArgMatches};

use crate::dialect::SimFlags;
use crate::dialect::tmcl::profile::Profile;
use crate::sim::store::FileStore;
use crate::sim::{Device, LogSink};

use super::{Backspace, Bus, BusOptions, Eeprom, LineEnd, Quirks, Switches};

/// The bus layout.
#[derive(Debug, Clone, clap::Args)]
pub struct BusFlags {
    /// Module addresses on the simulated RS-485 bus.
    #[arg(long, value_name = "LIST", value_delimiter = ',', default_value = "1", value_parser = clap::value_parser!(u8).range(1..))]
    pub modules: Vec<u8>,
}

/// The simulated module's switches and the choices the manual leaves open.
#[derive(Debug, Clone, clap::Args)]
pub struct ModuleFlags {
    /// Position of the left limit switch (microsteps); not connected by default.
    #[arg(
        long,
        value_name = "POS",
        allow_hyphen_values = true,
        help_heading = "Switches"
    )]
    pub left_switch: Option<i64>,

    /// Position of the right limit switch.
    #[arg(
        long,
        value_name = "POS",
        allow_hyphen_values = true,
        help_heading = "Switches"
    )]
    pub right_switch: Option<i64>,

    /// Position of the reference (home) switch, active at and right of it.
    #[arg(
        long,
        value_name = "POS",
        allow_hyphen_values = true,
        help_heading = "Switches"
    )]
    pub home_switch: Option<i64>,

    /// Switch to ASCII mode on command 139 without a binary reply.
    #[arg(long, help_heading = "Choices the manual leaves open")]
    pub no_reply_to_139: bool,

    /// Switch back to binary mode on BIN without an ASCII reply.
    #[arg(long, help_heading = "Choices the manual leaves open")]
    pub no_reply_to_bin: bool,

    /// Ending of ASCII replies: none, cr, lf or crlf.
    #[arg(long, value_name = "END", default_value = "cr", value_parser = line_end, help_heading = "Choices the manual leaves open")]
    pub reply_end: LineEnd,

    /// What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character
    /// echo mode).
    #[arg(long, value_name = "END", default_value = "cr", value_parser = line_end, help_heading = "Choices the manual leaves open")]
    pub echo_end: LineEnd,

    /// Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS).
    #[arg(long, value_name = "HOW", default_value = "erase", value_parser = backspace, help_heading = "Choices the manual leaves open")]
    pub backspace_echo: Backspace,
}

fn line_end(text: &str) -> Result<LineEnd, String> {
    text.parse()
}

fn backspace(text: &str) -> Result<Backspace, String> {
    text.parse()
}

/// Adds the flags of `group` to `tmclsh sim`.
pub fn add(group: SimFlags, cmd: Command) -> Command {
    match group {
        SimFlags::Bus => BusFlags::augment_args(cmd),
        SimFlags::Module => ModuleFlags::augment_args(cmd),
        SimFlags::Quirks => cmd,
    }
}

/// The first flag given that only the TMCL bus understands (another simulator would silently
/// ignore it).
pub fn given(matches: &ArgMatches) -> Option<&'static str> {
    let (Ok(bus), Ok(module)) = (
        BusFlags::from_arg_matches(matches),
        ModuleFlags::from_arg_matches(matches),
    ) else {
        return None;
    };
    [
        (bus.modules != [1], "--modules"),
        (module.left_switch.is_some(), "--left-switch"),
        (module.right_switch.is_some(), "--right-switch"),
        (module.home_switch.is_some(), "--home-switch"),
        (module.no_reply_to_139, "--no-reply-to-139"),
        (module.no_reply_to_bin, "--no-reply-to-bin"),
    ]
    .into_iter()
    .find_map(|(given, flag)| given.then_some(flag))
}

/// The simulated modules of `profile` on the bus the flags describe; `state` keeps their EEPROM
/// across restarts, `verbose` logs their traffic to stderr.
pub fn served(
    profile: &Arc<Profile>,
    matches: &ArgMatches,
    state: Option<&Path>,
    verbose: bool,
) -> Result<Box<dyn Device>, String> {
    let bus = BusFlags::from_arg_matches(matches).map_err(|e| e.to_string())?;
    let module = ModuleFlags::from_arg_matches(matches).map_err(|e| e.to_string())?;
    let mut seen = Vec::new();
    for &address in &bus.modules {
        if seen.contains(&address) {
            return Err(format!(
                "module address {address} is given twice in --modules"
            ));
        }
        seen.push(address);
    }
    let eeprom = match state {
        Some(path) => {
            Some(Eeprom::open(Box::new(FileStore::new(path))).map_err(|e| e.to_string())?)
        }
        None => None,
    };
    let log: Option<LogSink> = verbose.then(|| Box::new(|line: &str| eprintln!("sim {line}")) as _);
    let options = BusOptions {
        addresses: bus.modules,
        quirks: Quirks {
            reply_to_139: !module.no_reply_to_139,
            reply_to_bin: !module.no_reply_to_bin,
            reply_end: module.reply_end,
            echo_end: module.echo_end,
            backspace: module.backspace_echo,
        },
        switches: Switches {
            left: module.left_switch,
            right: module.right_switch,
            home: module.home_switch,
        },
        eeprom,
        log,
    };
    Ok(Box::new(Bus::new(profile.clone(), options)))
}
