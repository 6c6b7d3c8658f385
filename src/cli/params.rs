//! `tmclsh params [FILTER]`: the parameters of the module the protocol and profile say — a TMCL
//! profile's axis and global parameters, the SMD4's commands with their access and arguments.

use std::io::{self, Write};

use crate::dialect::Configured;
use crate::exit::Exit;

use super::connection::DialectArgs;

/// Arguments of `params`.
#[derive(Debug, clap::Args)]
pub(crate) struct ParamsArgs {
    /// Show parameters whose identifier or name contains FILTER, or whose number is FILTER
    /// (SMD4: commands whose mnemonic contains FILTER).
    pub filter: Option<String>,
    /// Print one JSON document instead of the table (fields in docs/machine-output.md).
    #[arg(long)]
    pub json: bool,
    /// Whose tables to print.
    #[command(flatten)]
    pub dialect: DialectArgs,
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
