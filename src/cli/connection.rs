//! Connection and session flags: one group ([`ModuleArgs`]) flattened the same way into the shell
//! and every subcommand that talks to a module, so that `cli::position` can move the ones written
//! before the subcommand behind it and `cli::relevance` can refuse those that would be ignored.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use crate::exit::Exit;
use crate::exit::ExitStatus;
use crate::link::Link;
use crate::profile::Profile;
use crate::protocol::Dialect;
use crate::protocol::smd4::PrefixStyle;
use crate::session::smd4::{Smd4Options, Smd4Session};
use crate::session::tmcl::{Echo, TmclSession};
use crate::session::transcript::Header;
use crate::session::{Session, SessionError, SessionOptions, Transcript};

use super::Failure;
use super::target::{Target, is_log_dir, log_file};

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
    #[arg(long, value_enum, default_value_t = Dialect::Tmcl, env = "TMCLSH_PROTOCOL")]
    pub protocol: Dialect,
}

/// Settings of the SMD4 dialect.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = "SMD4")]
pub struct Smd4Args {
    /// SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(0..=247))]
    pub address: Option<u32>,
    /// SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual's @3MOTOR:STOP.
    #[arg(long)]
    pub prefix_comma: bool,
    /// SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have
    /// no end marker).
    #[arg(long, value_name = "MS", value_parser = clap::value_parser!(u64).range(1..))]
    pub quiet_gap: Option<u64>,
}

impl Smd4Args {
    /// The SMD4 session options these flags select.
    pub fn options(&self) -> Smd4Options {
        let defaults = Smd4Options::default();
        Smd4Options {
            address: self.address,
            prefix: if self.prefix_comma {
                PrefixStyle::Comma
            } else {
                PrefixStyle::Attached
            },
            quiet_gap: self
                .quiet_gap
                .map(Duration::from_millis)
                .unwrap_or(defaults.quiet_gap),
        }
    }
}

/// How requests are sent and checked.
#[derive(Debug, Clone, clap::Args)]
pub struct SessionArgs {
    /// Address of the target module (1 = address character A).
    #[arg(long, short = 'm', value_name = "N", env = "TMCLSH_MODULE", default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..=26))]
    pub module: u8,
    /// Milliseconds to wait for a reply before giving up (exit code 3).
    #[arg(long, value_name = "MS", env = "TMCLSH_TIMEOUT", default_value_t = 1000, value_parser = clap::value_parser!(u64).range(1..))]
    pub timeout: u64,
    /// Set the target module's echo on opening: char, line (every reply attributed to its
    /// request) or none (global parameter 67 in RAM; it stays after tmclsh ends).
    #[arg(long, value_enum, value_name = "MODE")]
    pub echo: Option<EchoMode>,
    /// Append every byte sent and received, timestamped and decoded, to FILE; given a
    /// directory (or a path ending in /), write a new file there named by device and date.
    #[arg(long, value_name = "FILE", value_hint = clap::ValueHint::AnyPath)]
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

/// The echo modes of a TMCL module, as `--echo` and `:echo` name them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum EchoMode {
    /// Every character echoed as it arrives.
    Char,
    /// The whole line echoed after its end.
    Line,
    /// No echo, only the reply.
    None,
}

impl EchoMode {
    /// The session's echo mode.
    pub fn echo(self) -> Echo {
        match self {
            EchoMode::Char => Echo::Character,
            EchoMode::Line => Echo::Line,
            EchoMode::None => Echo::None,
        }
    }
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

    /// Opens the transcript, if asked for, starting it with `header`; a `--log` directory gets
    /// a new file named by `device` and the date.
    pub fn transcript(&self, header: &Header, device: &str) -> Result<Option<Transcript>, Failure> {
        let Some(path) = self.log.as_deref() else {
            return Ok(None);
        };
        let failed =
            |e: crate::session::transcript::TranscriptError| Failure::new(e.exit(), e.to_string());
        if !is_log_dir(path) {
            return Transcript::open(path, header).map(Some).map_err(failed);
        }
        std::fs::create_dir_all(path).map_err(|e| {
            Failure::new(
                Exit::Refused,
                format!("cannot create the log directory {}: {e}", path.display()),
            )
        })?;
        let file = log_file(path, device, std::time::SystemTime::now());
        Transcript::open(&file, header).map(Some).map_err(failed)
    }
}

impl ConnectionArgs {
    /// Whether the built-in simulator is meant.
    pub fn is_builtin(&self) -> bool {
        self.port.is_none() && self.tcp.is_none()
    }

