//! Modules of other profiles: every motor of a multi-axis module with its own motion, parameters
//! and switches; parameter roles, I/O, version string and interface from the profile; a bus of
//! different modules.

use crate::dialect::tmcl::profile::catalogue;
use crate::dialect::tmcl::protocol::Status;
use crate::dialect::tmcl::sim::control_cmd::Controlled;
use crate::dialect::tmcl::sim::{Bus, BusOptions, Switch, Switches};

use super::Sim;

const ROR: u8 = 1;
const MST: u8 = 3;
const MVP: u8 = 4;
const SAP: u8 = 5;
const GAP: u8 = 6;
const STAP: u8 = 7;
const RFS: u8 = 13;
const SIO: u8 = 14;
const GIO: u8 = 15;

#[test]
fn moving_one_motor_of_a_tmcm_6110_leaves_the_others_standing() {
    let mut sim = Sim::of("tmcm-6110");
    sim.ok(MVP, 0, 3, 10_000);
    sim.wait(0.1);
    let moving = sim.ok(GAP, 1, 3, 0);
    assert!(
        moving > 0 && moving < 10_000,
        "motor 3 is on its way: {moving}"
    );
    sim.wait(5.0);
    for motor in 0..6u8 {
        let expected = if motor == 3 { 10_000 } else { 0 };
        assert_eq!(
            sim.ok(GAP, 1, motor, 0),
            expected,
            "position of motor {motor}"
        );
        assert_eq!(sim.ok(GAP, 8, motor, 0), 1, "motor {motor} at its target");
    }
    assert_eq!(sim.ok(GAP, 0, 3, 0), 10_000, "motor 3's own target");
    assert_eq!(sim.ok(GAP, 0, 0, 0), 0, "motor 0's target is untouched");
}

#[test]
fn mst_stops_only_its_own_motor() {
    let mut sim = Sim::of("tmcm-6110");
    sim.ok(ROR, 0, 1, 500);
    sim.ok(ROR, 0, 2, 700);
    sim.wait(1.0);
    sim.ok(MST, 0, 1, 0);
    sim.wait(1.0);
    assert_eq!(sim.ok(GAP, 3, 1, 0), 0, "motor 1 stopped");
    assert_eq!(sim.ok(GAP, 2, 1, 0), 0, "motor 1's target speed is 0");
    assert_eq!(sim.ok(GAP, 3, 2, 0), 700, "motor 2 still turns");
    let before = sim.ok(GAP, 1, 2, 0);
    let stopped_at = sim.ok(GAP, 1, 1, 0);
    sim.wait(1.0);
    assert!(sim.ok(GAP, 1, 2, 0) > before, "motor 2 goes on");
    assert_eq!(sim.ok(GAP, 1, 1, 0), stopped_at, "motor 1 stands");
    let state = sim.bus.motor_of(sim.now, 1, 2).expect("motor 2");
    assert!(state.velocity > 0.0);
    assert!(
        sim.bus.motor_of(sim.now, 1, 6).is_none(),
        "a 6110 has motors 0..5"
    );
}

#[test]
fn each_motor_has_its_own_parameters_ranges_and_eeprom() {
    let mut sim = Sim::of("tmcm-6110");
    sim.ok(SAP, 4, 2, 500);
    assert_eq!(sim.ok(GAP, 4, 2, 0), 500);
    assert_eq!(sim.ok(GAP, 4, 0, 0), 1000, "motor 0 keeps the default");
    assert_eq!(sim.ok(GAP, 4, 5, 0), 1000, "motor 5 keeps the default");
    // AP4 is 0..2047 on TMC429 modules: the profile's range, for every motor.
    assert_eq!(sim.status(SAP, 4, 4, 2048), Status::InvalidValue);
    assert_eq!(sim.status(SAP, 4, 4, 2047), Status::Ok);
    // Motor 6 does not exist.
    assert_eq!(sim.status(GAP, 4, 6, 0), Status::InvalidValue);
    assert_eq!(sim.status(MVP, 0, 6, 100), Status::InvalidValue);
    // STAP keeps motor 2's value, and only motor 2's, in the EEPROM image.
    sim.ok(STAP, 4, 2, 0);
    let image = sim_image(&sim.bus);
    assert!(image.motors.contains(&(2, 4, 500)), "{:?}", image.motors);
    assert!(
        image.axis.contains(&(4, 1000)),
        "motor 0 keeps its stored value: {:?}",
        image.axis
    );
}

