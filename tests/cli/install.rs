//! `completions SHELL --install` and `man --install`: the files land in the user's standard
//! places under HOME or the XDG directories, are what the binary prints, and a symlink or
//! directory in their place is refused and left alone.

use std::path::Path;
use std::process::{Command, Output, Stdio};

use crate::util::{bin, code, stderr, stdout, tempdir};

/// `tmclsh ARGS` with HOME at `home` and the XDG variables as given (unset otherwise).
fn run_at(home: &Path, xdg: &[(&str, &Path)], args: &[&str]) -> Output {
    let mut command = Command::new(bin());
    command
        .args(args)
        .stdin(Stdio::null())
        .env("NO_COLOR", "1")
        .env("HOME", home)
        .env_remove("XDG_DATA_HOME")
        .env_remove("XDG_CONFIG_HOME");
    for (name, value) in xdg {
        command.env(name, value);
    }
    command.output().unwrap()
}

fn printed(args: &[&str]) -> Vec<u8> {
    let out = run_at(&tempdir(), &[], args);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    out.stdout
}

#[test]
fn install_writes_the_standard_places_under_home_and_says_where() {
    let home = tempdir();
    for (args, place) in [
        (
            &["completions", "bash", "--install"][..],
            ".local/share/bash-completion/completions/tmclsh",
        ),
        (
            &["completions", "zsh", "--install"],
            ".local/share/zsh/site-functions/_tmclsh",
        ),
        (
            &["completions", "fish", "--install"],
            ".config/fish/completions/tmclsh.fish",
        ),
        (&["man", "--install"], ".local/share/man/man1/tmclsh.1"),
    ] {
        let out = run_at(&home, &[], args);
        assert_eq!(code(&out), 0, "{args:?}: {}", stderr(&out));
        let path = home.join(place);
        assert!(
            stdout(&out).starts_with(&format!("wrote {};", path.display())),
            "{args:?}: {}",
            stdout(&out)
        );
        let without_install = &args[..args.len() - 1];
        assert!(
            std::fs::read(&path).unwrap() == printed(without_install),
            "{place} is what `tmclsh {}` prints",
            without_install.join(" ")
        );
        // Again: its own file is replaced.
        assert_eq!(code(&run_at(&home, &[], args)), 0);
    }
    let bash = stdout(&run_at(&home, &[], &["completions", "bash", "--install"]));
    assert!(bash.contains("bash-completion package"), "{bash}");
}

#[test]
fn install_follows_xdg_data_home_and_xdg_config_home() {
    let home = tempdir();
    let data = tempdir();
    let config = tempdir();
    let xdg = [
        ("XDG_DATA_HOME", data.as_path()),
        ("XDG_CONFIG_HOME", config.as_path()),
    ];
    assert_eq!(code(&run_at(&home, &xdg, &["man", "--install"])), 0);
    assert_eq!(
        code(&run_at(&home, &xdg, &["completions", "fish", "--install"])),
        0
    );
    assert!(data.join("man/man1/tmclsh.1").is_file());
    assert!(config.join("fish/completions/tmclsh.fish").is_file());
    assert!(!home.join(".local").exists() && !home.join(".config").exists());
}

#[test]
fn install_refuses_a_symlink_or_a_directory_in_the_place() {
    let home = tempdir();
    let dir = home.join(".local/share/man/man1");
    std::fs::create_dir_all(&dir).unwrap();
    let victim = home.join("victim");
    std::fs::write(&victim, "keep me").unwrap();
    std::os::unix::fs::symlink(&victim, dir.join("tmclsh.1")).unwrap();
    let out = run_at(&home, &[], &["man", "--install"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("not a regular file"),
        "{}",
        stderr(&out)
    );
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me");

    let place = home.join(".local/share/bash-completion/completions/tmclsh");
    std::fs::create_dir_all(&place).unwrap();
    let out = run_at(&home, &[], &["completions", "bash", "--install"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("directory"), "{}", stderr(&out));
}

#[test]
fn install_of_a_shell_without_a_standard_place_is_refused_with_the_way_to_do_it() {
    let out = run_at(&tempdir(), &[], &["completions", "elvish", "--install"]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("tmclsh completions elvish"),
        "{}",
        stderr(&out)
    );
}
