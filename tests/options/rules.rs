//! The rules around the table: environment variables, an option given on both sides, options of
//! the other dialect or link, the built-in simulator's notice, the SMD4 parameter table.

use std::net::TcpListener;
use std::process::{Command, Output, Stdio};

use crate::util::{bin, code, repo, run, run_with_stdin, stderr, stdout};

use super::table::{fixtures, fresh, run_guarded, s, strings};

/// Runs `tmclsh ARGS` with `vars` set.
fn run_env(args: &[&str], vars: &[(&str, &str)]) -> Output {
    Command::new(bin())
        .args(args)
        .envs(vars.iter().copied())
        .stdin(Stdio::null())
        .env("NO_COLOR", "1")
        .output()
        .expect("tmclsh runs")
}

#[test]
fn the_environment_gives_a_port_to_every_face_and_the_command_line_overrides_it() {
    let env = "/nonexistent/tmclsh-options/from-env";
    let given = "/nonexistent/tmclsh-options/given";
    let vars = [("TMCLSH_PORT", env)];
    for args in [
        &["-c", "GAP 1, 0"][..],
        &["snapshot", "save", &fresh("env.toml")],
        &["scan", "--addresses", "1"],
        &["download", s(&fixtures().program)],
    ] {
        let out = run_env(args, &vars);
        assert_eq!(code(&out), 3, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(env), "{args:?}: {}", stderr(&out));
        let mut before = vec!["--port", given];
        before.extend_from_slice(args);
        let mut after = args.to_vec();
        after.extend_from_slice(&["--port", given]);
        for line in [before, after] {
            let out = run_env(&line, &vars);
            assert_eq!(code(&out), 3, "{line:?}: {}", stderr(&out));
            assert!(stderr(&out).contains(given), "{line:?}: {}", stderr(&out));
        }
    }
    // --tcp on the command line wins over the port of the environment.
    let closed = {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        listener.local_addr().unwrap().to_string()
    };
    let out = run_env(&["--tcp", &closed, "-c", "GAP 1, 0"], &vars);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(stderr(&out).contains(&closed), "{}", stderr(&out));
    // A rate from the environment bothers nobody.
    let out = run_env(&["--sim", "-c", "GAP 1, 0"], &[("TMCLSH_BAUD", "19200")]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn an_option_given_before_and_after_the_subcommand_is_refused() {
    let script = fresh("noop.rhai");
    std::fs::write(&script, "let x = 1;\n").unwrap();
    for args in [
        &["--port", "/dev/a", "run", &script, "--port", "/dev/b"][..],
        &[
            "--timeout",
            "10",
            "snapshot",
            "save",
            "x.toml",
            "--timeout",
            "20",
        ],
        &["--port", "/dev/a", "scan", "--tcp", "127.0.0.1:1"],
        &["--port", "/dev/a", "--tcp", "127.0.0.1:1", "-c", "GAP 1, 0"],
    ] {
        let out = run(args);
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains("--"), "{args:?}: {}", stderr(&out));
    }
}

#[test]
fn options_of_the_other_dialect_or_link_are_refused() {
    let profile = fresh("profile.toml");
    std::fs::copy(repo().join("data/profiles/tmcm-142.toml"), &profile).unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["--protocol", "smd4", "--module", "2", "-c", "SYS:FW"],
            "--module",
        ),
        (
            &["--protocol", "smd4", "--no-enter", "-c", "SYS:FW"],
            "--no-enter",
        ),
        (
            &["--protocol", "smd4", "run", "x.rhai", "--stay-ascii"],
            "--stay-ascii",
        ),
        (
            &["--protocol", "smd4", "--profile", &profile, "-c", "SYS:FW"],
            "--profile",
        ),
        (
            &["sim", "--protocol", "smd4", "--profile", &profile],
            "--profile",
        ),
        (&["--address", "3", "-c", "GAP 1, 0"], "--address"),
        (
            &["snapshot", "save", "x.toml", "--quiet-gap", "50"],
            "--quiet-gap",
        ),
        (&["--baud", "19200", "-c", "GAP 1, 0"], "--baud"),
        (
            &["--tcp", "127.0.0.1:1", "--baud", "19200", "-c", "GAP 1, 0"],
            "--baud",
        ),
        (&["--profile", &profile, "ports"], "--profile"),
        (&["completions", "bash", "--profile", &profile], "--profile"),
        (&["--baud", "9600", "sim"], "--baud"),
    ];
    for (args, flag) in cases {
        let out = run_guarded(&strings(args), None).unwrap();
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(flag), "{args:?}: {}", stderr(&out));
    }
}

#[test]
fn every_batch_face_on_the_built_in_simulator_says_so_once() {
    let fx = fixtures();
    let script = fresh("once.rhai");
    std::fs::write(&script, "send(\"GAP 1, 0\");\n").unwrap();
    let tmcl = |args: &[&str]| (run(&[&["--sim"], args].concat()), "TMCM-142");
    let smd4 = |args: &[&str]| {
        let mut all = vec!["--sim", "--protocol", "smd4"];
        all.extend_from_slice(args);
        (run(&all), "SMD4")
    };
    for (out, module) in [
        tmcl(&["-c", "GAP 1, 0"]),
        (run_with_stdin(&["--sim"], "GAP 1, 0\n"), "TMCM-142"),
        tmcl(&["run", &script]),
        tmcl(&["download", s(&fx.program)]),
        tmcl(&["snapshot", "save", &fresh("once.toml")]),
        tmcl(&["snapshot", "diff", s(&fx.tmcl_snapshot)]),
        tmcl(&["scan", "--addresses", "1"]),
        smd4(&["-c", "SYS:FW"]),
        smd4(&["snapshot", "save", &fresh("once-smd4.toml")]),
        smd4(&["scan", "--addresses", "1"]),
    ] {
        let notice = format!(
            "using the built-in simulated {module}; give --port, --tcp or --can for hardware"
        );
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        assert_eq!(stderr(&out).matches(&notice).count(), 1, "{}", stderr(&out));
    }
    let out = run(&["params"]);
    assert!(!stderr(&out).contains("built-in"), "{}", stderr(&out));
}

#[test]
fn the_smd4_params_table_is_the_shells() {
    let cli = run(&["--protocol", "smd4", "params", "motor:v"]);
    let shell = run(&["--sim", "--protocol", "smd4", "-c", ":params MOTOR:V"]);
    assert_eq!(code(&cli), 0, "{}", stderr(&cli));
    assert!(stdout(&cli).contains("MOTOR:VMAX"), "{}", stdout(&cli));
    assert_eq!(stdout(&cli), stdout(&shell));
    let out = run(&["params", "--protocol", "smd4", "NOTHING_LIKE_IT"]);
    assert_eq!(code(&out), 1);
    assert!(stderr(&out).contains("no SMD4 command matches 'NOTHING_LIKE_IT'"));
}
