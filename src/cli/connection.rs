//! Connection and session flags: one group ([`ModuleArgs`]) flattened the same way into the shell
//! and every subcommand that talks to a module, so that `cli::position` can move the ones written
//! before the subcommand behind it and `cli::relevance` can refuse those that would be ignored.

use std::path::PathBuf;
use std::time::Duration;

use clap::{ArgMatches, Args, Command, FromArgMatches};

use crate::dialect::{
    Configured, Dialect, DialectConfig, DialectSession, Opening, Purpose, default_dialect,
    protocol_parser,
};
use crate::exit::{Exit, Failure};
use crate::link::Link;
use crate::link::line::{LineOptions, Modem, Rs485};
use crate::session::transcript::Header;
use crate::session::{LocalEcho, SessionOptions, Transcript};

use super::can::{CanSettings, CanSpec, DEFAULT_BITRATE, DEFAULT_REPLY_ID};
use super::link_kinds::{self, SIM};
use super::target::{Target, is_log_dir, log_file};
use super::value::ValueError;

/// Where the module is: a serial port, a TCP address, or the built-in simulator (`--sim`; the
/// interactive shell's when nothing is given). The kinds of link are listed in `link_kinds`.
#[derive(Debug, Clone, clap::Args)]
pub struct ConnectionArgs {
    /// Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the
    /// interactive shell starts (on the built-in simulated module).
    // Not `conflicts_with = "tcp"`: clap would count TMCLSH_PORT as given and refuse every --tcp
    // while it is set; `relevance` refuses the two on one command line instead.
    #[arg(long, value_name = "PATH", env = "TMCLSH_PORT", value_parser = parse_port)]
    pub port: Option<String>,
    /// Serial bit rate (8N1).
    #[arg(long, value_name = "N", env = "TMCLSH_BAUD", default_value_t = 9600, value_parser = parse_baud)]
    pub baud: u32,
    /// TCP address of the module or of a serial server (HOST:PORT).
    #[arg(long, value_name = "HOST:PORT", env = "TMCLSH_TCP")]
    pub tcp: Option<String>,
    /// CAN adapter of the modules' bus: slcan:PATH (a serial-line CAN adapter: CANable,
    /// USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module's CAN ID is --module.
    #[arg(long, value_name = "slcan:PATH|socketcan:IFACE", env = "TMCLSH_CAN", value_parser = parse_can)]
    pub can: Option<CanSpec>,
    /// The CAN bus's bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN's is set
    /// with `ip link`) [default: 1000000, the modules' default]
    #[arg(long, value_name = "BPS", value_parser = parse_can_bitrate)]
    pub can_bitrate: Option<u32>,
    /// The CAN ID the modules send their replies to (the modules' reply ID setting).
    #[arg(long, value_name = "N", default_value_t = DEFAULT_REPLY_ID, value_parser = clap::value_parser!(u16).range(0..=0x7FF))]
    pub can_reply_id: u16,
    /// Talk to the built-in simulated module: the explicit choice a command run without a
    /// terminal needs, so that no script passes against the simulator by accident.
    #[arg(long)]
    pub sim: bool,
    /// The serial line's settings: modem lines, RS-485, latency timer.
    #[command(flatten)]
    pub line: LineArgs,
}

/// The settings of a serial line (`link::line`).
#[derive(Debug, Clone, clap::Args)]
pub struct LineArgs {
    /// DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that
    /// resets on DTR is not reset by tmclsh starting or ending).
    #[arg(long, value_name = "on|off|keep", env = "TMCLSH_DTR", value_parser = modem)]
    pub dtr: Option<Modem>,
    /// RTS on opening the port: on, off, or keep (as for --dtr).
    #[arg(long, value_name = "on|off|keep", env = "TMCLSH_RTS", value_parser = modem)]
    pub rts: Option<Modem>,
    /// RS-485 direction: RTS high while tmclsh sends, low to receive (the driver's RS-485 mode
    /// where it has one, else tmclsh raises RTS around each write and waits until it has left).
    #[arg(long, env = "TMCLSH_RS485")]
    pub rs485: bool,
    /// RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them
    /// apart); implies --rs485.
    #[arg(long, value_name = "MS", env = "TMCLSH_RS485_DELAY", value_parser = rs485_delay)]
    pub rs485_delay: Option<Rs485>,
    /// Leave an FTDI adapter's latency timer as it is (tmclsh otherwise sets the low-latency
    /// flag, which lowers a 16 ms timer to 1 ms where the driver honours it).
    #[arg(long, env = "TMCLSH_KEEP_LATENCY")]
    pub keep_latency: bool,
}

