//! Scripting output: `--value` prints only the value, `--json` one object per line, and
//! `--keep-going` runs a piped file to its end and exits with the worst failure's code.

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

use serde_json::Value;

use crate::util::{bin, code, run, run_with_stdin, stderr, stdout};

fn lines(out: &std::process::Output) -> Vec<String> {
    stdout(out).lines().map(String::from).collect()
}

fn objects(out: &std::process::Output) -> Vec<Value> {
    stdout(out)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON: {l}: {e}")))
        .collect()
}

#[test]
fn value_prints_only_the_value() {
    let out = run(&[
        "--sim",
        "-c",
        "SAP 1, 0, -5000",
        "-c",
        "GAP 1, 0",
        "--value",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(lines(&out)[1], "-5000");
    // Written before the subcommand-free shell's -c, the same.
    let out = run(&["--sim", "--value", "-c", ":bin", "-c", "136 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(lines(&out).last().unwrap(), "142V1.06");
    let out = run(&[
        "--sim",
        "--protocol",
        "smd4",
        "--value",
        "-c",
        "SYS:FW",
        "-c",
        "MOTOR:VMAX",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(lines(&out), ["24044.12", "1.0000E+03,1.0000E+03"]);
}

#[test]
fn json_gives_one_object_per_line_with_status_value_raw_and_module() {
    let out = run(&[
        "--sim",
        "--json",
        "-c",
        "SAP actual_position, 0, -5000",
        "-c",
        "GAP actual_position, 0",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let objects = objects(&out);
    assert_eq!(objects.len(), 2);
    let read = &objects[1];
    assert_eq!(read["line"], 2);
    assert_eq!(read["input"], "GAP actual_position, 0");
    assert_eq!(read["module"], 1);
    assert_eq!(read["sent"], "AGAP 1, 0");
    assert_eq!(read["status"], 100);
    assert_eq!(read["value"], -5000);
    assert_eq!(read["raw"], "BA 100 -5000");
    assert_eq!(read["ok"], true);
    assert_eq!(read["exit"], 0);

    let out = run(&["--sim", "--protocol", "smd4", "--json", "-c", "MOTOR:VMAX"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let reply = &self::objects(&out)[0];
    assert_eq!(
        reply["items"],
        serde_json::json!(["1.0000E+03", "1.0000E+03"])
    );
    assert_eq!(reply["raw"], "0x0888,0x0000,1.0000E+03,1.0000E+03");
    assert_eq!(reply["error"], Value::Null);
    assert_eq!(reply["module"], Value::Null);
    assert!(reply["sflags"].is_u64(), "{reply}");
}

#[test]
fn failures_keep_their_line_in_value_and_json_output() {
    let input = "GAP 4, 0\nGPA 1, 0\nGAP 200, 0\n:params max_cur\nGAP 6, 0\n";
    let out = run_with_stdin(&["--sim", "--value", "--keep-going"], input);
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    assert_eq!(lines(&out)[..3], ["1000000", "", "0"]);
    assert!(lines(&out).iter().any(|l| l.contains("max_current")));

    let out = run_with_stdin(&["--sim", "--json", "--keep-going"], input);
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    let objects = objects(&out);
    assert_eq!(objects.len(), 5, "{}", stdout(&out));
    assert_eq!(objects[1]["exit"], 2);
    assert_eq!(objects[1]["ok"], false);
    assert!(
        objects[1]["failure"]
            .as_str()
            .unwrap()
            .contains("did you mean GAP?")
    );
    assert_eq!(objects[2]["status"], 3);
    assert_eq!(objects[2]["exit"], 1);
    assert!(
        objects[3]["output"]
            .as_str()
            .unwrap()
            .contains("max_current")
    );
    assert_eq!(objects[4]["value"], 8);
    assert_eq!(objects[4]["line"], 5);
}

#[test]
fn keep_going_runs_to_the_end_and_exits_with_the_worst_failure() {
    // Without it, the first failure ends the run.
    let input = "GPA 1, 0\nSAP 1, 0, 77\n";
    let out = run_with_stdin(&["--sim"], input);
    assert_eq!(code(&out), 2);
    assert!(stdout(&out).is_empty());

    for (input, worst, last) in [
        ("GPA 1, 0\nSAP 1, 0, 77\nGAP 1, 0\n", 2, "BA 100 77"),
        ("GAP 200, 0\nGPA\nGAP 1, 0\n", 1, "BA 100 0"),
        ("GPA\nCGAP 1, 0\nGAP 200, 0\nGAP 1, 0\n", 3, "BA 100 0"),
    ] {
        let out = run_with_stdin(&["--sim", "--keep-going", "--timeout", "100"], input);
        assert_eq!(code(&out), worst, "{input:?}: {}", stderr(&out));
        assert_eq!(
            lines(&out).last().map(String::as_str),
            Some(last),
            "the last line ran: {input:?}"
        );
    }
}

#[cfg(unix)]
#[test]
fn ctrl_c_still_ends_a_run_that_keeps_going() {
    let mut child = Command::new(bin())
        .args(["--sim", "--keep-going", "--value"])
        .env("NO_COLOR", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(b"GPA\nGAP 4, 0\n").unwrap();
    stdin.flush().unwrap();
    let mut reader = BufReader::new(child.stdout.take().unwrap());
    let mut line = String::new();
    for expected in ["", "1000000"] {
        line.clear();
        reader.read_line(&mut line).unwrap();
        assert_eq!(line.trim_end(), expected);
    }
    // stdin stays open: the run waits for more lines until Ctrl-C.
    nix::sys::signal::kill(
        nix::unistd::Pid::from_raw(child.id() as i32),
        nix::sys::signal::Signal::SIGINT,
    )
    .unwrap();
    let status = child.wait().unwrap();
    drop(stdin);
    assert_eq!(status.code(), Some(130));
}

#[test]
fn the_interactive_shell_refuses_the_output_flags() {
    let data = crate::util::tempdir();
    let mut command = Command::new(bin());
    command
        .args(["--json", "--keep-going"])
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("XDG_DATA_HOME", &data)
        .env("XDG_CONFIG_HOME", &data)
        .env("HOME", &data);
    let mut p = rexpect::session::spawn_command(command, Some(crate::util::EXPECT_MS)).unwrap();
    p.exp_string("--json, --keep-going shape the output of -c and piped lines")
        .unwrap();
    p.exp_eof().unwrap();
    match p.process().wait().unwrap() {
        rexpect::process::WaitStatus::Exited(_, code) => assert_eq!(code, 2),
        other => panic!("{other:?}"),
    }
}
