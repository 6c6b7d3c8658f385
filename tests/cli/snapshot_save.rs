//! `snapshot save` keeps an existing file unless told `--force`, on the command line and in the
//! shell alike.

use crate::util::{code, run, stderr, tempdir};

#[test]
fn an_existing_file_is_kept_without_force_and_nothing_is_sent() {
    let dir = tempdir();
    let file = dir.join("module.toml");
    std::fs::write(&file, "the only record\n").unwrap();
    let path = file.to_str().unwrap();
    let out = run(&["--sim", "snapshot", "save", path]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains(&format!("{path} exists; add --force to replace it")),
        "{}",
        stderr(&out)
    );
    assert!(
        !stderr(&out).contains("built-in simulated"),
        "refused before the link opened: {}",
        stderr(&out)
    );
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "the only record\n");

    let out = run(&["--sim", "snapshot", "save", path, "--force"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        std::fs::read_to_string(&file)
            .unwrap()
            .starts_with("# tmclsh parameter snapshot")
    );
}

#[test]
fn the_shell_helper_keeps_an_existing_file_too() {
    let dir = tempdir();
    let file = dir.join("shell.toml");
    let dangling = dir.join("dangling.toml");
    std::fs::write(&file, "keep\n").unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink(dir.join("nowhere"), &dangling).unwrap();
    let save = format!(":snapshot save {}", file.display());
    let out = run(&["--sim", "-c", &save]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("exists; add --force"),
        "{}",
        stderr(&out)
    );
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "keep\n");
    #[cfg(unix)]
    {
        // A symlink that points nowhere is a file name in use all the same.
        let out = run(&[
            "--sim",
            "-c",
            &format!(":snapshot save {}", dangling.display()),
        ]);
        assert_eq!(code(&out), 2, "{}", stderr(&out));
        assert!(!dir.join("nowhere").exists());
    }
    let out = run(&["--sim", "-c", &format!("{save} --force")]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        std::fs::read_to_string(&file)
            .unwrap()
            .starts_with("# tmclsh parameter snapshot")
    );
}
