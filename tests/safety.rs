//! Every exit path stops what the session set moving: a crash (injected while a simulated motor
//! turns, in the REPL, in a script's `download()`, in the middle of a download), Ctrl-C at the
//! idle REPL prompt, `:stop` of a program whose motion goes on. And what used to crash no longer
//! does: hostile program files and absurd times are refused with exit 2.
//!
//! The simulator runs on a manual clock, so "the motor stopped" is checked by letting ten
//! simulated seconds pass and reading its velocity on the console, and "it was turning" the same
//! way before. Crashes are injected through `TMCLSH_TEST_CRASH`, which every build reads.

use std::process::Command;

use rexpect::process::WaitStatus;
use rexpect::session::PtySession;
use tmclsh::dialect::tmcl::protocol::Status;

use crate::sim::{Sim, velocity_after};
use crate::smd4::{Drive, Via};
use crate::util::{bin, code, repo, run, stderr, tempdir, terminal};

/// The TMCL simulator on a pty with a manual clock.
fn tmcl_sim() -> Sim {
    Sim::start(&["--pty", "--manual-clock"])
}

/// The module executes binary commands again: back in binary mode and not in download mode
/// (where a command would be stored, status 101, instead of executed).
fn executes_binary_commands(sim: &Sim) {
    let mut port = sim.pty();
    let reply = port.transact(1, 6, 4, 0, 0);
    assert_eq!(reply.status, Status::Ok, "{reply:?}");
}

fn exit_code(p: &PtySession) -> i32 {
    match p.process().wait().expect("tmclsh ends") {
        WaitStatus::Exited(_, code) => code,
        other => panic!("tmclsh ended with {other:?}"),
    }
}

/// `tmclsh --port PTY ARGS` with extra environment variables.
fn on(sim: &Sim, args: &[&str], env: &[(&str, &str)]) -> std::process::Output {
    Command::new(bin())
        .args(["--port", &sim.first])
        .args(args)
        .env("NO_COLOR", "1")
        .env("RUST_BACKTRACE", "0")
        .envs(env.iter().copied())
        .output()
        .expect("tmclsh runs")
}

const CRASH: &str = "TMCLSH_TEST_CRASH";

fn assert_crash_report(text: &str, stopped: &str) {
    assert!(
        text.contains("tmclsh: internal error: crash injected"),
        "{text}"
    );
    assert!(
        text.contains(&format!("motors stopped: {stopped}")),
        "{text}"
    );
    assert!(text.contains("this is a bug in tmclsh"), "{text}");
}

#[test]
fn a_crash_in_the_repl_stops_the_motor_and_restores_binary_mode() {
    let mut sim = tmcl_sim();
    let mut p = terminal(&["--port", &sim.first], &[(CRASH, "repl:crash now")]);
    p.exp_string("A> ").unwrap();
    p.send_line("ROR 0, 200000").unwrap();
    p.exp_string("ok").unwrap();
    p.exp_string("A> ").unwrap();
    assert!(velocity_after(&mut sim, "1s") > 0.0, "the motor turns");
    p.send_line("crash now").unwrap();
    let text = p.exp_eof().unwrap();
    assert_crash_report(&text, "motor 0 of module 1 (A) with MST");
    assert!(
        text.contains("modules returned to the mode they were found in"),
        "{text}"
    );
    assert_eq!(exit_code(&p), 101);
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
    executes_binary_commands(&sim);
}

