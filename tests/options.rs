//! Options are never dropped: every connection and session option × every face of tmclsh (the
//! shell's `-c` and piped stdin, and each subcommand), written before and after the subcommand,
//! through the real binary. In each cell the option either takes an effect the test can see (a
//! missing port fails with its path, a log file appears, a timeout names its milliseconds, …) or
//! is refused with exit code 2 and its name — it never runs against the built-in simulator as if
//! it had not been given.

use std::io::Write;
use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::OnceLock;
use std::sync::mpsc::channel;

use crate::sim::{PATIENCE, Sim};
use crate::util::{bin, code, repo, run, run_with_stdin, stderr, stdout, tempdir};

/// The faces of tmclsh: the shell and every subcommand form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Face {
    ShellC,
    ShellStdin,
    Run,
    Download,
    SnapshotSave,
    SnapshotDiff,
    SnapshotDiffFiles,
    SnapshotRestore,
    Scan,
    Params,
    Ports,
    Completions,
    Asm,
    Disasm,
    Transcript,
    /// `tmclsh sim`.
    Serve,
}

use Face::*;

const FACES: [Face; 16] = [
    ShellC,
    ShellStdin,
    Run,
    Download,
    SnapshotSave,
    SnapshotDiff,
    SnapshotDiffFiles,
    SnapshotRestore,
    Scan,
    Params,
    Ports,
    Completions,
    Asm,
    Disasm,
    Transcript,
    Serve,
];

/// The faces that talk to a module.
const SESSIONS: [Face; 8] = [
    ShellC,
    ShellStdin,
    Run,
    Download,
    SnapshotSave,
    SnapshotDiff,
    SnapshotRestore,
    Scan,
];

/// Where the option under test is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Position {
    /// Before the subcommand (for the shell: before `-c LINE`).
    Before,
    /// After the subcommand and its arguments.
    After,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Dialect {
    Tmcl,
    Smd4,
}

/// Files the faces work on, made once.
struct Fixtures {
    dir: PathBuf,
    tmcl_snapshot: PathBuf,
    smd4_snapshot: PathBuf,
    /// A TMCL snapshot whose max_current (99) is out of range.
    bad_snapshot: PathBuf,
    program: PathBuf,
    binary: PathBuf,
    transcript: PathBuf,
}

fn fixtures() -> &'static Fixtures {
    static FIXTURES: OnceLock<Fixtures> = OnceLock::new();
    FIXTURES.get_or_init(|| {
        let dir = tempdir();
        let path = |name: &str| dir.join(name);
        let made = |out: Output| assert_eq!(code(&out), 0, "fixture: {}", stderr(&out));
        let fx = Fixtures {
            tmcl_snapshot: path("tmcl.toml"),
            smd4_snapshot: path("smd4.toml"),
            bad_snapshot: path("bad.toml"),
            program: repo().join("scripts/test2.tmc"),
            binary: path("test2.bin"),
            transcript: path("session.log"),
            dir: dir.clone(),
        };
        made(run(&["snapshot", "save", s(&fx.tmcl_snapshot)]));
        made(run(&[
            "--protocol",
            "smd4",
            "snapshot",
            "save",
            s(&fx.smd4_snapshot),
        ]));
        std::fs::write(
            &fx.bad_snapshot,
            "[module]\nname = \"TMCM-142\"\naddress = 1\n[axis.0]\nmax_current = { number = 6, value = 99 }\n",
        )
        .unwrap();
        made(run(&["asm", s(&fx.program), "-o", s(&fx.binary)]));
        made(run(&["--log", s(&fx.transcript), "-c", "GAP 1, 0"]));
        fx
    })
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// A fresh path for a file a cell writes.
fn fresh(name: &str) -> String {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    fixtures()
        .dir
        .join(format!("{n}-{name}"))
        .to_string_lossy()
        .into_owned()
}

/// How a face is run for one cell.
struct Setup {
    dialect: Dialect,
    /// The line the shell faces and scripts send.
    line: String,
    /// Options written after everything else (the conditions that make the effect visible).
    base: Vec<String>,
    /// The snapshot the snapshot faces read.
    snapshot: Option<PathBuf>,
    /// Simulators serving this cell alone.
    sims: Vec<Sim>,
}

