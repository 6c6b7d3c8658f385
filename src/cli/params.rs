//! `tmclsh params [FILTER]`: the parameters of the module the protocol and profile say — a TMCL
//! profile's axis and global parameters, the SMD4's commands with their access and arguments.
//! With `--values` (and `--motor N`) they are read from the module, as `:params --values` reads
//! them, over a link given as to every command that opens a session.

use std::io::{self, Write};

use crate::dialect::{Configured, Purpose};
use crate::exit::{Exit, Failure};
use crate::session::interrupt;
use crate::shell::values::{self, Wanted};

use super::connection::{
    Audience, CommandLine, ConnectionArgs, DialectArgs, DialectFlags, ModuleArgs, SessionArgs,
};

/// Arguments of `params`.
#[derive(Debug, clap::Args)]
pub(crate) struct ParamsArgs {
    /// Show parameters whose identifier or name contains FILTER, or whose number is FILTER
    /// (SMD4: commands whose mnemonic contains FILTER).
    pub filter: Option<String>,
    /// Print one JSON document instead of the table; not with --values (fields in docs/machine-output.md).
    #[arg(long, conflicts_with = "values")]
    pub json: bool,
    /// Read the readable parameters (those whose name contains FILTER) from the module, with
    /// what each value means; the link is given as for any command (--port, --tcp, --sim).
    #[arg(long)]
    pub values: bool,
    /// With --values: only motor N's axis parameters.
    #[arg(long, value_name = "N", requires = "values")]
    pub motor: Option<u8>,
    /// The command line as given, for the dialect's own options.
    #[command(flatten)]
    pub command_line: CommandLine,
    /// With --values: where the module is.
    #[command(flatten)]
    pub connection: ConnectionArgs,
    /// Whose tables to print.
    #[command(flatten)]
    pub dialect: DialectArgs,
    /// The module's tables.
    #[command(flatten)]
    pub profile: super::profile_option::ProfileOption,
    /// With --values: how requests are sent and checked.
    #[command(flatten)]
    pub session: SessionArgs,
    /// With --values: the settings of each dialect.
    #[command(flatten)]
    pub flags: DialectFlags,
}

/// Prints the table; a filter that matches nothing says so on stderr and exits 1 (as `grep`
/// does), so a script can test whether a parameter exists.
pub(crate) fn run(
    args: &ParamsArgs,
    configs: &Configured,
    out: &mut dyn Write,
) -> io::Result<Exit> {
    let filter = args.filter.as_deref().unwrap_or("");
    let config = configs.of(args.dialect.protocol);
    let matched = if args.json {
        match config.params_json(filter) {
            Ok(rows) => {
                let document = crate::json::json!({
                    "protocol": args.dialect.protocol.name,
                    "parameters": rows,
                });
                crate::json::write(&document, out)?;
                true
            }
            Err(message) => {
                super::diagnose(&message);
                false
            }
        }
    } else {
        config.write_params(filter, out)?
    };
    Ok(if matched {
        Exit::Success
    } else {
        Exit::DeviceError
    })
}

/// `--values`: reads the parameters from the module; none matching says so on stderr and exits
/// 1, as the table does.
pub(crate) fn read_values(
    args: &ParamsArgs,
    configs: &Configured,
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    let wanted = Wanted {
        filter: args.filter.clone().unwrap_or_default(),
        motor: args.motor,
    };
    let module = ModuleArgs {
        command_line: args.command_line.clone(),
        connection: args.connection.clone(),
        dialect: args.dialect.clone(),
        profile: super::profile_option::ProfileOption,
        session: args.session.clone(),
        flags: DialectFlags,
    };
    interrupt::install();
    let mut session = module.open(configs, Audience::Batch, Purpose::Talk)?;
    let mut out = crate::stdout::PipeSafe(out);
    let result = values::write_values(session.param_device(), &wanted, &mut out);
    for notice in session.take_notices() {
        super::diagnose(&notice);
    }
    interrupt::take();
    for message in session.close() {
        super::diagnose(&message);
    }
    if result? == 0 {
        super::diagnose(&values::none_matched(&wanted));
        return Ok(Exit::DeviceError);
    }
    Ok(Exit::Success)
}
