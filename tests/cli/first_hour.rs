//! A newcomer's first hour, against the real binary: a CI run with no link is refused rather
//! than passed on the simulator, `--sim` and `sim = true` choose it, `TMCLSH_TCP` reaches a
//! module, a misspelt variable or key is named, a broken configuration locks nobody out of help
//! and `config`, a TCP address given as a port is refused, and the wrong `--protocol` on a real
//! line is named as such, both ways.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

use crate::sim::Sim;
use crate::util::{bin, code, stderr, stdout, tempdir};

/// What a command run without a terminal and without a link says.
const NO_LINK: &str = "no module to talk to: give --port, --tcp or --can (or TMCLSH_PORT, \
                       TMCLSH_TCP or TMCLSH_CAN, or port, tcp or can in tmclsh.toml), or --sim \
                       for the built-in simulator";

/// A project directory of our own (its `tmclsh.toml`, if any, ours) and an empty user
/// configuration, with no TMCLSH_ variables but `env`.
fn tmclsh(dir: &Path, args: &[&str], env: &[(&str, &str)], input: Option<&str>) -> Output {
    use std::io::Write;
    let mut command = Command::new(bin());
    for (key, _) in std::env::vars() {
        if key.starts_with("TMCLSH_") {
            command.env_remove(key);
        }
    }
    let mut child = command
        .args(args)
        .current_dir(dir)
        .env("XDG_CONFIG_HOME", dir.join("user-config"))
        .env("NO_COLOR", "1")
        .envs(env.iter().copied())
        .stdin(if input.is_some() {
            Stdio::piped()
        } else {
            Stdio::null()
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("tmclsh runs");
    if let Some(text) = input {
        let mut stdin = child.stdin.take().unwrap();
        stdin.write_all(text.as_bytes()).unwrap();
    }
    child.wait_with_output().expect("tmclsh finishes")
}

/// A fresh project directory holding `config` as its `tmclsh.toml` (none when empty).
fn project(config: &str) -> PathBuf {
    let dir = tempdir();
    if !config.is_empty() {
        let file = dir.join("tmclsh.toml");
        std::fs::write(&file, config).unwrap();
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o644)).unwrap();
        }
    }
    dir
}

#[test]
fn a_run_without_a_link_is_refused_not_passed_on_the_simulator() {
    let dir = project("");
    let script = dir.join("move_check.rhai");
    std::fs::write(&script, "print(\"all good\");\n").unwrap();
    let script = script.to_str().unwrap();
    let cases: [(&[&str], Option<&str>); 6] = [
        (&["-c", "GAP 1, 0"], None),
        (&[], Some("GAP 1, 0\n")),
        (&["run", script], None),
        (&["scan", "--addresses", "1"], None),
        (&["snapshot", "save", "s.toml"], None),
        (&["--protocol", "smd4", "-c", "SYS:FW"], None),
    ];
    for (args, input) in cases {
        let out = tmclsh(&dir, args, &[], input);
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(NO_LINK), "{args:?}: {}", stderr(&out));
        assert!(!stdout(&out).contains("all good"), "{args:?}");
    }
    // A misspelt variable is no link either, and is named with the right one.
    let out = tmclsh(
        &dir,
        &["run", script],
        &[("TMCLSH_TPC", "127.0.0.1:1")],
        None,
    );
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains(
            "tmclsh: warning: unknown environment variable TMCLSH_TPC, ignored; did you mean \
             TMCLSH_TCP?"
        ),
        "{}",
        stderr(&out)
    );
}

#[test]
fn sim_on_the_command_line_or_in_the_project_chooses_the_simulator() {
    let dir = project("");
    let out = tmclsh(&dir, &["--sim", "-c", "GAP 1, 0"], &[], None);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 0\n");
    let out = tmclsh(&dir, &["--sim"], &[], Some("GAP 1, 0\n"));
    assert_eq!(stdout(&out), "BA 100 0\n", "{}", stderr(&out));

    let dir = project("sim = true\n");
    let out = tmclsh(&dir, &["-c", "GAP 1, 0"], &[], None);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 0\n");
    // Chosen in a file, which may be forgotten: said on stderr.
    assert!(
        stderr(&out).contains("(sim = true in a configuration file)"),
        "{}",
        stderr(&out)
    );
    let report = stdout(&tmclsh(&dir, &["config"], &[], None));
    assert!(
        report.contains("# link: the built-in simulator (project "),
        "{report}"
    );
    // A port from the environment outranks the file.
    let report = stdout(&tmclsh(
        &dir,
        &["config"],
        &[("TMCLSH_PORT", "/dev/ttyUSB5")],
        None,
    ));
    assert!(
        report.contains("# link: port /dev/ttyUSB5 (environment TMCLSH_PORT)"),
        "{report}"
    );
    assert!(
        report.contains("# sim = true (project ")
            && report.contains("TMCLSH_PORT=/dev/ttyUSB5 wins"),
        "{report}"
    );
}

