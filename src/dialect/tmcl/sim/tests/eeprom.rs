//! The simulated EEPROM: persistence across a restart through the state store, factory reset,
//! start-up in ASCII mode, the state file on disk.

use crate::dialect::tmcl::sim::{BusOptions, Eeprom};
use crate::sim::store::{FileStore, MemoryStore};

use super::Sim;

fn with_store(store: &MemoryStore) -> Sim {
    Sim::with(BusOptions {
        eeprom: Some(Eeprom::open(Box::new(store.clone())).unwrap()),
        ..BusOptions::default()
    })
}

#[test]
fn stored_values_survive_a_restart_and_ram_values_do_not() {
    let store = MemoryStore::new();
    let mut sim = with_store(&store);
    sim.sap(4, 4242);
    sim.ok(7, 4, 0, 0);
    sim.sap(5, 777); // not stored
    sim.ok(9, 12, 2, -9);
    sim.ok(11, 12, 2, 0);
    sim.ok(9, 13, 2, 5); // not stored
    drop(sim);
    let mut sim = with_store(&store);
    assert_eq!(sim.gap(4), 4242);
    assert_eq!(sim.gap(5), 100_000);
    assert_eq!(sim.ok(10, 12, 2, 0), -9);
    assert_eq!(sim.ok(10, 13, 2, 0), 0);
}

#[test]
fn the_store_is_written_only_when_stored_values_change() {
    let store = MemoryStore::new();
    let mut sim = with_store(&store);
    let initial = store.saves();
    assert_eq!(initial, 1, "the factory image is written at start");
    sim.sap(4, 1);
    sim.gap(4);
    assert_eq!(store.saves(), initial);
    sim.ok(7, 4, 0, 0);
    assert_eq!(store.saves(), initial + 1);
    sim.ok(7, 4, 0, 0);
    assert_eq!(store.saves(), initial + 1, "same value: nothing to write");
}

#[test]
fn gp67_bit0_starts_the_module_in_ascii_mode() {
    let store = MemoryStore::new();
    let mut sim = with_store(&store);
    sim.ok(9, 67, 0, 0x21); // EEPROM-only: stored at once
    drop(sim);
    let mut sim = with_store(&store);
    assert_eq!(sim.line("AGAP 4, 0"), "BA 100 1000000\r");
}

#[test]
fn factory_reset_is_persistent() {
    let store = MemoryStore::new();
    let mut sim = with_store(&store);
    sim.sap(4, 4242);
    sim.ok(7, 4, 0, 0);
    sim.send(
        &crate::dialect::tmcl::protocol::CommandFrame {
            address: 1,
            instruction: crate::dialect::tmcl::protocol::Instruction::new(137, 0, 0, 1234),
        }
        .encode(),
    );
    drop(sim);
    let mut sim = with_store(&store);
    assert_eq!(sim.gap(4), 1_000_000);
}

#[test]
fn a_lost_eeprom_magic_restores_factory_settings_at_power_up() {
    let store = MemoryStore::new();
    let mut sim = with_store(&store);
    sim.sap(4, 4242);
    sim.ok(7, 4, 0, 0);
    sim.ok(9, 64, 0, 0);
    drop(sim);
    let mut sim = with_store(&store);
    assert_eq!(sim.gap(4), 1_000_000);
    assert_eq!(sim.ok(10, 64, 0, 0), 228);
}

#[test]
fn programs_and_stored_coordinates_persist() {
    let store = MemoryStore::new();
    let mut sim = with_store(&store);
    sim.ok(132, 0, 0, 0);
    sim.frame(1, 22, 0, 0, 0);
    sim.ok(133, 0, 0, 0);
    sim.ok(9, 84, 0, 1);
    sim.ok(30, 2, 0, 654);
    drop(sim);
    let mut sim = with_store(&store);
    assert_eq!(sim.ok(134, 1, 0, 0), 22 << 16);
    assert_eq!(sim.ok(31, 2, 0, 0), 654);
}

#[test]
fn the_state_file_round_trips_and_reports_damage() {
    let dir = std::env::temp_dir().join(format!("tmclsh-state-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("eeprom.toml");
    let _ = std::fs::remove_file(&path);
    {
        let eeprom = Eeprom::open(Box::new(FileStore::new(&path))).unwrap();
        assert!(eeprom.loaded().is_none());
        let mut sim = Sim::with(BusOptions {
            eeprom: Some(eeprom),
            addresses: vec![1, 2],
            ..BusOptions::default()
        });
        sim.frame(2, 5, 4, 0, 31_337);
        sim.frame(2, 7, 4, 0, 0);
    }
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("31337"), "{text}");
    let eeprom = Eeprom::open(Box::new(FileStore::new(&path))).unwrap();
    let image = eeprom.loaded().unwrap();
    assert!(image.module(2).unwrap().axis.contains(&(4, 31_337)));
    std::fs::write(&path, "[[module]]\nslot = \"x\"\n").unwrap();
    let error = Eeprom::open(Box::new(FileStore::new(&path)))
        .err()
        .unwrap()
        .to_string();
    assert!(error.contains("damaged"), "{error}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_state_file_written_by_an_earlier_version_still_loads() {
    let store = MemoryStore::new();
    let mut writer = store.clone();
    crate::sim::store::Store::save(
        &mut writer,
        "# Simulated TMCL module EEPROM (tmclsh sim --state). Delete for factory settings.\n\
         [[module]]\nslot = 1\naxis = [[4, 4242]]\nglobal = [[2, 12, -9]]\n",
    )
    .unwrap();
    let mut sim = with_store(&store);
    assert_eq!(sim.gap(4), 4242);
    assert_eq!(sim.ok(10, 12, 2, 0), -9);
}
