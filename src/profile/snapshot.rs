//! How parameter snapshots treat each parameter, as data (the `[snapshot]` table of a profile):
//! which values are live, which settings a restore writes first, and which it leaves to the user.

use serde::Deserialize;

use super::Param;

/// The `[snapshot]` table of a profile file: parameter identifiers in three lists.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
pub struct SnapshotRules {
    /// Live values (positions, speeds, timers): saved, not compared, never written back.
    #[serde(default)]
    pub live: Vec<String>,
    /// Settings a restore writes before all others, in this order (unit modes, limits).
    #[serde(default)]
    pub first: Vec<String>,
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

impl SnapshotRules {
    /// The role of `param` under these rules.
    pub fn role(&self, param: &Param) -> SnapshotRole {
        let listed = |list: &[String]| list.contains(&param.ident);
        if !param.access.write {
            SnapshotRole::ReadOnly
        } else if listed(&self.live) {
            SnapshotRole::Live
        } else if listed(&self.manual) {
            SnapshotRole::Manual
        } else {
            SnapshotRole::Setting
        }
    }

    /// Where `ident` comes in the restore order: its place in `first`, or after all of them.
    pub fn rank(&self, ident: &str) -> usize {
        self.first
            .iter()
            .position(|i| i == ident)
            .unwrap_or(self.first.len())
    }

    /// Checks that every listed identifier names a parameter (a typo would silently not apply).
    pub(crate) fn check(&self, params: &[&Param]) -> Result<(), String> {
        let lists = [
            ("live", &self.live),
            ("first", &self.first),
            ("manual", &self.manual),
        ];
        for (list, idents) in lists {
            for ident in idents {
                if !params.iter().any(|p| p.ident == *ident) {
                    return Err(format!(
                        "[snapshot] {list} names '{ident}', which is not a parameter"
                    ));
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile::Profile;

    #[test]
    fn the_builtin_profile_classifies_settings_live_values_and_link_settings() {
        let profile = Profile::builtin();
        let rules = &profile.snapshot;
        let role = |ident: &str| {
            let p = profile
                .find_axis(ident)
                .or_else(|_| profile.find_global(ident))
                .unwrap();
            rules.role(p)
        };
        assert_eq!(role("max_current"), SnapshotRole::Setting);
        assert_eq!(role("actual_position"), SnapshotRole::Live);
        assert_eq!(role("serial_address"), SnapshotRole::Manual);
        assert_eq!(role("target_position_reached"), SnapshotRole::ReadOnly);
        assert_eq!(role("user_variable_3"), SnapshotRole::Setting);
        assert_eq!(rules.rank("unit_conversion_mode"), 0);
        assert!(rules.rank("max_current") < rules.rank("standby_current"));
    }

    #[test]
    fn a_rule_naming_no_parameter_is_refused() {
        let text = "[meta]\nmodule = \"X\"\n[[axis_parameter]]\nnumber = 1\nname = \"A\"\nident = \"a\"\naccess = \"RW\"\n[snapshot]\nlive = [\"b\"]\n";
        let builtin = Profile::builtin();
        let error = Profile::from_toml(text, Some(&builtin.commands)).unwrap_err();
        assert!(error.contains("[snapshot] live names 'b'"), "{error}");
    }
}
