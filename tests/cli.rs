//! The command-line surface: `params`, `completions`, `ports`, usage errors and exit codes.

use crate::util::{code, repo, run, stderr, stdout, tempdir};

#[test]
fn params_filter_lists_the_matching_parameters() {
    let out = run(&["params", "max"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let names: Vec<&str> = text
        .lines()
        .skip(1)
        .map(|l| l.split_whitespace().nth(2).unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "max_positioning_speed",
            "max_acceleration",
            "max_current",
            "max_encoder_deviation"
        ]
    );
    assert!(
        text.lines().next().unwrap().starts_with("kind"),
        "header: {text}"
    );
}

#[test]
fn params_without_filter_lists_axis_and_global_parameters() {
    let text = stdout(&run(&["params"]));
    assert!(text.contains("actual_position"));
    let host = text
        .lines()
        .find(|l| l.contains("serial_host_address"))
        .expect("GP 76 listed");
    assert_eq!(
        host.split_whitespace().take(4).collect::<Vec<_>>(),
        ["global/0", "76", "serial_host_address", "RWE"]
    );
    assert!(text.contains("user_variable_55"));
}

#[test]
fn params_with_a_filter_that_matches_nothing_says_so_and_exits_1() {
    let out = run(&["params", "no_such_thing"]);
    assert_eq!(code(&out), 1);
    assert!(stdout(&out).is_empty());
    assert!(stderr(&out).contains("no TMCM-142 parameter matches 'no_such_thing'"));
}

#[test]
fn a_user_profile_replaces_the_builtin_tables() {
    let dir = tempdir();
    let path = dir.join("custom.toml");
    std::fs::write(
        &path,
        "[meta]\nmodule = \"TMCM-X\"\n[[axis_parameter]]\nnumber = 9\nname = \"Max thing\"\nident = \"max_thing\"\naccess = \"RW\"\n",
    )
    .unwrap();
    let out = run(&["--profile", path.to_str().unwrap(), "params", "max"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("max_thing"));
    assert!(!stdout(&out).contains("max_current"));
}

#[test]
fn a_broken_profile_is_refused_with_exit_2() {
    let dir = tempdir();
    let path = dir.join("broken.toml");
    std::fs::write(&path, "[meta]\nmodule = 5\n").unwrap();
    let out = run(&["--profile", path.to_str().unwrap(), "params"]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("refused (schema in docs/profiles.md):\n  line 2: invalid type"),
        "{}",
        stderr(&out)
    );
    let out = run(&["--profile", "/nonexistent.toml", "params"]);
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("cannot read profile /nonexistent.toml"));
}

#[test]
fn usage_errors_exit_2_and_help_exits_0() {
    let out = run(&["--no-such-flag"]);
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("--no-such-flag"));
    let out = run(&["--help"]);
    assert_eq!(code(&out), 0);
    assert!(stdout(&out).contains("Usage: tmclsh"));
    let out = run(&["completions", "tcsh"]);
    assert_eq!(code(&out), 2);
}

