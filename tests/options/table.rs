//! The harness of the option table: the faces of tmclsh, how each is run with an option before
//! or after its subcommand, and the loop over every face and both positions.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::OnceLock;
use std::sync::mpsc::channel;

use crate::sim::{PATIENCE, Sim};
use crate::util::{bin, code, repo, run, stderr, stdout, tempdir};

/// The faces of tmclsh: the shell and every subcommand form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Face {
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

pub(super) use Face::*;

pub(super) const FACES: [Face; 16] = [
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
pub(super) const SESSIONS: [Face; 8] = [
    ShellC,
    ShellStdin,
    Run,
    Download,
    SnapshotSave,
    SnapshotDiff,
    SnapshotRestore,
    Scan,
];

/// The faces that talk to one TMCL module (every session but the scan).
pub(super) const ONE_MODULE: [Face; 7] = [
    ShellC,
    ShellStdin,
    Run,
    Download,
    SnapshotSave,
    SnapshotDiff,
    SnapshotRestore,
];

/// The faces that talk to one SMD4 drive (no program to download).
pub(super) const ONE_DRIVE: [Face; 6] = [
    ShellC,
    ShellStdin,
    Run,
    SnapshotSave,
    SnapshotDiff,
    SnapshotRestore,
];

/// Where the option under test is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Position {
    /// Before the subcommand (for the shell: before `-c LINE`).
    Before,
    /// After the subcommand and its arguments.
    After,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Dialect {
    Tmcl,
    Smd4,
}

/// Files the faces work on, made once.
pub(super) struct Fixtures {
    pub(super) dir: PathBuf,
    pub(super) tmcl_snapshot: PathBuf,
    pub(super) smd4_snapshot: PathBuf,
    /// A TMCL snapshot whose max_current (99) is out of range.
    pub(super) bad_snapshot: PathBuf,
    pub(super) program: PathBuf,
    pub(super) binary: PathBuf,
    pub(super) transcript: PathBuf,
}

pub(super) fn fixtures() -> &'static Fixtures {
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
        made(run(&["--sim", "snapshot", "save", s(&fx.tmcl_snapshot)]));
        made(run(&["--sim", "--protocol",
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
        made(run(&["--sim", "--log", s(&fx.transcript), "-c", "GAP 1, 0"]));
        fx
    })
}

pub(super) fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// A fresh path for a file a cell writes.
pub(super) fn fresh(name: &str) -> String {
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
pub(super) struct Setup {
    pub(super) dialect: Dialect,
    /// The line the shell faces and scripts send.
    pub(super) line: String,
    /// Options written after everything else (the conditions that make the effect visible).
    pub(super) base: Vec<String>,
    /// The snapshot the snapshot faces read.
    pub(super) snapshot: Option<PathBuf>,
    /// Simulators serving this cell alone.
    pub(super) sims: Vec<Sim>,
    /// Environment variables the cell runs with (a made-up sysfs tree).
    pub(super) env: Vec<(String, String)>,
}

impl Setup {
    pub(super) fn tmcl() -> Setup {
        Setup {
            dialect: Dialect::Tmcl,
            line: "GAP 1, 0".into(),
            base: Vec::new(),
            snapshot: None,
            sims: Vec::new(),
            env: Vec::new(),
        }
    }

    pub(super) fn smd4() -> Setup {
        Setup {
            dialect: Dialect::Smd4,
            line: "SYS:FW".into(),
            base: strings(&["--protocol", "smd4"]),
            snapshot: None,
            sims: Vec::new(),
            env: Vec::new(),
        }
    }

    pub(super) fn line(mut self, line: &str) -> Setup {
        self.line = line.into();
        self
    }

    pub(super) fn with(mut self, base: &[&str]) -> Setup {
        self.base.extend(strings(base));
        self
    }

    pub(super) fn snapshot(&self) -> &Path {
        self.snapshot.as_deref().unwrap_or(match self.dialect {
            Dialect::Tmcl => &fixtures().tmcl_snapshot,
            Dialect::Smd4 => &fixtures().smd4_snapshot,
        })
    }
}

pub(super) fn strings(items: &[&str]) -> Vec<String> {
    items.iter().map(|x| x.to_string()).collect()
}

/// A command line split around the option under test, and its stdin.
pub(super) struct Call {
    pub(super) words: Vec<String>,
    pub(super) rest: Vec<String>,
    pub(super) stdin: Option<String>,
    pub(super) env: Vec<(String, String)>,
    /// Whether the face talks to a module (and so needs a link: `--sim` when none is given).
    pub(super) talks: bool,
}

pub(super) fn call(face: Face, setup: &Setup) -> Call {
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
    let talks = matches!(
        face,
        ShellC | ShellStdin | Run | Download | SnapshotSave | SnapshotDiff | SnapshotRestore | Scan
    );
    Call {
        words: strings(words),
        rest,
        stdin,
        env: setup.env.clone(),
        talks,
    }
}

/// The whole command line with `option` at `position`.
pub(super) fn argv(call: &Call, option: &[String], position: Position) -> Vec<String> {
    let mut all = Vec::new();
    let links = ["--port", "--tcp", "--sim"];
    let linked = option.iter().chain(&call.rest).any(|w| {
        links
            .iter()
            .any(|l| w == l || w.starts_with(&format!("{l}=")))
    }) || call
        .env
        .iter()
        .any(|(name, _)| name == "TMCLSH_PORT" || name == "TMCLSH_TCP");
    if call.talks && !linked {
        // The built-in simulator, as every command run without a terminal must say.
        all.push("--sim".to_string());
    }
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
pub(super) fn run_guarded(args: &[String], stdin: Option<&str>) -> Result<Output, String> {
    run_guarded_env(args, stdin, &[])
}

/// [`run_guarded`] with environment variables set.
pub(super) fn run_guarded_env(
    args: &[String],
    stdin: Option<&str>,
    env: &[(String, String)],
) -> Result<Output, String> {
    let mut child = Command::new(bin())
        .args(args)
        .envs(env.iter().map(|(k, v)| (k, v)))
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
pub(super) type Check<'a> = &'a dyn Fn(Face, &Output, &Cell) -> Result<(), String>;

/// One run: the command line and the files it was told to write.
pub(super) struct Cell {
    pub(super) args: Vec<String>,
}

/// The table for one option: for every face and both positions, runs tmclsh and checks that the
/// option took effect (on the faces in `effect`, set up by `setup`) or was refused with exit code
/// 2 naming it (everywhere else). Panics with every failed cell.
pub(super) fn table(
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
            let result = run_guarded_env(&args, call.stdin.as_deref(), &call.env).and_then(|out| {
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

pub(super) fn no_special(_: Face, _: Position) -> Option<Result<(), String>> {
    None
}

pub(super) fn refused(out: &Output, flag: &str) -> Result<(), String> {
    if code(out) != 2 {
        return Err(format!("expected refusal (exit 2) naming {flag}"));
    }
    if !stderr(out).contains(flag) {
        return Err(format!("the refusal does not name {flag}"));
    }
    Ok(())
}

pub(super) fn expect(ok: bool, why: impl FnOnce() -> String) -> Result<(), String> {
    if ok { Ok(()) } else { Err(why()) }
}

pub(super) fn exit(out: &Output, expected: i32) -> Result<(), String> {
    expect(code(out) == expected, || {
        format!("expected exit {expected}")
    })
}

/// Exit 0, or 1 for a diff against a module whose state other cells changed.
pub(super) fn finished(face: Face, out: &Output) -> Result<(), String> {
    let ok = code(out) == 0 || (face == SnapshotDiff && code(out) == 1);
    expect(ok, || "expected the command to finish (exit 0)".into())
}

pub(super) fn says(out: &Output, text: &str) -> Result<(), String> {
    expect(stderr(out).contains(text), || {
        format!("stderr does not say {text:?}")
    })
}

pub(super) fn not_builtin(out: &Output) -> Result<(), String> {
    expect(!stderr(out).contains("built-in"), || {
        "served by the built-in simulator".into()
    })
}

/// The value of the option written last in the cell's command line.
pub(super) fn value_of<'a>(cell: &'a Cell, flag: &str) -> &'a str {
    let at = cell.args.iter().rposition(|a| a == flag).unwrap();
    &cell.args[at + 1]
}

pub(super) fn read(path: &str) -> String {
    std::fs::read_to_string(path).unwrap_or_default()
}
