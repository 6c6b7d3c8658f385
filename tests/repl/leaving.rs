//! Leaving the shell (`:quit`, Ctrl-D) with a motor turning warns, as `:stop` warns of a
//! program's motion, and says how to stop it; leaving stops nothing, and says nothing when all
//! stands still.

use super::{repl, type_in};

/// Starts motor 0 turning at the prompt.
fn turning() -> rexpect::session::PtySession {
    let (mut p, _) = repl(&["--sim"]);
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "ROR 0, 1000\r");
    p.exp_string("ok").unwrap();
    p.exp_string("A> ").unwrap();
    p
}

#[test]
fn quit_with_a_motor_turning_warns_and_says_how_to_stop_it() {
    let mut p = turning();
    type_in(&mut p, ":quit\r");
    p.exp_string("warning: motor 0 of module 1 (A) is still turning (actual_speed = ")
        .unwrap();
    p.exp_string("leaving the shell does not stop it; MST 0 does")
        .unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn ctrl_d_with_a_motor_turning_warns_too() {
    let mut p = turning();
    p.send_control('d').unwrap();
    p.exp_string("warning: motor 0 of module 1 (A) is still turning")
        .unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn leaving_with_every_motor_stopped_says_nothing_of_motion() {
    let mut p = turning();
    type_in(&mut p, "MST 0\r");
    p.exp_string("ok").unwrap();
    p.exp_string("A> ").unwrap();
    type_in(&mut p, ":quit\r");
    let rest = p.exp_eof().unwrap();
    assert!(!rest.contains("still turning"), "{rest}");
}

#[test]
fn target_alone_shows_the_target() {
    let (mut p, _) = repl(&["--sim"]);
    p.exp_string("A> ").unwrap();
    type_in(&mut p, ":target\r");
    p.exp_string("target: module 1 (A), TMCM-142").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn an_smd4_drive_left_turning_is_warned_of_too() {
    let (mut p, _) = repl(&["--sim", "--protocol", "smd4"]);
    p.exp_string("smd4> ").unwrap();
    type_in(&mut p, "MOTOR:RUNV,+\r");
    p.exp_string("smd4> ").unwrap();
    type_in(&mut p, ":quit\r");
    p.exp_string("the motor of ").unwrap();
    p.exp_string(
        "is still turning (no standby flag): leaving the shell does not stop it; MOTOR:STOP does",
    )
    .unwrap();
    p.exp_eof().unwrap();
}