#[test]
fn ports_lists_without_failing() {
    let out = run(&["ports"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn committed_completions_match_what_the_binary_generates() {
    let files = [
        ("bash", "tmclsh.bash"),
        ("zsh", "_tmclsh"),
        ("fish", "tmclsh.fish"),
        ("elvish", "tmclsh.elv"),
        ("powershell", "_tmclsh.ps1"),
    ];
    for (shell, file) in files {
        let out = run(&["completions", shell]);
        assert_eq!(code(&out), 0);
        let committed = std::fs::read(repo().join("completions").join(file))
            .unwrap_or_else(|e| panic!("completions/{file}: {e}"));
        assert!(
            committed == out.stdout,
            "completions/{file} is stale; regenerate with: cargo run -q -- completions {shell} > completions/{file}"
        );
    }
}

#[test]
fn the_usage_block_in_the_docs_is_the_real_help() {
    let out = run(&["-h"]);
    assert_eq!(code(&out), 0);
    let usage = std::fs::read_to_string(repo().join("docs/usage.md")).unwrap();
    let block = usage
        .split("<!-- usage: the output of `tmclsh -h`, checked by the test suite -->\n```text\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("docs/usage.md has the usage block");
    assert!(
        block == stdout(&out),
        "docs/usage.md's usage block is stale; regenerate it from `tmclsh -h`"
    );
}

#[test]
fn a_transposition_is_suggested_wherever_names_are() {
    for (args, suggestion) in [
        (&["--sim", "-c", "GPA 1, 0"][..], "did you mean GAP?"),
        (
            &["--sim", "-c", "GAP acutal_position, 0"],
            "did you mean actual_position?",
        ),
        (&["--sim", "-c", ":prmas"], "did you mean :params?"),
        (
            &["--sim", "--protocol", "smd4", "-c", "MOTRO:VMAX"],
            "did you mean MOTOR:VMAX?",
        ),
    ] {
        let out = run(args);
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(
            stderr(&out).contains(suggestion),
            "{args:?}: {}",
            stderr(&out)
        );
    }
}

/// A usage error on a terminal, where clap would pass an argument's escape sequence through:
/// shown escaped, nothing raw but clap's line ends.
#[test]
fn usage_errors_show_escape_sequences_from_arguments_escaped() {
    let mut p = crate::util::terminal(
        &["--timeout", "5\x1b]0;owned\x07\x7f", "--bogus\x1b[2J"],
        &[],
    );
    let shown = p.exp_eof().unwrap();
    assert!(shown.contains("--bogus\\x1B[2J"), "{shown:?}");
    assert!(
        !shown
            .chars()
            .any(|c| c.is_control() && c != '\n' && c != '\r'),
        "{shown:?}"
    );
    let out = run(&["--timeout", "5\x7f\u{9b}2J"]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("'5\\x7F\\u{9b}2J'"),
        "{}",
        stderr(&out)
    );
}

#[cfg(target_os = "linux")]
mod closed_stdout;
mod config;
mod doc_examples;
mod examples;
mod first_hour;
mod first_hour_shell;
mod forgiving;
mod helper_text;
mod history;
mod install;
mod log;
mod machine_output;
mod output;
mod ports;
mod snapshot_save;
mod values;
mod words;

#[test]
fn committed_man_page_matches_what_the_binary_generates() {
    let out = run(&["man"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let committed = std::fs::read(repo().join("man/tmclsh.1")).expect("man/tmclsh.1");
    assert!(
        committed == out.stdout,
        "man/tmclsh.1 is stale; regenerate with: cargo run -q -- man > man/tmclsh.1"
    );
    let page = stdout(&out);
    for section in [
        ".SH NAME",
        ".SH SYNOPSIS",
        ".SH OPTIONS",
        ".SH \"TMCLSH RUN\"",
        ".SH \"TMCLSH SNAPSHOT SAVE\"",
        ".SH \"EXIT STATUS\"",
        ".SH FILES",
    ] {
        assert!(page.contains(section), "no {section}");
    }
}

/// Runs the committed bash completion for the words typed so far (the last one being
/// completed) in `dir`; returns the candidates.
fn bash_completes(dir: &std::path::Path, words: &[&str]) -> Vec<String> {
    let script = repo().join("completions/tmclsh.bash");
    let quoted: Vec<String> = words.iter().map(|w| format!("'{w}'")).collect();
    let program = format!(
        "source '{}'\nCOMP_WORDS=({})\nCOMP_CWORD={}\n_tmclsh_with_files tmclsh '{}' '{}'\nprintf '%s\\n' \"${{COMPREPLY[@]}}\"\n",
        script.display(),
        quoted.join(" "),
        words.len() - 1,
        words[words.len() - 1],
        words[words.len() - 2],
    );
    let out = std::process::Command::new("bash")
        .arg("-c")
        .arg(program)
        .current_dir(dir)
        .output()
        .expect("bash runs");
    let mut found: Vec<String> = stdout(&out)
        .lines()
        .filter(|l| !l.is_empty())
        .map(String::from)
        .collect();
    found.sort();
    found
}

#[cfg(unix)]
#[test]
fn bash_completes_only_the_files_a_subcommand_takes() {
    if std::process::Command::new("bash")
        .arg("-c")
        .arg("true")
        .status()
        .is_err()
    {
        return; // no bash on this machine
    }
    let dir = tempdir();
    for file in ["a.rhai", "b.tmc", "c.bin", "d.txt"] {
        std::fs::write(dir.join(file), "").unwrap();
    }
    std::fs::create_dir(dir.join("sub")).unwrap();
    assert_eq!(
        bash_completes(&dir, &["tmclsh", "run", ""]),
        ["a.rhai", "sub"]
    );
    assert_eq!(
        bash_completes(&dir, &["tmclsh", "download", ""]),
        ["b.tmc", "c.bin", "sub"]
    );
    assert_eq!(
        bash_completes(&dir, &["tmclsh", "--timeout", "5", "asm", ""]),
        ["b.tmc", "sub"]
    );
    // An option's value is not a script: --log takes any path.
    assert!(bash_completes(&dir, &["tmclsh", "run", "--log", ""]).contains(&"d.txt".to_string()));
    let ports = bash_completes(&dir, &["tmclsh", "--port", ""]);
    assert!(ports.iter().all(|p| p.starts_with("/dev/")), "{ports:?}");
    // The rest is clap's completion.
    assert!(bash_completes(&dir, &["tmclsh", "ru"]).contains(&"run".to_string()));
}
