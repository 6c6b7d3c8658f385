//! Options are never dropped: every connection and session option × every face of tmclsh (the
//! shell's `-c` and piped stdin, and each subcommand), written before and after the subcommand,
//! through the real binary. In each cell the option either takes an effect the test can see (a
//! missing port fails with its path, a log file appears, a timeout names its milliseconds, …) or
//! is refused with exit code 2 and its name — it never runs against the built-in simulator as if
//! it had not been given.

#[cfg(unix)]
mod line;
mod rules;
mod table;

use std::net::TcpListener;

use crate::sim::Sim;
use crate::util::{run, stderr, stdout};

use table::*;

#[test]
fn port() {
    let path = "/nonexistent/tmclsh-options/ttyUSB9";
    table(
        &["--port", path],
        &SESSIONS,
        &|_| Setup::tmcl(),
        &|_, out, _| {
            exit(out, 3)?;
            says(out, path)?;
            not_builtin(out)
        },
        &no_special,
    );
}

#[test]
fn tcp() {
    // A port nothing listens on: bound, then closed.
    let address = {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        listener.local_addr().unwrap().to_string()
    };
    table(
        &["--tcp", &address],
        &SESSIONS,
        &|_| Setup::tmcl(),
        &|_, out, _| {
            exit(out, 3)?;
            says(out, &address)?;
            not_builtin(out)
        },
        &no_special,
    );
}

#[test]
fn baud() {
    let sim = Sim::start(&["--pty"]);
    let pty = sim.first.clone();
    table(
        &["--baud", "19200"],
        &SESSIONS,
        &|_| Setup::tmcl().with(&["--port", &pty, "--log", &fresh("baud.log")]),
        &|face, out, cell| {
            finished(face, out)?;
            let log = read(value_of(cell, "--log"));
            expect(log.contains("at 19200 baud"), || {
                format!("the transcript does not show 19200 baud:\n{log}")
            })
        },
        // `tmclsh sim --baud N` is the simulator's own option: it paces the simulated line.
        &|face, position| {
            (face == Serve && position == Position::After).then(|| {
                let paced = Sim::start(&["--baud", "19200"]);
                expect(paced.first.starts_with("/dev/"), || {
                    format!("sim --baud 19200 printed {}", paced.first)
                })
            })
        },
    );
}

#[test]
fn protocol() {
    let control = run(&[
        "snapshot",
        "diff",
        s(&fixtures().smd4_snapshot),
        s(&fixtures().smd4_snapshot),
    ]);
    table(
        &["--protocol", "smd4"],
        &[
            ShellC,
            ShellStdin,
            Run,
            SnapshotSave,
            SnapshotDiff,
            SnapshotDiffFiles,
            SnapshotRestore,
            Scan,
            Params,
            Serve,
        ],
        &|face| {
            let mut setup = Setup::smd4();
            setup.base.clear();
            if face == Serve {
                // A flag only the TMCL bus has: refused once the protocol is SMD4.
                setup.base = strings(&["--modules", "1,2"]);
            }
            setup
        },
        &|face, out, _| match face {
            Params => {
                let table = stdout(out);
                expect(
                    table.contains("MOTOR:VMAX") && !table.contains("max_current"),
                    || "not the SMD4 table".into(),
                )
            }
            Serve => {
                exit(out, 2)?;
                says(
                    out,
                    "--modules is a flag of the TMCL simulation (--protocol tmcl)",
                )
            }
            SnapshotDiffFiles => expect(stdout(out) != stdout(&control), || {
                "the same comparison as with the TMCL tables".into()
            }),
            _ => {
                finished(face, out)?;
                says(out, "using the built-in simulated SMD4")
            }
        },
        &no_special,
    );
}

#[test]
fn module() {
    table(
        &["--module", "2"],
        &ONE_MODULE,
        &|_| Setup::tmcl().with(&["--timeout", "30"]),
        &|_, out, _| {
            exit(out, 3)?;
            says(out, "module 2 (B)")
        },
        &no_special,
    );
}

#[test]
fn echo() {
    table(
        &["--echo", "line"],
        &ONE_MODULE,
        &|_| Setup::tmcl().with(&["--log", &fresh("echo.log")]),
        &|face, out, cell| {
            finished(face, out)?;
            let log = read(value_of(cell, "--log"));
            // GP 67 bit 4: line echo, written on opening.
            expect(log.contains("SGP 67, 0, 16"), || {
                format!("the transcript does not show the echo being set:\n{log}")
            })
        },
        &no_special,
    );
}

