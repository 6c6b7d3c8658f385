//! Which files are read, and what `tmclsh config` says of them: a project file another user
//! could have written (owned by someone else, or writable by everyone) is ignored with a note; a
//! broken file nearer the working directory is an error, never skipped for one further up; a
//! user file that is not a regular file is named for what it is; and settings that have no
//! effect (a port under `--tcp`, a TMCL profile under `--protocol smd4`) are shown as such.

use std::os::unix::fs::PermissionsExt;

use super::{Place, shown};
use crate::util::{code, stderr, stdout};

#[test]
fn a_project_file_others_could_have_written_is_ignored_with_a_note() {
    let place = Place::new();
    let file = place.project_file("port = \"/dev/planted\"\nlog_dir = \"/tmp/planted-logs\"\n");
    let planted = |mode: u32, owner: Option<u32>| {
        std::fs::set_permissions(&file, std::fs::Permissions::from_mode(mode)).unwrap();
        std::os::unix::fs::chown(&file, owner, None).unwrap();
    };
    for (mode, owner, why) in [
        (0o666, None, "writable by everyone (mode 666)"),
        (0o644, Some(12345), "owned by uid 12345"),
    ] {
        planted(mode, owner);
        let out = place.run(&["config"], &[]);
        let err = stderr(&out);
        assert_eq!(code(&out), 0, "{err}");
        assert!(
            err.contains(&format!("ignored {}: {why}", file.display())),
            "{err}"
        );
        let report = stdout(&out);
        assert!(report.contains("ignored"), "{report}");
        assert!(shown(&report, "port").contains("is not set"), "{report}");
        // The session uses the built-in simulator, not the planted port.
        let out = place.run(&["--sim", "-c", "GAP 4, 0"], &[]);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        assert!(stderr(&out).contains("ignored"), "{}", stderr(&out));
    }
    // The same file, the user's own and not writable by others, is used.
    planted(0o644, Some(0));
    let out = place.run(&["config"], &[]);
    assert!(
        shown(&stdout(&out), "port").contains("/dev/planted"),
        "{}",
        stdout(&out)
    );
    assert!(!stderr(&out).contains("ignored"), "{}", stderr(&out));
}

#[test]
fn a_broken_file_near_the_working_directory_is_an_error_not_skipped() {
    let place = Place::new();
    place.project_file("timeout = 130\n");
    let local = place.cwd.join("tmclsh.toml");
    std::fs::create_dir(&local).unwrap();
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert!(
        stderr(&out).contains(&format!(
            "{}: a directory, not a regular file",
            local.display()
        )),
        "{}",
        stderr(&out)
    );
    std::fs::remove_dir(&local).unwrap();
    nix::unistd::mkfifo(&local, nix::sys::stat::Mode::from_bits_truncate(0o600)).unwrap();
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert!(
        stderr(&out).contains("a named pipe (FIFO), not a regular file"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_user_file_that_is_not_a_regular_file_is_named_for_what_it_is() {
    let place = Place::new();
    let user = place.user.join("tmclsh").join("config.toml");
    std::fs::create_dir(&user).unwrap();
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("a directory, not a regular file"),
        "{}",
        stderr(&out)
    );
    std::fs::remove_dir(&user).unwrap();
    std::os::unix::fs::symlink(&user, &user).unwrap();
    let out = place.run(&["config"], &[]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("too many levels of symbolic links"),
        "{}",
        stderr(&out)
    );
    std::fs::remove_file(&user).unwrap();
    let out = place.run(&["config"], &[]);
    assert!(stdout(&out).contains("does not exist"), "{}", stdout(&out));
}

#[test]
fn config_shows_what_has_no_effect() {
    let place = Place::new();
    place.project_file("port = \"/dev/ttyUSB0\"\nprofile = \"tmcm-1140\"\n");
    let out = place.run(&["config", "--tcp", "127.0.0.1:4001"], &[]);
    let report = stdout(&out);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        shown(&report, "port").contains("is not used: --tcp 127.0.0.1:4001 wins"),
        "{report}"
    );
    let out = place.run(&["config", "--protocol", "smd4"], &[]);
    let report = stdout(&out);
    assert!(
        shown(&report, "profile").contains("is not used: TMCL only; the protocol is smd4"),
        "{report}"
    );
    assert!(shown(&report, "port").starts_with("port = "), "{report}");
}
