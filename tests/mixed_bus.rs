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
    p.send_line("ROR 5, 2000").unwrap();
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

/// The header line of a transcript and its identification notes, in order.
fn header_and_identifications(log: &str) -> (String, Vec<String>) {
    let header = log
        .lines()
        .find(|l| l.contains(" ## tmclsh transcript: "))
        .unwrap_or_else(|| panic!("no header: {log}"))
        .to_string();
    let notes = log
        .lines()
        .filter_map(|l| l.split_once(" -- identified: ").map(|(_, n)| n.to_string()))
        .collect();
    (header, notes)
}

#[test]
fn a_transcript_of_a_mixed_bus_names_each_modules_profile() {
    let sim = Sim::start(&["--pty", "--modules", "1:tmcm-142,2:tmcm-6110"]);
    let dir = tempdir();
    let log = dir.join("bus.log");
    let later = dir.join("later.log");
    // The second transcript starts once both modules are known, and sends to neither again.
    let input = format!("GAP 1, 0\n:target 2\nGAP 1, 5\n:log {}\n", later.display());
    let out = piped(&sim, &["--log", log.to_str().unwrap()], &input);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let both = [
        "module 1 (A), TMCM-142, firmware 142V1.06, profile tmcm-142 (built in)",
        "module 2 (B), TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)",
    ];
    for file in [&log, &later] {
        let text = std::fs::read_to_string(file).unwrap();
        let (header, notes) = header_and_identifications(&text);
        // As the first transcript's, the second's header (begun while module 2 is the target)
        // names the profile of a module that does not name itself.
        assert!(
            header.contains(
                "module \"TMCM-142\", profile \"built-in\", profiles \"per module, see the \
                 identification notes\""
            ),
            "{header}"
        );
        assert_eq!(notes, both, "{text}");
    }
    // The notes of the transcript begun mid-session come before anything else it records.
    let later_text = std::fs::read_to_string(&later).unwrap();
    assert!(
        later_text
            .lines()
            .nth(1)
            .is_some_and(|l| l.contains(" -- identified: module 1 (A)")),
        "{later_text}"
    );
    // Its replay sees the bus as the first transcript's does.
    let out = run(&["transcript", "to-rhai", later.to_str().unwrap()]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("a bus of different modules"),
        "{}",
        stderr(&out)
    );
    // A given profile is every module's: the header says so by naming no other way.
    let given = dir.join("given.log");
    let out = piped(
        &sim,
        &["--profile", "tmcm-6110", "--log", given.to_str().unwrap()],
        "GAP 1, 0\n:target 2\nGAP 1, 5\n",
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = std::fs::read_to_string(&given).unwrap();
    let (header, notes) = header_and_identifications(&text);
    assert!(
        header.contains("module \"TMCM-6110\", profile \"built-in\", version"),
        "{header}"
    );
    assert_eq!(notes.len(), 2, "{text}");
}

/// The lines of the simulator's `--verbose` traffic that module `n` received.
fn received_by(traffic: &str, n: u8) -> Vec<&str> {
    let to = format!("module {n} <- ");
    traffic.lines().filter(|l| l.contains(&to)).collect()
}

#[test]
fn switching_to_a_module_in_its_boot_loader_reports_it_and_sends_it_nothing_more() {
    let sim = Sim::start_capturing_stderr(&[
        "--pty",
        "--verbose",
        "--modules",
        "1:tmcm-142,2:tmcm-6110",
        "--boot-loader=2",
    ]);
    let dir = tempdir();
    let log = dir.join("bus.log");
    // Every way of turning to module 2 after the first: the target, its address character, the
    // target again; module 1 in between and after.
    let input = "GAP 1, 0\n:target 2\nGAP 1, 0\nBGAP 1, 0\n:target 2\nBSAP 4, 0, 9\n\
                 ASAP 4, 0, 77\nAGAP 4, 0\n";
    let out = piped(
        &sim,
        &["--keep-going", "--log", log.to_str().unwrap()],
        input,
    );
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    let err = stderr(&out);
    let report = "module 2 (B): TMCM-6110 in its boot loader (6110B131): no firmware is running";
    for line in [
        "line 2 (:target 2)",
        "line 4 (BGAP 1, 0)",
        "line 5 (:target 2)",
        "line 6 (BSAP 4, 0, 9)",
    ] {
        assert!(err.contains(&format!("{line}: {report}")), "{line}: {err}");
    }
    // Module 1 stayed the target and answered every line meant for it.
    assert_eq!(
        stdout(&out).lines().collect::<Vec<_>>(),
        ["BA 100 0", "BA 100 0", "BA 100 77", "BA 100 77"],
        "{err}"
    );
    let transcript = std::fs::read_to_string(&log).unwrap();
    let to_b: Vec<&str> = sent(&transcript)
        .into_iter()
        .filter(|l| l.contains("to module 2") || l.contains("to module B"))
        .collect();
    assert_eq!(to_b.len(), 1, "{transcript}");
    assert!(to_b[0].contains("136 to module 2"), "{transcript}");
    // What the boot loader itself received: the one 136 frame.
    let traffic = sim.quit();
    let received = received_by(&traffic, 2);
    assert_eq!(received.len(), 1, "{traffic}");
    assert!(received[0].contains(" 136"), "{traffic}");
    assert!(received_by(&traffic, 1).len() > 4, "{traffic}");
}

#[test]
fn switching_to_an_unknown_module_gives_it_the_generic_profile_with_one_notice() {
    let dir = tempdir();
    let unknown = crate::identify::module_answering(&dir, "9999V100");
    let bus = format!("1:tmcm-142,2:{}", unknown.display());
    let sim = Sim::start(&["--pty", "--modules", &bus]);
    let input = "GAP actual_position, 0\n:target 2\nGAP 1, 0\nGAP actual_position, 0\n\
                 :target 1\nGAP actual_position, 0\nBGAP 1, 0\n";
    let out = piped(&sim, &["--keep-going"], input);
    let err = stderr(&out);
    // The one refused line: a parameter name, which the generic profile has none of.
    assert_eq!(code(&out), 2, "{err}");
    assert!(
        err.contains("line 4 (GAP actual_position, 0): the generic TMCL module profile has no parameter names"),
        "{err}"
    );
    assert_eq!(
        err.matches("generic TMCL profile:").count(),
        1,
        "one notice: {err}"
    );
    // Module 2 sits at the host address of module 1 (both factory values): said once.
    let clash = "module 2 (B) is at the host address of module 1 (A)";
    assert_eq!(err.matches(clash).count(), 1, "{err}");
    assert_eq!(err.lines().count(), 3, "nothing else went wrong: {err}");
    assert_eq!(
        stdout(&out).lines().collect::<Vec<_>>(),
        [
            "BA 100 0",
            "target: module 2 (B), TMCM-9999, firmware 9999V100, profile generic (built in)",
            "BB 100 0",
            "target: module 1 (A), TMCM-142, firmware 142V1.06, profile tmcm-142 (built in)",
            "BA 100 0",
            "BB 100 0",
        ],
        "{err}"
    );
}

#[test]
fn each_unknown_module_on_a_bus_gets_a_generic_profile_notice_naming_it() {
    let dir = tempdir();
    let (b, c) = (
        crate::identify::module_answering(&dir, "9999V100"),
        crate::identify::module_answering(&dir, "8888V100"),
    );
    let bus = format!("1:tmcm-142,2:{},3:{}", b.display(), c.display());
    let sim = Sim::start(&["--pty", "--modules", &bus]);
    let input = ":target 2\nGAP 1, 0\n:target 3\nGAP 1, 0\n:target 2\nGAP 1, 0\n";
    let out = piped(&sim, &[], input);
    let err = stderr(&out);
    assert_eq!(code(&out), 0, "{err}");
    let notices: Vec<&str> = err
        .lines()
        .filter(|l| l.contains("generic TMCL profile"))
        .collect();
    assert_eq!(
        notices,
        [
            "tmclsh: module 2 (B), a TMCM-9999, uses the generic TMCL profile: commands and \
             motors 0..5 are checked, parameters by number only (0..255, no names, values \
             unchecked); `tmclsh profiles` lists the modules with tables",
            "tmclsh: module 3 (C), a TMCM-8888, uses the generic TMCL profile: commands and \
             motors 0..5 are checked, parameters by number only (0..255, no names, values \
             unchecked); `tmclsh profiles` lists the modules with tables",
        ],
        "one notice per unknown module, each naming it: {err}"
    );
}

#[test]
fn the_simulator_refuses_a_boot_loader_at_an_address_not_on_the_bus() {
    let out = run(&["sim", "--modules", "1,2", "--boot-loader=3"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("--boot-loader names module 3, which is not on the bus"),
        "{}",
        stderr(&out)
    );
    let out = run(&["sim", "--boot-loader=B"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("'B' is not a module address (1..255)"),
        "{}",
        stderr(&out)
    );
}

// Returning two modules to binary mode, the session sends module 2 its BIN after module 1 has
// left ASCII mode: module 1 takes those bytes for the start of a frame until its frame time-out.
// A session opened right after must still get its first frame answered.
#[test]
fn a_session_right_after_another_finds_every_module_answering_frames() {
    let sim = Sim::start(&["--pty", "--modules", "1:tmcm-142,2:tmcm-6110"]);
    for run in 0..4 {
        let out = piped(&sim, &["-v"], "GAP 1, 0\n:target 2\nGAP 1, 5\n");
        assert_eq!(code(&out), 0, "run {run}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("tmclsh: TMCM-142, firmware 142V1.06, profile tmcm-142"),
            "run {run}: {}",
            stderr(&out)
        );
    }
}
