//! Hostile files for a script's file functions: each refused with a message that names the path
//! and never its contents, nothing outside the sandbox written, and no hang (every run has a
//! generous deadline and is killed past it).

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::util::{bin, code, stderr, stdout, tempdir};

/// Long enough for any of these runs on a loaded machine; a hang is caught, not waited out.
const HANG_GUARD: Duration = Duration::from_secs(30);

/// Runs `tmclsh run SCRIPT EXTRA` in `cwd` with `source` as the script (in `cwd`), on the
/// built-in simulator; fails the test if it does not end within [`HANG_GUARD`].
fn run_script(cwd: &Path, source: &str, extra: &[&str]) -> Output {
    let script = cwd.join("s.rhai");
    std::fs::write(&script, source).unwrap();
    let mut child = Command::new(bin())
        .args(linked(extra))
        .arg("run")
        .arg(&script)
        .args(extra)
        .current_dir(cwd)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > HANG_GUARD {
            let _ = child.kill();
            panic!("tmclsh run hung on: {source}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// Expects a refusal (exit 2) naming `reason`, and neither output stream quoting `secret`.
fn refused(out: &Output, reason: &str, secret: &str) {
    let err = stderr(out);
    assert_eq!(code(out), 2, "{err}");
    assert!(err.contains(reason), "expected '{reason}' in: {err}");
    assert!(
        !err.contains(secret) && !stdout(out).contains(secret),
        "leaked: {err}"
    );
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A directory outside the sandbox (not the script's, not the working one) holding one file.
fn outside() -> (PathBuf, PathBuf) {
    let dir = tempdir();
    let file = dir.join("victim.toml");
    std::fs::write(&file, "# tmclsh parameter snapshot\nsecret = 1\n").unwrap();
    (dir, file)
}

#[test]
fn an_existing_file_tmclsh_did_not_write_is_not_replaced_without_overwrite() {
    let dir = tempdir();
    let cargo = dir.join("Cargo.toml");
    let original = "[package]\nname = \"secret-crate\"\n";
    std::fs::write(&cargo, original).unwrap();
    let out = run_script(&dir, "snapshot_save(\"Cargo.toml\");", &[]);
    refused(
        &out,
        "Cargo.toml: exists and is not a tmclsh snapshot; scripts replace only their own files (run with --overwrite",
        "secret-crate",
    );
    assert_eq!(std::fs::read_to_string(&cargo).unwrap(), original);
    let data = dir.join("data.csv");
    std::fs::write(&data, "name,secret-column\n").unwrap();
    let out = run_script(
        &dir,
        "record_csv(\"data.csv\", \"actual_position\", 10, 30);",
        &[],
    );
    refused(
        &out,
        "exists and is not a tmclsh recording",
        "secret-column",
    );
    assert_eq!(
        std::fs::read_to_string(&data).unwrap(),
        "name,secret-column\n"
    );

    // Its own files it replaces; with --overwrite, others too.
    let out = run_script(
        &dir,
        "snapshot_save(\"mine.toml\"); snapshot_save(\"mine.toml\"); record_csv(\"r.csv\", \"actual_position\", 10, 30); record_csv(\"r.csv\", \"actual_position\", 10, 30);",
        &[],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = run_script(&dir, "snapshot_save(\"Cargo.toml\");", &["--overwrite"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        std::fs::read_to_string(&cargo)
            .unwrap()
            .starts_with("# tmclsh parameter snapshot")
    );
}

#[test]
fn absolute_paths_and_dot_dot_outside_are_refused_and_allow_dir_widens() {
    let dir = tempdir();
    let (other, victim) = outside();
    let before = std::fs::read_to_string(&victim).unwrap();
    let new = other.join("new.toml");
    for source in [
        format!("snapshot_save(\"{}\");", path(&victim)),
        format!("snapshot_save(\"{}\");", path(&new)),
        format!("snapshot_diff(\"{}\");", path(&victim)),
        format!(
            "record_csv(\"{}\", \"actual_position\", 10, 30);",
            path(&other.join("r.csv"))
        ),
        format!("download(\"{}\");", path(&victim)),
        "snapshot_save(\"../escape.toml\");".to_string(),
        "snapshot_save(\"sub/../../escape.toml\");".to_string(),
    ] {
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        let out = run_script(&dir, &source, &[]);
        refused(&out, "outside the directories scripts may use", "secret");
        assert!(stderr(&out).contains("--allow-dir DIR"), "{}", stderr(&out));
    }
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), before);
    assert!(!new.exists() && !other.join("r.csv").exists());
    assert!(!dir.parent().unwrap().join("escape.toml").exists());

    let source = format!("snapshot_save(\"{}\");", path(&new));
    let out = run_script(&dir, &source, &["--allow-dir", path(&other)]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(new.exists());
}

#[cfg(unix)]
#[test]
fn a_symlink_out_of_the_directory_is_not_followed() {
    let dir = tempdir();
    let (_other, victim) = outside();
    let before = std::fs::read_to_string(&victim).unwrap();
    std::os::unix::fs::symlink(&victim, dir.join("link.toml")).unwrap();
    std::os::unix::fs::symlink(_other.as_path(), dir.join("linkdir")).unwrap();
    std::os::unix::fs::symlink(_other.join("gone.toml"), dir.join("dangling.toml")).unwrap();
    for source in [
        "snapshot_save(\"link.toml\");",
        "snapshot_diff(\"link.toml\");",
        "snapshot_restore(\"link.toml\");",
        "download(\"link.toml\");",
        "snapshot_save(\"linkdir/x.toml\");",
    ] {
        let out = run_script(&dir, source, &[]);
        refused(&out, "outside the directories scripts may use", "secret");
    }
    let out = run_script(&dir, "snapshot_save(\"dangling.toml\");", &[]);
    refused(&out, "a symlink to nothing", "secret");
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), before);
    assert!(!_other.join("x.toml").exists() && !_other.join("gone.toml").exists());

    // A symlink that stays inside is fine.
    let out = run_script(&dir, "snapshot_save(\"real.toml\");", &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    std::os::unix::fs::symlink(dir.join("real.toml"), dir.join("inside.toml")).unwrap();
    let out = run_script(
        &dir,
        "assert_eq(snapshot_diff(\"inside.toml\").len(), 0); snapshot_save(\"inside.toml\");",
        &[],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[cfg(unix)]
#[test]
fn fifos_devices_and_huge_files_are_refused_without_blocking() {
    let dir = tempdir();
    let fifo = dir.join("fifo.toml");
    nix::unistd::mkfifo(&fifo, nix::sys::stat::Mode::from_bits_truncate(0o600)).unwrap();
    std::os::unix::fs::symlink(&fifo, dir.join("to-fifo.toml")).unwrap();
    for name in ["fifo.toml", "to-fifo.toml"] {
        for call in [
            "snapshot_diff",
            "snapshot_restore",
            "download",
            "snapshot_save",
        ] {
            let out = run_script(&dir, &format!("{call}(\"{name}\");"), &[]);
            refused(&out, "a named pipe (FIFO), not a regular file", "secret");
        }
    }
    let out = run_script(&dir, "download(\"/dev/zero\");", &[]);
    refused(&out, "outside the directories", "secret");
    let out = run_script(&dir, "download(\"/dev/zero\");", &["--allow-dir", "/dev"]);
    refused(&out, "a character device, not a regular file", "secret");

    let huge = dir.join("huge.tmc");
    std::fs::File::create(&huge)
        .unwrap()
        .set_len(2 << 30)
        .unwrap(); // sparse
    let out = run_script(&dir, "download(\"huge.tmc\");", &[]);
    refused(&out, "larger than 4 MiB", "secret");
    let huge_toml = dir.join("huge.toml");
    std::fs::File::create(&huge_toml)
        .unwrap()
        .set_len(2 << 30)
        .unwrap();
    let out = run_script(&dir, "snapshot_diff(\"huge.toml\");", &[]);
    refused(&out, "larger than 4 MiB", "secret");
}

#[test]
fn errors_never_quote_the_file_not_even_when_caught() {
    let dir = tempdir();
    std::fs::write(
        dir.join("secret.toml"),
        "user = \"admin\"\npassword = \"hunter2\"\n",
    )
    .unwrap();
    std::fs::write(dir.join("secret.tmc"), "hunter2 is the password\n").unwrap();
    std::fs::write(
        dir.join("almost.toml"),
        "[module]\nname = \"hunter2\"\n[axis.0]\nhunter2 = { value = \"hunter2\" }\n",
    )
    .unwrap();
    for (call, reason) in [
        (
            "snapshot_diff(\"secret.toml\")",
            "secret.toml is not a tmclsh snapshot (the first problem is at line ",
        ),
        (
            "snapshot_restore(\"secret.toml\")",
            "secret.toml is not a tmclsh snapshot",
        ),
        (
            "download(\"secret.tmc\")",
            "secret.tmc is not a program for the TMCM-142 (the first problem is at line 1, column 12)",
        ),
        (
            "snapshot_restore(\"almost.toml\")",
            "[axis.0] an entry: not a parameter of the TMCM-142",
        ),
    ] {
        let out = run_script(&dir, &format!("{call};"), &[]);
        refused(&out, reason, "hunter2");
        let caught = format!("try {{ {call}; }} catch (e) {{ print(e); print(`${{e}}`); }}");
        let out = run_script(&dir, &caught, &[]);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        assert!(stdout(&out).contains(reason), "{}", stdout(&out));
        assert!(
            !stdout(&out).contains("hunter2"),
            "leaked to the script: {}",
            stdout(&out)
        );
    }
}

/// `--sim` unless `extra` names a link: a script run without a terminal must be told what it
/// talks to.
fn linked(extra: &[&str]) -> Vec<&'static str> {
    if extra.iter().any(|a| *a == "--port" || *a == "--tcp") {
        Vec::new()
    } else {
        vec!["--sim"]
    }
}
