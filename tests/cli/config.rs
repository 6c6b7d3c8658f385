//! Defaults that stick: the user's and the project's configuration files, ranked below the
//! command line and the environment, shown by `tmclsh config`, checked line by line, and never
//! refused where the option has no use.

mod sources;
#[cfg(unix)]
mod trust;

use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

use crate::util::{bin, code, repo, stderr, stdout, tempdir};

/// A place to run tmclsh in: a project directory (with a subdirectory to run from) and a user
/// configuration directory, no TMCLSH_ variables.
struct Place {
    project: PathBuf,
    cwd: PathBuf,
    user: PathBuf,
}

impl Place {
    fn new() -> Place {
        let root = tempdir();
        let place = Place {
            project: root.join("project"),
            cwd: root.join("project").join("work"),
            user: root.join("config"),
        };
        std::fs::create_dir_all(&place.cwd).unwrap();
        std::fs::create_dir_all(place.user.join("tmclsh")).unwrap();
        place
    }

    fn project_file(&self, text: &str) -> PathBuf {
        let path = self.project.join("tmclsh.toml");
        std::fs::write(&path, text).unwrap();
        path
    }

    fn user_file(&self, text: &str) -> PathBuf {
        let path = self.user.join("tmclsh").join("config.toml");
        std::fs::write(&path, text).unwrap();
        path
    }

    fn run(&self, args: &[&str], env: &[(&str, &str)]) -> Output {
        let mut command = Command::new(bin());
        for (key, _) in std::env::vars() {
            if key.starts_with("TMCLSH_") {
                command.env_remove(key);
            }
        }
        command
            .args(args)
            .current_dir(&self.cwd)
            .env("XDG_CONFIG_HOME", &self.user)
            .env("NO_COLOR", "1")
            .envs(env.iter().copied())
            .stdin(Stdio::null())
            .output()
            .expect("tmclsh runs")
    }
}

/// The line of `tmclsh config` that shows `key`.
fn shown<'a>(report: &'a str, key: &str) -> &'a str {
    report
        .lines()
        .find(|l| l.starts_with(&format!("{key} = ")) || l.starts_with(&format!("# {key} ")))
        .unwrap_or_else(|| panic!("{key} not shown:\n{report}"))
}

