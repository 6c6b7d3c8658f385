//! `tmclsh [CONNECTION] [-c LINE]...`: the shell — the REPL on a terminal, otherwise the `-c`
//! lines or stdin lines.

use std::io::IsTerminal;
use std::sync::Arc;

use crate::exit::{Exit, ExitStatus};
use crate::profile::Profile;
use crate::protocol::Dialect;
use crate::session::Session;
use crate::session::interrupt;
use crate::session::smd4::Smd4Session;
use crate::session::tmcl::TmclSession;
use crate::shell::Shell;
use crate::shell::batch::{self, Lines};

use super::Failure;
use super::connection::{ConnectionArgs, SessionArgs, Smd4Args};

/// Flags of the shell itself.
#[derive(Debug, Clone, clap::Args)]
pub struct ShellArgs {
    /// Where the module is.
    #[command(flatten)]
    pub connection: ConnectionArgs,
    /// How requests are sent and checked.
    #[command(flatten)]
    pub session: SessionArgs,
    /// SMD4 settings.
    #[command(flatten)]
    pub smd4: Smd4Args,
    /// Execute LINE and exit (repeatable; executed in order). Without -c, lines are read from
    /// stdin when it is not a terminal.
    #[arg(short = 'c', value_name = "LINE")]
    pub commands: Vec<String>,
}

/// Opens a session in the dialect the flags say (shared with `run` and the other subcommands).
pub fn open_session(
    connection: &ConnectionArgs,
    session: &SessionArgs,
    smd4: &Smd4Args,
    profile: &Arc<Profile>,
) -> Result<Session, Failure> {
    let options = session.options();
    let transcript = session.transcript()?;
    let link = connection.open(profile, options.timeout)?;
    let failure = |e: crate::session::SessionError| Failure::new(e.exit(), e.to_string());
    match connection.protocol {
        Dialect::Tmcl => {
            TmclSession::open(link, profile.clone(), options, transcript).map(Session::Tmcl)
        }
        Dialect::Smd4 => {
            Smd4Session::open(link, options, smd4.options(), transcript).map(Session::Smd4)
        }
    }
    .map_err(failure)
}

/// Opens a TMCL session (for subcommands that only exist for TMCL modules).
pub fn open_tmcl(
    connection: &ConnectionArgs,
    session: &SessionArgs,
    profile: &Arc<Profile>,
) -> Result<TmclSession, Failure> {
    if connection.protocol != Dialect::Tmcl {
        return Err(Failure::new(
            Exit::Refused,
            "this subcommand works with TMCL modules only",
        ));
    }
    let smd4 = Smd4Args {
        address: None,
        prefix_comma: false,
        quiet_gap: None,
    };
    match open_session(connection, session, &smd4, profile)? {
        Session::Tmcl(s) => Ok(s),
        Session::Smd4(_) => unreachable!("the protocol was checked to be TMCL"),
    }
}

/// Runs the shell: the REPL on a terminal, otherwise the `-c` lines or stdin lines.
pub fn run(args: ShellArgs, profile: &Arc<Profile>) -> Result<Exit, Failure> {
    interrupt::install();
    let interactive = args.commands.is_empty() && std::io::stdin().is_terminal();
    let session = open_session(&args.connection, &args.session, &args.smd4, profile)?;
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
        let module = match connection.protocol {
            Dialect::Tmcl => profile.module.as_str(),
            Dialect::Smd4 => "SMD4",
        };
        format!("tmclsh {version} — simulated {module} (built-in) — use --port to talk to hardware")
    } else {
        let module = match shell.session_ref() {
            Session::Tmcl(s) => format!("{}, module {}", profile.module, s.target()),
            Session::Smd4(_) => "SMD4".to_string(),
        };
        format!(
            "tmclsh {version} — {module} on {}",
            shell.session_ref().describe()
        )
    }
}
