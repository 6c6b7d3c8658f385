//! A bus of different modules (`tmclsh sim --modules 1:tmcm-142,2:tmcm-6110,3:tmcm-1260`) through
//! the real binary on a pty: switching the target identifies that module once and takes its
//! profile (validation, `:params`, the banner); the binary-only TMCM-1260 is talked to in frames
//! while the TMCM-142 and the TMCM-6110 stay in ASCII mode; a given profile wins for every module
//! with one warning each; Ctrl-C stops every motor the session moved on every module, each in its
//! own mode; a scan names each module; a transcript of the bus is not replayed with one profile.

use std::process::{Command, Output};

use rexpect::session::spawn_command;

use crate::sim::Sim;
use crate::util::{bin, code, run, run_with_stdin, stderr, stdout, tempdir};

const BUS: &str = "1:tmcm-142,2:tmcm-6110,3:tmcm-1260";

fn bus_sim(extra: &[&str]) -> Sim {
    let mut args = vec!["--pty", "--modules", BUS];
    args.extend_from_slice(extra);
    Sim::start(&args)
}

/// `tmclsh --port PTY ARGS` with `input` piped in.
fn piped(sim: &Sim, args: &[&str], input: &str) -> Output {
    let mut all = vec!["--port", sim.first.as_str()];
    all.extend_from_slice(args);
    run_with_stdin(&all, input)
}

/// The transcript lines that sent something.
fn sent(log: &str) -> Vec<&str> {
    log.lines().filter(|l| l.contains(" tx ")).collect()
}

#[test]
fn switching_target_identifies_each_module_once_and_takes_its_profile() {
    let sim = bus_sim(&[]);
    let dir = tempdir();
    let log = dir.join("bus.log");
    let input = "GAP 1, 0\n\
                 :target 2\n\
                 GAP 1, 5\n\
                 :params max_current\n\
                 :target 3\n\
                 GAP 1, 0\n\
                 :target 1\n\
                 GAP 1, 0\n\
                 :target 2\n\
                 GAP 1, 5\n";
    let out = piped(&sim, &["--log", log.to_str().unwrap()], input);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    for said in [
        "target: module 2 (B), TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)",
        "target: module 3 (C), TMCM-1260, firmware 1260V144, profile tmcm-1260 (built in)",
        "target: module 1 (A), TMCM-142, firmware 142V1.06, profile tmcm-142 (built in)",
    ] {
        assert!(text.contains(said), "{said}: {text}");
    }
    // `:params` shows the TMCM-6110's table (currents 0..255), not the TMCM-142's (0..15).
    let params = text
        .lines()
        .find(|l| l.contains("max_current"))
        .expect(&text);
    assert!(params.contains("0..255"), "{params}");
    let log = std::fs::read_to_string(&log).unwrap();
    let sent = sent(&log);
    // Each module asked once for its version, whatever the number of switches.
    for module in 1..=3 {
        let asked = sent
            .iter()
            .filter(|l| {
                let letter = char::from(b'@' + module);
                l.contains(&format!("136 to module {module} ({letter}) in binary"))
            })
            .count();
        assert_eq!(asked, 1, "module {module}: {log}");
    }
    // The TMCM-1260 in frames, the others in ASCII lines, on the same session.
    assert!(
        sent.iter()
            .any(|l| l.contains("GAP 1, 0 to module 3 (C) in binary")),
        "{log}"
    );
    assert!(
        !sent.iter().any(|l| l.ends_with("; to module 3 (C)")),
        "{log}"
    );
    assert!(
        !sent
            .iter()
            .any(|l| l.contains("139 to module 3") || l.contains("(139) to module 3")),
        "{log}"
    );
    assert!(sent.iter().any(|l| l.contains("\"BGAP 1, 5\\r\"")), "{log}");
    assert!(sent.iter().any(|l| l.contains("\"AGAP 1, 0\\r\"")), "{log}");
}

