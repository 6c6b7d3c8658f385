use std::collections::BTreeSet;
use std::path::PathBuf;

use super::*;
use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::profile::version::fits;

#[test]
fn every_file_of_data_profiles_is_built_in_and_loads() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/profiles");
    let on_disk: BTreeSet<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    let built_in: BTreeSet<String> = BUILTINS.iter().map(|b| b.name.to_string()).collect();
    assert_eq!(
        built_in, on_disk,
        "BUILTINS lists exactly data/profiles/*.toml"
    );
    assert_eq!(BUILTINS[0].name, DEFAULT);
    for (builtin, profile) in BUILTINS.iter().zip(all()) {
        assert_eq!(profile.name, builtin.name);
        assert!(profile.source.is_none(), "{}: built in", builtin.name);
        assert_eq!(
            std::fs::read_to_string(dir.join(format!("{}.toml", builtin.name))).unwrap(),
            builtin.text,
            "{} is the file's text",
            builtin.file
        );
    }
    assert!(Arc::ptr_eq(&all()[0], &Profile::builtin()));
}

#[test]
fn names_aliases_and_module_numbers_are_unique() {
    let mut names = BTreeSet::new();
    let mut numbers = BTreeSet::new();
    for p in all() {
        assert!(names.insert(p.name.to_ascii_lowercase()), "{}", p.name);
        for alias in &p.identity.aliases {
            assert!(names.insert(alias.to_ascii_lowercase()), "{alias}");
        }
        let number = p.identity.module_number.expect("a module number");
        assert!(numbers.insert(number), "{number}");
    }
    // Identification finds a module's file by the number it declares, without parsing it.
    for (builtin, profile) in BUILTINS.iter().zip(all()) {
        assert_eq!(
            builtin.declared_number(),
            profile.identity.module_number,
            "{}",
            builtin.file
        );
    }
    assert!(!names.contains(GENERIC));
}

#[test]
fn profiles_are_found_by_name_alias_and_module_number() {
    assert_eq!(by_name("tmcm-6110").unwrap().module, "TMCM-6110");
    assert_eq!(by_name("TMCM-6110").unwrap().name, "tmcm-6110");
    assert_eq!(by_name("pd-1141").unwrap().module, "TMCM-1141");
    assert_eq!(by_name("PD-1160").unwrap().module, "TMCM-1160");
    assert!(by_name("generic").unwrap().generic);
    assert!(by_name("tmcm-611").is_none());
    assert_eq!(by_module_number(6110).unwrap().axes, 6);
    assert_eq!(by_module_number(142).unwrap().module, "TMCM-142");
    assert!(by_module_number(9999).is_none());
    assert!(by_module_number(0).is_none());
}

#[test]
fn resolve_takes_a_name_an_alias_a_number_or_a_file() {
    let name = |s: &str| resolve(Path::new(s)).map(|p| p.name.clone());
    assert_eq!(name("tmcm-3110").unwrap(), "tmcm-3110");
    assert_eq!(name("PD-1141").unwrap(), "tmcm-1141");
    assert_eq!(name("6214").unwrap(), "tmcm-6214");
    assert_eq!(name("generic").unwrap(), "generic");
    let file = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/profiles/tmcm-1021.toml");
    let loaded = resolve(&file).unwrap();
    assert_eq!(loaded.module, "TMCM-1021");
    assert_eq!(loaded.source.as_deref(), Some(file.as_path()));
    let error = resolve(Path::new("tmcm-611")).unwrap_err().to_string();
    assert_eq!(
        error,
        "no built-in profile or file 'tmcm-611' (`tmclsh profiles` lists the built-in ones); \
         did you mean tmcm-6110?"
    );
    // A value written as a path is a file, whatever its name.
    let error = resolve(Path::new("./tmcm-6110")).unwrap_err().to_string();
    assert!(
        error.starts_with("cannot read profile ./tmcm-6110"),
        "{error}"
    );
    let error = resolve(Path::new("missing.toml")).unwrap_err().to_string();
    assert!(
        error.starts_with("cannot read profile missing.toml"),
        "{error}"
    );
}

#[test]
fn every_simulated_version_string_identifies_its_own_profile() {
    for p in all() {
        let answer = &p.sim.version_string;
        match identify(answer).unwrap_or_else(|e| panic!("{}: {e}", p.name)) {
            Identified::Known { version, profile } => {
                assert!(Arc::ptr_eq(&profile, p), "{answer}");
                let format = p.identity.version_format.as_deref().unwrap();
                assert!(fits(&version.text, format), "{answer} fits {format}");
            }
            other => panic!("{answer}: {other:?}"),
        }
        let loader = answer.replacen('V', "B", 1);
        match identify(&loader).unwrap() {
            Identified::BootLoader { version, profile } => {
                assert!(fits(
                    &version.text,
                    p.identity.bootloader_format.as_deref().unwrap()
                ));
                assert!(Arc::ptr_eq(profile.as_ref().unwrap(), p));
            }
            other => panic!("{loader}: {other:?}"),
        }
    }
}

#[test]
fn identification_names_module_firmware_and_profile() {
    let known = identify("6110V131").unwrap();
    assert_eq!(
        known.banner(),
        "TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)"
    );
    assert_eq!(known.profile().unwrap().name, "tmcm-6110");
    let unknown = identify("1234V100").unwrap();
    assert!(unknown.profile().unwrap().generic);
    assert_eq!(
        unknown.banner(),
        "TMCM-1234, firmware 1234V100, profile generic (built in): no profile for the TMCM-1234"
    );
    let loader = identify("142B1.06").unwrap();
    assert!(loader.profile().is_none());
    assert_eq!(
        loader.banner(),
        "TMCM-142 in its boot loader (142B1.06): no firmware is running; nothing else was sent"
    );
    assert!(identify("not a version").is_err());
}

#[test]
fn the_generic_profile_has_commands_and_no_parameters() {
    let g = generic();
    assert!(g.generic);
    assert!(g.axis.is_empty() && g.global.is_empty());
    assert_eq!(g.axes, 6);
    assert_eq!(g.identity.ascii_interface(), AsciiInterface::Unconfirmed);
    assert!(g.commands.by_mnemonic("SAC").is_none());
    assert!(g.commands.by_mnemonic("MVP").is_some());
    assert!(g.commands.by_mnemonic("ROR").unwrap().range_when.is_empty());
    assert!(matches!(
        g.find_axis("max_speed"),
        Err(crate::dialect::tmcl::profile::LookupError::NumbersOnly { .. })
    ));
}

#[test]
fn the_family_tables_differ_where_the_data_says() {
    let p = by_name("tmcm-1260").unwrap();
    assert_eq!(p.identity.ascii_interface(), AsciiInterface::No);
    assert!(p.commands.by_number(139).is_none(), "binary-only: no 139");
    assert!(p.commands.iter().all(|c| !c.ascii_allowed));
    let p = by_name("tmcm-1140").unwrap();
    assert!(p.commands.by_mnemonic("SAC").is_none());
    assert!(p.commands.by_mnemonic("EI").is_some());
    assert!(p.commands.by_mnemonic("SIO").unwrap().ascii_allowed);
    assert!(!p.commands.by_mnemonic("CALC").unwrap().ascii_allowed);
    assert_eq!(p.io_ports.iter().filter(|io| io.bank == 2).count(), 2);
    let p = by_name("tmcm-142").unwrap();
    assert!(p.commands.by_mnemonic("SAC").unwrap().ascii_allowed);
    assert_eq!(p.axis_param(4).unwrap().range_when.len(), 1);
}
