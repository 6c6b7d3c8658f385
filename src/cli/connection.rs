//! Connection and session flags: one group ([`ModuleArgs`]) flattened the same way into the shell
//! and every subcommand that talks to a module, so that `cli::position` can move the ones written
//! before the subcommand behind it and `cli::relevance` can refuse those that would be ignored.

use std::path::PathBuf;
use std::time::Duration;

use clap::{ArgMatches, Args, Command, FromArgMatches};

use crate::dialect::{
    Configured, DIALECTS, Dialect, DialectConfig, DialectSession, Opening, Purpose,
    default_dialect, protocol_parser,
};
use crate::exit::Exit;
use crate::exit::ExitStatus;
use crate::link::{Link, SerialLink, TcpLink};
use crate::session::transcript::Header;
use crate::session::{SessionOptions, Transcript};

use super::Failure;

/// Where the module is: a serial port, a TCP address, or (neither) the built-in simulator.
#[derive(Debug, Clone, clap::Args)]
pub struct ConnectionArgs {
    /// Serial port of the module (e.g. /dev/ttyUSB0); without --port or --tcp, tmclsh talks to
    /// its built-in simulated module.
    // Not `conflicts_with = "tcp"`: clap would count TMCLSH_PORT as given and refuse every --tcp
    // while it is set; `relevance` refuses the two on one command line instead.
    #[arg(long, value_name = "PATH", env = "TMCLSH_PORT")]
    pub port: Option<String>,
    /// Serial bit rate (8N1).
    #[arg(long, value_name = "N", env = "TMCLSH_BAUD", default_value_t = 9600)]
    pub baud: u32,
    /// TCP address of the module or of a serial server (HOST:PORT).
    #[arg(long, value_name = "HOST:PORT")]
    pub tcp: Option<String>,
}

/// Which protocol the module speaks: shared by the faces that talk to a module and by `params`.
#[derive(Debug, Clone, clap::Args)]
pub struct DialectArgs {
    /// The protocol the module speaks (also selects the built-in simulated module).
    #[arg(long, value_parser = protocol_parser(), default_value = default_dialect().name, env = "TMCLSH_PROTOCOL")]
    pub protocol: &'static Dialect,
}

/// The session flags of every dialect (`--address` …), each dialect's under the help heading it
/// sets (which, as with any flattened group, stays for the options after it); kept as parsed,
/// for the chosen dialect to read its own.
#[derive(Debug, Clone)]
pub struct DialectFlags(ArgMatches);

impl FromArgMatches for DialectFlags {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        Ok(DialectFlags(matches.clone()))
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        self.0 = matches.clone();
        Ok(())
    }
}

impl Args for DialectFlags {
    fn augment_args(cmd: Command) -> Command {
        DIALECTS.iter().fold(cmd, |cmd, d| (d.session_flags)(cmd))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// How requests are sent and checked.
#[derive(Debug, Clone, clap::Args)]
pub struct SessionArgs {
    /// Address of the target module (1 = address character A).
    #[arg(long, short = 'm', value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..=26))]
    pub module: u8,
    /// Milliseconds to wait for a reply before giving up (exit code 3).
    #[arg(long, value_name = "MS", default_value_t = 1000, value_parser = clap::value_parser!(u64).range(1..))]
    pub timeout: u64,
    /// Append every byte sent and received, timestamped and decoded, to FILE.
    #[arg(long, value_name = "FILE")]
    pub log: Option<PathBuf>,
    /// Send lines the validator would refuse (still canonicalised where they parse).
    #[arg(long)]
    pub no_validate: bool,
    /// Do not send the enter-ASCII-mode frame (the module is already in ASCII mode).
    #[arg(long)]
    pub no_enter: bool,
    /// Leave the modules in ASCII mode on exit instead of restoring the mode they were found in.
    #[arg(long)]
    pub stay_ascii: bool,
}

impl SessionArgs {
    /// The session options these flags select.
    pub fn options(&self) -> SessionOptions {
        SessionOptions {
            module: self.module,
            timeout: Duration::from_millis(self.timeout),
            validate: !self.no_validate,
            enter: !self.no_enter,
            stay_ascii: self.stay_ascii,
        }
    }

    /// Opens the transcript, if asked for, starting it with `header`.
    pub fn transcript(&self, header: &Header) -> Result<Option<Transcript>, Failure> {
        self.log
            .as_deref()
            .map(|path| {
                Transcript::open(path, header).map_err(|e| Failure::new(e.exit(), e.to_string()))
            })
            .transpose()
    }
}

impl ConnectionArgs {
    /// Whether the built-in simulator is meant.
    pub fn is_builtin(&self) -> bool {
        self.port.is_none() && self.tcp.is_none()
    }

    /// Opens the link: the TCP connection (--tcp, which only the command line gives, wins over a
    /// TMCLSH_PORT), the serial port, or the built-in simulator of `config`'s dialect.
    pub fn open(
        &self,
        config: &dyn DialectConfig,
        timeout: Duration,
    ) -> Result<Box<dyn Link>, Failure> {
        let link: Box<dyn Link> = if let Some(address) = &self.tcp {
            Box::new(
                TcpLink::connect(address, timeout)
                    .map_err(|e| Failure::new(Exit::Link, e.to_string()))?,
            )
        } else if let Some(path) = &self.port {
            Box::new(
                SerialLink::open(path, self.baud)
                    .map_err(|e| Failure::new(Exit::Link, e.to_string()))?,
            )
        } else {
            let name = format!("simulated {} (built-in)", config.simulated_module());
            crate::sim::builtin_link(config.simulator(), name)
        };
        Ok(link)
    }
}

/// Everything that says which module to talk to and how: flattened, the same way, into the shell
/// and every subcommand that opens a session in either dialect.
#[derive(Debug, Clone, clap::Args)]
pub struct ModuleArgs {
    /// Where the module is.
    #[command(flatten)]
    pub connection: ConnectionArgs,
    /// The protocol it speaks.
    #[command(flatten)]
    pub dialect: DialectArgs,
    /// How requests are sent and checked.
    #[command(flatten)]
    pub session: SessionArgs,
    /// The settings of each dialect.
    #[command(flatten)]
    pub flags: DialectFlags,
}

/// Who learns that the built-in simulator answers: a command run without a terminal says so on
/// stderr, the REPL in its banner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Audience {
    /// A command that runs to its end: the notice goes to stderr.
    Batch,
    /// The REPL, whose banner names the simulated module.
    Interactive,
}

impl ModuleArgs {
    /// The protocol the module speaks.
    pub fn protocol(&self) -> &'static Dialect {
        self.dialect.protocol
    }

    /// Opens the link, saying on stderr when a batch command is served by the built-in
    /// simulator (so nobody mistakes its answers for hardware's).
    pub fn link(
        &self,
        config: &dyn DialectConfig,
        timeout: Duration,
        audience: Audience,
    ) -> Result<Box<dyn Link>, Failure> {
        let link = self.connection.open(config, timeout)?;
        if self.connection.is_builtin() && audience == Audience::Batch {
            eprintln!(
                "tmclsh: using the built-in simulated {}; give --port or --tcp for hardware",
                config.simulated_module()
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
        let transcript = self.session.transcript(&config.header())?;
        let link = self.link(config, options.timeout, audience)?;
        config
            .open(Opening {
                link,
                options,
                transcript,
                flags: Some(&self.flags.0),
                purpose,
            })
            .map_err(|e| Failure::new(e.exit(), e.to_string()))
    }
}
