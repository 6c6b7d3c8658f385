//! The commissioning toolkit, the part no dialect owns: parameter snapshots (save, diff,
//! restore), live watches, recordings with a terminal chart, and the address lists of bus scans.
//! The scans themselves and the transcript replays belong to the dialects; the shell's helper
//! commands over all of it live in `shell::commission`.
//!
//! Everything that reads or writes parameters goes through [`ParamDevice`], a small seam each
//! dialect's session implements (in its folder's `commission.rs`), so the same tools serve every
//! module type. Values are [`ParamValue`]s — integers, real numbers or text — compared with each
//! parameter's [`Tolerance`]; how a snapshot treats each parameter is data ([`SnapshotRules`]).
//! Pure parts — the snapshot file, the diff, the restore order, CSV, chart rendering, address
//! lists — are functions tested without any I/O.

pub mod actions;
pub mod decoding;
pub mod device;
pub mod diff;
pub mod plot;
pub mod record;

pub mod restore;
pub mod rules;
pub mod scan;

pub mod snapshot;
pub mod value;
pub mod watch;

#[cfg(test)]
mod fake;

pub use device::{Access, ParamDevice, ParamError, ParamRef, Scope, StoreStep};
pub use rules::{SnapshotRole, SnapshotRules};
pub use snapshot::Snapshot;
pub use value::{ParamValue, Reading, Tolerance};
