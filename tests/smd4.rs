//! The SMD4 dialect end to end: the real `tmclsh` (shell, `-c`, stdin, `run`) against
//! `tmclsh sim --protocol smd4`, over its pseudo-terminal and over loopback TCP, steered through
//! the simulator's console. Expected replies come from the simulator's documented behaviour (data
//! in `data/smd4.toml`), read through the library where the value is computed, never typed in
//! as the answer to compare with.

mod addressing;
mod console;
#[cfg(unix)]
mod flags;
mod lines;
mod motion;
mod multiline;
mod quirks;
#[cfg(unix)]
mod repl;
mod scripts;

use std::io::Write;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::Instant;

use crate::sim::{PATIENCE, Sim};
use crate::util::bin;

/// How the client reaches the simulated drive.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Via {
    /// Its pseudo-terminal, as a serial port (`--port`).
    Pty,
    /// Loopback TCP (`--tcp`).
    Tcp,
}

/// Both ways, for tests that must hold on either.
pub const BOTH: [Via; 2] = [Via::Pty, Via::Tcp];

/// A running `tmclsh sim --protocol smd4` and how to reach it.
pub struct Drive {
    /// The simulator process.
    pub sim: Sim,
    via: Via,
}

impl Drive {
    /// Starts a simulated SMD4 served `via` the pty or TCP, with extra simulator flags.
    pub fn start(via: Via, extra: &[&str]) -> Drive {
        Drive::spawn(via, extra, false)
    }

    /// Like [`Drive::start`] with `--verbose`, keeping the traffic log for [`Drive::received`].
    pub fn logged(via: Via, extra: &[&str]) -> Drive {
        Drive::spawn(via, extra, true)
    }

    fn spawn(via: Via, extra: &[&str], verbose: bool) -> Drive {
        let mut args = vec!["--protocol", "smd4"];
        match via {
            Via::Pty => args.push("--pty"),
            Via::Tcp => args.extend(["--listen", "127.0.0.1:0"]),
        }
        if verbose {
            args.push("--verbose");
        }
        args.extend(extra);
        let sim = if verbose {
            Sim::start_capturing_stderr(&args)
        } else {
            Sim::start(&args)
        };
        Drive { sim, via }
    }

    /// The connection flags of a client.
    pub fn connection(&self) -> Vec<String> {
        let flag = match self.via {
            Via::Pty => "--port",
            Via::Tcp => "--tcp",
        };
        vec![
            "--protocol".into(),
            "smd4".into(),
            flag.into(),
            self.sim.first.clone(),
        ]
    }

    /// Runs `tmclsh CONNECTION ARGS` (the shell, non-interactive) to completion.
    pub fn run(&self, args: &[&str]) -> Output {
        self.run_with_stdin(args, "")
    }

    /// Runs `tmclsh CONNECTION ARGS` with `input` on its stdin.
    pub fn run_with_stdin(&self, args: &[&str], input: &str) -> Output {
        client(&self.connection(), args, input)
    }

    /// Runs `tmclsh run SCRIPT CONNECTION ARGS`.
    pub fn script(&self, script: &Path, args: &[&str]) -> Output {
        let mut all = vec!["run".to_string(), script.display().to_string()];
        all.extend(self.connection());
        let args: Vec<&str> = all
            .iter()
            .map(String::as_str)
            .chain(args.iter().copied())
            .collect();
        client(&[], &args, "")
    }

    /// Runs a console command that must succeed; returns the text after `ok`.
    pub fn console(&mut self, command: &str) -> String {
        let answer = self.sim.console(command);
        match answer.strip_prefix("ok") {
            Some(rest) => rest.trim().to_string(),
            None => panic!("console '{command}' answered {answer}"),
        }
    }

    /// Asks the console until `done` accepts the answer to `command` (a deadline, no sleeps).
    pub fn console_until(&mut self, command: &str, done: impl Fn(&str) -> bool) -> String {
        let deadline = Instant::now() + PATIENCE;
        loop {
            let answer = self.console(command);
            if done(&answer) {
                return answer;
            }
            assert!(
                Instant::now() < deadline,
                "console '{command}' still answers {answer}"
            );
        }
    }

    /// The simulator's motor as the console reports it.
    pub fn motor(&mut self) -> Motor {
        Motor::parse(&self.console("motor"))
    }

    /// Ends the simulator and returns the lines it received, in order (needs [`Drive::logged`]).
    pub fn received(self) -> Vec<String> {
        let log = self.sim.quit();
        log.lines()
            .filter_map(|l| l.split_once(" smd4 <- ").map(|(_, line)| line))
            .map(|quoted| quoted.trim_matches('"').to_string())
            .collect()
    }
}