fn parse_can(text: &str) -> Result<CanSpec, ValueError> {
    CanSpec::parse(text)
}

/// A bit rate slcan has a code for (`S0`…`S8`).
fn parse_can_bitrate(text: &str) -> Result<u32, ValueError> {
    let rates = &crate::link::can::slcan::BITRATES;
    text.trim()
        .parse::<u32>()
        .ok()
        .filter(|bps| rates.contains(bps))
        .ok_or(ValueError::CanBitrate(rates))
}

/// A `--port` value (also `port` in a configuration file, `TMCLSH_PORT`): a device, never a
/// TCP address, which would otherwise be opened as a file of that name.
fn parse_port(text: &str) -> Result<String, ValueError> {
    if looks_like_tcp(text) {
        return Err(ValueError::TcpAsPort(text.to_string()));
    }
    Ok(text.to_string())
}

/// Whether `text` has the shape `HOST:PORT` (a name or IPv4 address, or `[IPv6]`, then a port
/// number), which no device path or `usb:` name has.
fn looks_like_tcp(text: &str) -> bool {
    let Some((host, port)) = text.rsplit_once(':') else {
        return false;
    };
    let bracketed = host.starts_with('[') && host.ends_with(']') && host.len() > 2;
    let named = !host.is_empty()
        && host
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '.' || c == '-' || c == '_');
    !port.is_empty()
        && port.len() <= 5
        && port.chars().all(|c| c.is_ascii_digit())
        && !host.eq_ignore_ascii_case("usb")
        && (bracketed || named)
}

fn modem(text: &str) -> Result<Modem, ValueError> {
    Ok(text.parse::<Modem>()?)
}

fn rs485_delay(text: &str) -> Result<Rs485, ValueError> {
    Ok(Rs485::parse_delay(text)?)
}

impl LineArgs {
    /// The line settings these flags give.
    pub fn options(&self) -> LineOptions {
        LineOptions {
            dtr: self.dtr,
            rts: self.rts,
            rs485: self.rs485_delay.or_else(|| self.rs485.then(Rs485::default)),
            keep_latency: self.keep_latency,
        }
    }
}

/// The bit rates a serial port can be set to: from the slowest teletype rate to the fastest
/// USB adapters'.
pub const BAUD_RANGE: std::ops::RangeInclusive<u32> = 50..=12_000_000;

/// A `--baud` value (also `baud` in a configuration file, `TMCLSH_BAUD`): a whole number in
/// [`BAUD_RANGE`], refused otherwise before anything is opened (0 used to reach the serial link
/// after the module had been put into ASCII mode).
pub(super) fn parse_baud(text: &str) -> Result<u32, ValueError> {
    match text.trim().parse::<u32>() {
        Ok(baud) if BAUD_RANGE.contains(&baud) => Ok(baud),
        _ => Err(ValueError::Baud {
            lowest: *BAUD_RANGE.start(),
            highest: *BAUD_RANGE.end(),
        }),
    }
}

/// A `--reconnect` time: people's times (`30s`, `2m`, a bare number of milliseconds), at most
/// 7 days.
fn parse_wait(text: &str) -> Result<Duration, ValueError> {
    Ok(crate::duration::parse(text.trim())?)
}

