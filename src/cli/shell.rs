//! `tmclsh [CONNECTION] [-c LINE]...`: the shell — the REPL on a terminal, otherwise the `-c`
//! lines or stdin lines.

use std::io::IsTerminal;
use std::sync::Arc;

use crate::exit::{Exit, ExitStatus};
use crate::profile::Profile;
use crate::session::interrupt;
use crate::session::tmcl::TmclSession;
use crate::shell::Shell;
use crate::shell::batch::{self, Lines};

use super::Failure;
use super::connection::{ConnectionArgs, SessionArgs};

/// Flags of the shell itself.
#[derive(Debug, Clone, clap::Args)]
pub struct ShellArgs {
    /// Where the module is.
    #[command(flatten)]
    pub connection: ConnectionArgs,
    /// How requests are sent and checked.
    #[command(flatten)]
    pub session: SessionArgs,
    /// Execute LINE and exit (repeatable; executed in order). Without -c, lines are read from
    /// stdin when it is not a terminal.
    #[arg(short = 'c', value_name = "LINE")]
    pub commands: Vec<String>,
}

/// Opens a TMCL session as the flags say (shared with `run` and the other subcommands).
pub fn open_session(
    connection: &ConnectionArgs,
    session: &SessionArgs,
    profile: &Arc<Profile>,
) -> Result<TmclSession, Failure> {
    let options = session.options();
    let transcript = session.transcript()?;
    let link = connection.open(profile, options.timeout)?;
    TmclSession::open(link, profile.clone(), options, transcript)
        .map_err(|e| Failure::new(e.exit(), e.to_string()))
}

/// Runs the shell: the REPL on a terminal, otherwise the `-c` lines or stdin lines.
pub fn run(args: ShellArgs, profile: &Arc<Profile>) -> Result<Exit, Failure> {
    interrupt::install();
    let interactive = args.commands.is_empty() && std::io::stdin().is_terminal();
    let session = open_session(&args.connection, &args.session, profile)?;
    let mut shell = Shell::new(session);
    if interactive {
        let banner = banner(&args.connection, &shell, profile);
        return Ok(crate::repl::run(&mut shell, &banner));
    }
    let lines = if args.commands.is_empty() {
        Lines::stdin()
    } else {
        Lines::Given(args.commands.into_iter())
    };
    let mut out = std::io::stdout().lock();
    let mut err = std::io::stderr().lock();
    Ok(batch::run(&mut shell, lines, &mut out, &mut err))
}

fn banner(connection: &ConnectionArgs, shell: &Shell, profile: &Profile) -> String {
    let version = env!("CARGO_PKG_VERSION");
    if connection.is_builtin() {
        format!(
            "tmclsh {version} — simulated {} (built-in) — use --port to talk to hardware",
            profile.module
        )
    } else {
        format!(
            "tmclsh {version} — {} on {}, module {}",
            profile.module,
            shell.session_ref().describe(),
            shell.session_ref().target()
        )
    }
}
