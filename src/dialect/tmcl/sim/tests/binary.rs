//! Binary TMCL: every command of the table, status codes, addressing, checksums.

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::profile::commands::{CommandSpec, OperandKind};
use crate::dialect::tmcl::protocol::frame::decode_version_string;
use crate::dialect::tmcl::protocol::{CommandFrame, Instruction, ReplyFrame, Status};
use crate::dialect::tmcl::sim::control_cmd::Controlled;

use crate::sim::Device;

use super::Sim;

/// A valid instruction for a command, built from its operand layout.
fn sensible(spec: &CommandSpec) -> Instruction {
    let mut i = Instruction::new(spec.number, 0, 0, 0);
    for operand in &spec.operands {
        match operand.kind {
            OperandKind::Keyword | OperandKind::Type => {
                i.type_ = spec.keywords.last().map_or(0, |k| k.value)
            }
            OperandKind::AxisParam => i.type_ = 4,
            OperandKind::Bank | OperandKind::IoBank => i.motor = 2,
            OperandKind::Value => i.value = spec.value_range.map_or(1, |(lo, _)| lo.max(1) as i32),
            _ => {}
        }
    }
    i
}

#[test]
fn every_command_of_the_table_gets_the_answer_its_kind_calls_for() {
    let profile = Profile::builtin();
    for spec in profile.commands.iter() {
        if [132, 137, 139].contains(&spec.number) {
            continue; // no reply or a mode change: tested on their own
        }
        let mut sim = Sim::new();
        let i = sensible(spec);
        let reply = sim.frame(1, i.command.number(), i.type_, i.motor, i.value);
        assert_eq!(reply.command.number(), spec.number);
        let expected = if !spec.direct_mode {
            Status::InvalidCommand
        } else if spec.mnemonic == "SAC" || spec.mnemonic.starts_with("UF") {
            Status::NotAvailable // no user functions installed
        } else {
            Status::Ok
        };
        assert_eq!(
            reply.status,
            expected,
            "{} ({}): {i:?}",
            spec.display_name(),
            spec.number
        );
    }
}

#[test]
fn commands_the_module_does_not_have_are_invalid() {
    let mut sim = Sim::new();
    for command in [0, 16, 17, 18, 25, 26, 37, 38, 40, 100, 140, 255] {
        assert_eq!(
            sim.status(command, 0, 0, 0),
            Status::InvalidCommand,
            "{command}"
        );
    }
}

#[test]
fn replies_carry_host_and_module_address_and_echo_the_value() {
    let mut sim = Sim::new();
    let reply = sim.frame(1, 1, 0, 0, 1234);
    assert_eq!(
        reply,
        ReplyFrame {
            host: 2,
            module: 1,
            status: Status::Ok,
            command: 1.into(),
            value: 1234
        }
    );
    sim.ok(9, 76, 0, 7);
    assert_eq!(sim.frame(1, 3, 0, 0, 0).host, 7);
}

#[test]
fn a_bad_checksum_to_this_module_answers_status_1() {
    let mut sim = Sim::new();
    let mut bytes = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 1, 0, 0),
    }
    .encode();
    bytes[8] = bytes[8].wrapping_add(1);
    let out = sim.send(&bytes);
    let reply = ReplyFrame::decode(out[..].try_into().unwrap()).unwrap();
    assert_eq!(
        (reply.status, reply.command.number(), reply.value),
        (Status::WrongChecksum, 0, 0)
    );
    // To another module: silence.
    bytes[0] = 5;
    assert!(sim.send(&bytes).is_empty());
}

#[test]
fn frames_for_other_addresses_are_ignored() {
    let mut sim = Sim::new();
    let frame = CommandFrame {
        address: 2,
        instruction: Instruction::new(1, 0, 0, 100),
    };
    assert!(sim.send(&frame.encode()).is_empty());
    assert_eq!(sim.gap(2), 0, "the motor was not started");
}

