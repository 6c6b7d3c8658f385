//! Files named on the command line and in helpers that are not regular files: a FIFO (which
//! would block in `open()`), `/dev/zero` (which would stream for ever), `/dev/null` and a
//! directory, read or written by every command and helper. Each is refused with exit 2, the
//! file named and what it is, promptly: every run has a hang guard and is killed past it.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::util::{bin, code, stderr, tempdir, terminal};

/// Long enough for any of these runs on a loaded machine; a hang is caught, not waited out.
const HANG_GUARD: Duration = Duration::from_secs(30);

/// `tmclsh ARGS` in `dir` with `input` on stdin, killed (and the test failed) past the guard.
fn guarded(dir: &Path, args: &[&str], input: &str) -> Output {
    let mut child = Command::new(bin())
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let _ = stdin.write_all(input.as_bytes());
    drop(stdin);
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > HANG_GUARD {
            let _ = child.kill();
            panic!("tmclsh {args:?} hung");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// A directory holding a FIFO `pipe.toml`, a symlink `link.toml` to it, and a regular
/// `test2.tmc` and transcript `t.log` for the commands that need one input to be real.
fn hostile_dir() -> PathBuf {
    let dir = tempdir();
    nix::unistd::mkfifo(
        &dir.join("pipe.toml"),
        nix::sys::stat::Mode::from_bits_truncate(0o600),
    )
    .unwrap();
    std::os::unix::fs::symlink(dir.join("pipe.toml"), dir.join("link.toml")).unwrap();
    std::fs::create_dir(dir.join("adir")).unwrap();
    std::fs::copy(
        crate::util::repo().join("scripts/test2.tmc"),
        dir.join("test2.tmc"),
    )
    .unwrap();
    dir
}

/// What a refusal of `file` as `what` must say.
fn expected(file: &str) -> &'static str {
    match file {
        "/dev/zero" | "/dev/null" => "a character device, not a regular file",
        "adir" => "a directory, not a regular file",
        _ => "a named pipe (FIFO), not a regular file",
    }
}

fn refused(out: &Output, file: &str, case: &str) {
    let err = stderr(out);
    assert_eq!(code(out), 2, "{case}: {err}");
    assert!(
        err.contains(&format!("{file}: {}", expected(file))),
        "{case}: {err}"
    );
}

#[test]
fn command_line_files_that_are_not_regular_files_are_refused_without_blocking() {
    let dir = hostile_dir();
    for file in ["pipe.toml", "link.toml", "/dev/zero", "adir"] {
        let reads: [Vec<&str>; 10] = [
            vec!["--sim", "snapshot", "restore", file],
            vec!["snapshot", "diff", file],
            vec!["--profile", file, "params"],
            vec!["asm", file],
            vec!["disasm", file],
            vec!["--sim", "run", file],
            vec!["--sim", "download", file],
            vec!["sim", "--state", file],
            vec!["transcript", "to-rhai", file],
            vec!["--sim", "-c", "GAP 4, 0", "--profile", file],
        ];
        for args in reads {
            let out = guarded(&dir, &args, "");
            refused(&out, file, &format!("{args:?}"));
            // Refused before any link is opened.
            assert!(
                !stderr(&out).contains("using the built-in simulated"),
                "{args:?}: {}",
                stderr(&out)
            );
        }
    }
    // (An existing directory given to --log is a log directory.)
    for file in ["pipe.toml", "link.toml", "/dev/null"] {
        let writes: [Vec<&str>; 4] = [
            vec!["--sim", "--log", file, "-c", "GAP 4, 0"],
            vec!["--sim", "snapshot", "save", "--force", file],
            vec!["asm", "test2.tmc", "-o", file],
            vec!["--sim", "-c", "GAP 4, 0", "--log", file],
        ];
        for args in writes {
            let out = guarded(&dir, &args, "");
            refused(&out, file, &format!("{args:?}"));
        }
    }
}

#[test]
fn helpers_refuse_files_that_are_not_regular_files_and_the_session_goes_on() {
    let dir = hostile_dir();
    for file in ["pipe.toml", "link.toml", "/dev/zero", "/dev/null"] {
        for helper in [
            ":log",
            ":source",
            ":download",
            ":snapshot diff",
            ":snapshot restore",
            ":snapshot save --force",
            ":plot",
        ] {
            if file == "/dev/zero" && helper == ":snapshot save --force" {
                continue; // /dev/null stands for the devices written to
            }
            let line = format!("{helper} {file}");
            let out = guarded(
                &dir,
                &["--sim", "--keep-going"],
                &format!("{line}\nGAP 4, 0\n"),
            );
            refused(&out, file, &line);
            assert!(
                crate::util::stdout(&out).contains("1000000"),
                "{line}: the next line runs: {}",
                crate::util::stdout(&out)
            );
        }
        let line = format!(":record {file} actual_position 10ms 50ms");
        let out = guarded(&dir, &["--sim"], &format!("{line}\n"));
        refused(&out, file, &line);
    }
}

#[test]
fn a_helper_on_a_fifo_in_the_repl_gives_the_prompt_back_with_the_error() {
    let dir = hostile_dir();
    let pipe = dir.join("pipe.toml");
    let pipe = pipe.to_str().unwrap();
    let mut p = terminal(&[], &[]);
    p.exp_string("A> ").unwrap();
    for helper in [":source", ":log", ":snapshot diff", ":download"] {
        p.send_line(&format!("{helper} {pipe}")).unwrap();
        p.exp_string("a named pipe (FIFO), not a regular file")
            .unwrap();
        p.exp_string("A> ").unwrap();
    }
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("1000000").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_script_may_start_with_a_byte_order_mark() {
    let dir = tempdir();
    let script = dir.join("bom.rhai");
    std::fs::write(&script, "\u{feff}send(\"GAP 4, 0\");\n").unwrap();
    let out = guarded(&dir, &["--sim", "run", script.to_str().unwrap()], "");
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn sources_with_cr_only_line_ends_assemble_to_the_same_program() {
    let dir = hostile_dir();
    let source = std::fs::read_to_string(dir.join("test2.tmc")).unwrap();
    let endings = [
        ("lf.tmc", source.replace("\r\n", "\n")),
        ("cr.tmc", source.replace("\r\n", "\n").replace('\n', "\r")),
        (
            "crlf.tmc",
            source.replace("\r\n", "\n").replace('\n', "\r\n"),
        ),
        (
            "bom.tmc",
            format!("\u{feff}{}", source.replace("\r\n", "\n")),
        ),
    ];
    let mut programs = Vec::new();
    for (name, text) in endings {
        std::fs::write(dir.join(name), text).unwrap();
        let bin = format!("{name}.bin");
        let out = guarded(&dir, &["asm", name, "-o", &bin], "");
        assert_eq!(code(&out), 0, "{name}: {}", stderr(&out));
        programs.push(std::fs::read(dir.join(&bin)).unwrap());
    }
    assert!(programs.iter().all(|p| p == &programs[0]));
    assert!(programs[0].len() > 7 * 10, "the whole program");
}

#[test]
fn a_fifo_in_place_of_the_history_file_is_left_alone() {
    let data = tempdir();
    std::fs::create_dir_all(data.join("tmclsh")).unwrap();
    let history = data.join("tmclsh").join("history-tmcl");
    nix::unistd::mkfifo(&history, nix::sys::stat::Mode::from_bits_truncate(0o600)).unwrap();
    let mut p = terminal(&[], &[("XDG_DATA_HOME", data.to_str().unwrap())]);
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("1000000").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn huge_files_are_refused_by_their_size_not_read() {
    let dir = tempdir();
    for name in ["huge.toml", "huge.rhai", "huge.tmc", "huge.log"] {
        std::fs::File::create(dir.join(name))
            .unwrap()
            .set_len(2 << 30) // sparse
            .unwrap();
    }
    let cases: [(&[&str], &str); 6] = [
        (&["snapshot", "diff", "huge.toml"], "larger than 4 MiB"),
        (&["--sim", "run", "huge.rhai"], "larger than 4 MiB"),
        (&["asm", "huge.tmc"], "larger than 4 MiB"),
        (&["sim", "--state", "huge.toml"], "larger than 4 MiB"),
        (&["--profile", "huge.toml", "params"], "larger than 4 MiB"),
        (
            &["transcript", "to-rhai", "huge.log"],
            "larger than 256 MiB",
        ),
    ];
    for (args, why) in cases {
        let out = guarded(&dir, args, "");
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(why), "{args:?}: {}", stderr(&out));
    }
}