    /// Where the link goes (a `usb:` name resolved to its device file).
    pub fn target(&self) -> Result<Target, Failure> {
        Target::of(self.port.as_deref(), self.tcp.as_deref())
    }

    /// Opens the link: the TCP connection (--tcp, which only the command line gives, wins over a
    /// TMCLSH_PORT), the serial port, or the built-in simulated module speaking `dialect`.
    pub fn open(
        &self,
        dialect: Dialect,
        profile: &Arc<Profile>,
        timeout: Duration,
    ) -> Result<Box<dyn Link>, Failure> {
        self.target()?.open(self.baud, dialect, profile, timeout)
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
    /// SMD4 settings.
    #[command(flatten)]
    pub smd4: Smd4Args,
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
    pub fn protocol(&self) -> Dialect {
        self.dialect.protocol
    }

    /// Opens the link, saying on stderr when a batch command is served by the built-in
    /// simulator (so nobody mistakes its answers for hardware's).
    pub fn link(
        &self,
        profile: &Arc<Profile>,
        timeout: Duration,
        audience: Audience,
    ) -> Result<Box<dyn Link>, Failure> {
        let target = self.connection.target()?;
        self.link_to(&target, profile, timeout, audience)
    }

    /// Opens the transcript (named by the target in a `--log` directory), then the link.
    pub fn connect(
        &self,
        header: &Header,
        profile: &Arc<Profile>,
        timeout: Duration,
        audience: Audience,
    ) -> Result<(Option<Transcript>, Box<dyn Link>), Failure> {
        let target = self.connection.target()?;
        let device = target.file_name(self.protocol());
        let transcript = self.session.transcript(header, &device)?;
        let link = self.link_to(&target, profile, timeout, audience)?;
        Ok((transcript, link))
    }

    fn link_to(
        &self,
        target: &Target,
        profile: &Arc<Profile>,
        timeout: Duration,
        audience: Audience,
    ) -> Result<Box<dyn Link>, Failure> {
        let link = target.open(self.connection.baud, self.protocol(), profile, timeout)?;
        if *target == Target::Builtin && audience == Audience::Batch {
            eprintln!(
                "tmclsh: using the built-in simulated {}; give --port or --tcp for hardware",
                simulated_module(self.protocol(), profile)
            );
        }
        Ok(link)
    }

    /// Opens a session in the dialect the flags say.
    pub fn open(&self, profile: &Arc<Profile>, audience: Audience) -> Result<Session, Failure> {
        let options = self.session.options();
        let header = Header::new(self.protocol(), profile);
        let (transcript, link) = self.connect(&header, profile, options.timeout, audience)?;
        match self.protocol() {
            Dialect::Tmcl => TmclSession::open(link, profile.clone(), options, transcript)
                .and_then(|s| self.set_echo(s))
                .map(Session::Tmcl),
            Dialect::Smd4 => {
                Smd4Session::open(link, options, self.smd4.options(), transcript).map(Session::Smd4)
            }
        }
        .map_err(|e| Failure::new(e.exit(), e.to_string()))
    }

    /// Opens a TMCL session (for subcommands that only exist for TMCL modules).
    pub fn open_tmcl(&self, profile: &Arc<Profile>) -> Result<TmclSession, Failure> {
        if self.protocol() != Dialect::Tmcl {
            return Err(Failure::new(
                Exit::Refused,
                "this subcommand works with TMCL modules only",
            ));
        }
        let options = self.session.options();
        let header = Header::tmcl(profile);
        let (transcript, link) =
            self.connect(&header, profile, options.timeout, Audience::Batch)?;
        TmclSession::open(link, profile.clone(), options, transcript)
            .and_then(|s| self.set_echo(s))
            .map_err(|e| Failure::new(e.exit(), e.to_string()))
    }

    /// Sets the target's echo mode when `--echo` (or a configuration file) asks for one.
    fn set_echo(&self, mut session: TmclSession) -> Result<TmclSession, SessionError> {
        if let Some(mode) = self.session.echo {
            let target = session.target();
            session.set_echo(target, mode.echo())?;
        }
        Ok(session)
    }
}

/// The name of the built-in simulated module of `dialect`: the profile's module, or the SMD4.
pub fn simulated_module(dialect: Dialect, profile: &Profile) -> &str {
    match dialect {
        Dialect::Tmcl => profile.module.as_str(),
        Dialect::Smd4 => "SMD4",
    }
}
