//! Interrupts in the simulated program: a timer interrupt counting in a user variable, with the
//! manual clock; the program's context saved and restored around the handler.

use super::Sim;
use crate::dialect::tmcl::sim::control_cmd::Controlled;

const GAP: u8 = 6;
const SGP: u8 = 9;
const GGP: u8 = 10;
const CALC: u8 = 19;
const JA: u8 = 22;
const EI: u8 = 25;
const DI: u8 = 26;
const WAIT: u8 = 27;
const AGP: u8 = 35;
const VECT: u8 = 37;
const RETI: u8 = 38;

/// Timer 0 every `period` ms counts in user variable 0; the main loop is `main`, from address 4.
fn counting(main: &[(u8, u8, u8, i32)], period: i32) -> Vec<(u8, u8, u8, i32)> {
    let handler = 4 + main.len() as i32;
    let mut program = vec![
        (VECT, 0, 0, handler),
        (SGP, 0, 3, period),
        (EI, 0, 0, 0),
        (EI, 255, 0, 0),
    ];
    program.extend_from_slice(main);
    program.extend_from_slice(&[
        (GGP, 0, 2, 0),
        (CALC, 0, 0, 1),
        (AGP, 0, 2, 0),
        (RETI, 0, 0, 0),
    ]);
    program
}

#[test]
fn a_timer_interrupt_counts_in_a_user_variable() {
    let mut sim = Sim::of("tmcm-1140");
    sim.download(&counting(&[(JA, 0, 0, 4)], 100));
    sim.ok(129, 0, 0, 0);
    sim.wait(1.05);
    assert_eq!(sim.ok(GGP, 0, 2, 0), 10, "ten ticks of 100 ms in 1.05 s");
    sim.wait(1.0);
    assert_eq!(sim.ok(GGP, 0, 2, 0), 20);
    assert_eq!(sim.ok(135, 0, 0, 0), 1, "still running");
}

#[test]
fn a_wait_goes_on_after_the_handler_and_the_accumulator_is_restored() {
    // Main loop: accumulator 7, a long WAIT (100 ticks of 10 ms), then a copy of the
    // accumulator into variable 1; the handler changes the accumulator meanwhile.
    let main = [
        (CALC, 9, 0, 7),
        (WAIT, 0, 0, 100),
        (AGP, 1, 2, 0),
        (JA, 0, 0, 4),
    ];
    let mut sim = Sim::of("tmcm-6110");
    sim.download(&counting(&main, 250));
    sim.ok(129, 0, 0, 0);
    sim.wait(0.9);
    assert_eq!(sim.ok(GGP, 0, 2, 0), 3, "three ticks during the wait");
    assert_eq!(sim.ok(GGP, 1, 2, 0), 0, "the wait is not over");
    sim.wait(0.2);
    assert_eq!(
        sim.ok(GGP, 1, 2, 0),
        7,
        "the wait ended at 1 s; accumulator restored"
    );
}

#[test]
fn di_stops_the_timer_s_interrupts_and_a_module_without_vectors_refuses_them() {
    let mut sim = Sim::of("tmcm-1140");
    // After the first tick's handler, the main program disables timer 0.
    let main = [(WAIT, 0, 0, 15), (DI, 0, 0, 0), (JA, 0, 0, 6)];
    sim.download(&counting(&main, 100));
    sim.ok(129, 0, 0, 0);
    sim.wait(2.0);
    assert_eq!(sim.ok(GGP, 0, 2, 0), 1);
    // The TMCM-142's table has no interrupt commands: EI stops its program as invalid.
    let mut sim = Sim::of("tmcm-142");
    sim.download(&[(EI, 255, 0, 0), (JA, 0, 0, 0)]);
    sim.ok(129, 0, 0, 0);
    sim.wait(0.1);
    assert_eq!(sim.ok(135, 0, 0, 0), 0, "stopped");
    assert_eq!(sim.ok(135, 1, 0, 0), 1, "on an invalid instruction");
    assert_eq!(sim.ok(GGP, 130, 0, 0), 0, "at EI");
}

/// Counting in user variable 0 on interrupt `vector`, after `setup` (from address 1).
fn counting_on(vector: u8, setup: &[(u8, u8, u8, i32)]) -> Vec<(u8, u8, u8, i32)> {
    let main = 3 + setup.len() as i32;
    let handler = main + 1;
    let mut program = vec![(VECT, vector, 0, handler)];
    program.extend_from_slice(setup);
    program.extend_from_slice(&[(EI, vector, 0, 0), (EI, 255, 0, 0), (JA, 0, 0, main)]);
    program.extend_from_slice(&[
        (GGP, 0, 2, 0),
        (CALC, 0, 0, 1),
        (AGP, 0, 2, 0),
        (RETI, 0, 0, 0),
    ]);
    program
}

#[test]
fn an_input_interrupt_fires_on_the_edges_its_trigger_asks_for() {
    let mut sim = Sim::of("tmcm-1140");
    // Input 1 (vector 40), rising edges only (SGP 40, 3, 1).
    sim.download(&counting_on(40, &[(SGP, 40, 3, 1)]));
    sim.ok(129, 0, 0, 0);
    sim.wait(0.1);
    assert_eq!(sim.ok(GGP, 0, 2, 0), 0);
    for (high, count) in [(true, 1), (false, 1), (true, 2)] {
        sim.bus.set_input(sim.now, 1, 1, high).unwrap();
        sim.wait(0.1);
        assert_eq!(sim.ok(GGP, 0, 2, 0), count, "input 1 {high}");
    }
    // Another input has no effect.
    sim.bus.set_input(sim.now, 1, 2, true).unwrap();
    sim.wait(0.1);
    assert_eq!(sim.ok(GGP, 0, 2, 0), 2);
}

#[test]
fn the_position_reached_interrupt_fires_when_the_motor_arrives() {
    const MVP: u8 = 4;
    let mut sim = Sim::of("tmcm-1140");
    sim.download(&counting_on(3, &[(MVP, 0, 0, 500)]));
    sim.ok(129, 0, 0, 0);
    sim.wait(10.0);
    assert_eq!(sim.ok(GAP, 1, 0, 0), 500);
    assert_eq!(sim.ok(GGP, 0, 2, 0), 1, "arrived once");
    assert_eq!(sim.ok(135, 0, 0, 0), 1, "the main loop goes on");
}

#[test]
fn a_limit_switch_stopping_the_motor_raises_its_stop_switch_interrupt() {
    use crate::dialect::tmcl::profile::catalogue;
    use crate::dialect::tmcl::sim::{Bus, BusOptions, Switch};
    const ROR: u8 = 1;
    let options = BusOptions {
        motor_switches: vec![(0, Switch::Right, 3_000)],
        ..BusOptions::default()
    };
    let mut sim = Sim {
        bus: Bus::new(catalogue::by_name("tmcm-1140").unwrap(), options),
        now: std::time::Duration::ZERO,
    };
    // Right stop switch 0 is vector 28, its trigger SGP 28, 3, 1.
    sim.download(&counting_on(28, &[(SGP, 28, 3, 1), (ROR, 0, 0, 1000)]));
    sim.ok(129, 0, 0, 0);
    sim.wait(30.0);
    assert_eq!(
        sim.ok(GAP, 3, 0, 0),
        0,
        "the right switch stopped the motor"
    );
    assert_eq!(sim.ok(GGP, 0, 2, 0), 1);
}
