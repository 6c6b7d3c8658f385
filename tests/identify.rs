//! Identification on connect, through the real binary against `tmclsh sim` on a pty: every
//! built-in profile's simulated module is recognised from its 136 answer and talked to with its
//! own tables; a given profile wins with one warning; an unknown module number gets the generic
//! profile; a boot loader ends the session after the one exchange; a module already in ASCII mode
//! (no answer to 136) is talked to with a given profile, and without one is sent nothing on a
//! guess (exit 3).

use std::path::{Path, PathBuf};
use std::process::Output;

use crate::sim::Sim;
use crate::util::{code, repo, run, stderr, stdout, tempdir};

/// `tmclsh --port PTY ARGS`.
fn on(sim: &Sim, args: &[&str]) -> Output {
    let mut all = vec!["--port", sim.first.as_str()];
    all.extend_from_slice(args);
    run(&all)
}

/// The value of `key = "…"` or `key = N` on its first line in a profile file.
fn field(text: &str, key: &str) -> String {
    text.lines()
        .find_map(|line| {
            let rest = line.trim_start().strip_prefix(key)?;
            let value = rest.trim_start().strip_prefix('=')?;
            let value = value.split('#').next().unwrap().trim();
            Some(value.trim_matches('"').to_string())
        })
        .unwrap_or_else(|| panic!("no {key} in the profile"))
}