impl Setup {
    fn tmcl() -> Setup {
        Setup {
            dialect: Dialect::Tmcl,
            line: "GAP 1, 0".into(),
            base: Vec::new(),
            snapshot: None,
            sims: Vec::new(),
        }
    }

    fn smd4() -> Setup {
        Setup {
            dialect: Dialect::Smd4,
            line: "SYS:FW".into(),
            base: strings(&["--protocol", "smd4"]),
            snapshot: None,
            sims: Vec::new(),
        }
    }

    fn line(mut self, line: &str) -> Setup {
        self.line = line.into();
        self
    }

    fn with(mut self, base: &[&str]) -> Setup {
        self.base.extend(strings(base));
        self
    }

    fn snapshot(&self) -> &Path {
        self.snapshot.as_deref().unwrap_or(match self.dialect {
            Dialect::Tmcl => &fixtures().tmcl_snapshot,
            Dialect::Smd4 => &fixtures().smd4_snapshot,
        })
    }
}

fn strings(items: &[&str]) -> Vec<String> {
    items.iter().map(|x| x.to_string()).collect()
}

/// A command line split around the option under test, and its stdin.
struct Call {
    words: Vec<String>,
    rest: Vec<String>,
    stdin: Option<String>,
}

fn call(face: Face, setup: &Setup) -> Call {
    let fx = fixtures();
    let (words, rest, stdin): (&[&str], Vec<String>, Option<String>) = match face {
        ShellC => (&[], strings(&["-c", &setup.line]), None),
        ShellStdin => (&[], Vec::new(), Some(format!("{}\n", setup.line))),
        Run => {
            let script = fresh("script.rhai");
            let body = match setup.dialect {
                Dialect::Tmcl => format!("print(send({:?}));\n", setup.line),
                Dialect::Smd4 => format!("print(reply({:?}).raw);\n", setup.line),
            };
            std::fs::write(&script, body).unwrap();
            (&["run"], vec![script], None)
        }
        Download => (&["download"], strings(&[s(&fx.program)]), None),
        SnapshotSave => (&["snapshot", "save"], vec![fresh("saved.toml")], None),
        SnapshotDiff => (&["snapshot", "diff"], strings(&[s(setup.snapshot())]), None),
        SnapshotDiffFiles => {
            let file = s(setup.snapshot());
            (&["snapshot", "diff"], strings(&[file, file]), None)
        }
        SnapshotRestore => (
            &["snapshot", "restore"],
            strings(&[s(setup.snapshot())]),
            None,
        ),
        Scan => (&["scan"], strings(&["--addresses", "1"]), None),
        Params => (&["params"], Vec::new(), None),
        Ports => (&["ports"], Vec::new(), None),
        Completions => (&["completions"], strings(&["bash"]), None),
        Asm => (&["asm"], strings(&[s(&fx.program)]), None),
        Disasm => (&["disasm"], strings(&[s(&fx.binary)]), None),
        Transcript => (
            &["transcript", "to-rhai"],
            strings(&[s(&fx.transcript)]),
            None,
        ),
        Serve => (&["sim"], Vec::new(), None),
    };
    let mut rest = rest;
    rest.extend(setup.base.iter().cloned());
    Call {
        words: strings(words),
        rest,
        stdin,
    }
}

/// The whole command line with `option` at `position`.
fn argv(call: &Call, option: &[String], position: Position) -> Vec<String> {
    let mut all = Vec::new();
    match position {
        Position::Before => {
            all.extend(option.iter().cloned());
            all.extend(call.words.iter().cloned());
            all.extend(call.rest.iter().cloned());
        }
        Position::After => {
            all.extend(call.words.iter().cloned());
            all.extend(call.rest.iter().cloned());
            all.extend(option.iter().cloned());
        }
    }
    all
}

