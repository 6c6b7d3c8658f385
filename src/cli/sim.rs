//! `tmclsh sim`: the simulated module served on a pseudo-terminal or on TCP, with a control
//! console on stdin.

use std::io::{BufRead, Write};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use clap::{ArgMatches, Args, Command, FromArgMatches};

use crate::clock::{Clock, ManualClock, SystemClock};
use crate::dialect::{
    Configured, Dialect, DialectConfig, SimFlags, all, default_dialect, protocol_parser,
};
use crate::exit::{Exit, Failure};
use crate::link::can::slcan::AckStyle;
use crate::sim::Device;
use crate::sim::console::{self, Answer, Console};
use crate::sim::echo::AdapterEcho;
use crate::sim::fault::{Faults, Faulty};
use crate::sim::inprocess::SharedDevice;
use crate::sim::latency::Latency;
use crate::sim::pacing::Paced;
use crate::sim::slcan::{SlcanAdapter, SlcanOptions};

use super::value::ValueError;

/// Arguments of `sim`.
#[derive(Debug, clap::Args)]
#[command(after_long_help = console_help())]
pub(super) struct SimArgs {
    /// The protocol of the simulated module: a bus of TMCL modules (tmcl) or an SMD4 drive (smd4).
    #[arg(long, value_parser = protocol_parser(), default_value = default_dialect().name)]
    pub protocol: &'static Dialect,

    /// The simulated modules' tables (TMCL).
    #[command(flatten)]
    pub profile: super::profile_option::ProfileOption,

    /// Serve on a new pseudo-terminal (the default); its path is the first line printed.
    #[arg(long, conflicts_with = "listen")]
    pub pty: bool,

    /// Keep the symlink PATH pointed at the current pseudo-terminal, as udev keeps
    /// /dev/serial/by-id names pointed at an adapter: after the console's `unplug` it points at
    /// the new one (and is gone during the outage). An existing file that is not a symlink is
    /// refused.
    #[arg(long, value_name = "PATH", conflicts_with = "listen", value_hint = clap::ValueHint::FilePath)]
    pub link: Option<PathBuf>,

    /// Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free
    /// one); the bound address is the first line printed.
    #[arg(long, value_name = "ADDR")]
    pub listen: Option<String>,

    /// Serve the simulated bus as an slcan (serial-line CAN) adapter: requests and replies are
    /// TMCL's CAN frames (`--can slcan:PATH` on the other side).
    #[arg(long)]
    pub slcan: bool,

    /// How the slcan adapter acknowledges a transmitted frame: z, Z, cr (a bare CR) or none.
    #[arg(long, value_name = "z|Z|cr|none", default_value = "z", value_parser = slcan_ack, requires = "slcan")]
    pub slcan_ack: AckStyle,

    /// Put another node's frame on the CAN bus (a CANopen heartbeat, ID 0x705) before each
    /// reply, as on a bus the modules share with other nodes.
    #[arg(long, requires = "slcan")]
    pub foreign_frames: bool,

    /// The bus layout of the chosen dialect's simulator.
    #[command(flatten)]
    pub bus: SimFlagGroup<BUS>,

    /// Pace bytes like a serial line at N baud (10 bits per byte, both directions).
    // Its own id: the shell's --baud (a port's bit rate) written before `sim` is not this.
    #[arg(long, id = "pace_baud", value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub baud: Option<u32>,

    /// Hold the bytes the simulator sends until MS milliseconds pass or 62 wait, as an FTDI
    /// adapter's latency timer does (16 ms untouched; tmclsh lowers a real one where it can).
    #[arg(long, value_name = "MS", value_parser = clap::value_parser!(u64).range(1..=255))]
    pub latency: Option<u64>,

    /// Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts.
    #[arg(long, value_name = "FILE")]
    pub state: Option<PathBuf>,

    /// Hand every byte the host sends back to it, before the module's answer, as a 2-wire RS-485
    /// adapter without echo suppression does (tmclsh strips it: --local-echo).
    #[arg(long)]
    pub adapter_echo: bool,

    /// Log every frame and line received and sent, decoded, to stderr.
    #[arg(long, short)]
    pub verbose: bool,

    /// Let simulation time pass only on the console command `advance` (deterministic tests).
    #[arg(long)]
    pub manual_clock: bool,

    /// The setup of the chosen dialect's simulated module.
    #[command(flatten)]
    pub module: SimFlagGroup<MODULE>,

    /// Drop replies with this probability (0..1).
    #[arg(long, value_name = "RATE", default_value_t = 0.0, value_parser = rate, help_heading = "Faults")]
    pub drop_rate: f64,

