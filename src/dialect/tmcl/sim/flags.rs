//! The flags of `tmclsh sim` for the simulated TMCL bus: which modules it has (addresses, and
//! each one's profile where it differs from `--profile`), where the switches of each motor are,
//! and the choices the manual leaves open.

use std::path::Path;
use std::str::FromStr;
use std::sync::Arc;

use clap::{ArgMatches, Args, Command, FromArgMatches};

use crate::dialect::SimFlags;
use crate::dialect::tmcl::profile::Profile;
use crate::sim::error::SimStartError;
use crate::sim::store::FileStore;
use crate::sim::{Device, LogSink};

use super::{Backspace, Bus, BusOptions, Eeprom, LineEnd, Quirks, Switch, Switches};
use crate::dialect::tmcl::profile::catalogue;

/// One module of `--modules`: its address, and its profile where it is not the bus's.
#[derive(Debug, Clone)]
pub struct ModuleSpec {
    /// The factory address (1..255).
    pub address: u8,
    /// `N:PROFILE`: a built-in profile name, alias or module number, or a profile file.
    pub profile: Option<Arc<Profile>>,
}

/// `N` or `N:PROFILE`.
fn module_spec(text: &str) -> Result<ModuleSpec, SimStartError> {
    let (address, profile) = match text.split_once(':') {
        Some((a, p)) => (a.trim(), Some(p.trim())),
        None => (text.trim(), None),
    };
    let address = match address.parse::<i64>() {
        Ok(n @ 1..=255) => n as u8,
        Ok(n) => return Err(SimStartError::AddressRange(n)),
        Err(_) => return Err(SimStartError::NotAnAddress(address.to_string())),
    };
    let profile = match profile {
        Some("") => return Err(SimStartError::NoProfile(text.to_string())),
        Some(name) => Some(
            catalogue::resolve(Path::new(name)).map_err(|e| SimStartError::Profile(Box::new(e)))?,
        ),
        None => None,
    };
    Ok(ModuleSpec { address, profile })
}

/// Which modules run their boot loader: `--boot-loader` alone, every one; `--boot-loader=2,3`,
/// those addresses.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BootLoaders {
    /// Every module on the bus.
    All,
    /// The modules at these addresses.
    At(Vec<u8>),
}

/// `all` (the value of a bare `--boot-loader`) or a list of module addresses.
fn boot_loaders(text: &str) -> Result<BootLoaders, SimStartError> {
    if text == "all" {
        return Ok(BootLoaders::All);
    }
    text.split(',')
        .map(|a| match a.trim().parse::<i64>() {
            Ok(n @ 1..=255) => Ok(n as u8),
            _ => Err(SimStartError::BootLoaderAddress {
                word: a.to_string(),
                list: text.to_string(),
            }),
        })
        .collect::<Result<_, _>>()
        .map(BootLoaders::At)
}

/// A switch position for every motor (`POS`) or for one (`MOTOR:POS`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SwitchSpec {
    /// The motor, or `None` for every motor.
    pub motor: Option<u8>,
    /// Where the switch is, in physical microsteps.
    pub position: i64,
}

fn switch_spec(text: &str) -> Result<SwitchSpec, SimStartError> {
    let (motor, position) = match text.split_once(':') {
        Some((m, p)) => {
            let motor = m
                .trim()
                .parse::<u8>()
                .map_err(|_| SimStartError::NotAMotor {
                    word: m.to_string(),
                    spec: text.to_string(),
                })?;
            (Some(motor), p)
        }
        None => (None, text),
    };
    let position = position
        .trim()
        .parse::<i64>()
        .map_err(|_| SimStartError::NotAPosition(position.into()))?;
    Ok(SwitchSpec { motor, position })
}

/// The bus layout.
#[derive(Debug, Clone, clap::Args)]
pub struct BusFlags {
    /// Modules on the simulated RS-485 bus: addresses, each optionally with its own profile
    /// (`1,2` or `1:tmcm-142,2:tmcm-6110`; a module without one is of `--profile`).
    #[arg(long, value_name = "LIST", value_delimiter = ',', default_value = "1", value_parser = module_spec)]
    pub modules: Vec<ModuleSpec>,

    /// The modules run their boot loader: 136 answers with B for V (`6110B131`), every other
    /// command with invalid command; `--boot-loader=2,3` for the modules at those addresses only.
    #[arg(
        long,
        value_name = "ADDRESSES",
        num_args = 0..=1,
        require_equals = true,
        default_missing_value = "all",
        value_parser = boot_loaders
    )]
    pub boot_loader: Option<BootLoaders>,

    /// The modules hear each other's replies, as on a real RS-485 bus: a module whose address
    /// equals the host address (GP 76, 2 by default) takes the others' replies for commands and
    /// answers them. Every module drops a partial binary frame after 5 ms of quiet (the UART
    /// time-out of Trinamic's firmware), shared line or not.
    #[arg(long)]
    pub shared_line: bool,
}

