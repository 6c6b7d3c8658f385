//! Sessions: the only place where a protocol meets I/O. A session owns a link and speaks one
//! dialect over it — entering the module's ASCII mode, stripping echoes, matching replies to the
//! addressed module, timing out with a clear error, resynchronising, logging the transcript, and
//! stopping motors it set moving when a run is aborted. The REPL, `-c` lines, piped stdin and
//! Rhai scripts all go through the same session.

pub mod core;
mod error;
mod exchange;
pub mod interrupt;
pub mod notices;
pub mod relink;
pub(crate) mod rx;
pub mod transcript;
pub(crate) mod wire;

use std::time::Duration;

pub(crate) use error::barrier_failed;
pub use error::{NoiseKind, SessionError};
pub use transcript::Transcript;

/// How long a stop (MST, MOTOR:STOP) waits for its answer besides the exchange's wire time. Stops
/// go out at once; a module answers them at once; and after Ctrl-C the user hears within this that
/// the stop went out, however long the interrupted reply would have taken.
pub(crate) const STOP_CONFIRMATION: Duration = Duration::from_millis(50);

/// Settings shared by every dialect's session.
#[derive(Debug, Clone)]
pub struct SessionOptions {
    /// The module addressed by lines without an address character (`--module`).
    pub module: u8,
    /// How long to wait for a reply (`--timeout`).
    pub timeout: Duration,
    /// Refuse invalid lines before sending (off with `--no-validate`).
    pub validate: bool,
    /// How long a run that is not interactive waits for a lost link to come back
    /// (`--reconnect`); `None`: it fails at once (exit 3).
    pub reconnect: Option<Duration>,
    /// Whether the adapter hands back what is sent (`--local-echo`).
    pub local_echo: LocalEcho,
}

/// Whether the adapter echoes what the host sends (a 2-wire RS-485 converter without echo
/// suppression), so the session strips it (`--local-echo`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LocalEcho {
    /// Found out at open, from the first request that can tell.
    #[default]
    Auto,
    /// It does: strip it.
    On,
    /// It does not.
    Off,
}

impl Default for SessionOptions {
    fn default() -> Self {
        SessionOptions {
            module: 1,
            timeout: Duration::from_millis(1000),
            validate: true,
            reconnect: None,
            local_echo: LocalEcho::Auto,
        }
    }
}