fn sim_image(bus: &Bus) -> crate::dialect::tmcl::sim::ModuleImage {
    bus.images().into_iter().next().expect("one module")
}

#[test]
fn the_switches_of_each_motor_are_its_own() {
    let profile = catalogue::by_name("tmcm-6110").unwrap();
    let options = BusOptions {
        switches: Switches {
            right: Some(100_000),
            ..Switches::default()
        },
        motor_switches: vec![(1, Switch::Left, -300)],
        ..BusOptions::default()
    };
    let mut sim = Sim {
        bus: Bus::new(profile, options),
        now: std::time::Duration::ZERO,
    };
    // ROL 1 (command 2) drives motor 1 into its own left switch; motor 0 has none.
    sim.ok(2, 0, 1, 500);
    sim.ok(2, 0, 0, 500);
    sim.wait(3.0);
    assert_eq!(sim.ok(GAP, 1, 1, 0), -300, "motor 1 stopped at its switch");
    assert_eq!(sim.ok(GAP, 11, 1, 0), 1, "motor 1's left switch is active");
    assert_eq!(sim.ok(GAP, 11, 0, 0), 0, "motor 0 has no left switch");
    assert!(sim.ok(GAP, 1, 0, 0) < -300, "motor 0 runs on");
    // The every-motor right switch is at 100000 on each motor; move motor 4 there.
    sim.ok(ROR, 0, 4, 2047);
    sim.wait(5.0);
    assert_eq!(sim.ok(GAP, 10, 4, 0), 1, "motor 4's right switch");
    assert_eq!(sim.ok(GAP, 1, 4, 0), 100_000);
    // The console moves one motor's switch.
    sim.bus
        .set_switch(sim.now, 1, 5, Switch::Home, Some(0))
        .unwrap();
    assert_eq!(sim.ok(GAP, 9, 5, 0), 1, "motor 5 stands at its home switch");
    assert_eq!(sim.ok(GAP, 9, 3, 0), 0);
    let err = sim.bus.set_switch(sim.now, 1, 6, Switch::Home, Some(0));
    assert!(err.unwrap_err().to_string().contains("no motor 6"));
}

#[test]
fn reference_search_homes_one_motor() {
    let profile = catalogue::by_name("tmcm-6110").unwrap();
    let options = BusOptions {
        motor_switches: vec![(2, Switch::Left, -2_000)],
        ..BusOptions::default()
    };
    let mut sim = Sim {
        bus: Bus::new(profile, options),
        now: std::time::Duration::ZERO,
    };
    sim.ok(RFS, 0, 2, 0);
    sim.wait(0.05);
    assert_ne!(sim.ok(RFS, 2, 2, 0), 0, "motor 2 is searching");
    assert_eq!(sim.ok(RFS, 2, 0, 0), 0, "motor 0 is not");
    sim.wait(10.0);
    assert_eq!(sim.ok(RFS, 2, 2, 0), 0, "the search is over");
    assert_eq!(sim.ok(GAP, 1, 2, 0), 0, "the switch edge is position 0");
    sim.ok(MVP, 0, 2, 1000);
    sim.wait(2.0);
    assert_eq!(sim.ok(GAP, 1, 2, 0), 1000);
}

#[test]
fn parameter_numbers_mean_what_the_profile_says() {
    let mut sim = Sim::of("tmcm-6110");
    // AP 130 is the minimum speed of a Gen-A module (plain memory), not the TMCM-142's flag.
    assert_eq!(sim.ok(GAP, 130, 0, 0), 1);
    sim.ok(SAP, 130, 0, 7);
    assert_eq!(sim.ok(GAP, 130, 0, 0), 7);
    // AP 41 is the TMCM-6214's position-compare distance, not an encoder.
    let mut six = Sim::of("tmcm-6214");
    six.ok(SAP, 41, 0, 1234);
    assert_eq!(six.ok(GAP, 41, 0, 0), 1234);
    // On the TMCM-142 AP 130 is live: velocity reached.
    let mut one = Sim::new();
    assert_eq!(one.ok(GAP, 130, 0, 0), 1);
}

