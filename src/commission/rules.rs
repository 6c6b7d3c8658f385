//! How parameter snapshots treat each parameter, as data (the `[snapshot]` table of a profile, and
//! of `data/smd4.toml`): which values are live, which settings a restore writes first or last, and
//! which it leaves to the user.

use serde::Deserialize;

/// The `[snapshot]` table of a profile file: parameter identifiers in three lists.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
pub struct SnapshotRules {
    /// Live values (positions, speeds, timers): saved, not compared, never written back.
    #[serde(default)]
    pub live: Vec<String>,
    /// Settings a restore writes before all others, in this order (unit modes, limits).
    #[serde(default)]
    pub first: Vec<String>,
    /// Settings a restore writes after all others, in this order (a mode that hands the motor
    /// to another input).
    #[serde(default)]
    pub last: Vec<String>,
    /// Settings compared but never written by a restore (link and EEPROM protection).
    #[serde(default)]
    pub manual: Vec<String>,
}

/// What a snapshot does with a parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum SnapshotRole {
    /// A setting: saved, compared and restored.
    Setting,
    /// A setting that is saved and compared, but restored by hand.
    Manual,
    /// A live value: saved for the record only.
    Live,
    /// Not writable: saved for the record only, listed as skipped by a restore.
    ReadOnly,
}

/// A snapshot rule naming no parameter of the tables it came with.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("[snapshot] {list} names '{ident}', which is not a parameter")]
pub struct UnknownRuleName {
    /// The rule's list (`live`, `first`, `last`, `manual`).
    pub list: &'static str,
    /// The name it holds.
    pub ident: String,
}

impl SnapshotRules {
    /// The role of the parameter `ident`, writable or not, under these rules.
    pub fn role_of(&self, ident: &str, writable: bool) -> SnapshotRole {
        let listed = |list: &[String]| list.iter().any(|i| i == ident);
        if !writable {
            SnapshotRole::ReadOnly
        } else if listed(&self.live) {
            SnapshotRole::Live
        } else if listed(&self.manual) {
            SnapshotRole::Manual
        } else {
            SnapshotRole::Setting
        }
    }

    /// Where `ident` comes in the restore order: its place in `first`; after all of them when in
    /// neither list; after those, its place in `last`.
    pub fn rank(&self, ident: &str) -> usize {
        let first = self.first.iter().position(|i| i == ident);
        let last = self.last.iter().position(|i| i == ident);
        match (first, last) {
            (Some(i), _) => i,
            (None, Some(i)) => self.first.len() + 1 + i,
            (None, None) => self.first.len(),
        }
    }

    /// Checks every listed identifier with `known` (a typo would silently not apply).
    pub fn check_names(&self, known: impl Fn(&str) -> bool) -> Result<(), UnknownRuleName> {
        let lists = [
            ("live", &self.live),
            ("first", &self.first),
            ("last", &self.last),
            ("manual", &self.manual),
        ];
        for (list, idents) in lists {
            for ident in idents {
                if !known(ident) {
                    return Err(UnknownRuleName {
                        list,
                        ident: ident.clone(),
                    });
                }
            }
        }
        Ok(())
    }
}
