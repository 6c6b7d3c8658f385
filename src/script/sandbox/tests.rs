//! The path policy on real directories (the hostile cases through the binary are in
//! `tests/script/sandbox.rs`).

use super::*;

fn dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tmclsh-sandbox-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir.canonicalize().unwrap()
}

fn at(dir: &Path, name: &str) -> String {
    dir.join(name).display().to_string()
}

#[test]
fn only_files_tmclsh_wrote_are_replaced() {
    let d = dir("ours");
    let sandbox = Sandbox::new([d.as_path()], false);
    std::fs::write(d.join("a.toml"), "# tmclsh parameter snapshot: x\n").unwrap();
    std::fs::write(d.join("b.toml"), "[package]\n").unwrap();
    std::fs::write(d.join("c.csv"), "time_ms,actual_position\n0,1\n").unwrap();
    std::fs::write(d.join("d.csv"), "time_msx\n").unwrap();
    std::fs::write(d.join("e.toml"), "").unwrap();
    assert!(sandbox.create(&at(&d, "a.toml"), Kind::Snapshot).is_ok());
    assert_eq!(
        std::fs::read(d.join("a.toml")).unwrap(),
        b"",
        "emptied for writing"
    );
    assert!(sandbox.create(&at(&d, "c.csv"), Kind::Recording).is_ok());
    assert!(
        sandbox.create(&at(&d, "e.toml"), Kind::Snapshot).is_ok(),
        "an empty file"
    );
    for (name, kind) in [("b.toml", Kind::Snapshot), ("d.csv", Kind::Recording)] {
        let error = sandbox.create(&at(&d, name), kind).unwrap_err();
        assert!(
            error.reason.starts_with("exists and is not a tmclsh"),
            "{error}"
        );
        assert!(sandbox.check_writable(&at(&d, name), kind).is_err());
        assert_ne!(std::fs::read(d.join(name)).unwrap(), b"", "untouched");
    }
    let anything = Sandbox::new([d.as_path()], true);
    assert!(anything.create(&at(&d, "b.toml"), Kind::Snapshot).is_ok());
}

#[test]
fn checking_a_path_creates_nothing() {
    let d = dir("check");
    let sandbox = Sandbox::new([d.as_path()], false);
    sandbox
        .check_writable(&at(&d, "new.toml"), Kind::Snapshot)
        .unwrap();
    assert!(!d.join("new.toml").exists());
    let error = sandbox
        .check_writable(&at(&d, "new.txt"), Kind::Snapshot)
        .unwrap_err();
    assert!(error.reason.contains(".toml"), "{error}");
}

#[test]
fn reads_are_capped_and_regular_only() {
    let d = dir("read");
    let sandbox = Sandbox::new([d.as_path()], false);
    std::fs::write(d.join("small"), "12345").unwrap();
    assert_eq!(sandbox.read(&at(&d, "small"), 5).unwrap(), b"12345");
    let error = sandbox.read(&at(&d, "small"), 4).unwrap_err();
    assert!(error.reason.starts_with("larger than"), "{error}");
    let error = sandbox.read(&d.display().to_string(), 4).unwrap_err();
    assert!(error.reason.starts_with("a directory"), "{error}");
    let error = sandbox.read(&at(&d, "missing"), 4).unwrap_err();
    assert!(error.reason.starts_with("cannot read it"), "{error}");
}

#[test]
fn the_script_directory_and_the_working_directory_are_the_roots() {
    let d = dir("roots");
    let sandbox = Sandbox::for_script(&d.join("s.rhai"), &[], false);
    let cwd = std::env::current_dir().unwrap().canonicalize().unwrap();
    assert_eq!(sandbox.roots, [d.clone(), cwd]);
    let relative = Sandbox::for_script(Path::new("s.rhai"), std::slice::from_ref(&d), false);
    assert_eq!(
        relative.roots.len(),
        2,
        "the script's directory is the working one"
    );
}