/// Which protocol the module speaks: shared by the faces that talk to a module and by `params`.
#[derive(Debug, Clone, clap::Args)]
pub struct DialectArgs {
    /// The protocol the module speaks (also selects the built-in simulated module).
    #[arg(long, value_parser = protocol_parser(), default_value = default_dialect().name, env = "TMCLSH_PROTOCOL")]
    pub protocol: &'static Dialect,
}

/// The command line as given, kept whole for the chosen dialect to read its own options from
/// (SMD4's `--address`, TMCL's `--echo`). It adds no options; flattened first into
/// [`ModuleArgs`], it is taken before the groups after it take their values out.
#[derive(Debug, Clone)]
pub struct CommandLine(ArgMatches);

impl FromArgMatches for CommandLine {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        Ok(CommandLine(matches.clone()))
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        self.0 = matches.clone();
        Ok(())
    }
}

impl Args for CommandLine {
    fn augment_args(cmd: Command) -> Command {
        cmd
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        cmd
    }
}

/// The session flags of every dialect (`--address` …), each dialect's under the help heading it
/// sets; the heading is reset after them, so that a subcommand's own options declared after the
/// group stay under "Options". Their values are read by the dialect from the [`CommandLine`].
#[derive(Debug, Clone)]
pub struct DialectFlags;

impl FromArgMatches for DialectFlags {
    fn from_arg_matches(_: &ArgMatches) -> Result<Self, clap::Error> {
        Ok(DialectFlags)
    }

    fn update_from_arg_matches(&mut self, _: &ArgMatches) -> Result<(), clap::Error> {
        Ok(())
    }
}

impl Args for DialectFlags {
    fn augment_args(cmd: Command) -> Command {
        crate::dialect::all()
            .iter()
            .fold(cmd, |cmd, d| (d.session_flags)(cmd))
            .next_help_heading(None::<&str>)
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// `--timeout` when neither the command line, the environment nor a configuration file sets it.
pub const DEFAULT_TIMEOUT_MS: u64 = 1000;

/// How requests are sent and checked.
#[derive(Debug, Clone, clap::Args)]
pub struct SessionArgs {
    /// Address of the target module (1 = address character A).
    #[arg(long, short = 'm', value_name = "N", env = "TMCLSH_MODULE", default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..=26))]
    pub module: u8,
    /// Milliseconds to wait for a reply before giving up (exit code 3).
    #[arg(long, value_name = "MS", env = "TMCLSH_TIMEOUT", default_value_t = DEFAULT_TIMEOUT_MS, value_parser = clap::value_parser!(u64).range(1..))]
    pub timeout: u64,
    /// Append every byte sent and received, timestamped and decoded, to FILE; given a
    /// directory (or a path ending in /), write a new file there named by device and date.
    #[arg(long, value_name = "FILE", value_hint = clap::ValueHint::AnyPath)]
    pub log: Option<PathBuf>,
    /// Send lines the validator would refuse (still canonicalised where they parse).
    #[arg(long)]
    pub no_validate: bool,
    /// Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo
    /// suppression): on strips exactly those bytes from what comes back, comparing them; auto
    /// (the default) finds out at open and says so; off never strips.
    #[arg(long, value_enum, value_name = "WHEN", env = "TMCLSH_LOCAL_ECHO", num_args = 0..=1, default_value = "auto", default_missing_value = "on")]
    pub local_echo: LocalEchoArg,
    /// Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of
    /// ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always
    /// waits): the port is found again by the name given (a symlink or usb: name follows an
    /// adapter plugged back under another device name); an interrupted read is sent again, a
    /// motion or write never.
    #[arg(long, value_name = "WAIT", env = "TMCLSH_RECONNECT", value_parser = parse_wait)]
    pub reconnect: Option<Duration>,
    /// Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131,
    /// profile tmcm-6110 (built in)).
    // Its own id: `tmclsh sim --verbose` logs traffic, and `-v` before `sim` is not that.
    #[arg(long, short = 'v', id = "say_module")]
    pub verbose: bool,
}

/// `--local-echo`: whether the adapter echoes what is sent.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LocalEchoArg {
    /// Find out at open: the first request that comes straight back, byte for byte.
    Auto,
    /// The adapter echoes: strip it.
    On,
    /// It does not.
    Off,
}

impl From<LocalEchoArg> for LocalEcho {
    fn from(arg: LocalEchoArg) -> LocalEcho {
        match arg {
            LocalEchoArg::Auto => LocalEcho::Auto,
            LocalEchoArg::On => LocalEcho::On,
            LocalEchoArg::Off => LocalEcho::Off,
        }
    }
}

/// How many files of one second a `--log` directory may get.
const LOG_NAMES: u32 = 1000;

impl SessionArgs {
    /// The session options these flags select.
    pub fn options(&self) -> SessionOptions {
        SessionOptions {
            module: self.module,
            timeout: Duration::from_millis(self.timeout),
            validate: !self.no_validate,
            reconnect: self.reconnect,
            local_echo: self.local_echo.into(),
        }
    }

