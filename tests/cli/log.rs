//! `--log DIR` names a transcript per session by device and date; `:log time` puts the time
//! before each reply on screen, and `:log FILE|off` still works.

use std::path::Path;

use crate::repl::repl;
use crate::sim::Sim;
use crate::util::{code, run, run_with_stdin, stderr, stdout, tempdir};

/// The names of the files in `dir`.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Whether `name` is `DEVICE-YYYY-MM-DDTHH-MM-SS.log`.
fn named_by(name: &str, device: &str) -> bool {
    let Some(stamp) = name
        .strip_prefix(&format!("{device}-"))
        .and_then(|rest| rest.strip_suffix(".log"))
    else {
        return false;
    };
    let shape = "dddd-dd-ddTdd-dd-dd";
    stamp.len() == shape.len()
        && stamp.chars().zip(shape.chars()).all(|(c, s)| match s {
            'd' => c.is_ascii_digit(),
            _ => c == s,
        })
}

#[test]
fn a_log_directory_gets_a_file_per_session_named_by_device_and_date() {
    let dir = tempdir();
    let out = run(&["--sim", "--log", dir.to_str().unwrap(), "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let files = names(&dir);
    assert_eq!(files.len(), 1, "{files:?}");
    assert!(named_by(&files[0], "sim-tmcl"), "{files:?}");
    let text = std::fs::read_to_string(dir.join(&files[0])).unwrap();
    assert!(text.contains("## tmclsh transcript"), "{text}");
    assert!(text.contains("AGAP 1, 0"), "{text}");

    // A path ending with a separator is a directory, made when missing.
    let fresh = dir.join("rig").join("logs");
    let spelled = format!("{}/", fresh.display());
    let out = run(&[
        "--sim",
        "--protocol",
        "smd4",
        "-c",
        "SYS:FW",
        "--log",
        &spelled,
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let files = names(&fresh);
    assert!(
        files.len() == 1 && named_by(&files[0], "sim-smd4"),
        "{files:?}"
    );

    // A serial device names the file, as does a subcommand's session.
    let sim = Sim::start(&["--pty"]);
    let device = sim.first.strip_prefix("/dev/").unwrap().replace('/', "-");
    let serial = tempdir();
    let out = run(&[
        "snapshot",
        "save",
        serial.join("s.toml").to_str().unwrap(),
        "--port",
        &sim.first,
        "--log",
        serial.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let logs: Vec<String> = names(&serial)
        .into_iter()
        .filter(|n| n.ends_with(".log"))
        .collect();
    assert!(
        logs.len() == 1 && named_by(&logs[0], &device),
        "{logs:?} for {device}"
    );
}

#[test]
fn log_time_puts_the_time_before_each_reply() {
    let out = run_with_stdin(
        &["--sim"],
        ":log time on\nGAP 1, 0\n:log time off\nGAP 1, 0\n",
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "timestamps on screen on");
    let (time, reply) = lines[1].split_once(' ').unwrap();
    assert_eq!(reply, "BA 100 0");
    assert!(
        time.len() == "10:15:02.118Z".len() && time.ends_with('Z'),
        "{time}"
    );
    assert_eq!(lines[2], "timestamps on screen off");
    assert_eq!(lines[3], "BA 100 0");

    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line(":log time").unwrap();
    p.exp_string("timestamps on screen on").unwrap();
    p.send_line("GAP actual_position, 0").unwrap();
    p.exp_regex(r"\d\d:\d\d:\d\d\.\d\d\dZ actual_position = 0 usteps")
        .unwrap();
    p.send_line("GAP 300, 0").unwrap();
    p.exp_regex(r"\d\d:\d\d:\d\d\.\d\d\dZ error: ").unwrap();
    p.send_line(":log time off").unwrap();
    p.exp_string("timestamps on screen off").unwrap();
    p.send_line(":log time sideways").unwrap();
    p.exp_string("usage: :log time [on|off]").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn log_file_and_off_still_work() {
    let dir = tempdir();
    let file = dir.join("repl.log");
    let input = format!(
        ":log {}\nGAP 1, 0\n:log off\nGAP 4, 0\n:log\n",
        file.display()
    );
    let out = run_with_stdin(&["--sim"], &input);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("transcript stopped"));
    assert!(stdout(&out).contains("not logging; :log FILE starts"));
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(
        text.contains("AGAP 1, 0") && !text.contains("AGAP 4, 0"),
        "{text}"
    );
}

/// `sim-tmcl-YYYY-MM-DDTHH-MM-SS.log` for `at`, as tmclsh names a built-in session's file.
fn predicted(at: std::time::SystemTime) -> String {
    let stamp = humantime::format_rfc3339_seconds(at).to_string();
    format!(
        "sim-tmcl-{}.log",
        stamp.trim_end_matches('Z').replace(':', "-")
    )
}

#[cfg(unix)]
#[test]
fn a_log_directory_never_reuses_a_name_nor_follows_a_planted_symlink() {
    let dir = tempdir();
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, "keep me\n").unwrap();
    let logs = dir.join("logs");
    std::fs::create_dir(&logs).unwrap();
    // Every name the next minute could give, first choice and second: planted symlinks (as
    // another user could in a shared directory) and a session's file of the same second.
    let now = std::time::SystemTime::now();
    for s in 0..60 {
        let at = now + std::time::Duration::from_secs(s);
        let first = logs.join(predicted(at));
        std::os::unix::fs::symlink(&victim, &first).unwrap();
        let second = first.to_str().unwrap().replace(".log", "-2.log");
        std::fs::write(&second, "another session\n").unwrap();
    }
    let out = run(&["--sim", "--log", logs.to_str().unwrap(), "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me\n");
    let made: Vec<String> = names(&logs)
        .into_iter()
        .filter(|n| n.ends_with("-3.log"))
        .collect();
    assert_eq!(made.len(), 1, "{made:?}");
    let text = std::fs::read_to_string(logs.join(&made[0])).unwrap();
    assert!(text.contains("AGAP 1, 0"), "{text}");
    for name in names(&logs).iter().filter(|n| n.ends_with("-2.log")) {
        assert_eq!(
            std::fs::read_to_string(logs.join(name)).unwrap(),
            "another session\n"
        );
    }
}
