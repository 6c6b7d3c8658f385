//! `tmclsh run` as a process: every API function, each exit code, failure messages with file,
//! line, column and both values, Ctrl-C during a rotation, the operation cap, and the example
//! scripts of `scripts/`, against the simulator.

mod ending;
mod limits;
mod sandbox;

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

use crate::sim::Sim;
use crate::util::{bin, code, repo, run, stderr, stdout, tempdir};

/// Writes `source` to a script file and returns its path.
fn script(name: &str, source: &str) -> String {
    let path = tempdir().join(name);
    std::fs::write(&path, source).unwrap();
    path.display().to_string()
}

fn example(name: &str) -> String {
    repo().join("scripts").join(name).display().to_string()
}

#[test]
fn every_api_function_against_a_simulated_module() {
    let sim = Sim::start(&["--pty", "--left-switch", "-2000"]);
    let program = tempdir().join("p.tmc");
    std::fs::write(&program, "Loop: WAIT TICKS, 0, 10\n JA Loop\n").unwrap();
    let source = format!(
        r#"
        assert_eq(args, ["one", "two"]);
        // send / reply
        assert_eq(send("SAP 1, 0, 1234"), 1234);
        assert_eq(send("GAP actual_position, 0"), 1234);
        let r = reply("GAP 200, 0");
        assert_eq(r.status, 3); assert_eq(r.ok, false); assert_eq(r.raw, "BA 3 0"); assert_eq(r.value, 0);
        assert_eq(reply("GAP 1, 0").ok, true);
        // parameters by number and by name
        sap("max_current", 0, 9); assert_eq(gap(6, 0), 9); stap(6, 0);
        sap(6, 0, 3); rsap("max_current", 0); assert_eq(gap("max_current", 0), 9);
        sgp("user_variable_3", 2, -77); assert_eq(ggp(3, 2), -77); stgp(3, 2);
        sgp(3, 2, 5); rsgp("user_variable_3", 2); assert_eq(ggp("user_variable_3", 2), -77);
        assert_eq(ggp("serial_host_address", 0), 2);
        // motion in pps units
        sap("unit_conversion_mode", 0, 1); sap(4, 0, 200000); sap(5, 0, 2000000);
        sap(1, 0, 0);
        mvp_abs(0, 1000); wait_pos(0, 5000); assert_eq(gap(1, 0), 1000);
        mvp_rel(0, -500); wait_pos(0, 5000); assert_eq(gap(1, 0), 500);
        sco(3, 0, -300); assert_eq(gco(3, 0), -300);
        mvp_coord(0, 3); wait_pos(0, 5000); assert_eq(gap(1, 0), -300);
        ror(0, 5000); wait_until(|| gap("actual_speed", 0) == 5000, 5000); mst(0);
        wait_until(|| gap(3, 0) == 0, 5000);
        rol(0, 5000); wait_until(|| gap(3, 0) == -5000, 5000); mst(0);
        wait_until(|| gap(3, 0) == 0, 5000);
        // reference search against the left switch at -2000
        sap("reference_search_speed", 0, 100000); sap("reference_switch_speed", 0, 20000);
        rfs_start(0); assert(rfs_status(0) != 0, "searching");
        rfs_stop(0); wait_until(|| rfs_status(0) == 0, 5000);
        rfs_start(0); wait_until(|| rfs_status(0) == 0, 10000);
        assert_near(gap(1, 0), 0, 1);
        // I/O
        sio(1, 2, 1); assert_eq(gio(1, 2), 1); sio(1, 2, 0); assert_eq(gio(1, 2), 0);
        assert_eq(gio(3, 0), 0);
        // waiting and assertions
        sleep(1);
        assert(true); assert(1 < 2, "arithmetic"); assert_near(10, 12, 2); assert_near(1.5, 1.0, 0.5);
        // programs
        assert_eq(download("{program}"), 2);
        run_program(); assert_eq(program_status(), 1);
        stop_program(); assert_eq(program_status(), 0);
        // the module and the bus
        assert_eq(firmware_version(), "142V1.06");
        target(1); target("A");
        log("all functions called");
        print("done");
        "#,
        program = program.display()
    );
    let path = script("api.rhai", &source);
    let log = tempdir().join("api.log");
    let out = run(&[
        "run",
        &path,
        "--allow-dir",
        program.parent().unwrap().to_str().unwrap(),
        "--port",
        &sim.first,
        "--log",
        log.to_str().unwrap(),
        "--",
        "one",
        "two",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "done\n");
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(
        transcript.contains("script: all functions called"),
        "log goes to the transcript"
    );
}

#[test]
fn a_failed_assertion_names_file_line_column_and_both_values() {
    let path = script("fail.rhai", "let x = 1;\n\nassert_eq(gap(4, 0), 200);\n");
    let out = run(&["--sim", "run", &path]);
    assert_eq!(code(&out), 1);
    let err = stderr(&out);
    assert!(
        err.contains(&format!(
            "{path}:3:1: assert_eq failed: left = 1000000, right = 200"
        )),
        "{err}"
    );
    let path = script("near.rhai", "assert_near(10, 20, 3);");
    let err = stderr(&run(&["--sim", "run", &path]));
    assert!(
        err.contains(
            ":1:1: assert_near failed: left = 10, right = 20, tolerance = 3 (difference 10)"
        ),
        "{err}"
    );
    let path = script("msg.rhai", "\n  assert(false, \"the door is open\");");
    let err = stderr(&run(&["--sim", "run", &path]));
    assert!(
        err.contains(":2:3: assertion failed: the door is open"),
        "{err}"
    );
}

#[test]
fn each_exit_code() {
    let cases = [
        (
            "device.rhai",
            "send(\"GAP 200, 0\");",
            1,
            "module 1 (A) refused 'AGAP 200, 0': status 3 (wrong type)",
        ),
        ("runtime.rhai", "let a = [1]; a[5];", 1, "runtime.rhai:1:"),
        ("throw.rhai", "throw \"bad\";", 1, "error: bad"),
        (
            "syntax.rhai",
            "let x = ;",
            2,
            "syntax.rhai:1:9: does not compile",
        ),
        (
            "refused.rhai",
            "send(\"SAP 6, 0, 99\");",
            2,
            "99 is out of range for max_current",
        ),
        (
            "name.rhai",
            "gap(\"no_such_param\", 0);",
            2,
            "unknown axis parameter 'no_such_param'",
        ),
        ("motor.rhai", "gap(1, 300);", 2, "motor 300 does not fit"),
    ];
    for (name, source, expected, message) in cases {
        let path = script(name, source);
        let out = run(&["--sim", "run", &path]);
        assert_eq!(code(&out), expected, "{name}: {}", stderr(&out));
        assert!(stderr(&out).contains(message), "{name}: {}", stderr(&out));
    }
    let missing = run(&["--sim", "run", "/no/such/script.rhai"]);
    assert_eq!(code(&missing), 2);
    assert!(stderr(&missing).contains("cannot read script /no/such/script.rhai"));
}

#[test]
fn a_silent_module_is_exit_3() {
    let sim = Sim::start(&["--pty", "--silent-after", "0"]);
    let path = script("silent.rhai", "gap(1, 0);");
    let out = run(&["run", &path, "--port", &sim.first, "--timeout", "150"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(
        stderr(&out)
            .contains("module 1 (A) did not answer command 136 (firmware version) within 150 ms"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_syntax_error_is_reported_before_the_module_is_touched() {
    let sim = Sim::start(&["--pty", "--silent-after", "0"]);
    let path = script("broken.rhai", "gap(1, 0);\nlet = 5;");
    let out = run(&["run", &path, "--port", &sim.first, "--timeout", "150"]);
    assert_eq!(
        code(&out),
        2,
        "compile error, not a timeout: {}",
        stderr(&out)
    );
}

#[test]
fn a_failing_script_stops_the_motor_it_started() {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let path = script("spin_fail.rhai", "ror(0, 100000);\nassert_eq(1, 2);\n");
    let out = run(&["run", &path, "--port", &sim.first]);
    assert_eq!(code(&out), 1);
    assert!(
        stderr(&out).contains("stopped motor 0 of module 1 (A) with MST"),
        "{}",
        stderr(&out)
    );
    sim.console("advance 10s");
    assert!(sim.console("motor").contains("velocity 0"));
}

#[test]
fn ctrl_c_interrupts_a_sleeping_script_and_stops_the_rotation() {
    let err = signal_a_sleeping_script(nix::sys::signal::Signal::SIGINT, 130);
    assert!(!err.contains("ended by"), "{err}");
}

#[test]
fn sigterm_and_sighup_end_a_sleeping_script_with_the_rotation_stopped() {
    use nix::sys::signal::Signal;
    let err = signal_a_sleeping_script(Signal::SIGTERM, 143);
    assert!(err.contains("tmclsh: ended by SIGTERM"), "{err}");
    let err = signal_a_sleeping_script(Signal::SIGHUP, 129);
    assert!(err.contains("tmclsh: ended by SIGHUP"), "{err}");
}

/// Sends `signal` to a script sleeping with the motor turning; checks the exit code, the stop
/// and the stopped motor; returns stderr.
fn signal_a_sleeping_script(signal: nix::sys::signal::Signal, expected: i32) -> String {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let path = script(
        "spin.rhai",
        "ror(0, 100000);\nprint(\"spinning\");\nsleep(600000);\n",
    );
    let mut child = Command::new(bin())
        .args(["run", &path, "--port", &sim.first])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    assert_eq!(lines.next().unwrap().unwrap(), "spinning");
    sim.console("advance 1s");
    assert!(
        !sim.console("motor").contains("velocity 0 "),
        "turning before Ctrl-C"
    );
    nix::sys::signal::kill(nix::unistd::Pid::from_raw(child.id() as i32), signal).unwrap();
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(expected), "{err}");
    assert!(err.contains("spin.rhai:3:1: interrupted"), "{err}");
    assert!(
        err.contains("stopped motor 0 of module 1 (A) with MST"),
        "{err}"
    );
    sim.console("advance 10s");
    assert!(
        sim.console("motor").contains("velocity 0"),
        "the motor ends stopped"
    );
    err
}

#[test]
fn a_runaway_loop_hits_the_operation_cap() {
    let path = script("loop.rhai", "let n = 0;\nloop { n += 1; }\n");
    let out = run(&["--sim", "run", &path, "--max-operations", "10000"]);
    assert_eq!(code(&out), 1);
    assert!(
        stderr(&out)
            .contains("runaway script: too many operations (raise the cap with --max-operations)"),
        "{}",
        stderr(&out)
    );
    let path = script("deep.rhai", "fn f(n) { f(n + 1) }\nf(0);\n");
    let out = run(&["--sim", "run", &path, "--max-call-depth", "20"]);
    assert_eq!(code(&out), 1);
    assert!(
        stderr(&out).contains("calls nested too deeply"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_value_of_the_wrong_type_is_named_with_its_article() {
    for (source, said) in [
        (
            "gap([1], 0)",
            "a parameter is a number or a name, not an array",
        ),
        (
            "gap(#{}, 0)",
            "a parameter is a number or a name, not a map",
        ),
    ] {
        let out = run(&["--sim", "run", &script("type.rhai", source)]);
        assert_eq!(code(&out), 2, "{}", stderr(&out));
        assert!(stderr(&out).contains(said), "{}", stderr(&out));
    }
}

#[test]
fn scripts_cannot_import_or_eval() {
    // Not even a module that does not exist: the script is refused before anything is sent.
    let path = script("import.rhai", "print(gap(1, 0));\nimport \"os\" as os;");
    let out = run(&["--sim", "run", &path]);
    assert_eq!(code(&out), 2, "import does not compile: {}", stderr(&out));
    assert_eq!(stdout(&out), "", "nothing ran before the refusal");
    let path = script("eval.rhai", "eval(\"1\");");
    let out = run(&["--sim", "run", &path]);
    assert_eq!(code(&out), 2, "eval is not even a symbol: {}", stderr(&out));
}

#[test]
fn example_commission() {
    let out = run(&["--sim", "run", &example("commission.rhai"), "--", "7", "3"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("max_current = 7 (stored)"));
    assert!(stdout(&out).contains("commissioned: stored values verified after restore"));
}

#[test]
fn example_homing_in_each_mode() {
    for mode in ["1", "2", "3"] {
        let sim = Sim::start(&[
            "--pty",
            "--left-switch",
            "-3000",
            "--right-switch",
            "3000",
            "--home-switch",
            "500",
        ]);
        let out = run(&[
            "run",
            &example("homing.rhai"),
            "--port",
            &sim.first,
            "--",
            mode,
            "60000",
        ]);
        assert_eq!(code(&out), 0, "mode {mode}: {}", stderr(&out));
        assert!(
            stdout(&out).contains("homed: position 0"),
            "mode {mode}: {}",
            stdout(&out)
        );
    }
    let out = run(&["--sim", "run", &example("homing.rhai"), "--", "1", "300"]);
    assert_eq!(code(&out), 1, "no switch connected: the search times out");
    assert!(
        stderr(&out).contains(
            "timed out after 300 ms waiting for `rfs_status(0) == 0` (last value: false)"
        ),
        "{}",
        stderr(&out)
    );
}

#[test]
fn example_back_and_forth() {
    let out = run(&[
        "--sim",
        "run",
        &example("back_and_forth.rhai"),
        "--",
        "2",
        "2000",
        "200000",
        "4000000",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("cycle 2 of 2: reached 2000 and -2000"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn example_bus_scan_finds_the_modules_and_the_gap() {
    let sim = Sim::start(&["--pty", "--modules", "1,2,4"]);
    let out = run(&[
        "run",
        &example("bus_scan.rhai"),
        "--port",
        &sim.first,
        "--timeout",
        "400",
        "--",
        "5",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    for address in [1, 2, 4] {
        assert!(
            text.contains(&format!("module {address}: answers, firmware 142V1.06")),
            "{text}"
        );
    }
    assert!(
        !text.contains("module 3:") && !text.contains("module 5:"),
        "{text}"
    );
    assert!(text.contains("3 modules found: [1, 2, 4]"), "{text}");
}

#[test]
fn example_multi_axis_homes_and_moves_three_axes_of_a_tmcm_6110() {
    let sim = Sim::start(&[
        "--pty",
        "--profile",
        "tmcm-6110",
        "--left-switch",
        "-2000",
        "--left-switch",
        "1:-5000",
    ]);
    let out = run(&[
        "run",
        &example("multi_axis.rhai"),
        "--profile",
        "tmcm-6110",
        "--port",
        &sim.first,
        "--",
        "3",
        "1000",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    for line in [
        "axis 2: homed",
        "axis 1: at 2000, the other axes unmoved",
        "3 axes homed and positioned: [1000, 2000, 3000]",
    ] {
        assert!(text.contains(line), "{line} missing:\n{text}");
    }
    // Without switches the search finds nothing, and says where to look.
    let out = run(&[
        "--sim",
        "run",
        &example("multi_axis.rhai"),
        "--profile",
        "tmcm-6110",
        "--",
        "2",
        "1000",
        "300",
    ]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(
        stderr(&out).contains("axis 0: no left switch found"),
        "{}",
        stderr(&out)
    );
}
