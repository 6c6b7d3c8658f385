//! The session flags of the SMD4 dialect (`tmclsh --protocol smd4 --address 3 …`): the address
//! prefix, its spelling and the quiet gap that ends a multi-line reply.

use std::time::Duration;

use clap::{ArgMatches, FromArgMatches};

use super::protocol::PrefixStyle;
use super::session::Smd4SessionOptions;

/// Settings of the SMD4 dialect.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = "SMD4")]
pub struct SessionFlags {
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

impl SessionFlags {
    /// The SMD4 session options these flags select.
    pub fn options(&self) -> Smd4SessionOptions {
        let defaults = Smd4SessionOptions::default();
        Smd4SessionOptions {
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

/// The SMD4 session options a command line selects; the defaults without one.
pub fn options(matches: Option<&ArgMatches>) -> Smd4SessionOptions {
    matches
        .and_then(|m| SessionFlags::from_arg_matches(m).ok())
        .map_or_else(Smd4SessionOptions::default, |flags| flags.options())
}