#[test]
fn frames_split_anywhere_are_assembled_and_stale_halves_dropped() {
    let mut sim = Sim::new();
    let bytes = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 4, 0, 0),
    }
    .encode();
    assert!(sim.send(&bytes[..4]).is_empty());
    assert_eq!(sim.send(&bytes[4..]).len(), 9);
    // Half a frame, then silence longer than the frame time-out: the half is forgotten.
    assert!(sim.send(&bytes[..5]).is_empty());
    sim.wait(0.5);
    assert_eq!(sim.send(&bytes).len(), 9);
}

#[test]
fn motor_other_than_0_is_an_invalid_value() {
    let mut sim = Sim::new();
    assert_eq!(sim.status(6, 1, 1, 0), Status::InvalidValue);
    assert_eq!(sim.status(1, 0, 2, 100), Status::InvalidValue);
    assert_eq!(sim.status(4, 0, 1, 100), Status::InvalidValue);
}

#[test]
fn parameters_follow_their_access_rules_and_ranges() {
    let mut sim = Sim::new();
    assert_eq!(sim.gap(4), 1_000_000, "default from the profile");
    sim.sap(4, 500_000);
    assert_eq!(sim.gap(4), 500_000);
    assert_eq!(
        sim.status(5, 99, 0, 1),
        Status::WrongType,
        "unknown parameter"
    );
    assert_eq!(sim.status(6, 99, 0, 0), Status::WrongType);
    assert_eq!(sim.status(5, 8, 0, 1), Status::WrongType, "read-only");
    assert_eq!(
        sim.status(5, 6, 0, 16),
        Status::InvalidValue,
        "out of range"
    );
    assert_eq!(sim.status(5, 5, 0, 0), Status::InvalidValue);
    assert_eq!(
        sim.status(7, 0, 0, 0),
        Status::WrongType,
        "AP0 has no EEPROM copy"
    );
    // Global parameters.
    sim.ok(9, 10, 2, -77);
    assert_eq!(sim.ok(10, 10, 2, 0), -77);
    assert_eq!(
        sim.status(10, 56, 2, 0),
        Status::WrongType,
        "56 user variables"
    );
    assert_eq!(sim.status(9, 128, 0, 1), Status::WrongType, "read-only");
    assert_eq!(
        sim.status(10, 0, 1, 0),
        Status::WrongType,
        "bank 1 is unknown"
    );
    assert_eq!(sim.status(10, 0, 9, 0), Status::WrongType);
}

#[test]
fn store_and_restore_move_values_between_ram_and_eeprom() {
    let mut sim = Sim::new();
    sim.sap(4, 123_456);
    sim.ok(7, 4, 0, 0);
    sim.sap(4, 7);
    sim.ok(8, 4, 0, 0);
    assert_eq!(sim.gap(4), 123_456);
    sim.ok(9, 3, 2, 99);
    sim.ok(11, 3, 2, 0);
    sim.ok(9, 3, 2, 1);
    sim.ok(12, 3, 2, 0);
    assert_eq!(sim.ok(10, 3, 2, 0), 99);
}

#[test]
fn a_locked_eeprom_refuses_to_store() {
    let mut sim = Sim::new();
    sim.ok(9, 73, 0, 1234);
    assert_eq!(sim.ok(10, 73, 0, 0), 1);
    assert_eq!(sim.status(7, 4, 0, 0), Status::EepromLocked);
    assert_eq!(sim.status(11, 0, 2, 0), Status::EepromLocked);
    assert_eq!(
        sim.status(9, 77, 0, 1),
        Status::EepromLocked,
        "EEPROM-only GP"
    );
    assert_eq!(sim.status(9, 73, 0, 5), Status::InvalidValue);
    sim.ok(9, 73, 0, 4321);
    assert_eq!(sim.ok(10, 73, 0, 0), 0);
    sim.ok(7, 4, 0, 0);
}

