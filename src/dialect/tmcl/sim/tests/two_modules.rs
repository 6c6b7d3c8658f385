//! A bus of two modules: each answers only its own address, in both modes.

use crate::dialect::tmcl::protocol::{CommandFrame, Instruction, ReplyFrame, Status};
use crate::dialect::tmcl::sim::BusOptions;

use super::Sim;

fn two() -> Sim {
    Sim::with(BusOptions {
        addresses: vec![1, 3],
        ..BusOptions::default()
    })
}

#[test]
fn each_module_answers_its_own_address_in_binary() {
    let mut sim = two();
    sim.frame(3, 5, 4, 0, 333);
    let one = sim.frame(1, 6, 4, 0, 0);
    let three = sim.frame(3, 6, 4, 0, 0);
    assert_eq!((one.module, one.value), (1, 1_000_000));
    assert_eq!((three.module, three.value), (3, 333));
    let nobody = CommandFrame {
        address: 2,
        instruction: Instruction::new(6, 4, 0, 0),
    };
    assert!(sim.send(&nobody.encode()).is_empty());
}

#[test]
fn each_module_answers_its_own_address_in_ascii() {
    let mut sim = two();
    for address in [1, 3] {
        sim.frame(address, 9, 67, 0, 0x20);
    }
    let reply = sim.frame(3, 139, 0, 0, 0);
    assert_eq!(reply.status, Status::Ok);
    // Module 3 speaks ASCII, module 1 still binary.
    assert_eq!(sim.line("CSAP 4, 0, 77"), "BC 100 77\r");
    assert_eq!(sim.line("AGAP 4, 0"), "", "module 1 is not in ASCII mode");
    sim.wait(1.0); // let module 1's receiver drop the text it took for a frame
    let one = sim.frame(1, 6, 4, 0, 0);
    assert_eq!(one.value, 1_000_000);
    sim.frame(1, 139, 0, 0, 0);
    assert_eq!(sim.line("AGAP 4, 0"), "BA 100 1000000\r");
    assert_eq!(sim.line("CGAP 4, 0"), "BC 100 77\r");
}

#[test]
fn a_module_can_be_given_a_new_address() {
    let mut sim = two();
    let reply = sim.frame(1, 9, 66, 0, 7);
    assert_eq!(reply.module, 7, "the reply already carries the new address");
    let moved = sim.frame(7, 6, 1, 0, 0);
    assert_eq!(moved.status, Status::Ok);
    let old = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 1, 0, 0),
    };
    assert!(sim.send(&old.encode()).is_empty());
    let _: ReplyFrame = sim.frame(3, 6, 1, 0, 0);
}

#[test]
fn the_console_steers_each_module_and_says_what_it_cannot_do() {
    use crate::sim::Device;
    use std::time::Duration;
    let mut sim = two();
    let mut say = |command: &str| {
        sim.bus
            .control(Duration::ZERO, command)
            .map(|r| r.unwrap_or_else(|e| format!("error: {e}")))
    };
    let cases = [
        ("input 3 1", "input 3 = 1"),
        ("@3 input 4 low", "input 4 = 0"),
        ("input x 1", "error: 'x' is not a port number"),
        ("input 3 maybe", "error: 'maybe' is not a level; use 0 or 1"),
        ("analog 0 512", "analog 0 = 512"),
        ("analog 0 lots", "error: 'lots' is not a number"),
        ("switch left -500", "switch left at -500"),
        ("@3 switch home 0", "switch home at 0"),
        ("switch ref off", "switch home at off"),
        (
            "switch up 5",
            "error: 'up' is not a switch; use left, right or home",
        ),
        (
            "switch right far",
            "error: 'far' is not a position (or 'off')",
        ),
        ("switch x left 5", "error: 'x' is not a motor number"),
        ("motor", "position 0 target 0 velocity 0.000 pps reached 1"),
        ("motor 4", "error: no module 1 with a motor 4"),
        ("@x motor", "error: '@x' is not a module address"),
    ];
    for (command, expected) in cases {
        assert_eq!(say(command).as_deref(), Some(expected), "{command}");
    }
    assert_eq!(say("not a bus command"), None);
    assert_eq!(say("@3 faults"), None);
}