/// The simulated motors' switches and the choices the manual leaves open.
#[derive(Debug, Clone, clap::Args)]
pub struct ModuleFlags {
    /// Position of the left limit switch (microsteps) of every motor, or MOTOR:POS for one motor
    /// (repeatable); not connected by default.
    #[arg(
        long,
        value_name = "[MOTOR:]POS",
        allow_hyphen_values = true,
        action = clap::ArgAction::Append,
        value_parser = switch_spec,
        help_heading = "Switches"
    )]
    pub left_switch: Vec<SwitchSpec>,

    /// Position of the right limit switch, of every motor or MOTOR:POS.
    #[arg(
        long,
        value_name = "[MOTOR:]POS",
        allow_hyphen_values = true,
        action = clap::ArgAction::Append,
        value_parser = switch_spec,
        help_heading = "Switches"
    )]
    pub right_switch: Vec<SwitchSpec>,

    /// Position of the reference (home) switch, active at and right of it; of every motor or
    /// MOTOR:POS.
    #[arg(
        long,
        value_name = "[MOTOR:]POS",
        allow_hyphen_values = true,
        action = clap::ArgAction::Append,
        value_parser = switch_spec,
        help_heading = "Switches"
    )]
    pub home_switch: Vec<SwitchSpec>,

    /// Switch to ASCII mode on command 139 without a binary reply.
    #[arg(long, help_heading = "Choices the manual leaves open")]
    pub no_reply_to_139: bool,

    /// Switch back to binary mode on BIN without an ASCII reply.
    #[arg(long, help_heading = "Choices the manual leaves open")]
    pub no_reply_to_bin: bool,

    /// Answer 139 with invalid command and stay binary, as a module without the ASCII interface
    /// does (for a module whose interface is unconfirmed, such as the TMCM-3110).
    #[arg(long, help_heading = "Choices the manual leaves open")]
    pub no_ascii: bool,

    /// Ending of ASCII replies: none, cr, lf or crlf.
    #[arg(long, value_name = "END", default_value = "cr", value_parser = LineEnd::from_str, help_heading = "Choices the manual leaves open")]
    pub reply_end: LineEnd,

    /// What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character
    /// echo mode).
    #[arg(long, value_name = "END", default_value = "cr", value_parser = LineEnd::from_str, help_heading = "Choices the manual leaves open")]
    pub echo_end: LineEnd,

    /// Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS).
    #[arg(long, value_name = "HOW", default_value = "erase", value_parser = Backspace::from_str, help_heading = "Choices the manual leaves open")]
    pub backspace_echo: Backspace,
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
    let default_bus = matches!(
        bus.modules.as_slice(),
        [ModuleSpec {
            address: 1,
            profile: None
        }]
    );
    [
        (!default_bus, "--modules"),
        (bus.boot_loader.is_some(), "--boot-loader"),
        (bus.shared_line, "--shared-line"),
        (!module.left_switch.is_empty(), "--left-switch"),
        (!module.right_switch.is_empty(), "--right-switch"),
        (!module.home_switch.is_empty(), "--home-switch"),
        (module.no_reply_to_139, "--no-reply-to-139"),
        (module.no_reply_to_bin, "--no-reply-to-bin"),
        (module.no_ascii, "--no-ascii"),
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
) -> Result<Box<dyn Device>, SimStartError> {
    let bus = BusFlags::from_arg_matches(matches)?;
    let module = ModuleFlags::from_arg_matches(matches)?;
    let mut seen = Vec::new();
    for spec in &bus.modules {
        if seen.contains(&spec.address) {
            return Err(SimStartError::Twice(spec.address));
        }
        seen.push(spec.address);
    }
    let module_profiles: Vec<(u8, Arc<Profile>)> = bus
        .modules
        .iter()
        .map(|s| {
            (
                s.address,
                s.profile.clone().unwrap_or_else(|| profile.clone()),
            )
        })
        .collect();
    let boot_loader = match bus.boot_loader {
        None => Vec::new(),
        Some(BootLoaders::All) => seen.clone(),
        Some(BootLoaders::At(addresses)) => {
            if let Some(a) = addresses.iter().find(|a| !seen.contains(a)) {
                return Err(SimStartError::BootLoaderOffBus(*a));
            }
            addresses
        }
    };
    let (switches, motor_switches) = switch_layout(&module, &module_profiles)?;
    let eeprom = match state {
        Some(path) => Some(Eeprom::open(Box::new(FileStore::new(path)))?),
        None => None,
    };
    let log: Option<LogSink> = verbose.then(|| Box::new(|line: &str| eprintln!("sim {line}")) as _);
    let options = BusOptions {
        addresses: seen,
        profiles: module_profiles,
        quirks: Quirks {
            reply_to_139: !module.no_reply_to_139,
            reply_to_bin: !module.no_reply_to_bin,
            reply_end: module.reply_end,
            echo_end: module.echo_end,
            backspace: module.backspace_echo,
            ascii: !module.no_ascii,
        },
        switches,
        motor_switches,
        eeprom,
        boot_loader,
        log,
        shared_line: bus.shared_line,
    };
    Ok(Box::new(Bus::new(profile.clone(), options)))
}

/// One motor's own switch: the motor, which switch, where.
type MotorSwitch = (u8, Switch, i64);

/// The switches of every motor and those of single motors, from the switch flags: a motor's own
/// position wins over the every-motor one, and of the same form the last given; a motor no module
/// on the bus has is refused.
fn switch_layout(
    flags: &ModuleFlags,
    modules: &[(u8, Arc<Profile>)],
) -> Result<(Switches, Vec<MotorSwitch>), SimStartError> {
    let most = modules
        .iter()
        .map(|(_, p)| p.axes.max(1))
        .max()
        .unwrap_or(1);
    let mut every = Switches::default();
    let mut single = Vec::new();
    let given = [
        (Switch::Left, "--left-switch", &flags.left_switch),
        (Switch::Right, "--right-switch", &flags.right_switch),
        (Switch::Home, "--home-switch", &flags.home_switch),
    ];
    for (which, flag, specs) in given {
        for spec in specs {
            match spec.motor {
                None => every.set(which, Some(spec.position)),
                Some(motor) if motor >= most => {
                    return Err(SimStartError::NoMotor {
                        flag,
                        motor,
                        position: spec.position,
                        motors: most,
                    });
                }
                Some(m) => single.push((m, which, spec.position)),
            }
        }
    }
    Ok((every, single))
}