#[test]
fn the_version_string_is_the_profiles() {
    for profile in catalogue::all() {
        let mut sim = Sim {
            bus: Bus::new(profile.clone(), BusOptions::default()),
            now: std::time::Duration::ZERO,
        };
        let frame = crate::dialect::tmcl::protocol::CommandFrame {
            address: 1,
            instruction: crate::dialect::tmcl::protocol::Instruction::new(136, 0, 0, 0),
        };
        let out = sim.send(&frame.encode());
        assert_eq!(out.len(), 9, "{}", profile.name);
        assert_eq!(
            &out[1..9],
            profile.sim.version_string.as_bytes(),
            "{}",
            profile.name
        );
    }
}

#[test]
fn a_binary_only_module_refuses_139_and_stays_binary() {
    for name in ["tmcm-1260", "tmcm-6214"] {
        let mut sim = Sim::of(name);
        assert_eq!(sim.status(139, 0, 0, 0), Status::InvalidCommand, "{name}");
        assert_eq!(sim.bus.is_ascii(1), Some(false));
        // Still answering binary frames.
        assert_eq!(sim.ok(GAP, 4, 0, 0), 51_200, "{name}");
    }
    // An ASCII-capable module answers 139 and switches.
    let mut sim = Sim::of("tmcm-6110");
    assert_eq!(sim.status(139, 0, 0, 0), Status::Ok);
    assert_eq!(sim.bus.is_ascii(1), Some(true));
    let answer = sim.line("AGAP 4, 5");
    assert!(answer.ends_with("BA 100 1000\r"), "{answer:?}");
}

#[test]
fn io_follows_the_profiles_port_map() {
    let mut sim = Sim::of("tmcm-6110");
    sim.ok(SIO, 7, 2, 1);
    assert_eq!(sim.ok(GIO, 7, 2, 0), 1, "OUT7");
    assert_eq!(sim.bus.output(sim.now, 1, 7), Some(true));
    assert_eq!(sim.status(SIO, 8, 2, 1), Status::WrongType, "no OUT8");
    assert_eq!(sim.ok(GIO, 7, 0, 0), 0, "IN7");
    sim.bus.set_input(sim.now, 1, 7, true).unwrap();
    assert_eq!(sim.ok(GIO, 7, 0, 0), 1);
    sim.bus.set_analog(sim.now, 1, 8, 4095).unwrap();
    assert_eq!(sim.ok(GIO, 8, 1, 0), 4095, "VIN");
    assert_eq!(
        sim.status(GIO, 1, 1, 0),
        Status::WrongType,
        "port 1 is not analog"
    );
    let mut small = Sim::of("tmcm-1160");
    assert_eq!(
        small.status(GIO, 2, 0, 0),
        Status::WrongType,
        "IN0..IN1 only"
    );
}

#[test]
fn the_position_event_waits_for_every_motor_of_its_mask() {
    let mut sim = Sim::of("tmcm-6110");
    sim.ok(MVP, 0, 0, 1_000);
    sim.ok(MVP, 0, 2, 20_000);
    // Motors 0 and 2 (mask 0b101).
    sim.ok(138, 0, 0, 0b101);
    sim.wait(0.2);
    assert!(
        sim.output().is_empty(),
        "motor 0 has arrived, motor 2 has not"
    );
    sim.wait(5.0);
    let out = sim.output();
    assert_eq!(out.len(), 9, "one event frame: {out:02X?}");
    assert_eq!(out[2], Status::PositionReachedEvent.code());
    // A mask with no motor of the module is refused.
    assert_eq!(sim.status(138, 0, 0, 1 << 6), Status::InvalidValue);
}

#[test]
fn a_bus_of_different_modules() {
    let options = BusOptions {
        addresses: vec![1, 2],
        profiles: vec![(2, catalogue::by_name("tmcm-6110").unwrap())],
        ..BusOptions::default()
    };
    let mut sim = Sim::with(options);
    assert_eq!(
        sim.bus.modules(),
        [(1, "TMCM-142".to_string()), (2, "TMCM-6110".to_string())]
    );
    let version = |sim: &mut Sim, address| {
        let frame = crate::dialect::tmcl::protocol::CommandFrame {
            address,
            instruction: crate::dialect::tmcl::protocol::Instruction::new(136, 0, 0, 0),
        };
        String::from_utf8(sim.send(&frame.encode())[1..9].to_vec()).unwrap()
    };
    assert_eq!(version(&mut sim, 1), "142V1.06");
    assert_eq!(version(&mut sim, 2), "6110V131");
    assert_eq!(sim.frame(1, GAP, 4, 5, 0).status, Status::InvalidValue);
    let six = sim.frame(2, GAP, 4, 5, 0);
    assert_eq!((six.status, six.value), (Status::Ok, 1000));
}