#[test]
fn motion_commands_start_and_stop_the_motor() {
    let mut sim = Sim::new();
    sim.sap(255, 1); // pps
    sim.sap(5, 1000);
    sim.ok(1, 0, 0, 2000);
    assert_eq!(sim.gap(2), 2000);
    sim.wait(1.0);
    assert_eq!(sim.gap(3), 1000, "ramping with 1000 pps²");
    assert_eq!(sim.gap(1), 500);
    sim.ok(3, 0, 0, 0);
    assert_eq!(sim.gap(2), 0);
    sim.wait(1.0);
    assert_eq!(sim.gap(3), 0);
    assert_eq!(sim.gap(1), 1000);
    sim.ok(2, 0, 0, 1000);
    assert_eq!(sim.gap(2), -1000);
    assert_eq!(
        sim.status(1, 0, 0, -5),
        Status::InvalidValue,
        "range 0..2^31-1"
    );
}

#[test]
fn mvp_abs_rel_and_coord_set_the_target() {
    let mut sim = Sim::new();
    assert_eq!(sim.ok(4, 0, 0, 1000), 1000);
    assert_eq!(sim.gap(0), 1000);
    assert_eq!(sim.ok(4, 1, 0, -300), 700, "REL answers the new target");
    assert_eq!(sim.gap(0), 700);
    sim.ok(30, 3, 0, -4242);
    assert_eq!(sim.ok(31, 3, 0, 0), -4242);
    sim.ok(4, 2, 0, 3);
    assert_eq!(sim.gap(0), -4242);
    assert_eq!(sim.status(4, 3, 0, 0), Status::WrongType, "no MVP type 3");
    assert_eq!(
        sim.status(4, 2, 0, 21),
        Status::InvalidValue,
        "coordinates 0..20"
    );
}

#[test]
fn coordinates_capture_and_take_the_accumulator() {
    let mut sim = Sim::new();
    sim.ok(1, 0, 0, 100_000);
    sim.wait(2.0);
    sim.ok(32, 5, 0, 0);
    let captured = sim.ok(31, 5, 0, 0);
    assert_ne!(captured, 0);
    assert!(captured.abs_diff(sim.gap(1)) == 0);
    assert_eq!(sim.status(30, 21, 0, 1), Status::WrongType);
    sim.ok(39, 5, 0, 0); // ACO: the accumulator is 0 in direct mode
    assert_eq!(sim.ok(31, 5, 0, 0), 0);
}

#[test]
fn accumulator_commands_write_parameters() {
    let mut sim = Sim::new();
    sim.ok(34, 4, 0, 0); // AAP 4: accumulator (0) to max speed
    assert_eq!(sim.gap(4), 0);
    sim.ok(35, 7, 2, 0);
    assert_eq!(sim.ok(10, 7, 2, 0), 0);
}

#[test]
fn inputs_read_what_was_set_and_outputs_read_back() {
    let mut sim = Sim::new();
    assert_eq!(sim.ok(15, 3, 0, 0), 0);
    sim.bus.set_input(sim.now, 1, 3, true).unwrap();
    assert_eq!(sim.ok(15, 3, 0, 0), 1);
    sim.bus.set_analog(sim.now, 1, 1, 512).unwrap();
    assert_eq!(sim.ok(15, 1, 1, 0), 512);
    sim.ok(14, 2, 2, 1);
    assert_eq!(sim.ok(15, 2, 2, 0), 1);
    assert_eq!(sim.bus.output(sim.now, 1, 2), Some(true));
    assert_eq!(sim.status(14, 9, 2, 1), Status::WrongType, "no output 9");
    assert_eq!(
        sim.status(14, 0, 0, 1),
        Status::InvalidValue,
        "outputs are bank 2"
    );
    assert_eq!(sim.status(14, 0, 2, 2), Status::InvalidValue, "0 or 1");
    assert_eq!(sim.status(15, 0, 5, 0), Status::InvalidValue, "no bank 5");
    assert!(sim.bus.set_analog(sim.now, 1, 1, 5000).is_err());
    assert!(sim.bus.set_input(sim.now, 1, 1, true).is_err());
}

