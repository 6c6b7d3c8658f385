//! Why the command line refuses an option's value: what was given and what the option takes.
//! Each option's value parser returns one; clap prints it after `invalid value '…' for '--…'`,
//! and a configuration file or an environment variable is checked by the same parser.

use crate::duration::DurationError;
use crate::link::line::SettingError;

/// An option's value refused before anything is opened.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ValueError {
    /// `--port` given a TCP address, which would be opened as a file of that name.
    #[error(
        "{0} is a TCP address (HOST:PORT), not a serial port: give it with --tcp (or \
         TMCLSH_TCP, or tcp = \"{0}\" in tmclsh.toml)"
    )]
    TcpAsPort(String),
    /// A bit rate that is no whole number within the bounds a serial port can be set to.
    #[error("a bit rate is a whole number from {lowest} to {highest}, such as 9600 or 115200")]
    Baud {
        /// The slowest rate.
        lowest: u32,
        /// The fastest rate.
        highest: u32,
    },
    /// A CAN bit rate slcan has no code for.
    #[error("a CAN bit rate is one of {}", list(.0))]
    CanBitrate(&'static [u32]),
    /// A `--can` value that names no adapter.
    #[error(
        "'{0}' names no CAN adapter: give slcan:PATH (a serial-line CAN adapter, e.g. \
         slcan:/dev/ttyACM0) or socketcan:IFACE (Linux, e.g. socketcan:can0)"
    )]
    CanAdapter(String),
    /// A serial line setting (`--dtr`, `--rts`, `--rs485-delay`).
    #[error(transparent)]
    Setting(#[from] SettingError),
    /// A time that is not one, or too long.
    #[error(transparent)]
    Time(#[from] DurationError),
    /// A time of 0 where one must pass.
    #[error("the time must be at least 1 ms")]
    ZeroTime,
    /// An slcan acknowledgement style the simulator does not have.
    #[error("'{0}' is no acknowledgement: z, Z, cr or none")]
    Acknowledgement(String),
    /// A fault rate outside 0..1.
    #[error("'{0}' is not a rate between 0 and 1")]
    Rate(String),
}

/// Numbers as a list in a message: `10000, 20000, 50000`.
fn list(numbers: &[u32]) -> String {
    let numbers: Vec<String> = numbers.iter().map(u32::to_string).collect();
    numbers.join(", ")
}
