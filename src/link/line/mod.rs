//! What a real serial line adds to a byte pipe: the modem lines (DTR, RTS) and RS-485 direction
//! the user asks for, an FTDI adapter's latency timer, the rate the driver really set, who holds
//! a port that cannot be opened, and the state `:line` shows. The settings are pure data here;
//! the system calls are in `os.rs` (Linux) and fall back to "not available" elsewhere.

pub mod holder;
pub mod latency;
mod os;
pub(super) mod refusal;
pub mod settings;
pub mod state;
pub mod sysfs;

pub use settings::{LineOptions, Modem, Rs485, SettingError};
pub use state::{Counters, LineState, ModemLines};

pub(super) use os::{Os, Saved};