#[test]
fn a_profile_file_without_roles_moves_like_the_tmcm_142() {
    let text = crate::dialect::tmcl::profile::BUILTIN_TOML;
    let cut = text.find("[simulation.axis_roles]").expect("the table");
    let profile = crate::dialect::tmcl::profile::Profile::from_toml(&text[..cut], None).unwrap();
    assert!(profile.sim.axis_roles.is_empty());
    let mut sim = Sim {
        bus: Bus::new(std::sync::Arc::new(profile), BusOptions::default()),
        now: std::time::Duration::ZERO,
    };
    sim.sap(255, 1);
    sim.ok(MVP, 0, 0, 5_000);
    sim.wait(10.0);
    assert_eq!(sim.gap(1), 5_000);
}

#[test]
fn a_role_naming_no_parameter_is_refused() {
    let text = format!(
        "{}\nmax_speed = 99\n",
        crate::dialect::tmcl::profile::BUILTIN_TOML.replace("max_speed = 4\n", "")
    );
    let error = crate::dialect::tmcl::profile::Profile::from_toml(&text, None).unwrap_err();
    assert!(error.contains("axis_roles.max_speed = 99"), "{error}");
    let typo = format!(
        "{}\nmax_sped = 4\n",
        crate::dialect::tmcl::profile::BUILTIN_TOML
    );
    let error = crate::dialect::tmcl::profile::Profile::from_toml(&typo, None).unwrap_err();
    assert!(error.contains("max_sped"), "{error}");
}

#[test]
fn a_boot_loader_answers_136_with_b_and_nothing_else() {
    for (name, expected) in [("tmcm-142", "142B1.06"), ("tmcm-6110", "6110B131")] {
        let options = BusOptions {
            boot_loader: vec![1],
            ..BusOptions::default()
        };
        let mut sim = Sim {
            bus: Bus::new(catalogue::by_name(name).unwrap(), options),
            now: std::time::Duration::ZERO,
        };
        let frame = crate::dialect::tmcl::protocol::CommandFrame {
            address: 1,
            instruction: crate::dialect::tmcl::protocol::Instruction::new(136, 0, 0, 0),
        };
        let out = sim.send(&frame.encode());
        assert_eq!(&out[1..9], expected.as_bytes());
        let identified = catalogue::identify(expected).unwrap();
        assert!(matches!(
            identified,
            catalogue::Identified::BootLoader { .. }
        ));
        assert_eq!(sim.status(GAP, 4, 0, 0), Status::InvalidCommand, "{name}");
        assert_eq!(sim.status(MVP, 0, 0, 100), Status::InvalidCommand);
        assert_eq!(sim.status(139, 0, 0, 0), Status::InvalidCommand);
        assert_eq!(sim.bus.is_ascii(1), Some(false));
        assert_eq!(
            sim.bus.motor(sim.now, 1).unwrap().target,
            0,
            "nothing moved"
        );
    }
}

fn six_with_store(store: &crate::sim::store::MemoryStore) -> Sim {
    let options = BusOptions {
        eeprom: Some(crate::dialect::tmcl::sim::Eeprom::open(Box::new(store.clone())).unwrap()),
        ..BusOptions::default()
    };
    Sim {
        bus: Bus::new(catalogue::by_name("tmcm-6110").unwrap(), options),
        now: std::time::Duration::ZERO,
    }
}

#[test]
fn each_motors_stored_values_survive_a_restart() {
    let store = crate::sim::store::MemoryStore::new();
    let mut sim = six_with_store(&store);
    sim.ok(SAP, 4, 4, 1234);
    sim.ok(STAP, 4, 4, 0);
    sim.ok(SAP, 4, 1, 999); // not stored
    drop(sim);
    let mut sim = six_with_store(&store);
    assert_eq!(sim.ok(GAP, 4, 4, 0), 1234);
    assert_eq!(sim.ok(GAP, 4, 1, 0), 1000);
    assert_eq!(sim.ok(GAP, 4, 0, 0), 1000);
    // RSAP restores one motor's value only.
    sim.ok(SAP, 4, 4, 5);
    sim.ok(SAP, 4, 3, 6);
    sim.ok(8, 4, 4, 0);
    assert_eq!(sim.ok(GAP, 4, 4, 0), 1234);
    assert_eq!(sim.ok(GAP, 4, 3, 0), 6);
}

