//! The REPL itself, on a pseudo-terminal as a user has it, against a served drive with quirks:
//! replies decoded (values, user/real pairs, flag names, error meanings), `:flags`, a refused
//! line, and the prompt after each. Output is read until the expected text appears, with a
//! deadline.

use std::fs::File;
use std::io::{Read, Write};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::time::Instant;

use tmclsh::dialect::smd4::protocol::ErrorCode;

use super::{Drive, Via};
use crate::sim::PATIENCE;
use crate::util::{bin, tempdir};

/// `tmclsh` with its stdin, stdout and stderr on a new pseudo-terminal.
struct Terminal {
    child: Child,
    master: File,
    bytes: Receiver<Vec<u8>>,
    seen: String,
}

impl Terminal {
    fn start(args: &[String]) -> Terminal {
        let pair = nix::pty::openpty(None, None).expect("a pseudo-terminal");
        let slave = pair.slave;
        let home = tempdir();
        let child = Command::new(bin())
            .args(args)
            .env("NO_COLOR", "1")
            .env("TERM", "xterm")
            .env("HOME", &home)
            .env("XDG_DATA_HOME", home.join("data"))
            .stdin(Stdio::from(slave.try_clone().unwrap()))
            .stdout(Stdio::from(slave.try_clone().unwrap()))
            .stderr(Stdio::from(slave))
            .spawn()
            .expect("tmclsh runs");
        let master = File::from(pair.master);
        let mut reader = master.try_clone().unwrap();
        let (tx, bytes) = channel();
        std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            // Ends with an error (EIO) once the child has exited and closed its side.
            while let Ok(n) = reader.read(&mut buf) {
                if n == 0 || tx.send(buf[..n].to_vec()).is_err() {
                    break;
                }
            }
        });
        Terminal {
            child,
            master,
            bytes,
            seen: String::new(),
        }
    }

    /// Reads until `text` has appeared; returns everything up to and including it.
    fn expect(&mut self, text: &str) -> String {
        let deadline = Instant::now() + PATIENCE;
        loop {
            if let Some(i) = self.seen.find(text) {
                let rest = self.seen.split_off(i + text.len());
                return std::mem::replace(&mut self.seen, rest);
            }
            let left = deadline.saturating_duration_since(Instant::now());
            match self.bytes.recv_timeout(left) {
                Ok(bytes) => {
                    // A terminal answers a cursor position query; so do we.
                    if bytes.windows(4).any(|w| w == b"\x1b[6n") {
                        self.master.write_all(b"\x1b[1;1R").unwrap();
                    }
                    self.seen.push_str(&String::from_utf8_lossy(&bytes));
                }
                Err(_) => panic!(
                    "'{text}' did not appear; the terminal shows {:?}",
                    self.seen
                ),
            }
        }
    }

    /// Types a line and returns what the shell printed for it, up to the next prompt.
    fn enter(&mut self, line: &str) -> String {
        self.master.write_all(line.as_bytes()).unwrap();
        self.master.write_all(b"\r").unwrap();
        // The echo of the line ends where the shell's output starts.
        self.expect("\r\n");
        self.expect("smd4")
    }
}

impl Drop for Terminal {
    fn drop(&mut self) {
        // Our own child, by its id.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

#[test]
fn the_repl_decodes_replies_whatever_the_drive_s_spelling() {
    let mut drive = Drive::start(
        Via::Pty,
        &[
            "--float-missing-e",
            "--error-spelling",
            "bare",
            "--flag-case",
            "lower",
        ],
    );
    drive.console("limit pos 1");
    let mut terminal = Terminal::start(&drive.connection());
    terminal.expect("smd4> ");

    let shown = terminal.enter("MOTOR:VMAX,2000");
    assert!(
        shown.contains("2000 Hz requested, 2000 Hz real"),
        "{shown:?}"
    );
    assert!(
        shown.contains("[Limit Positive, External Enable, Standby, Boost Operational]"),
        "{shown:?}"
    );
    let shown = terminal.enter("MOTOR:IR,0.5");
    assert!(shown.contains("0.50516 A rms"), "{shown:?}");
    let shown = terminal.enter("SYS:MODE");
    assert!(shown.contains("1 (Remote)"), "{shown:?}");

    let shown = terminal.enter("MOTOR:RUNV,+");
    assert!(
        shown.contains("ok [Limit Positive, External Enable,"),
        "{shown:?}"
    );
    let shown = terminal.enter("MOTOR:RES,16");
    let stop = ErrorCode::StopMotorFirst;
    let decoded = format!(
        "error {} ({}): {}",
        stop.code(),
        stop.name(),
        stop.meaning()
    );
    assert!(shown.contains(&decoded), "{shown:?}");

    let shown = terminal.enter("MOTOR:ESTOP");
    assert!(shown.contains("errors: Emergency Stop"), "{shown:?}");
    let shown = terminal.enter(":flags");
    assert!(shown.contains("EFLAGS 0x0020"), "{shown:?}");
    assert!(shown.contains("[X]  5 Emergency Stop"), "{shown:?}");
    assert!(shown.contains("[X]  2 Limit Positive"), "{shown:?}");

    let shown = terminal.enter("MOTOR:RES,7");
    assert!(
        shown.contains("error: 7 is not accepted by MOTOR:RES"),
        "{shown:?}"
    );
    let shown = terminal.enter(":help addressing");
    assert!(shown.contains("addressing mode"), "{shown:?}");

    terminal.master.write_all(b":quit\r").unwrap();
    // The terminal reports end of file once the shell has exited and closed its side.
    let deadline = Instant::now() + PATIENCE;
    loop {
        let left = deadline.saturating_duration_since(Instant::now());
        match terminal.bytes.recv_timeout(left) {
            Ok(_) => {}
            Err(RecvTimeoutError::Disconnected) => break,
            Err(RecvTimeoutError::Timeout) => panic!("the REPL did not quit"),
        }
    }
    assert!(terminal.child.wait().unwrap().success());
}
