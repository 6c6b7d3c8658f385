//! The program runner: the manual's test2 program, program control (129 run, 128 stop, 130 step,
//! 131 reset, 135 status), arithmetic and jumps, waits, and the errors that stop a program.

use crate::dialect::tmcl::protocol::Status;
use crate::dialect::tmcl::sim::{BusOptions, Eeprom, Switches};
use crate::sim::Device;
use crate::sim::store::MemoryStore;

use super::Sim;

/// One stored instruction: (command, type, motor, value).
type Word = (u8, u8, u8, i32);

/// test2.tmc (manual §5.2), assembled by hand.
const TEST2: [Word; 13] = [
    (2, 0, 0, 500_000),    // 0: ROL 0, 500000
    (27, 0, 0, 500),       // 1: WAIT TICKS, 0, 500
    (3, 0, 0, 0),          // 2: MST 0
    (1, 0, 0, 250_000),    // 3: ROR 0, 250000
    (27, 0, 0, 500),       // 4: WAIT TICKS, 0, 500
    (3, 0, 0, 0),          // 5: MST 0
    (5, 4, 0, 500_000),    // 6: SAP 4, 0, 500000
    (5, 5, 0, 50_000),     // 7: SAP 5, 0, 50000
    (4, 0, 0, 1_000_000),  // 8: Loop: MVP ABS, 0, 1000000
    (27, 1, 0, 0),         // 9: WAIT POS, 0, 0
    (4, 0, 0, -1_000_000), // 10: MVP ABS, 0, -1000000
    (27, 1, 0, 0),         // 11: WAIT POS, 0, 0
    (22, 0, 0, 8),         // 12: JA Loop
];

fn status(sim: &mut Sim) -> (i32, i32, i32) {
    // (application status, program counter, last program error)
    (
        sim.ok(135, 0, 0, 0),
        sim.ok(10, 130, 0, 0),
        sim.ok(135, 1, 0, 0),
    )
}

#[test]
fn test2_swings_between_the_two_positions_while_gap_is_answered() {
    let mut sim = Sim::new();
    sim.download(&TEST2);
    sim.ok(138, 1, 0, 1); // a second reply on every arrival
    assert_eq!(sim.ok(129, 0, 0, 0), 0);
    assert_eq!(status(&mut sim).0, 1, "running");
    sim.at(2.0);
    assert!(sim.gap(3) < 0, "ROL: turning left");
    assert_eq!(sim.ok(10, 130, 0, 0), 1, "in WAIT TICKS");
    sim.at(7.0);
    assert!(sim.gap(3) > 0, "ROR: turning right");
    // The swing, independently: 2,000,000 steps at 500000 units (x 15625/2^20 pps) and
    // 50000 pps², plus the instruction after each WAIT POS.
    let v = 500_000.0 * 15_625.0 / 1_048_576.0;
    let a = 50_000.0;
    let swing = 2_000_000.0 / v + v / a;
    let mut arrivals = Vec::new();
    while arrivals.len() < 4 {
        let due = sim.bus.next_due(sim.now).expect("an arrival is due");
        sim.now = due;
        let out = sim.output();
        if out.is_empty() {
            continue;
        }
        assert_eq!(out[2], 128, "the second reply of 138");
        let position = sim.gap(1); // GAP keeps being answered while the program runs
        let expected = if arrivals.len() % 2 == 0 {
            1_000_000
        } else {
            -1_000_000
        };
        assert_eq!(position, expected);
        arrivals.push(sim.now.as_secs_f64());
        sim.wait(1.0);
        assert_eq!(sim.gap(0), -expected, "on its way back");
    }
    for pair in arrivals.windows(2) {
        let took = pair[1] - pair[0];
        assert!((took - swing).abs() < 1e-3, "{took} s, expected {swing} s");
    }
    assert_eq!(status(&mut sim).0, 1, "still running");
    assert_eq!(status(&mut sim).2, 0, "no error");
}

#[test]
fn stop_halts_the_program_and_run_continues_it() {
    let mut sim = Sim::new();
    sim.download(&TEST2);
    sim.ok(129, 1, 0, 0); // run from address 0
    sim.at(20.0);
    sim.ok(128, 0, 0, 0);
    let (state, pc, _) = status(&mut sim);
    assert_eq!((state, pc), (0, 9), "stopped in WAIT POS");
    sim.at(400.0);
    assert_eq!(sim.gap(1), 1_000_000, "the motor finishes its move");
    sim.ok(3, 0, 0, 0);
    assert_eq!(
        sim.ok(10, 130, 0, 0),
        9,
        "the program does not go on by itself"
    );
    sim.ok(129, 0, 0, 0);
    sim.wait(0.01);
    assert!(
        sim.ok(10, 130, 0, 0) >= 10,
        "continued from where it stopped"
    );
}