    /// Corrupt one byte of a reply with this probability.
    #[arg(long, value_name = "RATE", default_value_t = 0.0, value_parser = rate, help_heading = "Faults")]
    pub corrupt_rate: f64,

    /// Delay replies with this probability, by --delay-ms.
    #[arg(long, value_name = "RATE", default_value_t = 0.0, value_parser = rate, help_heading = "Faults")]
    pub delay_rate: f64,

    /// How long a delayed reply is held back.
    #[arg(
        long,
        value_name = "MS",
        default_value_t = 500,
        help_heading = "Faults"
    )]
    pub delay_ms: u64,

    /// Answer nothing after N replies (commands still execute).
    #[arg(long, value_name = "N", help_heading = "Faults")]
    pub silent_after: Option<u64>,

    /// Hang up after N replies (pty: a new one appears, its path printed; TCP: the connection
    /// closes and the next client is served).
    #[arg(long, value_name = "N", help_heading = "Faults")]
    pub hangup_after: Option<u64>,

    /// Seed of the fault decisions: the same seed and traffic give the same faults, so a run
    /// replays exactly (also --fault-seed; the console's `seed N` restarts them).
    #[arg(
        long,
        visible_alias = "fault-seed",
        value_name = "N",
        default_value_t = 1,
        help_heading = "Faults"
    )]
    pub seed: u64,

    /// The quirk switches of each dialect's simulator.
    #[command(flatten)]
    pub quirks: SimFlagGroup<QUIRKS>,
}

/// The simulator flags of every dialect in one group of `sim --help` ([`SimFlags`]), kept as
/// parsed for the chosen dialect to read its own.
#[derive(Debug, Clone)]
pub(super) struct SimFlagGroup<const G: u8>(ArgMatches);

const BUS: u8 = 0;
const MODULE: u8 = 1;
const QUIRKS: u8 = 2;

impl<const G: u8> FromArgMatches for SimFlagGroup<G> {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        Ok(SimFlagGroup(matches.clone()))
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        self.0 = matches.clone();
        Ok(())
    }
}

