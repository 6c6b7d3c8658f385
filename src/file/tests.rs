use super::*;
use std::path::PathBuf;

/// A fresh directory of this test's own.
fn dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tmclsh-file-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[cfg(unix)]
fn fifo(at: &Path) {
    nix::unistd::mkfifo(at, nix::sys::stat::Mode::from_bits_truncate(0o600)).unwrap();
}

#[test]
fn a_regular_file_reads_whole_and_a_larger_one_is_refused() {
    let d = dir("read");
    let path = d.as_path().join("f.txt");
    std::fs::write(&path, "hello").unwrap();
    assert_eq!(read_text(&path, 5).unwrap(), "hello");
    let error = read(&path, 4).unwrap_err();
    assert!(error.reason.starts_with("larger than 0 KiB"), "{error}");
}

#[cfg(unix)]
#[test]
fn a_fifo_is_refused_without_blocking_for_reading_and_writing() {
    let d = dir("fifo");
    let path = d.as_path().join("pipe");
    fifo(&path);
    for error in [
        read(&path, READ_LIMIT).unwrap_err(),
        create(&path).unwrap_err(),
        open(&path, Mode::Append, Follow::Yes).unwrap_err(),
    ] {
        assert_eq!(
            error.to_string(),
            format!(
                "{}: a named pipe (FIFO), not a regular file",
                path.display()
            )
        );
    }
    assert_eq!(describe_path(&path), "a named pipe (FIFO)");
}

#[cfg(unix)]
#[test]
fn devices_and_directories_are_named_for_what_they_are() {
    let error = read(Path::new("/dev/zero"), READ_LIMIT).unwrap_err();
    assert_eq!(error.reason, "a character device, not a regular file");
    let error = create(Path::new("/dev/null")).unwrap_err();
    assert_eq!(error.reason, "a character device, not a regular file");
    let d = dir("dev");
    let error = read(d.as_path(), READ_LIMIT).unwrap_err();
    assert_eq!(error.reason, "a directory, not a regular file");
}

#[cfg(unix)]
#[test]
fn symlinks_are_followed_only_when_asked_and_loops_are_told() {
    let d = dir("link");
    let real = d.as_path().join("real");
    std::fs::write(&real, "x").unwrap();
    let link = d.as_path().join("link");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    assert_eq!(read(&link, 10).unwrap(), b"x");
    let error = open(&link, Mode::Read, Follow::No).unwrap_err();
    assert_eq!(error.reason, "a symlink, not a regular file");
    let error = open(&link, Mode::CreateNew, Follow::No).unwrap_err();
    assert_eq!(error.reason, "a symlink, not a regular file");
    assert_eq!(std::fs::read(&real).unwrap(), b"x", "not written through");
    let looped = d.as_path().join("loop");
    std::os::unix::fs::symlink(&looped, &looped).unwrap();
    assert_eq!(describe_path(&looped), "a symlink loop");
    assert_eq!(describe_path(&d.as_path().join("none")), "missing");
}

#[test]
fn create_empties_a_file_and_missing_files_are_told_apart() {
    let d = dir("create");
    let path = d.as_path().join("out");
    std::fs::write(&path, "old contents").unwrap();
    write(&path, b"new").unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"new");
    let missing = d.as_path().join("missing");
    assert!(read(&missing, 10).unwrap_err().is_missing());
    assert_eq!(read_text_if_any(&missing, 10).unwrap(), None);
    let error = open(&path, Mode::CreateNew, Follow::No).unwrap_err();
    assert_eq!(error.reason, "exists already; not replaced");
}