#[test]
fn firmware_version_as_string_and_number() {
    let mut sim = Sim::new();
    let out = sim.send(
        &CommandFrame {
            address: 1,
            instruction: Instruction::new(136, 0, 0, 0),
        }
        .encode(),
    );
    let (host, text) = decode_version_string(out[..].try_into().unwrap());
    assert_eq!((host, text.as_str()), (2, "142V1.06"));
    assert_eq!(sim.ok(136, 1, 0, 0), 0x0106);
    assert_eq!(sim.status(136, 2, 0, 0), Status::WrongType);
}

#[test]
fn factory_reset_sends_no_reply_and_restores_defaults() {
    let mut sim = Sim::new();
    sim.sap(4, 5);
    sim.ok(7, 4, 0, 0);
    sim.ok(9, 0, 2, 42);
    sim.ok(11, 0, 2, 0);
    assert_eq!(
        sim.status(137, 0, 0, 1),
        Status::InvalidValue,
        "must be 1234"
    );
    let silent = sim.send(
        &CommandFrame {
            address: 1,
            instruction: Instruction::new(137, 0, 0, 1234),
        }
        .encode(),
    );
    assert!(silent.is_empty());
    assert_eq!(sim.gap(4), 1_000_000);
    assert_eq!(sim.ok(10, 0, 2, 0), 0);
}

#[test]
fn download_stores_instructions_and_memory_reads_them_back() {
    let mut sim = Sim::new();
    assert_eq!(sim.ok(10, 129, 0, 0), 0, "GP129: not in download mode");
    sim.ok(132, 0, 0, 10);
    let stored = sim.frame(1, 4, 1, 0, -5000);
    assert_eq!(stored.status, Status::Stored);
    assert_eq!(
        sim.frame(1, 22, 0, 0, 10).status,
        Status::Stored,
        "program-only too"
    );
    sim.ok(133, 0, 0, 0);
    assert_eq!(sim.ok(10, 129, 0, 0), 0);
    assert_eq!(sim.gap(0), 0, "stored, not executed");
    assert_eq!(sim.ok(134, 0, 0, 10), -5000);
    assert_eq!(sim.ok(134, 1, 0, 10), 4 << 16 | 1 << 8);
    assert_eq!(sim.ok(134, 1, 0, 11), 22 << 16);
    assert_eq!(sim.ok(134, 0, 0, 11), 10);
    assert_eq!(sim.status(134, 0, 0, 2048), Status::InvalidValue);
    assert_eq!(sim.status(132, 0, 0, 4000), Status::InvalidValue);
}

#[test]
fn code_protection_guards_memory() {
    let mut sim = Sim::new();
    sim.ok(132, 0, 0, 0);
    sim.frame(1, 3, 0, 0, 0);
    sim.ok(133, 0, 0, 0);
    sim.ok(9, 81, 0, 3);
    assert_eq!(sim.status(134, 0, 0, 0), Status::NotAvailable);
    assert_eq!(sim.status(132, 0, 0, 0), Status::NotAvailable);
    sim.ok(9, 81, 0, 0);
    assert_eq!(
        sim.ok(134, 1, 0, 0),
        0,
        "dropping protection erased the program"
    );
}

#[test]
fn application_status_and_reset() {
    let mut sim = Sim::new();
    assert_eq!(sim.ok(135, 0, 0, 0), 0);
    sim.ok(131, 0, 0, 0);
    assert_eq!(sim.ok(135, 0, 0, 0), 3);
    assert_eq!(sim.ok(10, 128, 0, 0), 3);
    assert_eq!(sim.ok(10, 130, 0, 0), 0);
    sim.ok(128, 0, 0, 0);
    assert_eq!(sim.ok(135, 0, 0, 0), 0);
}