impl<const G: u8> Args for SimFlagGroup<G> {
    fn augment_args(cmd: Command) -> Command {
        let group = match G {
            BUS => SimFlags::Bus,
            MODULE => SimFlags::Module,
            _ => SimFlags::Quirks,
        };
        all().iter().fold(cmd, |cmd, d| (d.sim_flags)(group, cmd))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// The console commands of every dialect's simulator.
fn console_help() -> String {
    console::help(all().iter().map(|d| d.console))
}

fn slcan_ack(text: &str) -> Result<AckStyle, ValueError> {
    AckStyle::parse(text).ok_or_else(|| ValueError::Acknowledgement(text.to_string()))
}

fn rate(text: &str) -> Result<f64, ValueError> {
    text.parse::<f64>()
        .ok()
        .filter(|r| (0.0..=1.0).contains(r))
        .ok_or_else(|| ValueError::Rate(text.to_string()))
}

/// The simulated modules of the chosen dialect, after refusing the flags only another
/// dialect's simulator understands.
fn device(args: &SimArgs, configs: &Configured) -> Result<Box<dyn Device>, Failure> {
    let chosen = args.protocol;
    let flags = &args.bus.0;
    for other in all().iter().filter(|d| !std::ptr::eq(**d, chosen)) {
        if let Some(flag) = (other.sim_flag_given)(flags) {
            return Err(Failure::new(
                Exit::Refused,
                foreign_flag(flag, other, chosen),
            ));
        }
    }
    let served = configs
        .of(chosen)
        .served_simulator(flags, args.state.as_deref(), args.verbose)?;
    Ok(served)
}

/// The refusal of a simulator flag of `owner` given to the simulation of `chosen`: `--no-ascii
/// is a flag of the TMCL simulation (--protocol tmcl); the SMD4 simulation has no such flag`.
fn foreign_flag(flag: &str, owner: &Dialect, chosen: &Dialect) -> String {
    format!(
        "{flag} is a flag of the {} simulation (--protocol {}); the {} simulation has no such \
         flag",
        owner.name.to_uppercase(),
        owner.name,
        chosen.name.to_uppercase()
    )
}

/// Faults, line pacing, an echoing adapter and an adapter's latency timer around any simulated
/// device (faults inside, so replies are judged whole; the echo outside the pacing, so the whole
/// request comes back before anything the module sends, as on a half-duplex bus; the latency
/// timer outermost, holding what the adapter hands the host, echo included).
fn decorate(
    device: Box<dyn Device>,
    args: &SimArgs,
    config: &dyn DialectConfig,
) -> Result<Box<dyn Device>, Failure> {
    let faults = Faults {
        drop_rate: args.drop_rate,
        corrupt_rate: args.corrupt_rate,
        delay_rate: args.delay_rate,
        delay: Duration::from_millis(args.delay_ms),
        silent_after: args.silent_after,
        hangup_after: args.hangup_after,
        seed: args.seed,
    };
    let device: Box<dyn Device> = Box::new(Faulty::new(device, faults));
    // The adapter outside the faults: a dropped reply is a frame that never comes.
    let device: Box<dyn Device> = if args.slcan {
        let bus = config.can_device(device).ok_or_else(|| {
            Failure::new(
                Exit::Refused,
                format!(
                    "--slcan: the {} simulation has no CAN interface",
                    args.protocol.name.to_uppercase()
                ),
            )
        })?;
        let options = SlcanOptions {
            ack: args.slcan_ack,
            foreign: args.foreign_frames,
        };
        Box::new(SlcanAdapter::new(bus, options))
    } else {
        device
    };
    let device: Box<dyn Device> = match args.baud {
        Some(baud) => Box::new(Paced::new(device, baud)),
        None => device,
    };
    let device: Box<dyn Device> = if args.adapter_echo {
        Box::new(AdapterEcho::new(device))
    } else {
        device
    };
    // The adapter's timer sits between the line and the host: outermost.
    Ok(match args.latency {
        Some(ms) => Box::new(Latency::new(device, Duration::from_millis(ms))),
        None => device,
    })
}

/// Runs the simulator until interrupted (or `quit` on the console).
#[cfg(unix)]
pub(super) fn run(
    args: &SimArgs,
    configs: &Configured,
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    use crate::sim::serve::{Server, wake_pair};

    let config = configs.of(args.protocol);
    let device = decorate(device(args, configs)?, args, config)?;
    let device: SharedDevice = Arc::new(Mutex::new(device));
    let manual = args.manual_clock.then(|| Arc::new(ManualClock::new()));
    let clock: Arc<dyn Clock> = match &manual {
        Some(manual) => manual.clone(),
        None => Arc::new(SystemClock::new()),
    };
    let io_error = |e: std::io::Error| Failure::new(Exit::Link, format!("sim: {e}"));
    let (waker, wake) = wake_pair().map_err(io_error)?;
    let verbose = args.verbose;
    let log = Box::new(move |line: &str| {
        if verbose {
            eprintln!("sim: {line}");
        }
    });
    let mut server = Server::new(device.clone(), clock.clone(), wake, log);
    let listener = match &args.listen {
        Some(address) => {
            let listener = std::net::TcpListener::bind(address).map_err(|e| {
                Failure::new(Exit::Link, format!("cannot listen on {address}: {e}"))
            })?;
            let bound = listener.local_addr().map_err(io_error)?;
            writeln!(out, "{bound}")
                .and_then(|()| out.flush())
                .map_err(io_error)?;
            Some(listener)
        }
        None => None,
    };
    // Its `help` names only the commands of the simulator it drives.
    let commands = args.protocol.console;
    let mut console = Console::new(device, clock, manual, commands).with_line(server.line());
    if listener.is_none() {
        console = console.with_unplug(server.unplug_handle());
    }
    std::thread::spawn(move || {
        for line in std::io::stdin().lock().lines() {
            let Ok(line) = line else { break };
            let answer = console.run(&line);
            if answer == Answer::Quit {
                std::process::exit(0);
            }
            crate::stdout::line(&answer.line());
            waker.wake();
        }
    });
    let result = match listener {
        Some(listener) => server.serve_tcp(&listener),
        None => {
            let mut first = true;
            server.serve_pty_linked(args.link.as_deref(), &mut |path| {
                if first {
                    let _ = writeln!(out, "{}", path.display()).and_then(|()| out.flush());
                    first = false;
                } else {
                    crate::stdout::line(&format!("pty {}", path.display()));
                }
            })
        }
    };
    result.map(|()| Exit::Success).map_err(io_error)
}

/// Serving needs pseudo-terminals and poll(2).
#[cfg(not(unix))]
pub fn run(_: &SimArgs, _: &Configured, _: &mut dyn Write) -> Result<Exit, Failure> {
    Err(Failure::new(
        Exit::Refused,
        "tmclsh sim serves on Unix-like systems only; use the built-in simulator of the shell",
    ))
}
