//! `tmclsh [CONNECTION] [-c LINE]...`: the shell — the REPL on a terminal, otherwise the `-c`
//! lines or stdin lines.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use crate::dialect::{Configured, DialectSession, Purpose};
use crate::exit::{Exit, Failure};
use crate::session::interrupt;
use crate::shell::Shell;
use crate::shell::batch::{self, Lines, Output};

use super::connection::{Audience, ModuleArgs};
use super::ports;

/// Flags of the shell itself.
#[derive(Debug, Clone, clap::Args)]
pub struct ShellArgs {
    /// Execute LINE and exit (repeatable; executed in order). Without -c, lines are read from
    /// stdin when it is not a terminal.
    #[arg(short = 'c', value_name = "LINE")]
    pub commands: Vec<String>,
    /// With -c or piped lines: print only each reply's value (TMCL: -5000 of BA 100 -5000;
    /// SMD4: the data items), an empty line for a line that failed.
    #[arg(long, conflicts_with = "json")]
    pub value: bool,
    /// With -c or piped lines: print one JSON object per line (status, value or items, raw
    /// reply, module, exit code).
    #[arg(long)]
    pub json: bool,
    /// With -c or piped lines: go on past a failing line; the exit code is then the worst
    /// failure's (130 before 3 before 1 before 2).
    #[arg(long)]
    pub keep_going: bool,
    /// Which module, and how to talk to it.
    #[command(flatten)]
    pub module: ModuleArgs,
}

/// Runs the shell: the REPL on a terminal, otherwise the `-c` lines or stdin lines.
pub fn run(args: ShellArgs, configs: &Configured) -> Result<Exit, Failure> {
    interrupt::install();
    let interactive = args.commands.is_empty() && std::io::stdin().is_terminal();
    let options = batch::Options {
        output: match (args.value, args.json) {
            (true, _) => Output::Value,
            (_, true) => Output::Json,
            _ => Output::Reply,
        },
        keep_going: args.keep_going,
    };
    if interactive {
        refuse_batch_flags(&args)?;
    }
    let audience = if interactive {
        Audience::Interactive
    } else {
        Audience::Batch
    };
    let session = if interactive {
        match wait_for_port(&args.module)? {
            Waited::GaveUp => return Ok(Exit::Interrupted),
            Waited::No => args.module.open(configs, audience, Purpose::Talk)?,
            Waited::Appeared => open_when_ready(&args.module, configs, audience)?,
        }
    } else {
        args.module.open(configs, audience, Purpose::Talk)?
    };
    let mut shell = Shell::new(session);
    if interactive {
        let banner = banner(&args.module, &shell, configs);
        return Ok(crate::repl::run(&mut shell, &banner));
    }
    let lines = if args.commands.is_empty() {
        Lines::stdin()
    } else {
        Lines::Given(args.commands.into_iter())
    };
    let mut out = crate::stdout::Stdout;
    let mut err = std::io::stderr().lock();
    Ok(batch::run(&mut shell, lines, options, &mut out, &mut err))
}

/// The output flags shape -c and piped lines; the interactive shell has neither.
fn refuse_batch_flags(args: &ShellArgs) -> Result<(), Failure> {
    let given: Vec<&str> = [
        (args.value, "--value"),
        (args.json, "--json"),
        (args.keep_going, "--keep-going"),
    ]
    .into_iter()
    .filter_map(|(set, flag)| set.then_some(flag))
    .collect();
    if given.is_empty() {
        return Ok(());
    }
    Err(Failure::new(
        Exit::Refused,
        format!(
            "{} shape the output of -c and piped lines; the interactive shell shows decoded replies",
            given.join(", ")
        ),
    ))
}

/// How often a missing port is looked for.
const PORT_POLL: Duration = Duration::from_millis(100);

/// How long a port that just appeared may refuse to open: udev sets its owner and mode a moment
/// after the device file appears.
const SETTLING: Duration = Duration::from_secs(2);

/// Whether the REPL had to wait for its port.
enum Waited {
    /// It was there (or the link is not a serial port).
    No,
    /// It appeared.
    Appeared,
    /// Ctrl-C.
    GaveUp,
}

/// The REPL waits for a serial port that is not there (an adapter not plugged in yet, a `usb:`
/// name no adapter answers to), as tio does; Ctrl-C gives up. Runs to an end never wait: they
/// fail at once with exit 3.
fn wait_for_port(module: &ModuleArgs) -> Result<Waited, Failure> {
    let Some(port) = module.chosen_port() else {
        return Ok(Waited::No);
    };
    let present = || ports::present(port).map_err(Failure::from);
    if present()? {
        return Ok(Waited::No);
    }
    crate::stdout::line(&format!("waiting for {port}… (Ctrl-C to give up)"));
    let mut next_look = Instant::now() + PORT_POLL;
    loop {
        if interrupt::take() {
            crate::stdout::line(&format!("gave up waiting for {port}"));
            return Ok(Waited::GaveUp);
        }
        std::thread::sleep(interrupt::SLICE);
        if Instant::now() >= next_look {
            if present()? {
                crate::stdout::line(&format!("{port} is there"));
                return Ok(Waited::Appeared);
            }
            next_look = Instant::now() + PORT_POLL;
        }
    }
}

/// Opens a port that has just appeared, trying again while it settles.
fn open_when_ready(
    module: &ModuleArgs,
    configs: &Configured,
    audience: Audience,
) -> Result<Box<dyn DialectSession>, Failure> {
    let since = Instant::now();
    loop {
        match module.open(configs, audience, Purpose::Talk) {
            Err(failure) if failure.exit == Exit::Link && since.elapsed() < SETTLING => {
                if interrupt::take() {
                    return Err(Failure::new(Exit::Interrupted, "interrupted"));
                }
                std::thread::sleep(PORT_POLL);
            }
            result => return result,
        }
    }
}

/// The first line of the REPL: what the session talks to (TMCL: the module as identified, and
/// the profile), and for the built-in simulator, that it is one.
fn banner(module: &ModuleArgs, shell: &Shell, configs: &Configured) -> String {
    let version = env!("CARGO_PKG_VERSION");
    let talking_to = shell.session_ref().banner();
    if module.is_builtin() {
        let simulated = configs.of(module.protocol()).simulated_module();
        let what = if talking_to == simulated {
            String::new()
        } else {
            format!(": {talking_to}")
        };
        format!(
            "tmclsh {version} — simulated {simulated} (built-in){what} — use --port to talk to hardware"
        )
    } else {
        format!(
            "tmclsh {version} — {talking_to} on {}",
            shell.session_ref().describe()
        )
    }
}
