//! The commissioning toolkit: parameter snapshots (save, diff, restore), bus scans, live watches,
//! recordings with a terminal chart, and transcripts turned into regression scripts.
//!
//! Everything that reads or writes parameters goes through [`ParamDevice`], a small seam each
//! dialect's session implements (TMCL in [`tmcl`], SMD4 in [`smd4`]), so the same tools serve
//! every module type. Values are [`ParamValue`]s — integers, real numbers or text — compared
//! with each parameter's [`Tolerance`].
//! Pure parts — the snapshot file, the diff, the restore order, CSV, chart rendering, transcript
//! parsing and script generation, the scan table — are functions tested without any I/O.

pub mod actions;
pub mod device;
pub mod diff;
pub mod plot;
pub mod progress;
pub mod record;

pub mod restore;
pub mod rules;
pub mod scan;

pub mod snapshot;
pub mod value;
pub mod watch;

#[cfg(test)]
mod fake;

pub use device::{Access, ParamDevice, ParamRef, Scope, StoreStep};
pub use rules::{SnapshotRole, SnapshotRules};
pub use snapshot::Snapshot;
pub use value::{ParamValue, Reading, Tolerance};