#[test]
fn a_line_to_the_first_module_is_checked_with_its_profile_after_a_switch_back() {
    let sim = bus_sim(&[]);
    // Motor 5 is valid on the TMCM-6110, refused (exit 2) on the TMCM-142 after switching back.
    let out = piped(&sim, &[], ":target 2\nGAP 1, 5\n:target 1\nGAP 1, 5\n");
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("motor 5 does not exist: the TMCM-142"),
        "{}",
        stderr(&out)
    );
    // An address character picks the module's profile too, without switching.
    let dir = tempdir();
    let log = dir.join("second.log");
    let out = piped(
        &sim,
        &["--log", log.to_str().unwrap()],
        "B GAP 1, 5\nGAP 1, 0\n",
    );
    let log = std::fs::read_to_string(&log).unwrap_or_default();
    assert_eq!(code(&out), 0, "{}{log}", stderr(&out));
}

#[test]
fn module_at_start_and_target_in_a_script_identify_that_module() {
    let sim = bus_sim(&[]);
    let out = piped(&sim, &["-v", "--module", "2"], "GAP 1, 5\n");
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out)
            .contains("TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in), module 2"),
        "{}",
        stderr(&out)
    );
    let dir = tempdir();
    let script = dir.join("bus.rhai");
    std::fs::write(
        &script,
        "target(3);\n\
         ror(0, 300);\n\
         mst(0);\n\
         target(2);\n\
         sap(\"max_current\", 5, 200);\n\
         assert_eq(gap(\"max_current\", 5), 200);\n\
         target(1);\n\
         assert_eq(gap(\"actual_position\", 0), 0);\n",
    )
    .unwrap();
    let out = Command::new(bin())
        .args(["--port", &sim.first, "run", script.to_str().unwrap()])
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    assert_eq!(code(&out), 0, "{}{}", stdout(&out), stderr(&out));
}