#[test]
fn step_runs_one_instruction_at_a_time() {
    let mut sim = Sim::new();
    sim.download(&TEST2);
    sim.ok(131, 0, 0, 0);
    assert_eq!(status(&mut sim).0, 3, "reset");
    sim.ok(130, 0, 0, 0);
    let (state, pc, _) = status(&mut sim);
    assert_eq!((state, pc), (2, 1), "ROL done, paused before WAIT");
    sim.wait(1.0);
    assert!(sim.gap(3) < 0);
    assert_eq!(
        sim.ok(10, 130, 0, 0),
        1,
        "no further instruction without a step"
    );
    sim.ok(130, 0, 0, 0); // WAIT TICKS 500: the step lasts 5 s
    sim.wait(4.9);
    assert_eq!(sim.ok(10, 130, 0, 0), 1);
    sim.wait(0.2);
    assert_eq!(sim.ok(10, 130, 0, 0), 2);
    assert!(sim.gap(3) < 0, "MST not yet executed");
}

#[test]
fn ascii_run_and_stop() {
    let mut sim = Sim::new();
    sim.download(&TEST2);
    sim.ok(9, 67, 0, 0x20);
    sim.ok(139, 0, 0, 0);
    assert_eq!(sim.line("ARUN"), "BA 100 0\r");
    sim.wait(1.0);
    assert_eq!(sim.line("AGGP 128, 0"), "BA 100 1\r");
    assert_eq!(sim.line("ASTOP"), "BA 100 0\r");
    assert_eq!(sim.line("AGGP 128, 0"), "BA 100 0\r");
}

#[test]
fn arithmetic_comparisons_and_subroutines() {
    // Sum 1..10 into user variable 0, using the X register and a subroutine.
    let program = [
        (19, 9, 0, 0),  // 0: CALC LOAD, 0
        (33, 9, 0, 0),  // 1: CALCX LOAD      x := acc (running sum 0)
        (19, 9, 0, 1),  // 2: CALC LOAD, 1    acc := counter 1
        (23, 0, 0, 9),  // 3: Loop: CSUB Add
        (19, 0, 0, 1),  // 4: CALC ADD, 1
        (20, 0, 0, 10), // 5: COMP 10
        (21, 7, 0, 3),  // 6: JC LE, Loop
        (35, 1, 2, 0),  // 7: AGP 1, 2        last counter (11) to user variable 1
        (22, 0, 0, 15), // 8: JA End
        (33, 10, 0, 0), // 9: Add: CALCX SWAP  acc := sum, x := counter
        (33, 0, 0, 0),  // 10: CALCX ADD      sum + counter
        (35, 0, 2, 0),  // 11: AGP 0, 2
        (33, 10, 0, 0), // 12: CALCX SWAP     acc := counter, x := sum
        (24, 0, 0, 0),  // 13: RSUB
        (28, 0, 0, 0),  // 14: STOP (never reached)
        (10, 1, 2, 0),  // 15: End: GGP 1, 2  acc := 11
        (19, 2, 0, 3),  // 16: CALC MUL, 3
        (34, 4, 0, 0),  // 17: AAP 4, 0       33 to max speed
        (28, 0, 0, 0),  // 18: STOP
    ];
    let mut sim = Sim::new();
    sim.download(&program);
    sim.ok(129, 0, 0, 0);
    sim.wait(1.0);
    assert_eq!(sim.ok(10, 0, 2, 0), 55);
    assert_eq!(sim.ok(10, 1, 2, 0), 11);
    assert_eq!(sim.gap(4), 33);
    assert_eq!(
        status(&mut sim),
        (0, 0, 0),
        "STOP: stopped, counter back at 0"
    );
}

#[test]
fn direct_commands_leave_the_accumulator_alone() {
    let program = [
        (19, 9, 0, 42),  // CALC LOAD, 42
        (27, 0, 0, 100), // WAIT TICKS, 0, 100
        (34, 4, 0, 0),   // AAP 4, 0
        (28, 0, 0, 0),   // STOP
    ];
    let mut sim = Sim::new();
    sim.download(&program);
    sim.ok(129, 0, 0, 0);
    sim.wait(0.5);
    assert_eq!(sim.gap(1), 0, "a read in direct mode during the wait");
    assert_eq!(sim.ok(10, 0, 2, 0), 0);
    sim.wait(1.0);
    assert_eq!(sim.gap(4), 42);
}

#[test]
fn wait_timeouts_set_eto_for_jc_and_cle_clears_it() {
    let program = [
        (27, 2, 0, 50), // 0: WAIT REFSW, 0, 50 (no switch: times out after 0.5 s)
        (21, 8, 0, 4),  // 1: JC ETO, TimedOut
        (19, 9, 0, 1),  // 2: CALC LOAD, 1
        (22, 0, 0, 6),  // 3: JA Done
        (36, 1, 0, 0),  // 4: TimedOut: CLE ETO
        (19, 9, 0, 2),  // 5: CALC LOAD, 2
        (21, 8, 0, 0),  // 6: Done: JC ETO, 0 (cleared: not taken)
        (35, 0, 2, 0),  // 7: AGP 0, 2
        (28, 0, 0, 0),  // 8: STOP
    ];
    let mut sim = Sim::new();
    sim.download(&program);
    sim.ok(129, 0, 0, 0);
    sim.wait(0.4);
    assert_eq!(sim.ok(10, 130, 0, 0), 0, "still waiting");
    sim.wait(0.2);
    assert_eq!(sim.ok(10, 0, 2, 0), 2, "timed out and took the ETO branch");
    assert_eq!(status(&mut sim).0, 0);
}