    /// Opens the transcript, if asked for, starting it with `header`; a `--log` directory gets
    /// a new file named by `device` and the date.
    pub fn transcript(&self, header: &Header, device: &str) -> Result<Option<Transcript>, Failure> {
        let Some(path) = self.log.as_deref() else {
            return Ok(None);
        };
        if !is_log_dir(path) {
            return Transcript::open(path, header)
                .map(Some)
                .map_err(Failure::from);
        }
        std::fs::create_dir_all(path).map_err(|e| {
            Failure::new(
                Exit::Refused,
                format!("cannot create the log directory {}: {e}", path.display()),
            )
        })?;
        // A new file, never an existing one: not another session's of the same second, not
        // a symlink planted with the name this one would get.
        let now = std::time::SystemTime::now();
        for n in 1..=LOG_NAMES {
            let file = log_file(path, device, now, n);
            if file.symlink_metadata().is_ok() {
                continue;
            }
            match Transcript::create_new(&file, header) {
                Ok(transcript) => return Ok(Some(transcript)),
                Err(_) if file.symlink_metadata().is_ok() => continue,
                Err(e) => return Err(e.into()),
            }
        }
        Err(Failure::new(
            Exit::Refused,
            format!(
                "cannot start a transcript in {}: {LOG_NAMES} files of this second exist",
                path.display()
            ),
        ))
    }
}

impl ConnectionArgs {
    /// The CAN link `--can` names, with its bus settings.
    fn can_target(&self) -> Target {
        Target::Can {
            spec: self.can.clone().expect("chosen only when given"),
            settings: CanSettings {
                bitrate: self.can_bitrate.unwrap_or(DEFAULT_BITRATE),
                reply_id: self.can_reply_id,
                baud: self.baud,
            },
        }
    }
}

/// Everything that says which module to talk to and how: flattened, the same way, into the shell
/// and every subcommand that opens a session in either dialect.
#[derive(Debug, Clone, clap::Args)]
pub struct ModuleArgs {
    /// The command line as given, for the dialect's own options.
    #[command(flatten)]
    pub command_line: CommandLine,
    /// Where the module is.
    #[command(flatten)]
    pub connection: ConnectionArgs,
    /// The protocol it speaks.
    #[command(flatten)]
    pub dialect: DialectArgs,
    /// The module's tables.
    #[command(flatten)]
    pub profile: super::profile_option::ProfileOption,
    /// How requests are sent and checked.
    #[command(flatten)]
    pub session: SessionArgs,
    /// The settings of each dialect.
    #[command(flatten)]
    pub flags: DialectFlags,
}

/// Who the session is for: a command run without a terminal needs a link chosen (the built-in
/// simulator only by `--sim`), the REPL opens on the simulator when none is, saying so in its
/// banner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Audience {
    /// A command that runs to its end: the notice goes to stderr.
    Batch,
    /// The REPL, whose banner names the simulated module.
    Interactive,
}