/// Runs the real binary with `connection` then `args`, `input` on stdin.
pub fn client(connection: &[String], args: &[&str], input: &str) -> Output {
    let mut child = Command::new(bin())
        .args(connection)
        .args(args)
        .env("NO_COLOR", "1")
        .env_remove("TMCLSH_PORT")
        .env_remove("TMCLSH_PROTOCOL")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("tmclsh runs");
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(input.as_bytes()).unwrap();
    drop(stdin);
    child.wait_with_output().expect("tmclsh finishes")
}

/// The console's `motor` answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motor {
    pub position: f64,
    pub velocity: f64,
    pub standby: bool,
}

impl Motor {
    fn parse(text: &str) -> Motor {
        let words: Vec<&str> = text.split_whitespace().collect();
        let field = |name: &str| -> &str {
            let i = words
                .iter()
                .position(|w| *w == name)
                .unwrap_or_else(|| panic!("no {name} in '{text}'"));
            words[i + 1]
        };
        Motor {
            position: field("position").parse().unwrap(),
            velocity: field("velocity").parse().unwrap(),
            standby: field("standby") == "1",
        }
    }
}

/// stdout lines.
pub fn lines(output: &Output) -> Vec<String> {
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(String::from)
        .collect()
}

/// Asserts the exit code, showing stderr when it differs.
#[track_caller]
pub fn assert_exit(output: &Output, expected: i32) {
    assert_eq!(
        output.status.code(),
        Some(expected),
        "stdout: {}\nstderr: {}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
}

/// A client reading stdin as it arrives (`tmclsh CONNECTION ARGS < pipe`), so a test can act
/// between its lines: advance the simulation, press Ctrl-C.
pub struct Streaming {
    child: std::process::Child,
    stdin: Option<std::process::ChildStdin>,
    lines: std::sync::mpsc::Receiver<String>,
    stderr: std::sync::mpsc::Receiver<String>,
}

impl Streaming {
    /// Starts the shell on `drive` with `args`, stdin a pipe.
    pub fn start(drive: &Drive, args: &[&str]) -> Streaming {
        let mut all = drive.connection();
        all.extend(args.iter().map(|a| a.to_string()));
        Streaming::spawn(&all)
    }

    /// Starts `tmclsh run SCRIPT` on `drive`.
    pub fn script(drive: &Drive, script: &Path) -> Streaming {
        let mut all = vec!["run".to_string(), script.display().to_string()];
        all.extend(drive.connection());
        Streaming::spawn(&all)
    }

    fn spawn(args: &[String]) -> Streaming {
        use std::io::{BufRead, BufReader, Read};
        let mut child = Command::new(bin())
            .args(args)
            .env("NO_COLOR", "1")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("tmclsh runs");
        let stdout = child.stdout.take().unwrap();
        let mut stderr = child.stderr.take().unwrap();
        let (tx, lines) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let Ok(line) = line else { break };
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        let (tx, stderr_text) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = stderr.read_to_string(&mut text);
            let _ = tx.send(text);
        });
        Streaming {
            stdin: child.stdin.take(),
            child,
            lines,
            stderr: stderr_text,
        }
    }

    /// Types one line.
    pub fn send(&mut self, line: &str) {
        let stdin = self.stdin.as_mut().expect("stdin still open");
        writeln!(stdin, "{line}").unwrap();
        stdin.flush().unwrap();
    }

    /// The next stdout line.
    pub fn line(&mut self) -> String {
        self.lines
            .recv_timeout(PATIENCE)
            .expect("tmclsh printed a line in time")
    }

    /// Ctrl-C: SIGINT to this child, by its id.
    #[cfg(unix)]
    pub fn interrupt(&self) {
        use nix::sys::signal::{Signal, kill};
        use nix::unistd::Pid;
        kill(Pid::from_raw(self.child.id() as i32), Signal::SIGINT).expect("SIGINT delivered");
    }

    /// Closes stdin and waits for the exit; returns the exit code and stderr.
    pub fn finish(mut self) -> (i32, String) {
        drop(self.stdin.take());
        self.exit()
    }

    /// Waits for the exit with stdin still open (after Ctrl-C: the end of input must not be
    /// what ends the run); returns the exit code and stderr.
    pub fn exit(mut self) -> (i32, String) {
        // stderr closes when the process ends.
        let stderr = self
            .stderr
            .recv_timeout(PATIENCE)
            .expect("tmclsh exited in time");
        let status = self.child.wait().unwrap();
        (status.code().expect("exited normally"), stderr)
    }
}

impl Drop for Streaming {
    fn drop(&mut self) {
        // Our own child, by its id (a no-op once it has exited and been waited for).
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
