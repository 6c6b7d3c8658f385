use super::*;

#[test]
fn builtin_profile_has_the_tmcm142_tables() {
    let p = Profile::builtin();
    assert_eq!(p.module, "TMCM-142");
    assert_eq!(p.axes, 1);
    assert_eq!(p.program_memory, 2048);
    let ap = p.axis_param(4).unwrap();
    assert_eq!(ap.ident, "max_positioning_speed");
    assert_eq!(
        ap.access,
        Access {
            read: true,
            write: true,
            store: true
        }
    );
    assert_eq!(ap.range, Some((0, 2147483647)));
    assert_eq!(p.axis_param(8).unwrap().access.letters(), "R");
    assert_eq!(p.global_param(0, 76).unwrap().ident, "serial_host_address");
    assert_eq!(p.global_param(2, 55).unwrap().ident, "user_variable_55");
    assert!(p.global_param(2, 56).is_none());
    assert!(
        p.global.iter().all(|g| g.bank() != 1),
        "bank 1 placeholder is not a parameter"
    );
}

#[test]
fn lookup_by_identifier_name_and_unique_prefix() {
    let p = Profile::builtin();
    assert_eq!(p.find_axis("actual_position").unwrap().number, 1);
    assert_eq!(p.find_axis("ACTUAL_POSITION").unwrap().number, 1);
    assert_eq!(p.find_axis("Actual position").unwrap().number, 1);
    assert_eq!(p.find_axis("max_cur").unwrap().number, 6);
    assert_eq!(p.find_global("user_variable_7").unwrap().number, 7);
    assert!(matches!(
        p.find_axis("max_"),
        Err(LookupError::Ambiguous { .. })
    ));
    match p.find_axis("max_curent") {
        Err(LookupError::Unknown { suggestion, .. }) => {
            assert_eq!(suggestion.as_deref(), Some("max_current"))
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn filter_matches_identifier_name_or_number() {
    let p = Profile::builtin();
    let max: Vec<u8> = p.matching("max").map(|p| p.number).collect();
    assert_eq!(max, vec![4, 5, 6, 212]);
    assert_eq!(p.matching("194").count(), 1);
    assert_eq!(p.matching("").count(), p.axis.len() + p.global.len());
}

#[test]
fn a_user_profile_without_commands_uses_the_builtin_table() {
    let text = r#"
        [meta]
        module = "TMCM-9999"
        axes = 3
        [[axis_parameter]]
        number = 4
        name = "Max speed"
        ident = "max_speed"
        access = "RW"
        range = [0, 100]
        [[global_parameter]]
        bank = 2
        number = 0
        number_last = 3
        name = "vars"
        ident = "var"
        access = "RWE"
    "#;
    let p = Profile::from_toml(text, Some(&Profile::builtin().commands)).unwrap();
    assert_eq!(p.module, "TMCM-9999");
    assert_eq!(p.axes, 3);
    assert_eq!(p.find_axis("max_speed").unwrap().range, Some((0, 100)));
    assert_eq!(p.global.len(), 4);
    assert_eq!(p.find_global("var_3").unwrap().number, 3);
    assert!(p.commands.by_mnemonic("GAP").is_some());
}

#[test]
fn schema_errors_are_reported() {
    assert!(
        Profile::from_toml("[meta]\n", None)
            .unwrap_err()
            .contains("module")
    );
    let duplicate = r#"
        [meta]
        module = "X"
        [[axis_parameter]]
        number = 1
        name = "a"
        ident = "a"
        [[axis_parameter]]
        number = 1
        name = "b"
        ident = "b"
    "#;
    let e = Profile::from_toml(duplicate, Some(&Profile::builtin().commands)).unwrap_err();
    assert!(
        e.starts_with("line 9: axis parameter 1 is defined twice (first on line 5)"),
        "{e}"
    );
    let e = Profile::from_file(Path::new("/nonexistent/profile.toml")).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("cannot read profile /nonexistent/profile.toml"),
        "{e}"
    );
}

#[test]
fn every_power_up_value_lies_in_its_range() {
    let p = Profile::builtin();
    for param in p.axis.iter().chain(&p.global) {
        let value = param.default.unwrap_or(0);
        assert!(
            param.accepts(value),
            "{} ({}) powers up at {value}, outside {}: give it a default in data/profiles/tmcm-142.toml",
            param.ident,
            param.number,
            param.range_text()
        );
    }
}

#[cfg(test)]
mod snapshot_rules {
    use super::*;
    use crate::commission::SnapshotRole;

    #[test]
    fn the_builtin_profile_classifies_settings_live_values_and_link_settings() {
        let profile = Profile::builtin();
        let rules = &profile.snapshot;
        let role = |ident: &str| {
            let p = profile
                .find_axis(ident)
                .or_else(|_| profile.find_global(ident))
                .unwrap();
            rules.role_of(&p.ident, p.access.write)
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