#[test]
fn tick_timer_counts_milliseconds_and_can_be_set() {
    let mut sim = Sim::new();
    sim.wait(1.5);
    assert_eq!(sim.ok(10, 132, 0, 0), 1500);
    sim.ok(9, 132, 0, 10);
    sim.wait(0.25);
    assert_eq!(sim.ok(10, 132, 0, 0), 260);
    let a = sim.ok(10, 133, 0, 0);
    let b = sim.ok(10, 133, 0, 0);
    assert_ne!(a, b, "random numbers change");
}

#[test]
fn position_reached_event_sends_a_second_reply_on_arrival() {
    let mut sim = Sim::new();
    sim.sap(255, 1);
    sim.sap(4, 1000);
    sim.sap(5, 1000);
    assert_eq!(sim.ok(138, 0, 0, 1), 1);
    sim.ok(4, 0, 0, 3000); // 1 s up, 2 s cruise, 1 s down
    let due = sim.bus.next_due(sim.now).unwrap();
    assert!(
        due.as_secs_f64() - 4.0 < 1e-6 && due.as_secs_f64() >= 4.0,
        "{due:?}"
    );
    sim.at(3.999);
    assert!(sim.output().is_empty());
    sim.at(4.0);
    let out = sim.output();
    let event = ReplyFrame::decode(out[..].try_into().unwrap()).unwrap();
    assert_eq!(
        (event.status, event.command.number(), event.value),
        (Status::PositionReachedEvent, 138, 1)
    );
    // Type 0 fires once.
    sim.ok(4, 0, 0, 0);
    sim.wait(100.0);
    assert!(sim.output().is_empty());
}

#[test]
fn enter_ascii_mode_replies_then_speaks_ascii() {
    let mut sim = Sim::new();
    assert_eq!(sim.ok(139, 0, 0, 0), 0);
    assert_eq!(sim.line("AGAP 4, 0"), "AGAP 4, 0\rBA 100 1000000\r");
}

#[test]
fn calculations_in_direct_mode_work_on_the_one_accumulator() {
    let mut sim = Sim::new();
    assert_eq!(sim.status(19, 9, 0, 700), Status::Ok); // CALC LOAD, 700
    assert_eq!(sim.status(19, 0, 0, 11), Status::Ok); // CALC ADD, 11
    assert_eq!(sim.status(19, 3, 0, 0), Status::InvalidValue); // CALC DIV, 0
    assert_eq!(sim.status(33, 9, 0, 0), Status::Ok); // CALCX LOAD: X := 711
    assert_eq!(sim.status(34, 4, 0, 0), Status::Ok); // AAP 4, 0
    assert_eq!(sim.frame(1, 6, 4, 0, 0).value, 711); // GAP 4, 0
}

#[test]
fn the_type_byte_of_134_and_135_is_dont_care_beyond_the_extension() {
    // The profile marks both type_ignored (manual §6.5: "don't care"); only type 1, the
    // simulator's documented extension, answers differently.
    let mut sim = Sim::new();
    sim.ok(132, 0, 0, 0);
    sim.frame(1, 4, 1, 0, -5000);
    sim.ok(133, 0, 0, 0);
    for type_ in [0, 2, 7, 255] {
        assert_eq!(sim.ok(134, type_, 0, 0), -5000, "134 type {type_}");
        assert_eq!(sim.ok(135, type_, 0, 0), 0, "135 type {type_}: stopped");
    }
    assert_eq!(sim.ok(134, 1, 0, 0), 4 << 16 | 1 << 8);
    // 136 selects string or binary by its type: not ignored.
    assert_eq!(sim.status(136, 2, 0, 0), Status::WrongType);
}

#[test]
fn stgp_and_rsgp_take_the_user_variable_bank_only() {
    let mut sim = Sim::new();
    sim.ok(11, 3, 2, 0);
    sim.ok(12, 3, 2, 0);
    for command in [11, 12] {
        assert_eq!(sim.status(command, 67, 0, 0), Status::InvalidValue);
    }
    // SGP and GGP keep every bank.
    sim.ok(9, 67, 0, 0x21);
    assert_eq!(sim.ok(10, 67, 0, 0), 0x21);
}
