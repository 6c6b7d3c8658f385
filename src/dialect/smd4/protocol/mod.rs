//! The text protocol of AML SMD4 stepper drives: requests `[@addr]MNEMONIC[,arg…]`, replies
//! `[prefix,]SFLAGS,EFLAGS[,data…]`, flag words, error codes, the command table and validation.
//! Pure code: text in, values out. The command table, flag names, error texts and simulator
//! constants are data (`data/smd4.toml`), loaded once by [`Smd4Spec::builtin`].
//!
//! A session uses it like this: [`validate()`] the typed [`Request`] (refuse with exit 2), send
//! [`Request::wire`], feed the received lines to a [`ReplyCollector`] built from
//! [`Expectation::for_request`], [`check_reply`] the [`Smd4Reply`] (a [`Noise`] means exit 3) and
//! look at it (a [`DeviceError`] means exit 1).

pub mod check;
pub mod commands;
pub mod errors;
pub mod flags;
pub mod format;
pub mod hints;
pub mod items;
pub(crate) mod load;
pub mod multiline;
pub mod reply;
pub mod request;
pub mod sniff;
pub mod spec;
pub mod tolerance;
pub mod types;
pub mod validate;

#[cfg(test)]
mod tests;

pub use check::{Noise, check_reply, is_reply_to};
pub use commands::{
    ArgProblem, ArgSpec, Choice, Example, Kind, ReplyShape, Smd4Command, Smd4CommandTable,
};
pub use errors::{DeviceError, ErrorCode, ErrorInfo};
pub use flags::{Eflags, FlagBit, FlagTable, Sflags};
pub use format::{ErrorSpelling, FlagCase, FloatStyle};
pub use hints::{WordCompletion, complete, hint, hint_for_line, usage};
pub use items::{DataItem, Value};
pub use multiline::{CollectorState, ReplyCollector, default_quiet_gap};
pub use reply::{Expectation, ReplyError, Smd4Reply, parse_reply};
pub use request::{ADDRESSING_HELP, PrefixStyle, Request, RequestError};
pub use spec::{SimConstants, Smd4Spec, SnapshotSpec};
pub use tolerance::RealTolerance;
pub use types::{ArgValue, ItemType};
pub use validate::{Action, Checked, MAX_ADDRESS, ValidationError, validate};