#[test]
fn a_hostile_state_file_cannot_reach_a_motor_or_bank_the_module_lacks() {
    use crate::sim::store::Store;
    let mut store = crate::sim::store::MemoryStore::new();
    store
        .save(
            "[[module]]\nslot = 1\naxis = [[4, 7], [255, 1]]\n\
             motors = [[200, 4, 5], [5, 4, 55], [6, 4, 66]]\n\
             global = [[9, 0, 1], [3, 27, 2], [0, 64, 228]]\n",
        )
        .unwrap();
    let mut sim = six_with_store(&store);
    assert_eq!(sim.ok(GAP, 4, 0, 0), 7);
    assert_eq!(sim.ok(GAP, 4, 5, 0), 55);
    assert_eq!(sim.status(GAP, 4, 6, 0), Status::InvalidValue);
    // Bank 3 is there (in RAM: its rows are not EEPROM backed, so the file's value is not used).
    assert_eq!(sim.ok(10, 27, 3, 0), 0);
    sim.ok(9, 27, 3, 2);
    assert_eq!(sim.ok(10, 27, 3, 0), 2);
}

#[test]
fn a_program_moves_and_waits_for_one_motor() {
    let mut sim = Sim::of("tmcm-6110");
    // MVP ABS, 4, 3000; WAIT POS, 4, 0; SIO 7, 2, 1; STOP
    sim.download(&[
        (MVP, 0, 4, 3000),
        (27, 1, 4, 0),
        (SIO, 7, 2, 1),
        (28, 0, 0, 0),
    ]);
    sim.ok(129, 1, 0, 0);
    sim.wait(0.05);
    assert_eq!(
        sim.bus.output(sim.now, 1, 7),
        Some(false),
        "still waiting for motor 4"
    );
    sim.wait(3.0);
    assert_eq!(sim.bus.output(sim.now, 1, 7), Some(true));
    assert_eq!(sim.ok(GAP, 1, 4, 0), 3000);
    assert_eq!(sim.ok(GAP, 1, 0, 0), 0);
    // WAIT on a motor the module lacks is a program error, not a crash.
    let mut sim = Sim::of("tmcm-1140");
    sim.download(&[(27, 1, 3, 0), (28, 0, 0, 0)]);
    sim.ok(129, 1, 0, 0);
    sim.wait(0.1);
    assert_eq!(sim.ok(135, 1, 0, 0), 1, "invalid instruction");
}

#[test]
fn a_sweep_of_commands_motors_and_types_gets_one_answer_each() {
    for name in ["tmcm-6110", "tmcm-1260", "tmcm-142"] {
        let mut sim = Sim::of(name);
        let axes = catalogue::by_name(name).unwrap().axes;
        for command in (0u8..=255).filter(|c| !(128..=139).contains(c) && *c != 9) {
            for motor in [0u8, 1, 5, 6, 255] {
                for type_ in [0u8, 1, 255] {
                    for value in [0, -1, i32::MAX] {
                        let reply = sim.frame(1, command, type_, motor, value);
                        let axis_command = matches!(command, 1..=8 | 13);
                        if axis_command && motor >= axes {
                            assert_eq!(
                                reply.status,
                                Status::InvalidValue,
                                "{name}: command {command} motor {motor}"
                            );
                        }
                    }
                }
            }
            sim.wait(0.01);
        }
    }
}