#[test]
fn tmclsh_tcp_reaches_a_module_and_config_shows_the_link_in_effect() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    let dir = project("");
    let env = [("TMCLSH_TCP", sim.first.as_str())];
    let out = tmclsh(&dir, &["-c", "GAP 1, 0"], &env, None);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 0\n");
    assert!(!stderr(&out).contains("simulated"), "{}", stderr(&out));

    // Whatever its source, the target shown is the one in effect: flag > env > file.
    let dir = project("tcp = \"10.0.0.9:4001\"\n");
    let link = |args: &[&str], env: &[(&str, &str)]| {
        let out = tmclsh(&dir, args, env, None);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        stdout(&out)
            .lines()
            .find(|l| l.starts_with("# link: "))
            .unwrap_or_default()
            .to_string()
    };
    assert!(link(&["config"], &[]).starts_with("# link: TCP 10.0.0.9:4001 (project "));
    assert_eq!(
        link(&["config"], &[("TMCLSH_TCP", "10.0.0.8:4001")]),
        "# link: TCP 10.0.0.8:4001 (environment TMCLSH_TCP)"
    );
    assert_eq!(
        link(
            &["config", "--tcp", "10.0.0.7:4001"],
            &[
                ("TMCLSH_TCP", "10.0.0.8:4001"),
                ("TMCLSH_PORT", "/dev/ttyUSB1")
            ]
        ),
        "# link: TCP 10.0.0.7:4001 (command line)"
    );
    assert_eq!(
        link(
            &["config", "--port", "/dev/ttyUSB2"],
            &[("TMCLSH_TCP", "10.0.0.8:4001")]
        ),
        "# link: port /dev/ttyUSB2 (command line)"
    );
    // Two of one source are refused: nobody can tell which was meant.
    let env = [
        ("TMCLSH_TCP", "10.0.0.8:4001"),
        ("TMCLSH_PORT", "/dev/ttyUSB1"),
    ];
    let out = tmclsh(&dir, &["-c", "GAP 1, 0"], &env, None);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("TMCLSH_PORT and TMCLSH_TCP name different links; give one"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_tcp_address_given_as_a_port_is_refused_with_the_hint() {
    let hint = "is a TCP address (HOST:PORT), not a serial port: give it with --tcp";
    let dir = project("");
    let out = tmclsh(
        &dir,
        &["--port", "192.168.1.20:4001", "-c", "GAP 1, 0"],
        &[],
        None,
    );
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains(hint), "{}", stderr(&out));
    let out = tmclsh(
        &dir,
        &["-c", "GAP 1, 0"],
        &[("TMCLSH_PORT", "moxa:4001")],
        None,
    );
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("TMCLSH_PORT"), "{}", stderr(&out));
    assert!(stderr(&out).contains(hint), "{}", stderr(&out));
    let dir = project("port = \"moxa.local:4001\"\n");
    let out = tmclsh(&dir, &["-c", "GAP 1, 0"], &[], None);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("tmclsh.toml:1: port: "),
        "{}",
        stderr(&out)
    );
    assert!(stderr(&out).contains(hint), "{}", stderr(&out));
    // Device names and usb: names are no TCP addresses.
    let dir = project("port = \"usb:0403:6001\"\n");
    let out = tmclsh(&dir, &["config"], &[], None);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn a_misspelt_key_is_named_with_the_nearest_and_does_not_stop_the_run() {
    let dir = project("sim = true\npotr = \"/dev/ttyUSB0\"\n");
    let out = tmclsh(&dir, &["-c", "GAP 1, 0"], &[], None);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out).contains(":2: unknown key `potr`, ignored")
            && stderr(&out).contains("did you mean `port`?"),
        "{}",
        stderr(&out)
    );
    // Help, the version, completions and the manual stay quiet about the set-up.
    let env = [("TMCLSH_POTR", "/dev/ttyUSB0")];
    for args in [
        &["--help"][..],
        &["--version"],
        &["completions", "bash"],
        &["man"],
    ] {
        let out = tmclsh(&dir, args, &env, None);
        assert_eq!(code(&out), 0, "{args:?}: {}", stderr(&out));
        assert_eq!(stderr(&out), "", "{args:?}");
    }
}

#[test]
fn a_broken_configuration_locks_nobody_out_of_help_and_config() {
    let dir = project("timeout = 200\nbaud = \"fast\"\n[port]\n");
    for args in [
        &["--help"][..],
        &["--version"],
        &["completions", "bash"],
        &["man"],
    ] {
        let out = tmclsh(&dir, args, &[], None);
        assert_eq!(code(&out), 0, "{args:?}: {}", stderr(&out));
        assert!(!stdout(&out).is_empty(), "{args:?}");
    }
    // A file that is not TOML is shown with its line; one that is, with each bad value's line
    // and what could be read.
    let out = tmclsh(&dir, &["config"], &[], None);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stdout(&out).contains("# error: "), "{}", stdout(&out));
    assert!(stdout(&out).contains("tmclsh.toml:3: "), "{}", stdout(&out));
    let dir = project("timeout = 200\nbaud = \"fast\"\n");
    let out = tmclsh(&dir, &["config"], &[], None);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let report = stdout(&out);
    assert!(
        report.contains("tmclsh.toml:2: baud must be a number"),
        "{report}"
    );
    assert!(report.contains("timeout = 200 "), "{report}");
    // Everything else is refused, naming the file and line.
    let out = tmclsh(&dir, &["--sim", "-c", "GAP 1, 0"], &[], None);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("configuration refused: ")
            && stderr(&out).contains("tmclsh.toml:2: "),
        "{}",
        stderr(&out)
    );
}

#[cfg(unix)]
#[test]
fn the_wrong_protocol_on_a_real_line_is_named_both_ways() {
    let dir = project("");
    let drive = Sim::start(&["--pty", "--protocol", "smd4"]);
    let out = tmclsh(&dir, &["--port", &drive.first, "-c", "GAP 1, 0"], &[], None);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("looks like an AML SMD4 drive"), "{err}");
    assert!(err.contains("give --protocol smd4"), "{err}");
    assert!(!err.contains("does not answer in ASCII mode"), "{err}");

    let module = Sim::start(&["--pty"]);
    let args = [
        "--protocol",
        "smd4",
        "--port",
        &module.first,
        "-c",
        "SYS:FW",
    ];
    let out = tmclsh(&dir, &args, &[], None);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("looks like a Trinamic TMCL module"), "{err}");
    assert!(err.contains("give --protocol tmcl"), "{err}");
}