#[test]
fn local_echo() {
    // Said to strip an echo where nothing echoes: what comes back first is not the request.
    table(
        &["--local-echo", "on"],
        &SESSIONS,
        &|_| Setup::tmcl(),
        &|_, out, _| {
            exit(out, 3)?;
            says(out, "line noise: the adapter's echo of what was sent")
        },
        &no_special,
    );
}

#[test]
fn timeout() {
    // Accepts connections (the backlog) and never answers.
    let silent = TcpListener::bind("127.0.0.1:0").unwrap();
    let address = silent.local_addr().unwrap().to_string();
    table(
        &["--timeout", "40"],
        &SESSIONS,
        &|_| Setup::tmcl().with(&["--tcp", &address]),
        &|_, out, _| {
            exit(out, 3)?;
            says(out, "40 ms")
        },
        &no_special,
    );
    drop(silent);
}

#[test]
fn log() {
    let log = fresh("session.log");
    table(
        &["--log", &log],
        &SESSIONS,
        &|_| {
            let _ = std::fs::remove_file(&log);
            Setup::tmcl()
        },
        &|face, out, _| {
            finished(face, out)?;
            let text = read(&log);
            expect(text.contains("session opened"), || {
                format!("no transcript in {log}: {text:?}")
            })
        },
        &no_special,
    );
}

#[test]
fn no_validate() {
    table(
        &["--no-validate"],
        &[ShellC, ShellStdin, Run, SnapshotRestore],
        &|_| {
            let mut setup = Setup::tmcl().line("GAP 300, 0");
            setup.snapshot = Some(fixtures().bad_snapshot.clone());
            setup
        },
        // Sent although out of range, and refused by the module itself.
        &|_, out, _| {
            exit(out, 1)?;
            says(out, "not validated")
        },
        &no_special,
    );
}

#[test]
fn no_enter() {
    // The built-in module starts in binary mode: without the 139 frame it cannot answer lines.
    table(
        &["--no-enter"],
        &ONE_MODULE,
        &|_| Setup::tmcl().with(&["--timeout", "30"]),
        &|_, out, _| {
            exit(out, 3)?;
            says(out, "does not answer in ASCII mode")
        },
        &no_special,
    );
}

#[test]
fn stay_ascii() {
    let faces = ONE_MODULE;
    // What the transcript says last about module A: found or entered ASCII mode, or left it.
    let left_ascii = |log: &str| {
        read(log)
            .lines()
            .rfind(|l| l.contains("-- module 1 (A) "))
            .is_some_and(|l| l.contains("left ASCII mode"))
    };
    // Without the option each of these faces puts the module back in binary mode at the end.
    for face in faces {
        let log = fresh("control.log");
        let call = call(face, &Setup::tmcl().with(&["--log", &log]));
        let out = run_guarded(&argv(&call, &[], Position::After), call.stdin.as_deref()).unwrap();
        assert!(
            finished(face, &out).is_ok() && left_ascii(&log),
            "{face:?} without --stay-ascii: {}\n{}",
            stderr(&out),
            read(&log)
        );
    }
    table(
        &["--stay-ascii"],
        &faces,
        &|_| Setup::tmcl().with(&["--log", &fresh("stay.log")]),
        &|face, out, cell| {
            finished(face, out)?;
            let log = value_of(cell, "--log");
            let text = read(log);
            expect(text.contains("in ASCII mode") && !left_ascii(log), || {
                format!("the module was put back in binary mode:\n{text}")
            })
        },
        &no_special,
    );
}

#[test]
fn reconnect() {
    // The wait only shows when a link is lost (`tests/lost.rs`); the transcript says the policy.
    table(
        &["--reconnect", "5s"],
        &SESSIONS,
        &|_| Setup::tmcl().with(&["--log", &fresh("reconnect.log")]),
        &|face, out, cell| {
            finished(face, out)?;
            let log = read(value_of(cell, "--log"));
            expect(log.contains("a lost link is waited for up to 5 s"), || {
                format!("no reconnect policy in the transcript:\n{log}")
            })
        },
        &no_special,
    );
}

