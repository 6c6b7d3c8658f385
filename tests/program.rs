//! Stand-alone programs from the terminal: `tmclsh download` of the manual's test2.tmc to the
//! simulator over a pty, started with the ASCII RUN helper, queried while it runs, stopped,
//! stepped — with the simulator's manual clock so the motion is exact.

use crate::sim::Sim;
use crate::util::{code, repo, run, stderr, stdout, tempdir};

fn test2() -> String {
    repo()
        .join("scripts")
        .join("test2.tmc")
        .display()
        .to_string()
}

/// `tmclsh --port PTY -c LINE...`, returning stdout lines (and asserting success).
fn lines(sim: &Sim, commands: &[&str]) -> Vec<String> {
    let mut args = vec!["--port", sim.first.as_str()];
    for c in commands {
        args.push("-c");
        args.push(c);
    }
    let out = run(&args);
    assert_eq!(code(&out), 0, "{commands:?}: {}", stderr(&out));
    stdout(&out).lines().map(str::to_string).collect()
}

#[test]
fn test2_downloaded_runs_between_the_two_positions_while_queries_are_answered() {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let out = run(&["download", &test2(), "--port", &sim.first]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(
        stdout(&out).trim(),
        "downloaded 13 instructions to module 1 (A), verified by reading back; the module is in ASCII mode"
    );
    let got = lines(&sim, &[":run", ":status"]);
    assert_eq!(
        got[0],
        "program started on module 1 (A); the module is in ASCII mode"
    );
    assert_eq!(
        got[1],
        "program on module 1 (A): running (1); the module is in ASCII mode"
    );
    // ROL for 5 s, ROR for 5 s, then the loop between +1000000 and -1000000.
    sim.console("advance 2s");
    assert!(
        lines(&sim, &["GAP actual_speed, 0"])[0].starts_with("BA 100 -"),
        "ROL turns left"
    );
    sim.console("advance 100s");
    assert_eq!(lines(&sim, &["GAP target_position, 0"]), ["BA 100 1000000"]);
    sim.console("advance 60s");
    assert_eq!(
        lines(&sim, &["GAP target_position, 0"]),
        ["BA 100 -1000000"],
        "on the way back"
    );
    sim.console("advance 300s");
    let position = lines(&sim, &["GAP actual_position, 0", "GAP target_position, 0"]);
    assert_eq!(position[1], "BA 100 1000000", "and forth again");
    // :stop halts the program; the motor finishes nothing more.
    let got = lines(&sim, &[":stop", ":status"]);
    assert_eq!(
        got[1],
        "program on module 1 (A): stopped (0); the module is in ASCII mode"
    );
    sim.console("advance 600s");
    let before = lines(&sim, &["GAP target_position, 0"]);
    sim.console("advance 600s");
    assert_eq!(
        lines(&sim, &["GAP target_position, 0"]),
        before,
        "no new targets once stopped"
    );
}

#[test]
fn stepping_advances_one_instruction_from_ascii_mode() {
    let sim = Sim::start(&["--pty", "--manual-clock"]);
    let out = run(&["download", &test2(), "--port", &sim.first]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let got = lines(
        &sim,
        &[
            ":reset",
            ":status",
            ":step",
            ":status",
            "GGP program_counter, 0",
            "GAP target_speed, 0",
        ],
    );
    assert_eq!(
        got[1],
        "program on module 1 (A): reset (3); the module is in ASCII mode"
    );
    assert_eq!(
        got[2],
        "program step done on module 1 (A); the module is in ASCII mode"
    );
    assert_eq!(
        got[3],
        "program on module 1 (A): stepping (2); the module is in ASCII mode"
    );
    assert_eq!(got[4], "BA 100 1", "the program counter moved by one");
    assert_eq!(
        got[5], "BA 100 -500000",
        "the first instruction, ROL 0, 500000, ran"
    );
}

#[test]
fn download_with_run_and_from_a_program_file() {
    let sim = Sim::start(&["--pty", "--manual-clock"]);
    let bin = tempdir().join("test2.bin");
    let out = run(&["asm", &test2(), "-o", bin.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = run(&[
        "download",
        bin.to_str().unwrap(),
        "--port",
        &sim.first,
        "--run",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out)
            .contains("verified by reading back; program started; the module is in ASCII mode")
    );
    assert_eq!(
        lines(&sim, &[":status"]),
        ["program on module 1 (A): running (1); the module is in ASCII mode"]
    );
}

#[test]
fn download_refuses_bad_programs_before_touching_the_module() {
    let sim = Sim::start(&["--pty", "--silent-after", "0"]);
    let source = tempdir().join("bad.tmc");
    std::fs::write(&source, "MVP ABX, 0, 5\nJA Nowhere\n").unwrap();
    let out = run(&[
        "download",
        source.to_str().unwrap(),
        "--port",
        &sim.first,
        "--timeout",
        "100",
    ]);
    assert_eq!(code(&out), 2, "refused, not a timeout: {}", stderr(&out));
    assert!(stderr(&out).contains("bad.tmc:1:"), "{}", stderr(&out));
    let out = run(&["--sim", "download", &test2(), "--protocol", "smd4"]);
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("TMCL modules only"));
}

#[test]
fn the_built_in_module_runs_programs_too() {
    let out = run(&[
        "--sim",
        "-c",
        &format!(":download {} --run", test2()),
        "-c",
        ":status",
        "-c",
        ":stop",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("downloaded 13 instructions"), "{text}");
    assert!(text.contains("running (1)"), "{text}");
    assert!(text.contains("program stopped on module 1 (A)"), "{text}");
}

/// Timer 0 every 100 ms counts in user variable 0 (`VECT`, `SGP n, 3, ms`, `EI`, `RETI`).
const TIMER_PROGRAM: &str = "\
      VECT 0, Tick
      SGP 0, 3, 100
      EI 0
      EI 255
Loop: JA Loop

Tick: GGP 0, 2
      CALC ADD, 1
      AGP 0, 2
      RETI
";

#[test]
fn a_timer_interrupt_program_counts_on_a_module_with_interrupts() {
    let mut sim = Sim::start(&["--pty", "--manual-clock", "--profile", "tmcm-1140"]);
    let dir = tempdir();
    let file = dir.join("timer.tmc");
    std::fs::write(&file, TIMER_PROGRAM).unwrap();
    let file = file.display().to_string();
    let out = run(&[
        "download",
        &file,
        "--port",
        &sim.first,
        "--profile",
        "tmcm-1140",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).starts_with("downloaded 9 instructions to module 1 (A), verified"),
        "{}",
        stdout(&out)
    );
    lines(&sim, &[":run"]);
    sim.console("advance 1050ms");
    assert_eq!(lines(&sim, &["GGP 0, 2"]), ["BA 100 10"]);
    sim.console("advance 1s");
    assert_eq!(lines(&sim, &["GGP 0, 2"]), ["BA 100 20"]);
}

#[test]
fn download_and_upload_refuse_an_smd4_drive_named_by_the_environment() {
    // `--protocol smd4` on the command line is refused by clap's layer; the variable reaches the
    // subcommand itself, which must refuse before opening anything.
    for args in [
        &["download", &test2(), "--sim"][..],
        &["upload", "--sim"][..],
    ] {
        let out = std::process::Command::new(crate::util::bin())
            .args(args)
            .env("TMCLSH_PROTOCOL", "smd4")
            .env("NO_COLOR", "1")
            .stdin(std::process::Stdio::null())
            .output()
            .unwrap();
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert_eq!(
            stderr(&out),
            "tmclsh: this subcommand works with TMCL modules only\n",
            "{args:?}"
        );
        assert_eq!(stdout(&out), "", "{args:?}");
    }
}