#[test]
fn waits_for_position_switches_and_reference_search() {
    let program = [
        (5, 255, 0, 1),  // 0: SAP 255, 0, 1 (pps)
        (4, 0, 0, 2000), // 1: MVP ABS, 0, 2000
        (27, 1, 0, 0),   // 2: WAIT POS
        (10, 132, 0, 0), // 3: GGP 132, 0 (tick timer)
        (35, 0, 2, 0),   // 4: AGP 0, 2
        (1, 0, 0, 5000), // 5: ROR 0, 5000
        (27, 3, 0, 0),   // 6: WAIT LIMSW
        (6, 1, 0, 0),    // 7: GAP 1, 0
        (35, 1, 2, 0),   // 8: AGP 1, 2
        (5, 193, 0, 1),  // 9: SAP 193, 0, 1
        (13, 0, 0, 0),   // 10: RFS START
        (27, 4, 0, 0),   // 11: WAIT RFS
        (2, 0, 0, 5000), // 12: ROL 0, 5000  (from the new 0 at the left switch: blocked)
        (27, 0, 0, 10),  // 13: WAIT TICKS 10
        (6, 1, 0, 0),    // 14: GAP 1, 0
        (35, 2, 2, 0),   // 15: AGP 2, 2
        (28, 0, 0, 0),   // 16: STOP
    ];
    let mut sim = Sim::with(BusOptions {
        switches: Switches {
            left: Some(-3000),
            right: Some(6000),
            home: None,
        },
        ..BusOptions::default()
    });
    sim.sap(4, 1000);
    sim.sap(5, 1000);
    sim.download(&program);
    sim.ok(129, 0, 0, 0);
    sim.at(200.0);
    // 2000 steps at 1000 pps and 1000 pps²: 3 s (plus the instructions before).
    let arrival_ms = sim.ok(10, 0, 2, 0);
    assert!((3000..3010).contains(&arrival_ms), "{arrival_ms}");
    assert_eq!(sim.ok(10, 1, 2, 0), 6000, "stopped at the right switch");
    assert_eq!(
        sim.ok(10, 2, 2, 0),
        0,
        "at the left switch after the search"
    );
    assert_eq!(status(&mut sim), (0, 0, 0));
}

#[test]
fn program_errors_stop_the_program_and_say_why() {
    // (program, error code, program counter at the error)
    let cases: [(&[Word], i32, i32); 7] = [
        (&[(22, 0, 0, 5000)], 2, 0),             // bad jump
        (&[(23, 0, 0, 0)], 3, 0),                // CSUB to itself: stack overflow
        (&[(24, 0, 0, 0)], 4, 0),                // RSUB without CSUB
        (&[(3, 0, 0, 0), (0, 0, 0, 0)], 1, 1),   // command 0
        (&[(100, 0, 0, 0)], 1, 0),               // no such command
        (&[(19, 9, 0, 1), (19, 3, 0, 0)], 6, 1), // DIV by 0
        (&[(27, 9, 0, 0)], 1, 0),                // WAIT type 9
    ];
    for (program, error, at) in cases {
        let mut sim = Sim::new();
        sim.download(program);
        sim.ok(129, 0, 0, 0);
        sim.wait(1.0);
        assert_eq!(status(&mut sim), (0, at, error), "{program:?}");
    }
    // Running off the end of memory.
    let mut sim = Sim::new();
    sim.ok(132, 0, 0, 2047);
    assert_eq!(sim.frame(1, 3, 0, 0, 0).status, Status::Stored);
    sim.ok(133, 0, 0, 0);
    sim.ok(129, 1, 0, 2047);
    sim.wait(1.0);
    assert_eq!(status(&mut sim), (0, 2048, 5));
    assert_eq!(sim.status(129, 1, 0, 2048), Status::InvalidValue);
}

#[test]
fn auto_start_runs_the_stored_program_at_power_up() {
    let store = MemoryStore::new();
    let options = || BusOptions {
        eeprom: Some(Eeprom::open(Box::new(store.clone())).unwrap()),
        ..BusOptions::default()
    };
    let mut sim = Sim::with(options());
    sim.download(&TEST2);
    sim.ok(9, 77, 0, 1);
    drop(sim);
    let mut sim = Sim::with(options());
    assert_eq!(sim.ok(135, 0, 0, 0), 1, "running after power-up");
    sim.wait(1.0);
    assert!(sim.gap(3) < 0);
}