#[test]
fn precedence_is_command_line_environment_project_user_built_in() {
    // Every combination of the four places that can set --timeout; the highest one set wins,
    // both in what `tmclsh config` says and in what the session waits.
    let layers = [
        ("command line", "110"),
        ("environment TMCLSH_TIMEOUT", "120"),
        ("project", "130"),
        ("user", "140"),
    ];
    let mut failures = Vec::new();
    for set in 0..16u32 {
        let place = Place::new();
        let on = |layer: usize| set & (1 << layer) != 0;
        let mut args: Vec<&str> = Vec::new();
        let mut env = Vec::new();
        if on(0) {
            args.extend(["--timeout", layers[0].1]);
        }
        if on(1) {
            env.push(("TMCLSH_TIMEOUT", layers[1].1));
        }
        if on(2) {
            place.project_file(&format!("timeout = {}\n", layers[2].1));
        }
        if on(3) {
            place.user_file(&format!("\n\ntimeout = {}\n", layers[3].1));
        }
        let (origin, value) = (0..4)
            .find(|&l| on(l))
            .map(|l| layers[l])
            .unwrap_or(("built-in", "1000"));
        let mut config = vec!["config"];
        config.extend(&args);
        let report = stdout(&place.run(&config, &env));
        let line = shown(&report, "timeout");
        if !(line.starts_with(&format!("timeout = {value} "))
            && line.contains(&format!("# {origin}")))
        {
            failures.push(format!(
                "set {set:04b}: expected {value} from {origin}: {line}"
            ));
        }
        if origin == "project" && !line.contains("tmclsh.toml:1") {
            failures.push(format!("set {set:04b}: no file and line: {line}"));
        }
        if origin == "user" && !line.contains("config.toml:3") {
            failures.push(format!("set {set:04b}: no file and line: {line}"));
        }
        if value != "1000" {
            // Module C is not on the bus: the session waits the timeout in effect.
            let mut shell = vec!["--sim", "-c", "CGAP 1, 0"];
            shell.extend(&args);
            let out = place.run(&shell, &env);
            let waited = format!("within {value} ms");
            if code(&out) != 3 || !stderr(&out).contains(&waited) {
                failures.push(format!(
                    "set {set:04b}: did not wait {value} ms: {}",
                    stderr(&out)
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_key_takes_effect_from_a_file() {
    let place = Place::new();
    let profile = place.project.join("custom.toml");
    std::fs::write(
        &profile,
        "[meta]\nmodule = \"TMCM-X\"\n[[axis_parameter]]\nnumber = 9\nname = \"Max thing\"\nident = \"max_thing\"\naccess = \"RW\"\n",
    )
    .unwrap();
    // Paths are relative to the file that names them, not to the working directory.
    place.project_file("profile = \"custom.toml\"\n");
    let out = place.run(&["params", "max"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("max_thing"), "{}", stdout(&out));

    place.project_file("port = \"/nonexistent/tmclsh-config/ttyUSB7\"\nbaud = 19200\n");
    let out = place.run(&["-c", "GAP 1, 0"], &[]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("/nonexistent/tmclsh-config/ttyUSB7"),
        "{}",
        stderr(&out)
    );

    place.project_file("protocol = \"smd4\"\nsim = true\n");
    let out = place.run(&["-c", "SYS:FW"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stderr(&out).contains("simulated SMD4"), "{}", stderr(&out));

    place.project_file("module = 2\ntimeout = 100\n");
    let out = place.run(&["--sim", "-c", "GAP 1, 0"], &[]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("module 2 (B)") && stderr(&out).contains("within 100 ms"),
        "{}",
        stderr(&out)
    );

    let log = place.cwd.join("echo.log");
    place.project_file("echo = \"line\"\n");
    let out = place.run(
        &["--sim", "-c", "GGP 67, 0", "--log", log.to_str().unwrap()],
        &[],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out).trim(), "BA 100 16", "GP 67 bit 4: line echo");
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(transcript.contains("SGP 67, 0, 16"), "{transcript}");

    // Stripping an echo where nothing echoes: line noise, from the file and the environment.
    place.project_file("local_echo = \"on\"\n");
    let out = place.run(&["--sim", "-c", "GAP 1, 0"], &[]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("line noise: the adapter's echo"),
        "{}",
        stderr(&out)
    );
    place.project_file("");
    let out = place.run(&["--sim", "-c", "GAP 1, 0"], &[("TMCLSH_LOCAL_ECHO", "on")]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    let out = place.run(
        &["--sim", "-c", "GAP 1, 0"],
        &[("TMCLSH_LOCAL_ECHO", "off")],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));

    // A log directory, relative to the file, made when missing; a transcript per session.
    place.project_file("log_dir = \"logs\"\n");
    for _ in 0..2 {
        let out = place.run(&["--sim", "-c", "GAP 1, 0"], &[]);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
    }
    let logs: Vec<_> = std::fs::read_dir(place.project.join("logs"))
        .unwrap()
        .collect();
    assert!(
        !logs.is_empty(),
        "no transcript in the configured directory"
    );
    // --log on the command line wins.
    let out = place.run(
        &["--sim", "-c", "GAP 1, 0", "--log", log.to_str().unwrap()],
        &[],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn configured_values_are_never_refused_where_they_have_no_use() {
    let place = Place::new();
    place.user_file("port = \"/nonexistent/tmclsh-config/ttyUSB8\"\nbaud = 19200\nmodule = 2\necho = \"none\"\nprofile = \"custom.toml\"\n");
    std::fs::copy(
        repo().join("data/profiles/tmcm-142.toml"),
        place.user.join("tmclsh/custom.toml"),
    )
    .unwrap();
    let program = repo().join("scripts/test2.tmc");
    let program = program.to_str().unwrap();
    for args in [
        &["asm", program][..],
        &["ports"],
        &["completions", "bash"],
        &["params", "max_current"],
        &["config"],
    ] {
        let out = place.run(args, &[]);
        assert_eq!(code(&out), 0, "{args:?}: {}", stderr(&out));
    }
    // SMD4 drives have no --module or --echo: configured ones are not refused, nor is
    // --tcp on the command line over a configured port.
    let sim = crate::sim::Sim::start(&["--protocol", "smd4", "--listen", "127.0.0.1:0"]);
    let out = place.run(
        &["--protocol", "smd4", "--tcp", &sim.first, "-c", "SYS:FW"],
        &[],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    // The same options on the command line are refused as before.
    let out = place.run(&["asm", program, "--port", "/dev/x"], &[]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
}

#[test]
fn a_bad_file_is_refused_with_its_file_and_line() {
    let place = Place::new();
    for (text, line, says) in [
        ("\n\nbaud = \"fast\"\n", 3, "baud must be a number"),
        (
            "module = 27\n",
            1,
            "module: invalid value '27': 27 is not in 1..=26",
        ),
        ("timeout = 0\n", 1, "timeout: invalid value '0'"),
        ("protocol = \"smd5\"\n", 1, "possible values: tmcl, smd4"),
        ("echo = true\n", 1, "echo must be a string in quotes"),
        ("port = \"\"\n", 1, "port is empty"),
        ("profile = \"missing.toml\"\n", 1, "profile: no such file"),
        ("[port]\npath = 1\n", 1, "port must be a string"),
        ("baud = 9600\nbaud = 19200\n", 2, "duplicate key"),
        ("port = /dev/ttyUSB0\n", 1, ""),
    ] {
        let file = place.project_file(text);
        let out = place.run(&["--sim", "-c", "GAP 1, 0"], &[]);
        let err = stderr(&out);
        assert_eq!(code(&out), 2, "{text:?}: {err}");
        let place_of = format!("{}:{line}: ", file.display());
        assert!(
            err.contains(&place_of),
            "{text:?}: expected {place_of}: {err}"
        );
        assert!(err.contains(says), "{text:?}: {err}");
        assert!(
            !err.contains("built-in simulated"),
            "refused before anything ran: {err}"
        );
    }
    // The user's file too.
    std::fs::remove_file(place.project.join("tmclsh.toml")).unwrap();
    let file = place.user_file("baud = \"fast\"\n");
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 2);
    let said = format!("# error: {}:1: baud must be a number", file.display());
    assert!(stdout(&out).contains(&said), "{}", stdout(&out));
}

#[test]
fn an_unknown_key_is_a_warning_with_the_nearest() {
    let place = Place::new();
    let file = place.project_file("sim = true\nprotcol = \"smd4\"\n");
    let out = place.run(&["-c", "GAP 1, 0"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let said = format!(
        "tmclsh: warning: {}:2: unknown key `protcol`, ignored",
        file.display()
    );
    assert!(stderr(&out).contains(&said), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("did you mean `protocol`?"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn config_names_the_files_and_what_is_not_set() {
    let place = Place::new();
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let report = stdout(&out);
    assert!(
        report.contains("project file: none (no tmclsh.toml in"),
        "{report}"
    );
    assert!(report.contains("user file: none ("), "{report}");
    let baud = shown(&report, "baud");
    assert!(
        baud.starts_with("baud = 9600 ") && baud.ends_with("# built-in"),
        "{baud}"
    );
    assert!(shown(&report, "port").contains("not set: no serial port"));
    let file = place.project_file("baud = 115200\n");
    let report = stdout(&place.run(
        &["--port", "/dev/ttyUSB3", "config"],
        &[("TMCLSH_PROTOCOL", "smd4")],
    ));
    assert!(
        report.contains(&format!("project file: {}", file.display())),
        "{report}"
    );
    assert!(
        shown(&report, "port").contains("# command line"),
        "{report}"
    );
    assert!(shown(&report, "protocol").contains("\"smd4\""), "{report}");
    assert!(
        shown(&report, "protocol").contains("# environment TMCLSH_PROTOCOL"),
        "{report}"
    );
    assert!(
        shown(&report, "baud").contains(&format!("# project {}:1", file.display())),
        "{report}"
    );
}

#[test]
fn a_profile_is_a_built_in_name_or_a_file() {
    let place = Place::new();
    // A name stays a name (no file beside the configuration needed).
    place.project_file("profile = \"tmcm-6110\"\nsim = true\n");
    let out = place.run(&["-c", "GAP 4, 5"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("simulated TMCM-6110"),
        "{}",
        stderr(&out)
    );
    let out = place.run(&["config"], &[]);
    assert!(
        stdout(&out).contains("profile = \"tmcm-6110\""),
        "{}",
        stdout(&out)
    );
    // A name that is no built-in profile is refused when the profile loads, with the nearest.
    place.project_file("profile = \"tmcm-6111\"\n");
    let out = place.run(&["params"], &[]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("did you mean tmcm-6110?"),
        "{}",
        stderr(&out)
    );
    // A path is checked as a file at once.
    place.project_file("profile = \"rig/tmcm-6110\"\n");
    let out = place.run(&["params"], &[]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("profile: no such file"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_serial_line_settings_come_from_the_project_file() {
    let sim = crate::sim::Sim::start(&["--pty"]);
    let place = Place::new();
    place.project_file(&format!(
        "port = \"{}\"\ndtr = \"off\"\nrts = \"keep\"\nrs485 = true\nrs485_delay = \"1,2\"\nkeep_latency = true\n",
        sim.first
    ));
    let out = place.run(&["-c", "GAP 1, 0"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("--dtr off, --rts keep, --rs485 not applied"),
        "{}",
        stderr(&out)
    );
    let out = place.run(&["config"], &[]);
    let report = stdout(&out);
    assert!(
        shown(&report, "dtr").starts_with("dtr = \"off\" "),
        "{report}"
    );
    assert!(
        shown(&report, "rs485").starts_with("rs485 = true "),
        "{report}"
    );
    assert!(
        shown(&report, "keep_latency").starts_with("keep_latency = true "),
        "{report}"
    );
    // A flag's key is true or false.
    place.project_file("rs485 = \"yes\"\n");
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("rs485 must be true or false"),
        "{}",
        stderr(&out)
    );
    place.project_file("dtr = \"up\"\n");
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("on, off or keep"), "{}", stderr(&out));
}
