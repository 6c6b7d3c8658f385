//! Transcripts say what they are of: a header naming dialect and module, written by `--log` and
//! `:log`, read by `transcript to-rhai`, which refuses (exit 2) what it cannot recognise. A
//! transcript that cannot be written ends a run that asked for it (exit 3); the REPL says so
//! and goes on without it.

use std::path::Path;
use std::process::Command;

use rexpect::session::spawn_command;

use super::run_piped;
use crate::sim::Sim;
use crate::util::{bin, code, run, stderr, stdout, tempdir};

fn arg(path: &Path) -> &str {
    path.to_str().unwrap()
}

fn to_rhai(log: &Path, script: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec!["transcript", "to-rhai", arg(log), "-o", arg(script)];
    args.extend_from_slice(extra);
    run(&args)
}

#[test]
fn log_started_in_an_smd4_session_replays_as_smd4() {
    let dir = tempdir();
    let (log, script) = (dir.join("s.log"), dir.join("s.rhai"));
    let input = format!(
        "MOTOR:VMAX,1500\n:log {}\nMOTOR:VMAX,2000\nMOTOR:VMAX\nSYS:MODE\n",
        arg(&log)
    );
    let out = run_piped(&["--sim", "--protocol", "smd4"], input.into_bytes());
    assert_eq!(out.code, 0, "{}", out.stderr());
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(
        text.lines()
            .next()
            .unwrap()
            .contains(" ## tmclsh transcript: dialect \"smd4\", module \"SMD4\", version "),
        "{text}"
    );
    let out = to_rhai(&log, &script, &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out).is_empty(),
        "no guess, no notice: {}",
        stderr(&out)
    );
    let replay = std::fs::read_to_string(&script).unwrap();
    assert!(
        replay.contains("// Replay of the SMD4 transcript s.log"),
        "{replay}"
    );
    assert!(
        replay.contains("assert_eq(check(\"MOTOR:VMAX\", [2000.0, 2000.0]), \"\");"),
        "{replay}"
    );
    let out = run(&["--sim", "run", arg(&script), "--protocol", "smd4"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn the_header_names_the_profile_and_a_transcript_of_another_module_is_refused() {
    let dir = tempdir();
    let profile = dir.join("m.toml");
    std::fs::write(
        &profile,
        "[meta]\nmodule = \"TMCM-9\"\n[[axis_parameter]]\nnumber = 4\nname = \"Speed\"\n\
         ident = \"speed\"\naccess = \"RW\"\n",
    )
    .unwrap();
    let (log, script) = (dir.join("t.log"), dir.join("t.rhai"));
    let out = run(&[
        "--sim",
        "--profile",
        arg(&profile),
        "--log",
        arg(&log),
        "-c",
        "SAP speed, 0, 7",
        "-c",
        "GAP speed, 0",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = std::fs::read_to_string(&log).unwrap();
    let expected = format!(
        "dialect \"tmcl\", module \"TMCM-9\", profile \"{}\"",
        arg(&profile)
    );
    assert!(text.lines().next().unwrap().contains(&expected), "{text}");
    let out = to_rhai(&log, &script, &[]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("a transcript of a TMCM-9 (profile "),
        "{}",
        stderr(&out)
    );
    let out = to_rhai(&log, &script, &["--profile", arg(&profile)]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let replay = std::fs::read_to_string(&script).unwrap();
    assert!(
        replay.contains("assert_eq(send(\"AGAP 4, 0\"), 7);  // speed"),
        "{replay}"
    );
}

#[test]
fn what_to_rhai_cannot_recognise_is_refused_with_exit_2() {
    let dir = tempdir();
    let script = dir.join("x.rhai");
    let header = |dialect: &str| {
        format!(
            "2026-01-01T00:00:00.000Z ## tmclsh transcript: dialect \"{dialect}\", module \"M\"\n"
        )
    };
    let smd4 = header("smd4").replace("\"M\"", "\"SMD4\"");
    let cases: [(&str, Vec<u8>, &str); 7] = [
        (
            "binary garbage",
            vec![0x89, b'P', b'N', b'G', 0xFF, 0, 1, 2],
            "line 1: not text",
        ),
        (
            "text garbage",
            b"hello\nworld\n".to_vec(),
            "line 1: no time stamp: \"hello\"",
        ),
        ("empty", Vec::new(), "no TMCL exchange to replay"),
        (
            "header only",
            smd4.clone().into_bytes(),
            "no SMD4 exchange to replay",
        ),
        (
            "only a failure",
            format!(
                "{smd4}2026-01-01T00:00:00.001Z tx \"SYS:FW\\r\\n\" ; to SMD4\n\
                     2026-01-01T00:00:00.002Z -- no reply within 1000 ms\n"
            )
            .into_bytes(),
            "no SMD4 exchange to replay",
        ),
        (
            "unknown dialect",
            header("canopen").into_bytes(),
            "unknown dialect 'canopen'",
        ),
        (
            "two dialects",
            format!("{}{smd4}", header("tmcl").replace("\"M\"", "\"TMCM-142\"")).into_bytes(),
            "different modules",
        ),
    ];
    for (class, bytes, message) in cases {
        let log = dir.join("x.log");
        std::fs::write(&log, bytes).unwrap();
        let out = to_rhai(&log, &script, &[]);
        assert_eq!(code(&out), 2, "{class}: {}", stderr(&out));
        assert!(stderr(&out).contains(message), "{class}: {}", stderr(&out));
        assert!(stderr(&out).len() < 400, "{class}: a short message");
    }
}

#[test]
fn a_transcript_from_before_headers_is_read_with_a_notice() {
    let dir = tempdir();
    let (log, script) = (dir.join("old.log"), dir.join("old.rhai"));
    std::fs::write(
        &log,
        "2026-01-01T00:00:00.000Z -- SMD4 session opened on simulated SMD4 (built-in)\n\
         2026-01-01T00:00:00.001Z tx \"SYS:MODE\\r\\n\" ; to SMD4\n\
         2026-01-01T00:00:00.002Z rx \"0x0888,0x0000,1 (Remote)\\r\\n\" ; sflags 0x0888\n",
    )
    .unwrap();
    let out = to_rhai(&log, &script, &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("no header (a transcript from an older tmclsh): read as SMD4"),
        "{}",
        stderr(&out)
    );
    assert!(
        std::fs::read_to_string(&script)
            .unwrap()
            .contains("check(\"SYS:MODE\", [1])")
    );
}

#[test]
fn a_transcript_that_cannot_be_written_fails_the_run_with_exit_3() {
    let dir = tempdir();
    let script = dir.join("s.rhai");
    std::fs::write(&script, "send(\"GAP 4, 0\");\n").unwrap();
    let log = dir.join("t.log");
    let faces: [(&str, Vec<&str>, &[u8]); 3] = [
        (
            "-c",
            vec!["--sim", "--log", arg(&log), "-c", "GAP 4, 0"],
            b"",
        ),
        ("stdin", vec!["--sim", "--log", arg(&log)], b"GAP 4, 0\n"),
        (
            "run",
            vec!["--sim", "run", arg(&script), "--log", arg(&log)],
            b"",
        ),
    ];
    for (face, args, input) in faces {
        // No room at all: the header cannot be written.
        let mut command = with_disk_of(0, &args);
        let out = piped(&mut command, input);
        assert_eq!(code(&out), 3, "{face}: {}", stderr(&out));
        let expected = format!("cannot write the transcript {}: ", log.display());
        assert!(stderr(&out).contains(&expected), "{face}: {}", stderr(&out));
        assert!(out.stdout.is_empty(), "{face}: nothing ran");
    }
    // A device is no transcript: refused before anything runs.
    let out = run_piped(
        &["--sim", "--log", "/dev/full", "-c", "GAP 4, 0"],
        Vec::new(),
    );
    assert_eq!(out.code, 2, "{}", out.stderr());
    assert!(
        out.stderr()
            .contains("/dev/full: a character device, not a regular file"),
        "{}",
        out.stderr()
    );
    let out = run_piped(&["--sim"], b"GAP 4, 0\n:log /dev/full\nGAP 5, 0\n".to_vec());
    assert_eq!(out.code, 2, "{}", out.stderr());
    assert_eq!(out.stdout, "BA 100 1000000\n");
}

/// Runs `command` with `input` on its stdin.
fn piped(command: &mut Command, input: &[u8]) -> std::process::Output {
    use std::io::Write;
    let mut child = command
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(input).unwrap();
    child.wait_with_output().unwrap()
}

/// `tmclsh ARGS` in a shell whose file size limit is a few blocks, as on a full disk: the
/// transcript fails after its first lines (SIGXFSZ ignored, so the write fails with EFBIG).
fn with_small_disk(args: &[&str]) -> Command {
    with_disk_of(4, args)
}

/// `tmclsh ARGS` with a file size limit of `blocks`.
fn with_disk_of(blocks: u32, args: &[&str]) -> Command {
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg(format!(
            "trap '' XFSZ; ulimit -f {blocks}; exec \"$0\" \"$@\""
        ))
        .arg(bin())
        .args(args)
        .env("NO_COLOR", "1");
    command
}

#[test]
fn a_transcript_that_fills_the_disk_mid_run_ends_it_with_exit_3() {
    let dir = tempdir();
    let log = dir.join("full.log");
    let mut args = vec!["--sim", "--log", arg(&log)];
    for _ in 0..60 {
        args.extend(["-c", "GAP 4, 0"]);
    }
    let out = with_small_disk(&args).output().unwrap();
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    let replies = stdout(&out).lines().count();
    assert!(
        (1..60).contains(&replies),
        "stopped early: {replies} replies"
    );
    let err = stderr(&out);
    assert!(err.contains("cannot write the transcript"), "{err}");
    assert!(
        err.contains("the run stops: it asked for a transcript that cannot be written"),
        "{err}"
    );
    // What was written still reads back.
    let script = dir.join("full.rhai");
    let out = to_rhai(&log, &script, &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));

    // A script learns at its end.
    let rhai = dir.join("many.rhai");
    std::fs::write(&rhai, "for i in 0..60 { send(\"GAP 4, 0\"); }\n").unwrap();
    let log = dir.join("script.log");
    let out = with_small_disk(&["--sim", "run", arg(&rhai), "--log", arg(&log)])
        .output()
        .unwrap();
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("the run asked for a transcript, so it failed"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_script_whose_transcript_fills_the_disk_stops_at_once_with_its_motor_stopped() {
    let mut sim = Sim::start(&["--pty", "--manual-clock"]);
    let dir = tempdir();
    let rhai = dir.join("spin.rhai");
    std::fs::write(
        &rhai,
        "ror(0, 50000);\nfor i in 0..60 { gap(4, 0); }\nprint(\"all read\");\n",
    )
    .unwrap();
    let log = dir.join("spin.log");
    let out = with_small_disk(&["run", arg(&rhai), "--port", &sim.first, "--log", arg(&log)])
        .output()
        .unwrap();
    let err = stderr(&out);
    assert_eq!(code(&out), 3, "{err}");
    assert!(
        err.contains("the run stops: it asked for a transcript that cannot be written"),
        "{err}"
    );
    assert!(err.contains("cannot write the transcript"), "{err}");
    assert!(
        err.contains("stopped motor 0 of module 1 (A) with MST"),
        "{err}"
    );
    assert_eq!(stdout(&out), "", "the script stopped before its end");
    sim.console("advance 10s");
    assert!(
        sim.console("motor").contains("velocity 0"),
        "the motor ends stopped"
    );
}

#[test]
fn the_repl_says_the_transcript_failed_and_goes_on_without_it() {
    let dir = tempdir();
    let log = dir.join("repl.log");
    let mut command = with_small_disk(&[]);
    command
        .env("TERM", "xterm")
        .env("HOME", &dir)
        .env("XDG_DATA_HOME", &dir);
    let mut p =
        spawn_command(command, Some(crate::util::EXPECT_MS)).expect("tmclsh starts in a pty");
    p.exp_string("A> ").unwrap();
    p.send_line(":log /dev/full").unwrap();
    p.exp_string("/dev/full: a character device, not a regular file")
        .unwrap();
    p.send_line(&format!(":log {}", arg(&log))).unwrap();
    p.exp_string("logging to").unwrap();
    // Replies until the transcript fills the small disk: the notice comes before the reply
    // whose exchange could not be recorded, and nothing comes between it and the next prompt.
    let failed_after = (1..=30).find(|_| {
        p.send_line("GAP 4, 0").unwrap();
        let before = p.exp_string("= 1000000 usteps/t").unwrap();
        let between = p.exp_string("A> ").unwrap();
        assert!(!between.contains("cannot write"), "{between:?}");
        before.contains("cannot write the transcript")
    });
    assert!(failed_after.is_some(), "the transcript never failed");
    p.send_line(":log").unwrap();
    p.exp_string("not logging: cannot write the transcript")
        .unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("= 1000000 usteps/t").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}