impl ModuleArgs {
    /// Whether `--timeout` was set by anyone (the command line, `TMCLSH_TIMEOUT`, a configuration
    /// file), not left at its built-in default.
    pub fn timeout_given(&self) -> bool {
        let source = self.command_line.0.value_source("timeout");
        source != Some(clap::parser::ValueSource::DefaultValue)
            || self.session.timeout != DEFAULT_TIMEOUT_MS
    }

    /// The protocol the module speaks.
    pub fn protocol(&self) -> &'static Dialect {
        self.dialect.protocol
    }

    /// The link chosen (see `link_kinds`): the id of its kind, `sim`, or `None`; exit 2 when
    /// two of one source name different links.
    fn chosen(&self) -> Result<Option<&'static str>, Failure> {
        link_kinds::chosen(&self.command_line.0).map_err(Failure::from)
    }

    /// Whether the built-in simulator answers: chosen, or (for the interactive shell) nothing
    /// else was.
    pub fn is_builtin(&self) -> bool {
        matches!(self.chosen(), Ok(None | Some(SIM)))
    }

    /// The serial port chosen, if a serial port is the link.
    pub fn chosen_port(&self) -> Option<&str> {
        match self.chosen() {
            Ok(Some("port")) => self.connection.port.as_deref(),
            _ => None,
        }
    }

    /// Where the link goes (a `usb:` name resolved to its device file). A command run without
    /// a terminal must be told: with no link chosen it is refused (exit 2), so that no script or
    /// CI job passes against the simulator by accident; the interactive shell opens on it.
    pub fn target(&self, audience: Audience) -> Result<Target, Failure> {
        match self.chosen()? {
            Some(SIM) => Ok(Target::Builtin),
            Some("tcp") => Target::of(None, self.connection.tcp.as_deref()),
            Some("can") => Ok(self.connection.can_target()),
            Some(_) => Target::of(self.connection.port.as_deref(), None),
            None if audience == Audience::Interactive => Ok(Target::Builtin),
            None => Err(Failure::new(Exit::Refused, link_kinds::no_link())),
        }
    }

    /// Opens the transcript (named by the target in a `--log` directory), then the link.
    pub fn connect(
        &self,
        config: &dyn DialectConfig,
        timeout: Duration,
        audience: Audience,
    ) -> Result<(Option<Transcript>, Box<dyn Link>), Failure> {
        let target = self.target(audience)?;
        let device = target.file_name(self.protocol());
        let transcript = self.session.transcript(&config.header(), &device)?;
        let link = self.link_to(&target, config, timeout, audience)?;
        Ok((transcript, link))
    }

    fn link_to(
        &self,
        target: &Target,
        config: &dyn DialectConfig,
        timeout: Duration,
        audience: Audience,
    ) -> Result<Box<dyn Link>, Failure> {
        let link = target.open_line(
            self.connection.baud,
            &self.connection.line.options(),
            config,
            timeout,
        )?;
        if *target == Target::Builtin && audience == Audience::Batch {
            // `sim = true` in a file may be forgotten: it is named.
            let written = self.command_line.0.value_source(SIM)
                == Some(clap::parser::ValueSource::CommandLine);
            let from = if written {
                ""
            } else {
                " (sim = true in a configuration file)"
            };
            eprintln!(
                "tmclsh: using the built-in simulated {}{from}; give {} for hardware",
                config.simulated_module(),
                link_kinds::hardware_flags()
            );
        }
        Ok(link)
    }

    /// Opens a session in the dialect the flags say, for `purpose`.
    pub fn open(
        &self,
        configs: &Configured,
        audience: Audience,
        purpose: Purpose,
    ) -> Result<Box<dyn DialectSession>, Failure> {
        let config = configs.of(self.protocol());
        let options = self.session.options();
        let (transcript, link) = self.connect(config, options.timeout, audience)?;
        let session = config
            .open(Opening {
                link,
                options,
                transcript,
                flags: Some(&self.command_line.0),
                purpose,
            })
            .map_err(Failure::from)?;
        if self.session.verbose && purpose == Purpose::Talk {
            super::diagnose(&session.banner());
        }
        Ok(session)
    }
}
