//! `tmclsh sim`: the simulated module served on a pseudo-terminal or on TCP, with a control
//! console on stdin.

use std::io::{BufRead, Write};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use crate::exit::Exit;
use crate::profile::Profile;
use crate::protocol::Dialect;
use crate::sim::Device;
use crate::sim::clock::{Clock, ManualClock, SystemClock};
use crate::sim::console::{self, Answer, Console};
use crate::sim::fault::{Faults, Faulty};
use crate::sim::inprocess::SharedDevice;
use crate::sim::pacing::Paced;
use crate::sim::tmcl::{Backspace, Bus, BusOptions, FileStore, LineEnd, Quirks, Switches};

use super::Failure;
use super::sim_smd4::Smd4SimArgs;

/// Arguments of `sim`.
#[derive(Debug, clap::Args)]
#[command(after_long_help = console::HELP)]
pub struct SimArgs {
    /// The protocol of the simulated module: a TMCM-142 bus (tmcl) or an SMD4 drive (smd4).
    #[arg(long, value_enum, default_value_t = Dialect::Tmcl)]
    pub protocol: Dialect,

    /// Serve on a new pseudo-terminal (the default); its path is the first line printed.
    #[arg(long, conflicts_with = "listen")]
    pub pty: bool,

    /// Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free
    /// one); the bound address is the first line printed.
    #[arg(long, value_name = "ADDR")]
    pub listen: Option<String>,

    /// Module addresses on the simulated RS-485 bus.
    #[arg(long, value_name = "LIST", value_delimiter = ',', default_value = "1", value_parser = clap::value_parser!(u8).range(1..))]
    pub modules: Vec<u8>,

    /// Pace bytes like a serial line at N baud (10 bits per byte, both directions).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub baud: Option<u32>,

    /// Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts.
    #[arg(long, value_name = "FILE")]
    pub state: Option<PathBuf>,

    /// Log every frame and line received and sent, decoded, to stderr.
    #[arg(long, short)]
    pub verbose: bool,

    /// Let simulation time pass only on the console command `advance` (deterministic tests).
    #[arg(long)]
    pub manual_clock: bool,

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

    /// SMD4 quirk switches.
    #[command(flatten)]
    pub smd4: Smd4SimArgs,
}

fn line_end(text: &str) -> Result<LineEnd, String> {
    text.parse()
}

fn backspace(text: &str) -> Result<Backspace, String> {
    text.parse()
}

fn rate(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|r| (0.0..=1.0).contains(r))
        .ok_or_else(|| format!("'{text}' is not a rate between 0 and 1"))
}

/// The simulated modules on the bus.
fn device(args: &SimArgs, profile: Arc<Profile>) -> Result<Box<dyn Device>, Failure> {
    if args.protocol == Dialect::Smd4 {
        if let Some(flag) = tmcl_only_flag(args) {
            return Err(Failure::new(
                Exit::Refused,
                format!("{flag} applies to the simulated TMCM-142 (--protocol tmcl) only"),
            ));
        }
        return Ok(args.smd4.device(args.state.as_deref(), args.verbose));
    }
    let mut seen = Vec::new();
    for &address in &args.modules {
        if seen.contains(&address) {
            return Err(Failure::new(
                Exit::Refused,
                format!("module address {address} is given twice in --modules"),
            ));
        }
        seen.push(address);
    }
    let store = match &args.state {
        Some(path) => Some(Box::new(
            FileStore::open(path).map_err(|e| Failure::new(Exit::Refused, e.to_string()))?,
        ) as Box<dyn crate::sim::tmcl::StateStore>),
        None => None,
    };
    let log: Option<crate::sim::tmcl::LogSink> = args
        .verbose
        .then(|| Box::new(|line: &str| eprintln!("sim {line}")) as _);
    let options = BusOptions {
        addresses: args.modules.clone(),
        quirks: Quirks {
            reply_to_139: !args.no_reply_to_139,
            reply_to_bin: !args.no_reply_to_bin,
            reply_end: args.reply_end,
            echo_end: args.echo_end,
            backspace: args.backspace_echo,
        },
        switches: Switches {
            left: args.left_switch,
            right: args.right_switch,
            home: args.home_switch,
        },
        store,
        log,
    };
    Ok(Box::new(Bus::new(profile, options)))
}

/// The first flag given that only the TMCL bus understands (the SMD4 would silently ignore it).
fn tmcl_only_flag(args: &SimArgs) -> Option<&'static str> {
    [
        (args.modules != [1], "--modules"),
        (args.left_switch.is_some(), "--left-switch"),
        (args.right_switch.is_some(), "--right-switch"),
        (args.home_switch.is_some(), "--home-switch"),
        (args.no_reply_to_139, "--no-reply-to-139"),
        (args.no_reply_to_bin, "--no-reply-to-bin"),
    ]
    .into_iter()
    .find_map(|(given, flag)| given.then_some(flag))
}

/// Faults and line pacing around any simulated device (faults inside, so replies are judged
/// whole).
fn decorate(device: Box<dyn Device>, args: &SimArgs) -> Box<dyn Device> {
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
    match args.baud {
        Some(baud) => Box::new(Paced::new(device, baud)),
        None => device,
    }
}

/// Runs the simulator until interrupted (or `quit` on the console).
#[cfg(unix)]
pub fn run(args: &SimArgs, profile: Arc<Profile>, out: &mut dyn Write) -> Result<Exit, Failure> {
    use crate::sim::serve::{Server, wake_pair};

    let device: SharedDevice = Arc::new(Mutex::new(decorate(device(args, profile)?, args)));
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
    let console = Console::new(device, clock, manual);
    std::thread::spawn(move || {
        for line in std::io::stdin().lock().lines() {
            let Ok(line) = line else { break };
            let answer = console.run(&line);
            if answer == Answer::Quit {
                std::process::exit(0);
            }
            println!("{}", answer.line());
            waker.wake();
        }
    });
    let result = match listener {
        Some(listener) => server.serve_tcp(&listener),
        None => {
            let mut first = true;
            server.serve_pty(&mut |path| {
                if first {
                    let _ = writeln!(out, "{}", path.display()).and_then(|()| out.flush());
                    first = false;
                } else {
                    println!("pty {}", path.display());
                }
            })
        }
    };
    result.map(|()| Exit::Success).map_err(io_error)
}

/// Serving needs pseudo-terminals and poll(2).
#[cfg(not(unix))]
pub fn run(_: &SimArgs, _: Arc<Profile>, _: &mut dyn Write) -> Result<Exit, Failure> {
    Err(Failure::new(
        Exit::Refused,
        "tmclsh sim serves on Unix-like systems only; use the built-in simulator of the shell",
    ))
}
