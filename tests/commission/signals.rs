//! SIGTERM and SIGHUP end the REPL as Ctrl-C ends a run: at the idle prompt (where the line editor
//! blocks in a read), during `:watch` and during a command, the motor this session set turning is
//! stopped (read back on the simulator's console), the terminal is back in line mode, and the exit
//! code is 128 + the signal's number. A terminal that goes away without a SIGHUP is one too.

use nix::sys::signal::Signal;

use super::repl::Terminal;
use crate::sim::{Sim, velocity_after};

/// A REPL on a simulator with a manual clock, its motor set turning by `ROR 0, 50000`.
fn turning() -> (Sim, Terminal) {
    turning_with(&[])
}

fn turning_with(flags: &[&str]) -> (Sim, Terminal) {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let mut args = vec!["--port", sim.first.as_str()];
    args.extend(flags);
    let mut term = Terminal::spawn(&args);
    term.until("A> ");
    term.send("ROR 0, 50000\r");
    term.until("ok");
    term.until("A> ");
    assert!(velocity_after(&mut sim, "1s") > 0.0, "the motor turns");
    (sim, term)
}

/// Signal at the idle prompt: the message names the signal and the stop, the motor stops.
fn at_the_prompt(signal: Signal, name: &str, code: i32) {
    let (mut sim, mut term) = turning();
    term.signal(signal);
    term.until(&format!("{name}: leaving the shell"));
    term.until("stopped motor 0 of module 1 (A) with MST");
    assert_eq!(term.exit_code(), code);
    assert!(term.cooked(), "the terminal is back in line mode");
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
}

#[test]
fn sigterm_at_the_idle_prompt_stops_the_motor_and_exits_143() {
    at_the_prompt(Signal::SIGTERM, "SIGTERM", 143);
}

#[test]
fn sighup_at_the_idle_prompt_stops_the_motor_and_exits_129() {
    at_the_prompt(Signal::SIGHUP, "SIGHUP", 129);
}

#[test]
fn sigterm_with_nothing_moving_says_so() {
    let _sim = Sim::start(&["--pty", "--manual-clock"]);
    let mut term = Terminal::spawn(&["--port", &_sim.first]);
    term.until("A> ");
    term.signal(Signal::SIGTERM);
    term.until("nothing this session started was moving");
    assert_eq!(term.exit_code(), 143);
    assert!(term.cooked());
}

#[test]
fn sigterm_during_a_watch_restores_the_terminal_and_stops_the_motor() {
    let (mut sim, mut term) = turning();
    term.send(":watch actual_speed\r");
    term.until("any key stops");
    term.signal(Signal::SIGTERM);
    term.until("stopped motor 0 of module 1 (A) with MST");
    assert_eq!(term.exit_code(), 143);
    assert!(term.cooked(), "the terminal is back in line mode");
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
}

#[test]
fn sigterm_while_a_reply_is_awaited_stops_the_motor_and_exits_143() {
    // A minute's timeout: only the signal can end the wait this test makes.
    let (mut sim, mut term) = turning_with(&["--timeout", "60000"]);
    // Replies held back until simulated time passes, which the test does not let happen.
    assert!(sim.console("delay 1 100000").starts_with("ok"));
    term.send("GAP 3, 0\r");
    // The request is on the line: the simulator has seen it (its echo is held back too).
    let deadline = std::time::Instant::now() + crate::sim::PATIENCE;
    while sim.console("faults").contains("delayed 0") {
        assert!(
            std::time::Instant::now() < deadline,
            "the request never arrived"
        );
    }
    term.signal(Signal::SIGTERM);
    term.until("SIGTERM: leaving the shell");
    assert_eq!(term.exit_code(), 143);
    assert!(term.cooked());
    assert!(sim.console("delay 0 0").starts_with("ok"));
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
}

#[test]
fn a_terminal_that_goes_away_is_a_hang_up() {
    let (mut sim, mut term) = turning();
    term.hang_up();
    assert_eq!(term.exit_code(), 129);
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
}

/// Piped lines wait for more input with the motor turning: SIGTERM stops it and exits 143.
#[test]
fn sigterm_ends_piped_lines_with_the_motor_stopped() {
    use std::io::{BufRead, BufReader, Write};
    use std::process::{Command, Stdio};

    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let mut child = Command::new(crate::util::bin())
        .args(["--port", &sim.first])
        .env("NO_COLOR", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(b"ROR 0, 50000\n").unwrap();
    stdin.flush().unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    assert!(line.starts_with("BA 100"), "{line}");
    assert!(velocity_after(&mut sim, "1s") > 0.0, "the motor turns");
    // stdin stays open: the run waits for more lines.
    nix::sys::signal::kill(
        nix::unistd::Pid::from_raw(child.id() as i32),
        Signal::SIGTERM,
    )
    .unwrap();
    let out = child.wait_with_output().unwrap();
    drop(stdin);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(143), "{err}");
    assert!(
        err.contains("stopped motor 0 of module 1 (A) with MST"),
        "{err}"
    );
    assert!(err.contains("tmclsh: ended by SIGTERM"), "{err}");
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
}