#[test]
fn a_crash_in_the_middle_of_a_download_leaves_download_mode_before_mst() {
    let mut sim = tmcl_sim();
    let program = repo().join("scripts/test2.tmc");
    let download = format!(":download {}", program.display());
    let out = on(
        &sim,
        &["-c", "ROR 0, 200000", "-c", &download],
        &[(CRASH, "download:2")],
    );
    assert_eq!(code(&out), 101, "{}", stderr(&out));
    assert_crash_report(&stderr(&out), "motor 0 of module 1 (A) with MST");
    // In download mode the MST would have been stored as a program instruction.
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
    executes_binary_commands(&sim);
    // Without a crash, nothing stops the motor: the check above can fail.
    let out = on(&sim, &["-c", "ROR 0, 200000"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(velocity_after(&mut sim, "10s") > 0.0);
}

#[test]
fn ctrl_c_in_the_middle_of_a_download_leaves_download_mode_before_mst() {
    use nix::sys::signal::{Signal, kill};
    use nix::unistd::Pid;

    let mut sim = tmcl_sim();
    // Replies held back 200 ms of simulated time, released as the test lets time pass, keep
    // the download going until it is interrupted.
    assert!(sim.console("delay 1 200").starts_with("ok"));
    let dir = tempdir();
    let log = dir.join("t.log");
    let program = repo().join("scripts/test2.tmc");
    let mut child = Command::new(bin())
        .args(["--port", &sim.first, "--log", &log.display().to_string()])
        .args([
            "-c",
            "ROR 0, 200000",
            "-c",
            &format!(":download {}", program.display()),
        ])
        .env("NO_COLOR", "1")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("tmclsh runs");
    let deadline = std::time::Instant::now() + crate::sim::PATIENCE;
    let let_time_pass = |sim: &mut Sim| {
        assert!(std::time::Instant::now() < deadline, "tmclsh got stuck");
        assert!(sim.console("advance 50ms").starts_with("ok"));
    };
    // The first instruction stored: the module is in download mode now.
    while !std::fs::read_to_string(&log)
        .unwrap_or_default()
        .contains("command loaded into TMCL program memory")
    {
        let_time_pass(&mut sim);
    }
    kill(Pid::from_raw(child.id() as i32), Signal::SIGINT).expect("SIGINT delivered");
    while child.try_wait().unwrap().is_none() {
        let_time_pass(&mut sim);
    }
    let out = child.wait_with_output().expect("tmclsh ends");
    assert_eq!(code(&out), 130, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("stopped motor 0 of module 1 (A) with MST"),
        "{}",
        stderr(&out)
    );
    assert!(
        stderr(&out).contains("module 1 (A): program memory now holds a partial program ("),
        "{}",
        stderr(&out)
    );
    assert!(sim.console("delay 0 0").starts_with("ok"));
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
    executes_binary_commands(&sim);
}

#[test]
fn a_crash_inside_a_script_s_download_stops_the_motor_the_script_started() {
    let mut sim = tmcl_sim();
    let dir = tempdir();
    std::fs::write(dir.join("p.tmc"), "ROL 0, 1000\n").unwrap();
    let script = dir.join("s.rhai");
    let program = dir.join("p.tmc");
    std::fs::write(
        &script,
        format!("ror(0, 200000);\ndownload(\"{}\");\n", program.display()),
    )
    .unwrap();
    let out = on(
        &sim,
        &["run", &script.display().to_string()],
        &[(CRASH, "assemble")],
    );
    assert_eq!(code(&out), 101, "{}", stderr(&out));
    assert_crash_report(&stderr(&out), "motor 0 of module 1 (A) with MST");
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
    executes_binary_commands(&sim);
}

#[test]
fn a_crash_with_an_smd4_drive_sends_motor_stop() {
    let mut drive = Drive::start(Via::Pty, &["--manual-clock"]);
    let args = drive.connection();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let mut p = terminal(&args, &[(CRASH, "repl:crash now")]);
    p.exp_string("smd4> ").unwrap();
    p.send_line("MOTOR:RUNV,+").unwrap();
    // The reply, not a redraw of the line being typed, says the drive has it.
    p.exp_string("\r\nok").unwrap();
    p.exp_string("smd4> ").unwrap();
    drive.console("advance 5s");
    assert!(drive.motor().velocity > 0.0, "the motor turns");
    p.send_line("crash now").unwrap();
    let text = p.exp_eof().unwrap();
    assert_crash_report(&text, "the motor of the drive with MOTOR:STOP");
    assert_eq!(exit_code(&p), 101);
    drive.console("advance 5s");
    assert_eq!(drive.motor().velocity, 0.0);
}

#[test]
fn ctrl_c_at_the_idle_prompt_stops_the_motor_this_session_started() {
    let mut sim = tmcl_sim();
    let mut p = terminal(&["--port", &sim.first], &[]);
    p.exp_string("A> ").unwrap();
    // Nothing moving: Ctrl-C only clears the line, as before.
    p.send_control('c').unwrap();
    p.exp_string("\r\n").unwrap();
    let shown = p.exp_string("A> ").unwrap();
    assert!(!shown.contains("MST"), "{shown}");
    p.send_line("ROR 0, 200000").unwrap();
    p.exp_string("ok").unwrap();
    p.exp_string("A> ").unwrap();
    assert!(velocity_after(&mut sim, "1s") > 0.0, "the motor turns");
    p.send_control('c').unwrap();
    p.exp_string("stopped motor 0 of module 1 (A) with MST")
        .unwrap();
    p.exp_string("A> ").unwrap();
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
    // Stopped: the next Ctrl-C is a plain one again.
    p.send_control('c').unwrap();
    p.exp_string("\r\n").unwrap();
    let shown = p.exp_string("A> ").unwrap();
    assert!(!shown.contains("MST"), "{shown}");
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
    assert_eq!(exit_code(&p), 0);
}

#[test]
fn ctrl_c_at_the_idle_smd4_prompt_sends_motor_stop() {
    let mut drive = Drive::start(Via::Pty, &["--manual-clock"]);
    let args = drive.connection();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let mut p = terminal(&args, &[]);
    p.exp_string("smd4> ").unwrap();
    p.send_line("MOTOR:RUNV,+").unwrap();
    // The reply, not a redraw of the line being typed, says the drive has it.
    p.exp_string("\r\nok").unwrap();
    p.exp_string("smd4> ").unwrap();
    drive.console("advance 5s");
    assert!(drive.motor().velocity > 0.0, "the motor turns");
    p.send_control('c').unwrap();
    p.exp_string("with MOTOR:STOP").unwrap();
    p.exp_string("smd4> ").unwrap();
    drive.console("advance 5s");
    assert_eq!(drive.motor().velocity, 0.0);
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn stop_warns_that_the_program_s_motion_goes_on_and_ctrl_c_then_stops_it() {
    let mut sim = tmcl_sim();
    let program = repo().join("scripts/test2.tmc");
    let mut p = terminal(&["--port", &sim.first], &[]);
    p.exp_string("A> ").unwrap();
    p.send_line(&format!(":download {}", program.display()))
        .unwrap();
    p.exp_string("downloaded").unwrap();
    p.send_line(":run").unwrap();
    p.exp_string("program started").unwrap();
    p.exp_string("A> ").unwrap();
    // The program's first instruction, ROL 0, 500000, sets the motor turning left.
    assert!(
        velocity_after(&mut sim, "2s") < 0.0,
        "the program turns the motor"
    );
    p.send_line(":stop").unwrap();
    p.exp_string("program stopped").unwrap();
    p.exp_string("warning: motor 0 of module 1 (A) is still turning")
        .unwrap();
    p.exp_string("A> ").unwrap();
    assert!(
        velocity_after(&mut sim, "10s") < 0.0,
        "STOP does not stop the motion"
    );
    p.send_control('c').unwrap();
    p.exp_string("stopped motor 0 of module 1 (A) with MST")
        .unwrap();
    p.exp_string("A> ").unwrap();
    assert_eq!(velocity_after(&mut sim, "10s"), 0.0);
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

/// Program files that overflowed the stack or panicked before.
fn hostile_files() -> Vec<(&'static str, String, &'static str)> {
    vec![
        (
            "nested.tmc",
            format!(
                "X = {}1{}\nROL 0, X\n",
                "(".repeat(100_000),
                ")".repeat(100_000)
            ),
            "parentheses and signs nest more than 64 levels deep",
        ),
        (
            "minus.tmc",
            format!("ROL 0, {}1\n", "-".repeat(20_000)),
            "parentheses and signs nest more than 64 levels deep",
        ),
        (
            "division.tmc",
            "Min = -(0xFFFFFFFF + 1) * 0x80000000\nX = Min / -1\nROL 0, X\n".to_string(),
            "overflow in '/'",
        ),
    ]
}

#[test]
fn hostile_program_files_are_refused_by_asm_and_download() {
    let sim = tmcl_sim();
    let dir = tempdir();
    for (name, source, message) in hostile_files() {
        let path = dir.join(name);
        std::fs::write(&path, source).unwrap();
        let path = path.display().to_string();
        let out = run(&["asm", &path]);
        assert_eq!(code(&out), 2, "asm {name}: {}", stderr(&out));
        assert!(
            stderr(&out).contains(message),
            "asm {name}: {}",
            stderr(&out)
        );
        let out = on(&sim, &["download", &path], &[]);
        assert_eq!(code(&out), 2, "download {name}: {}", stderr(&out));
        assert!(
            stderr(&out).contains(message),
            "download {name}: {}",
            stderr(&out)
        );
    }
}

#[test]
fn hostile_program_files_refused_by_download_helpers_stop_the_turning_motor() {
    let mut sim = tmcl_sim();
    let dir = tempdir();
    for (name, source, message) in hostile_files() {
        let path = dir.join(name);
        std::fs::write(&path, source).unwrap();
        let download = format!(":download {}", path.display());
        let out = on(&sim, &["-c", "ROR 0, 200000", "-c", &download], &[]);
        assert_eq!(code(&out), 2, ":download {name}: {}", stderr(&out));
        let err = stderr(&out);
        assert!(err.contains(message), ":download {name}: {err}");
        assert!(
            err.contains("stopped motor 0 of module 1 (A) with MST"),
            "{err}"
        );
        assert_eq!(velocity_after(&mut sim, "10s"), 0.0, ":download {name}");

        let script = dir.join(format!("{name}.rhai"));
        std::fs::write(
            &script,
            format!("ror(0, 200000);\ndownload(\"{}\");\n", path.display()),
        )
        .unwrap();
        let out = on(&sim, &["run", &script.display().to_string()], &[]);
        assert_eq!(code(&out), 2, "download() {name}: {}", stderr(&out));
        let err = stderr(&out);
        // A script is told where the first problem is, never what the file holds (the sandbox).
        assert!(
            err.contains("is not a program for the TMCM-142 (the first problem is at line"),
            "download() {name}: {err}"
        );
        assert_eq!(velocity_after(&mut sim, "10s"), 0.0, "download() {name}");
    }
    executes_binary_commands(&sim);
}

#[test]
fn absurd_times_are_refused_before_any_clock_sees_them() {
    let dir = tempdir();
    let csv = dir.join("r.csv").display().to_string();
    let record = format!(":record {csv} actual_position 10ms 300000000000y");
    for line in [
        ":scan 1 300000000000y",
        ":watch actual_position 300000000000y",
        record.as_str(),
    ] {
        let out = run(&["--sim", "-c", line]);
        assert_eq!(code(&out), 2, "{line}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("'300000000000y' is longer than 7 days"),
            "{line}: {}",
            stderr(&out)
        );
    }
    let drive = Drive::start(Via::Pty, &[]);
    let out = drive.run(&["-c", ":scan 1 300000000000y"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("is longer than 7 days"),
        "{}",
        stderr(&out)
    );
}