#[test]
fn binary() {
    table(
        &["--binary"],
        &ONE_MODULE,
        &|_| Setup::tmcl().with(&["--log", &fresh("binary.log")]),
        &|face, out, cell| {
            finished(face, out)?;
            let log = read(value_of(cell, "--log"));
            expect(
                log.contains("binary direct mode: --binary given") && !log.contains("(139)"),
                || format!("not a binary session:\n{log}"),
            )
        },
        &no_special,
    );
}

#[test]
fn verbose() {
    table(
        &["-v"],
        &ONE_MODULE,
        &|_| Setup::tmcl(),
        &|face, out, _| {
            finished(face, out)?;
            says(
                out,
                "tmclsh: TMCM-142, firmware 142V1.06, profile tmcm-142 (built in)\n",
            )
        },
        // `tmclsh sim -v` is the simulator's own option: it logs its traffic.
        &|face, position| {
            (face == Serve && position == Position::After).then(|| {
                let logging = Sim::start(&["-v"]);
                expect(logging.first.starts_with("/dev/"), || {
                    format!("sim -v printed {}", logging.first)
                })
            })
        },
    );
}

#[test]
fn address() {
    table(
        &["--address", "1"],
        &ONE_DRIVE,
        &|_| Setup::smd4().with(&["--log", &fresh("address.log")]),
        &|face, out, cell| {
            finished(face, out)?;
            let log = read(value_of(cell, "--log"));
            expect(
                log.contains("tx \"@1SYS:") || log.contains("tx \"@1MOTOR:"),
                || format!("no request with the @1 prefix:\n{log}"),
            )
        },
        &no_special,
    );
}

#[test]
fn prefix_comma() {
    table(
        &["--prefix-comma"],
        &[
            ShellC,
            ShellStdin,
            Run,
            SnapshotSave,
            SnapshotDiff,
            SnapshotRestore,
            Scan,
        ],
        &|face| {
            let setup = Setup::smd4().with(&["--log", &fresh("comma.log")]);
            // A scan chooses its addresses itself.
            if face == Scan {
                setup
            } else {
                setup.with(&["--address", "1"])
            }
        },
        &|face, out, cell| {
            finished(face, out)?;
            let log = read(value_of(cell, "--log"));
            expect(log.contains("tx \"@1,"), || {
                format!("no request with the @1, prefix:\n{log}")
            })
        },
        &no_special,
    );
}

#[test]
fn quiet_gap() {
    // The reply's last line, as the built-in drive sends it.
    let whole = run(&["--sim", "--protocol", "smd4", "-c", "COMS:NET:IPCONF"]);
    assert!(stdout(&whole).contains("DHCP State"), "{}", stdout(&whole));
    // A drive on a slow line: a byte every 8 ms, so a 1 ms quiet gap ends the reply after its
    // first line. One drive per cell: the rest of a cut reply is still on its way afterwards.
    table(
        &["--quiet-gap", "1"],
        &[ShellC, ShellStdin, Run],
        &|_| {
            let sim = Sim::start(&["--pty", "--protocol", "smd4", "--baud", "1200"]);
            let mut setup = Setup::smd4()
                .line("COMS:NET:IPCONF")
                .with(&["--port", &sim.first]);
            setup.sims.push(sim);
            setup
        },
        &|_, out, _| {
            exit(out, 0)?;
            expect(!stdout(out).contains("DHCP State"), || {
                "the whole multi-line reply was awaited".into()
            })
        },
        &no_special,
    );
}

#[test]
fn command_lines() {
    // GAP 4 (max_positioning_speed) answers 1000000, the faces' own GAP 1 answers 0.
    table(
        &["-c", "GAP 4, 0"],
        &[ShellC, ShellStdin],
        &|_| Setup::tmcl(),
        &|face, out, _| {
            exit(out, 0)?;
            let text = stdout(out);
            let mut lines: Vec<&str> = text.lines().collect();
            lines.sort_unstable();
            let expected: &[&str] = match face {
                // Both -c lines run, in the order written.
                ShellC => &["BA 100 0", "BA 100 1000000"],
                // -c replaces stdin.
                _ => &["BA 100 1000000"],
            };
            expect(lines == expected, || format!("ran {lines:?}"))
        },
        &no_special,
    );
}