/// Runs tmclsh with a hang guard: a cell that would serve or wait forever (an option dropped
/// from `sim`, say) is killed after [`PATIENCE`] and reported.
fn run_guarded(args: &[String], stdin: Option<&str>) -> Result<Output, String> {
    let mut child = Command::new(bin())
        .args(args)
        .stdin(if stdin.is_some() {
            Stdio::piped()
        } else {
            Stdio::null()
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .env("NO_COLOR", "1")
        .spawn()
        .expect("tmclsh runs");
    if let Some(text) = stdin {
        let mut pipe = child.stdin.take().unwrap();
        pipe.write_all(text.as_bytes()).unwrap();
    }
    let pid = nix::unistd::Pid::from_raw(child.id() as i32);
    let (tx, rx) = channel();
    std::thread::spawn(move || {
        let _ = tx.send(child.wait_with_output());
    });
    match rx.recv_timeout(PATIENCE) {
        Ok(out) => Ok(out.expect("tmclsh finishes")),
        Err(_) => {
            // Our own child, by its id.
            let _ = nix::sys::signal::kill(pid, nix::sys::signal::Signal::SIGKILL);
            Err(format!("still running after {PATIENCE:?}"))
        }
    }
}

/// What a cell checks when the option takes effect.
type Check<'a> = &'a dyn Fn(Face, &Output, &Cell) -> Result<(), String>;

/// One run: the command line and the files it was told to write.
struct Cell {
    args: Vec<String>,
}

/// The table for one option: for every face and both positions, runs tmclsh and checks that the
/// option took effect (on the faces in `effect`, set up by `setup`) or was refused with exit code
/// 2 naming it (everywhere else). Panics with every failed cell.
fn table(
    option: &[&str],
    effect: &[Face],
    setup: &dyn Fn(Face) -> Setup,
    check: Check,
    special: &dyn Fn(Face, Position) -> Option<Result<(), String>>,
) {
    let option = strings(option);
    let mut failures = Vec::new();
    for face in FACES {
        for position in [Position::Before, Position::After] {
            if let Some(result) = special(face, position) {
                if let Err(why) = result {
                    failures.push(format!("{face:?} {position:?}: {why}"));
                }
                continue;
            }
            let takes_effect = effect.contains(&face);
            let setup = if takes_effect {
                setup(face)
            } else {
                Setup::tmcl()
            };
            let call = call(face, &setup);
            let args = argv(&call, &option, position);
            let result = run_guarded(&args, call.stdin.as_deref()).and_then(|out| {
                let cell = Cell { args: args.clone() };
                if takes_effect {
                    check(face, &out, &cell)
                } else {
                    refused(&out, &option[0])
                }
                .map_err(|why| {
                    format!(
                        "{why}\n    exit {:?}\n    stdout: {}\n    stderr: {}",
                        out.status.code(),
                        stdout(&out).trim_end(),
                        stderr(&out).trim_end()
                    )
                })
            });
            if let Err(why) = result {
                failures.push(format!(
                    "{face:?} {position:?}: tmclsh {}\n    {why}",
                    args.join(" ")
                ));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cells failed for {}:\n{}",
        failures.len(),
        FACES.len() * 2,
        option[0],
        failures.join("\n")
    );
}

fn no_special(_: Face, _: Position) -> Option<Result<(), String>> {
    None
}

fn refused(out: &Output, flag: &str) -> Result<(), String> {
    if code(out) != 2 {
        return Err(format!("expected refusal (exit 2) naming {flag}"));
    }
    if !stderr(out).contains(flag) {
        return Err(format!("the refusal does not name {flag}"));
    }
    Ok(())
}

fn expect(ok: bool, why: impl FnOnce() -> String) -> Result<(), String> {
    if ok { Ok(()) } else { Err(why()) }
}

fn exit(out: &Output, expected: i32) -> Result<(), String> {
    expect(code(out) == expected, || {
        format!("expected exit {expected}")
    })
}

/// Exit 0, or 1 for a diff against a module whose state other cells changed.
fn finished(face: Face, out: &Output) -> Result<(), String> {
    let ok = code(out) == 0 || (face == SnapshotDiff && code(out) == 1);
    expect(ok, || "expected the command to finish (exit 0)".into())
}

fn says(out: &Output, text: &str) -> Result<(), String> {
    expect(stderr(out).contains(text), || {
        format!("stderr does not say {text:?}")
    })
}

fn not_builtin(out: &Output) -> Result<(), String> {
    expect(!stderr(out).contains("built-in"), || {
        "served by the built-in simulator".into()
    })
}

/// The value of the option written last in the cell's command line.
fn value_of<'a>(cell: &'a Cell, flag: &str) -> &'a str {
    let at = cell.args.iter().rposition(|a| a == flag).unwrap();
    &cell.args[at + 1]
}

fn read(path: &str) -> String {
    std::fs::read_to_string(path).unwrap_or_default()
}

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
                says(out, "--modules applies to the simulated TMCM-142")
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
        &[
            ShellC,
            ShellStdin,
            Run,
            Download,
            SnapshotSave,
            SnapshotDiff,
            SnapshotRestore,
        ],
        &|_| Setup::tmcl().with(&["--timeout", "30"]),
        &|_, out, _| {
            exit(out, 3)?;
            says(out, "module B")
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
        &[
            ShellC,
            ShellStdin,
            Run,
            Download,
            SnapshotSave,
            SnapshotDiff,
            SnapshotRestore,
        ],
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
    let faces = [
        ShellC,
        ShellStdin,
        Run,
        Download,
        SnapshotSave,
        SnapshotDiff,
        SnapshotRestore,
    ];
    // What the transcript says last about module A: found or entered ASCII mode, or left it.
    let left_ascii = |log: &str| {
        read(log)
            .lines()
            .rfind(|l| l.contains("-- module A "))
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
fn address() {
    table(
        &["--address", "1"],
        &[
            ShellC,
            ShellStdin,
            Run,
            SnapshotSave,
            SnapshotDiff,
            SnapshotRestore,
        ],
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
    let whole = run(&["--protocol", "smd4", "-c", "COMS:NET:IPCONF"]);
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

/// Runs `tmclsh ARGS` with `vars` set.
fn run_env(args: &[&str], vars: &[(&str, &str)]) -> Output {
    Command::new(bin())
        .args(args)
        .envs(vars.iter().copied())
        .stdin(Stdio::null())
        .env("NO_COLOR", "1")
        .output()
        .expect("tmclsh runs")
}

#[test]
fn the_environment_gives_a_port_to_every_face_and_the_command_line_overrides_it() {
    let env = "/nonexistent/tmclsh-options/from-env";
    let given = "/nonexistent/tmclsh-options/given";
    let vars = [("TMCLSH_PORT", env)];
    for args in [
        &["-c", "GAP 1, 0"][..],
        &["snapshot", "save", &fresh("env.toml")],
        &["scan", "--addresses", "1"],
        &["download", s(&fixtures().program)],
    ] {
        let out = run_env(args, &vars);
        assert_eq!(code(&out), 3, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(env), "{args:?}: {}", stderr(&out));
        let mut before = vec!["--port", given];
        before.extend_from_slice(args);
        let mut after = args.to_vec();
        after.extend_from_slice(&["--port", given]);
        for line in [before, after] {
            let out = run_env(&line, &vars);
            assert_eq!(code(&out), 3, "{line:?}: {}", stderr(&out));
            assert!(stderr(&out).contains(given), "{line:?}: {}", stderr(&out));
        }
    }
    // --tcp on the command line wins over the port of the environment.
    let closed = {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        listener.local_addr().unwrap().to_string()
    };
    let out = run_env(&["--tcp", &closed, "-c", "GAP 1, 0"], &vars);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(stderr(&out).contains(&closed), "{}", stderr(&out));
    // A rate from the environment bothers nobody.
    let out = run_env(&["-c", "GAP 1, 0"], &[("TMCLSH_BAUD", "19200")]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn an_option_given_before_and_after_the_subcommand_is_refused() {
    let script = fresh("noop.rhai");
    std::fs::write(&script, "let x = 1;\n").unwrap();
    for args in [
        &["--port", "/dev/a", "run", &script, "--port", "/dev/b"][..],
        &[
            "--timeout",
            "10",
            "snapshot",
            "save",
            "x.toml",
            "--timeout",
            "20",
        ],
        &["--port", "/dev/a", "scan", "--tcp", "127.0.0.1:1"],
        &["--port", "/dev/a", "--tcp", "127.0.0.1:1", "-c", "GAP 1, 0"],
    ] {
        let out = run(args);
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains("--"), "{args:?}: {}", stderr(&out));
    }
}

#[test]
fn options_of_the_other_dialect_or_link_are_refused() {
    let profile = fresh("profile.toml");
    std::fs::copy(repo().join("data/tmcm142.toml"), &profile).unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["--protocol", "smd4", "--module", "2", "-c", "SYS:FW"],
            "--module",
        ),
        (
            &["--protocol", "smd4", "--no-enter", "-c", "SYS:FW"],
            "--no-enter",
        ),
        (
            &["--protocol", "smd4", "run", "x.rhai", "--stay-ascii"],
            "--stay-ascii",
        ),
        (
            &["--protocol", "smd4", "--profile", &profile, "-c", "SYS:FW"],
            "--profile",
        ),
        (
            &["sim", "--protocol", "smd4", "--profile", &profile],
            "--profile",
        ),
        (&["--address", "3", "-c", "GAP 1, 0"], "--address"),
        (
            &["snapshot", "save", "x.toml", "--quiet-gap", "50"],
            "--quiet-gap",
        ),
        (&["--baud", "19200", "-c", "GAP 1, 0"], "--baud"),
        (
            &["--tcp", "127.0.0.1:1", "--baud", "19200", "-c", "GAP 1, 0"],
            "--baud",
        ),
        (&["--profile", &profile, "ports"], "--profile"),
        (&["completions", "bash", "--profile", &profile], "--profile"),
        (&["--baud", "9600", "sim"], "--baud"),
    ];
    for (args, flag) in cases {
        let out = run_guarded(&strings(args), None).unwrap();
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(flag), "{args:?}: {}", stderr(&out));
    }
}

#[test]
fn every_batch_face_on_the_built_in_simulator_says_so_once() {
    let fx = fixtures();
    let script = fresh("once.rhai");
    std::fs::write(&script, "send(\"GAP 1, 0\");\n").unwrap();
    let tmcl = |args: &[&str]| (run(args), "TMCM-142");
    let smd4 = |args: &[&str]| {
        let mut all = vec!["--protocol", "smd4"];
        all.extend_from_slice(args);
        (run(&all), "SMD4")
    };
    for (out, module) in [
        tmcl(&["-c", "GAP 1, 0"]),
        (run_with_stdin(&[], "GAP 1, 0\n"), "TMCM-142"),
        tmcl(&["run", &script]),
        tmcl(&["download", s(&fx.program)]),
        tmcl(&["snapshot", "save", &fresh("once.toml")]),
        tmcl(&["snapshot", "diff", s(&fx.tmcl_snapshot)]),
        tmcl(&["scan", "--addresses", "1"]),
        smd4(&["-c", "SYS:FW"]),
        smd4(&["snapshot", "save", &fresh("once-smd4.toml")]),
        smd4(&["scan", "--addresses", "1"]),
    ] {
        let notice =
            format!("using the built-in simulated {module}; give --port or --tcp for hardware");
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        assert_eq!(stderr(&out).matches(&notice).count(), 1, "{}", stderr(&out));
    }
    let out = run(&["params"]);
    assert!(!stderr(&out).contains("built-in"), "{}", stderr(&out));
}

#[test]
fn the_smd4_params_table_is_the_shells() {
    let cli = run(&["--protocol", "smd4", "params", "motor:v"]);
    let shell = run(&["--protocol", "smd4", "-c", ":params MOTOR:V"]);
    assert_eq!(code(&cli), 0, "{}", stderr(&cli));
    assert!(stdout(&cli).contains("MOTOR:VMAX"), "{}", stdout(&cli));
    assert_eq!(stdout(&cli), stdout(&shell));
    let out = run(&["params", "--protocol", "smd4", "NOTHING_LIKE_IT"]);
    assert_eq!(code(&out), 0);
    assert!(stderr(&out).contains("no SMD4 command matches 'NOTHING_LIKE_IT'"));
}