/// Every built-in profile: (name, file text).
fn built_in() -> Vec<(String, String)> {
    let mut profiles: Vec<(String, String)> = std::fs::read_dir(repo().join("data/profiles"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect();
    profiles.sort();
    profiles
}

/// A TMCM-142 profile file whose simulated module answers 136 with `version`.
pub(crate) fn module_answering(dir: &Path, version: &str) -> PathBuf {
    let text = std::fs::read_to_string(repo().join("data/profiles/tmcm-142.toml")).unwrap();
    let text: String = text
        .lines()
        // The formats tie the string to the module number; this module claims another.
        .filter(|l| !l.starts_with("version_format") && !l.starts_with("bootloader_format"))
        .map(|l| {
            if l.starts_with("version_string") {
                format!("version_string = \"{version}\"\n")
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    let path = dir.join(format!("answers-{version}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn every_built_in_profile_s_module_is_identified_and_talked_to_with_its_tables() {
    for (name, text) in built_in() {
        let module = field(&text, "module");
        let version = field(&text, "version_string");
        let last_motor: u8 = field(&text, "axes").parse::<u8>().unwrap() - 1;
        let sim = Sim::start(&["--pty", "--profile", &name]);
        // No --profile: the module's answer chooses it. The last motor is only valid with the
        // module's own axis count (5 on a TMCM-6110, refused by the default TMCM-142 profile).
        let line = format!("GAP 1, {last_motor}");
        let out = on(&sim, &["-v", "-c", &line]);
        assert_eq!(code(&out), 0, "{name}: {}", stderr(&out));
        let said = format!("tmclsh: {module}, firmware {version}, profile {name} (built in)\n");
        assert!(stderr(&out).contains(&said), "{name}: {}", stderr(&out));
        assert_eq!(stdout(&out).trim_end(), "BA 100 0", "{name}");
    }
}

#[test]
fn without_an_identified_module_the_default_profile_refuses_a_six_axis_motor() {
    // The control for the test above: motor 5 needs the TMCM-6110's own profile.
    let out = run(&["--sim", "-c", "GAP 1, 5"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
}

#[test]
fn a_given_profile_wins_over_the_answer_with_one_warning() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    let out = on(&sim, &["--profile", "tmcm-1140", "-v", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.contains("tmclsh: TMCM-6110, firmware 6110V131, profile tmcm-1140 (built in)\n"),
        "{err}"
    );
    let warnings: Vec<&str> = err
        .lines()
        .filter(|l| l.contains("but the profile given is tmcm-1140"))
        .collect();
    assert_eq!(warnings.len(), 1, "{err}");
    assert!(warnings[0].contains("is a TMCM-6110 (6110V131)"), "{err}");
    // The given (one-axis) profile is the one that checks lines.
    let out = on(&sim, &["--profile", "tmcm-1140", "-c", "GAP 1, 5"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    // A matching profile says nothing more.
    let out = on(&sim, &["--profile", "6110", "-c", "GAP 1, 5"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(!stderr(&out).contains("profile given"), "{}", stderr(&out));
}

#[test]
fn a_profile_file_is_named_by_its_path() {
    let dir = tempdir();
    let file = dir.join("my-6110.toml");
    std::fs::copy(repo().join("data/profiles/tmcm-6110.toml"), &file).unwrap();
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    let out = on(
        &sim,
        &["--profile", file.to_str().unwrap(), "-v", "-c", "GAP 1, 5"],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let said = format!(
        "tmclsh: TMCM-6110, firmware 6110V131, profile {} (file)\n",
        file.display()
    );
    assert!(stderr(&out).contains(&said), "{}", stderr(&out));
}

#[test]
fn a_module_without_a_profile_gets_the_generic_one_and_one_notice() {
    let dir = tempdir();
    let sim = Sim::start(&[
        "--pty",
        "--profile",
        module_answering(&dir, "9999V100").to_str().unwrap(),
    ]);
    let out = on(&sim, &["-v", "-c", "GAP 1, 0", "-c", "GAP 4, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.contains("tmclsh: TMCM-9999, firmware 9999V100, profile generic (built in)\n"),
        "{err}"
    );
    assert_eq!(
        err.matches("generic TMCL profile").count(),
        1,
        "one notice: {err}"
    );
    // Parameters by number only.
    let out = on(&sim, &["-c", "GAP actual_position, 0"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
}

#[test]
fn a_boot_loader_is_reported_and_nothing_else_is_sent() {
    let dir = tempdir();
    let profile = module_answering(&dir, "142B1.06");
    let sim = Sim::start_capturing_stderr(&[
        "--pty",
        "--verbose",
        "--profile",
        profile.to_str().unwrap(),
    ]);
    let log = dir.join("session.log");
    let out = on(
        &sim,
        &[
            "--log",
            log.to_str().unwrap(),
            "-c",
            "GAP 1, 0",
            "-c",
            "MVP ABS, 0, 100",
        ],
    );
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("TMCM-142 in its boot loader (142B1.06): no firmware is running"),
        "{}",
        stderr(&out)
    );
    assert_eq!(stdout(&out), "");
    let transcript = std::fs::read_to_string(&log).unwrap();
    let sent: Vec<&str> = transcript.lines().filter(|l| l.contains(" tx ")).collect();
    assert_eq!(sent.len(), 1, "{transcript}");
    assert!(sent[0].contains("136 to module 1"), "{transcript}");
    // The module itself received the one frame.
    let traffic = sim.quit();
    let received: Vec<&str> = traffic.lines().filter(|l| l.contains(" <- ")).collect();
    assert_eq!(received.len(), 1, "{traffic}");
}

#[test]
fn a_module_already_in_ascii_mode_is_talked_to_with_a_given_profile_and_never_guessed() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    {
        let mut port = sim.pty();
        assert_eq!(port.transact(1, 139, 0, 0, 0).value, 0);
    }
    // It takes the 136 frame as a line for nobody and does not answer: one timeout, a notice,
    // and the given profile (or the default) is used.
    let out = on(
        &sim,
        &[
            "--timeout",
            "300",
            "--profile",
            "tmcm-6110",
            "-v",
            "-c",
            "GAP 4, 5",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.contains("module 1 (A) did not answer command 136 (firmware version) within 300 ms"),
        "{err}"
    );
    assert!(
        err.contains(
            "tmclsh: TMCM-6110 (not identified: no answer to 136), profile tmcm-6110 (built in)"
        ),
        "{err}"
    );
    assert_eq!(stdout(&out).trim_end(), "BA 100 1000");
    // Without a profile nothing is guessed: no 139 to a module that did not say what it is. It
    // answers a line in ASCII mode, so it was left there: the default profile, in ASCII mode.
    // (The session above put the module back in binary mode, as GP 67 says it starts in binary.)
    {
        let mut port = sim.pty();
        assert_eq!(port.transact(1, 139, 0, 0, 0).value, 0);
    }
    let dir = tempdir();
    let log = dir.join("guess.log");
    let out = on(
        &sim,
        &[
            "--timeout",
            "300",
            "--log",
            log.to_str().unwrap(),
            "-c",
            "GAP 4, 0",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let err = stderr(&out);
    for said in [
        "answers in ASCII mode",
        "using the profile tmcm-142 (built in)",
    ] {
        assert!(err.contains(said), "{said}: {err}");
    }
    let log = std::fs::read_to_string(&log).unwrap();
    assert!(!log.contains("(139)"), "{log}");
}

#[test]
fn a_module_that_answers_neither_136_nor_an_ascii_line_is_sent_nothing_on_a_guess() {
    // Nothing at address 5: asked twice in binary and once in ASCII, then exit 3 with the
    // likely causes and the two ways on.
    let sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let log = dir.join("none.log");
    let out = on(
        &sim,
        &[
            "--timeout",
            "200",
            "-m",
            "5",
            "--log",
            log.to_str().unwrap(),
            "-c",
            "GAP 4, 0",
        ],
    );
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    let err = stderr(&out);
    for said in [
        "module 5 (E) is not identified",
        "already in ASCII mode",
        "--profile NAME",
        "--binary",
    ] {
        assert!(err.contains(said), "{said}: {err}");
    }
    let log = std::fs::read_to_string(&log).unwrap();
    assert!(!log.contains("(139)") && !log.contains("GAP 4"), "{log}");
}

#[test]
fn no_enter_asks_nothing_before_the_first_line() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    {
        let mut port = sim.pty();
        assert_eq!(port.transact(1, 139, 0, 0, 0).value, 0);
    }
    let dir = tempdir();
    let log = dir.join("session.log");
    let out = on(
        &sim,
        &[
            "--profile",
            "tmcm-6110",
            "--no-enter",
            "-v",
            "--log",
            log.to_str().unwrap(),
            "-c",
            "GAP 4, 0",
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("tmclsh: TMCM-6110, profile tmcm-6110 (built in)\n"),
        "{}",
        stderr(&out)
    );
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(!transcript.contains("136"), "{transcript}");
}

#[test]
fn a_scan_names_a_boot_loader_and_an_unknown_module_and_asks_the_loader_nothing_more() {
    let dir = tempdir();
    let loader = Sim::start_capturing_stderr(&[
        "--pty",
        "--verbose",
        "--profile",
        module_answering(&dir, "142B1.06").to_str().unwrap(),
    ]);
    let out = run(&[
        "scan",
        "--port",
        &loader.first,
        "--addresses",
        "1-2",
        "--timeout",
        "1000",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("142B1.06  ?       TMCM-142 (boot loader)"),
        "{}",
        stdout(&out)
    );
    // 136 type 1 and type 0 only: no echo read.
    let traffic = loader.quit();
    let received: Vec<&str> = traffic.lines().filter(|l| l.contains(" <- ")).collect();
    assert_eq!(received.len(), 2, "{traffic}");

    let unknown = Sim::start(&[
        "--pty",
        "--profile",
        module_answering(&dir, "9999V100").to_str().unwrap(),
    ]);
    let out = run(&[
        "scan",
        "--port",
        &unknown.first,
        "--addresses",
        "1",
        "--timeout",
        "1000",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("9999V100  char    TMCM-9999 (no profile)"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn a_transcript_of_an_identified_module_replays_with_that_module_s_profile() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    let dir = tempdir();
    let log = dir.join("session.log");
    let log = log.to_str().unwrap();
    let out = on(&sim, &["--log", log, "-c", "GAP 4, 5"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    // The header was written before the module was asked: it names the default profile.
    let text = std::fs::read_to_string(log).unwrap();
    assert!(text.contains("module \"TMCM-142\""), "{text}");
    let out = run(&["--profile", "tmcm-6110", "transcript", "to-rhai", log]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("send(\"AGAP 4, 5\")"),
        "{}",
        stdout(&out)
    );
    // The identification is the session's own business, not replayed.
    assert!(!stdout(&out).contains("6110V131"), "{}", stdout(&out));
    let out = run(&["transcript", "to-rhai", log]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("a transcript of a TMCM-6110"),
        "{}",
        stderr(&out)
    );
}