#[test]
fn the_tmc429_divisors_scale_speed_and_acceleration_of_their_motor() {
    let mut sim = Sim::of("tmcm-6110");
    sim.ok(ROR, 0, 0, 1000);
    sim.ok(ROR, 0, 1, 1000);
    sim.wait(1.0);
    let pps = |sim: &mut Sim, m| sim.bus.motor_of(sim.now, 1, m).unwrap().velocity;
    let full = pps(&mut sim, 0);
    assert!((full - 30_517.578125).abs() < 1e-6, "{full}");
    // Pulse divisor one up: the same speed value is half the step rate, on motor 0 only.
    sim.ok(SAP, 154, 0, 4);
    sim.wait(1.0);
    assert!((pps(&mut sim, 0) - full / 2.0).abs() < 1e-6);
    assert_eq!(
        sim.ok(GAP, 3, 0, 0),
        1000,
        "in its own units, the speed is unchanged"
    );
    assert!(
        (pps(&mut sim, 1) - full).abs() < 1e-6,
        "motor 1 keeps its rate"
    );
    sim.ok(MST, 0, 0, 0);
    sim.ok(MST, 0, 1, 0);
    sim.wait(1.0);
    // A move with pulse and ramp divisors up takes longer than the same move without.
    sim.ok(SAP, 153, 0, 9);
    let start = sim.ok(GAP, 1, 0, 0);
    let start_1 = sim.ok(GAP, 1, 1, 0);
    sim.ok(MVP, 0, 0, start + 20_000);
    sim.ok(MVP, 0, 1, start_1 + 20_000);
    let arrived = |sim: &mut Sim, m| sim.ok(GAP, 8, m, 0) == 1;
    let mut waited = 0;
    while !arrived(&mut sim, 1) {
        sim.wait(0.01);
        waited += 1;
    }
    assert!(!arrived(&mut sim, 0), "motor 0 is slower");
    while !arrived(&mut sim, 0) {
        sim.wait(0.01);
        waited += 1;
        assert!(waited < 10_000, "motor 0 never arrived");
    }
    assert_eq!(sim.ok(GAP, 1, 0, 0), start + 20_000);
    // RSAP brings back the stored default, and the rate with it.
    sim.ok(ROR, 0, 0, 1000);
    sim.ok(8, 154, 0, 0);
    sim.wait(2.0);
    assert!((pps(&mut sim, 0) - full).abs() < 1e-6);
}

#[test]
fn each_motor_has_its_own_coordinates() {
    const SCO: u8 = 30;
    const GCO: u8 = 31;
    const CCO: u8 = 32;
    let store = crate::sim::store::MemoryStore::new();
    let mut sim = six_with_store(&store);
    sim.ok(9, 84, 0, 1); // coordinates kept in EEPROM
    sim.ok(SCO, 1, 3, 500);
    sim.ok(SCO, 1, 0, 700);
    assert_eq!(sim.ok(GCO, 1, 3, 0), 500);
    assert_eq!(sim.ok(GCO, 1, 0, 0), 700);
    assert_eq!(sim.ok(GCO, 1, 2, 0), 0);
    assert_eq!(sim.status(SCO, 1, 6, 1), Status::InvalidValue, "no motor 6");
    // MVP COORD moves the motor to its own coordinate.
    sim.ok(MVP, 2, 3, 1);
    sim.wait(2.0);
    assert_eq!(sim.ok(GAP, 1, 3, 0), 500);
    assert_eq!(sim.ok(GAP, 1, 0, 0), 0);
    // CCO captures the motor's own position.
    sim.ok(CCO, 2, 3, 0);
    assert_eq!(sim.ok(GCO, 2, 3, 0), 500);
    assert_eq!(sim.ok(GCO, 2, 0, 0), 0);
    drop(sim);
    let mut sim = six_with_store(&store);
    assert_eq!(sim.ok(GCO, 1, 3, 0), 500, "kept per motor across a restart");
    assert_eq!(sim.ok(GCO, 1, 0, 0), 700);
    assert_eq!(sim.ok(GCO, 2, 3, 0), 500);
}

#[test]
fn an_unconfirmed_interface_can_be_simulated_either_way() {
    let profile = catalogue::by_name("tmcm-3110").unwrap();
    let with = |ascii| {
        let options = BusOptions {
            quirks: crate::dialect::tmcl::sim::Quirks {
                ascii,
                ..Default::default()
            },
            ..BusOptions::default()
        };
        Sim {
            bus: Bus::new(profile.clone(), options),
            now: std::time::Duration::ZERO,
        }
    };
    let mut answers = with(true);
    assert_eq!(answers.status(139, 0, 0, 0), Status::Ok);
    assert_eq!(answers.bus.is_ascii(1), Some(true));
    let mut silent = with(false);
    assert_eq!(silent.status(139, 0, 0, 0), Status::InvalidCommand);
    assert_eq!(silent.bus.is_ascii(1), Some(false));
    assert_eq!(silent.ok(GAP, 4, 2, 0), 1000, "still binary");
}