#[test]
fn a_given_profile_wins_for_every_module_with_a_warning_each() {
    let sim = bus_sim(&[]);
    let out = piped(
        &sim,
        &["--profile", "tmcm-142"],
        ":target 2\nGAP 1, 0\n:target 3\nGAP 1, 0\n",
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let err = stderr(&out);
    for module in ["2 (B) is a TMCM-6110", "3 (C) is a TMCM-1260"] {
        let warning = format!("module {module}");
        assert_eq!(err.matches(&warning).count(), 1, "{err}");
    }
    assert!(
        stdout(&out).contains("TMCM-6110, firmware 6110V131, profile tmcm-142 (built in)"),
        "{}",
        stdout(&out)
    );
    // The given profile checks module 2's lines: one motor.
    let out = piped(&sim, &["--profile", "tmcm-142"], ":target 2\nGAP 1, 5\n");
    assert_eq!(code(&out), 2, "{}", stderr(&out));
}

#[test]
fn ctrl_c_stops_every_motor_the_session_moved_on_every_module() {
    let mut sim = bus_sim(&["--manual-clock"]);
    let data = tempdir();
    let mut command = Command::new(bin());
    command
        .args(["--port", &sim.first])
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("XDG_DATA_HOME", &data)
        .env("HOME", &data);
    let mut p = spawn_command(command, Some(crate::util::EXPECT_MS)).unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("ROR 0, 200000").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line(":target 3").unwrap();
    p.exp_string("TMCM-1260").unwrap();
    p.exp_string("C[bin]> ").unwrap();
    p.send_line("ROR 0, 200000").unwrap();
    p.exp_string("C[bin]> ").unwrap();
    p.send_line(":target 2").unwrap();
    p.exp_string("B> ").unwrap();
    p.send_line("ROR 5, 200000").unwrap();
    p.exp_string("B> ").unwrap();
    let turning = [("@1", "0"), ("@3", "0"), ("@2", "5")];
    for (module, motor) in turning {
        assert!(velocity(&mut sim, module, motor) > 0.0, "{module} turns");
    }
    p.send_control('c').unwrap();
    // The binary-mode module first: frames before lines, so one quiet gap at most.
    p.exp_string("stopped motor 0 of module 3 (C) with MST")
        .unwrap();
    p.exp_string("stopped motor 0 of module 1 (A) with MST")
        .unwrap();
    p.exp_string("stopped motor 5 of module 2 (B) with MST")
        .unwrap();
    p.exp_string("B> ").unwrap();
    assert!(sim.console("advance 10s").starts_with("ok"));
    for (module, motor) in turning {
        assert_eq!(velocity(&mut sim, module, motor), 0.0, "{module} stopped");
    }
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

/// The velocity of `motor` of the module at `slot` (`@2`) after a simulated second.
fn velocity(sim: &mut Sim, slot: &str, motor: &str) -> f64 {
    assert!(sim.console("advance 1s").starts_with("ok"));
    let line = sim.console(&format!("{slot} motor {motor}"));
    let words: Vec<&str> = line.split_whitespace().collect();
    let at = words.iter().position(|w| *w == "velocity").expect(&line);
    words[at + 1].parse().expect(&line)
}

#[test]
fn a_scan_of_a_mixed_bus_names_each_module_from_its_own_answer() {
    let sim = bus_sim(&[]);
    let out = run(&["--port", &sim.first, "scan", "--addresses", "1-4"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    for (address, firmware, module) in [
        ("1", "142V1.06", "TMCM-142"),
        ("2", "6110V131", "TMCM-6110"),
        ("3", "1260V144", "TMCM-1260"),
    ] {
        let row = text
            .lines()
            .find(|l| l.split_whitespace().next() == Some(address))
            .expect(&text);
        assert!(row.contains(firmware) && row.ends_with(module), "{row}");
    }
    assert!(text.contains("3 modules answered"), "{text}");
    // The REPL's :scan waits as briefly per reply as `tmclsh scan`.
    let out = piped(&sim, &[], ":scan 1-4\n");
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("(at most 100 ms per reply)"),
        "{}",
        stdout(&out)
    );
    let out = piped(&sim, &["--timeout", "300"], ":scan 1-4\n");
    assert!(
        stdout(&out).contains("(at most 300 ms per reply)"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn a_transcript_of_a_mixed_bus_is_not_replayed_with_one_profile() {
    let sim = bus_sim(&[]);
    let dir = tempdir();
    let log = dir.join("bus.log");
    let log = log.to_str().unwrap();
    let out = piped(&sim, &["--log", log], "GAP 1, 0\n:target 2\nGAP 1, 5\n");
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = run(&["transcript", "to-rhai", log]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("a bus of different modules"), "{err}");
    assert!(err.contains("module 2 (B), TMCM-6110"), "{err}");
    // With the same profile given to the session, the replay checks every line alike.
    let log2 = dir.join("given.log");
    let log2 = log2.to_str().unwrap();
    let out = piped(
        &sim,
        &["--profile", "tmcm-6110", "--log", log2],
        "GAP 1, 0\n:target 2\nGAP 1, 5\n",
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = run(&["--profile", "tmcm-6110", "transcript", "to-rhai", log2]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("BGAP 1, 5"), "{}", stdout(&out));
}

#[test]
fn frames_and_lines_interleave_line_by_line_without_losing_a_reply() {
    let sim = bus_sim(&[]);
    // Every line alternates mode: ASCII to A and B, a frame to C, by address character alone.
    let mut input = String::new();
    let mut expected = Vec::new();
    for n in 1..=12 {
        input.push_str(&format!(
            "ASAP 4, 0, {n}\nCSAP 4, 0, {}\nBSAP 4, 5, {}\n",
            n + 100,
            n + 200
        ));
        input.push_str("CGAP 4, 0\nAGAP 4, 0\nBGAP 4, 5\n");
        expected.extend([
            format!("BA 100 {n}"),
            format!("BC 100 {}", n + 100),
            format!("BB 100 {}", n + 200),
            format!("BC 100 {}", n + 100),
            format!("BA 100 {n}"),
            format!("BB 100 {}", n + 200),
        ]);
    }
    let out = piped(&sim, &[], &input);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let shown: Vec<String> = stdout(&out).lines().map(str::to_string).collect();
    assert_eq!(shown, expected, "{}", stderr(&out));
}
