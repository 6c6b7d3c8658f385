//! `:watch` in the real REPL on a pseudo-terminal: it redraws until a key, gives the prompt back
//! with the terminal restored, and Ctrl-C stops the motor.

use std::fs::File;
use std::io::{Read, Write};
use std::os::fd::{AsFd, OwnedFd};
use std::process::{Child, Command, Stdio};
use std::time::Instant;

use nix::poll::{PollFd, PollFlags, PollTimeout, poll};
use nix::sys::termios::{LocalFlags, tcgetattr};

use crate::sim::{PATIENCE, Sim};
use crate::util::{bin, tempdir};

/// `tmclsh` running on the slave side of a pseudo-terminal.
pub(super) struct Terminal {
    master: File,
    child: Child,
    seen: String,
    /// Output before this has been matched by [`Terminal::until`].
    cursor: usize,
    /// Cursor-position queries answered so far.
    answered: usize,
}

impl Terminal {
    pub(super) fn spawn(args: &[&str]) -> Terminal {
        Terminal::spawn_sized(args, None)
    }

    /// As [`Terminal::spawn`], on a terminal `columns` wide.
    pub(super) fn spawn_sized(args: &[&str], columns: Option<u16>) -> Terminal {
        let size = columns.map(|ws_col| nix::pty::Winsize {
            ws_row: 24,
            ws_col,
            ws_xpixel: 0,
            ws_ypixel: 0,
        });
        let pty = nix::pty::openpty(size.as_ref(), None).expect("a pseudo-terminal");
        // The master stays ours: tmclsh holding it too would never see the terminal go away.
        nix::fcntl::fcntl(
            &pty.master,
            nix::fcntl::FcntlArg::F_SETFD(nix::fcntl::FdFlag::FD_CLOEXEC),
        )
        .expect("close-on-exec");
        let slave: OwnedFd = pty.slave;
        let home = tempdir();
        let child = Command::new(bin())
            .args(args)
            .stdin(Stdio::from(slave.try_clone().unwrap()))
            .stdout(Stdio::from(slave.try_clone().unwrap()))
            .stderr(Stdio::from(slave))
            .env("TERM", "xterm")
            .env("HOME", &home)
            .env("XDG_DATA_HOME", &home)
            .env("NO_COLOR", "1")
            .spawn()
            .expect("tmclsh starts");
        Terminal {
            master: File::from(pty.master),
            child,
            seen: String::new(),
            cursor: 0,
            answered: 0,
        }
    }

    pub(super) fn send(&mut self, text: &str) {
        self.master.write_all(text.as_bytes()).unwrap();
        self.master.flush().unwrap();
    }

    /// Reads until the output after the last match contains `needle` (answering cursor-position
    /// queries as a terminal would); returns the output up to and including it. Output read
    /// beyond the match stays for the next call, so a prompt that arrived in the same read as
    /// the previous needle is still found.
    pub(super) fn until(&mut self, needle: &str) -> String {
        let deadline = Instant::now() + PATIENCE;
        let start = self.cursor;
        while !self.seen[start..].contains(needle) {
            assert!(
                Instant::now() < deadline,
                "waited for {needle:?}; the terminal shows {:?}",
                &self.seen[start..]
            );
            let mut fds = [PollFd::new(self.master.as_fd(), PollFlags::POLLIN)];
            if poll(&mut fds, PollTimeout::from(50u16)).unwrap() == 0 {
                continue;
            }
            let mut buf = [0u8; 4096];
            // EIO means the child closed the terminal.
            let n: usize = self.master.read(&mut buf).unwrap_or_default();
            assert!(
                n > 0,
                "tmclsh closed the terminal; it showed {:?}",
                &self.seen[start..]
            );
            self.seen.push_str(&String::from_utf8_lossy(&buf[..n]));
            // Counted over everything seen: a query may arrive split over two reads.
            let queries = self.seen.matches("\x1b[6n").count();
            for _ in self.answered..queries {
                self.send("\x1b[1;1R");
            }
            self.answered = queries;
        }
        let end = start + self.seen[start..].find(needle).expect("found above") + needle.len();
        self.cursor = end;
        self.seen[start..end].to_string()
    }

    /// Waits for the exit code.
    pub(super) fn exit_code(&mut self) -> i32 {
        let deadline = Instant::now() + PATIENCE;
        loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                return status.code().expect("exited normally");
            }
            assert!(Instant::now() < deadline, "tmclsh did not exit");
            // Keep the terminal drained so the child never blocks on a full buffer.
            let mut fds = [PollFd::new(self.master.as_fd(), PollFlags::POLLIN)];
            if poll(&mut fds, PollTimeout::from(50u16)).unwrap_or(0) > 0 {
                let mut buf = [0u8; 4096];
                let _ = self.master.read(&mut buf);
            }
        }
    }

    /// Closes the terminal's master side, as a terminal emulator that goes away does (no SIGHUP:
    /// tmclsh is not the session leader here); its reads then fail.
    pub(super) fn hang_up(&mut self) {
        self.master = File::open("/dev/null").unwrap();
    }

    /// Sends `signal` to tmclsh, by its process id.
    pub(super) fn signal(&self, signal: nix::sys::signal::Signal) {
        let pid = nix::unistd::Pid::from_raw(self.child.id() as i32);
        nix::sys::signal::kill(pid, signal).expect("the signal is delivered");
    }

    /// Whether the terminal is back in line mode with echo (not left raw).
    pub(super) fn cooked(&self) -> bool {
        let modes = tcgetattr(self.master.as_fd()).unwrap();
        modes
            .local_flags
            .contains(LocalFlags::ICANON | LocalFlags::ECHO)
    }
}

impl Drop for Terminal {
    fn drop(&mut self) {
        // Our own child, by its handle.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

#[test]
fn watch_redraws_until_a_key_and_restores_the_terminal() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    let mut term = Terminal::spawn(&["--tcp", &sim.first]);
    term.until("A> ");
    term.send(":watch actual_position,max_current 50ms\r");
    let first = term.until("any key stops");
    assert!(first.contains("actual_position"), "{first}");
    let redrawn = term.until("any key stops");
    let redrawn = redrawn + term.until("max_current").as_str();
    assert!(redrawn.contains("\x1b["), "redrawn in place: {redrawn:?}");
    assert!(redrawn.contains("any key stops"));
    term.send("q");
    term.until("A> ");
    term.send("GAP max_current, 0\r");
    term.until("max_current = 8\r");
    term.send(":quit\r");
    assert_eq!(term.exit_code(), 0);
    assert!(term.cooked(), "the terminal is back in line mode with echo");
}

#[test]
fn on_a_narrow_terminal_each_frame_moves_up_over_exactly_the_rows_it_drew() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    let mut term = Terminal::spawn_sized(&["--tcp", &sim.first], Some(60));
    term.until("A> ");
    term.send(":watch actual_position,max_positioning_speed 50ms\r");
    // Every frame starts with a clear-down (CSI J); four of them bound three whole frames.
    let mut shown = String::new();
    for _ in 0..4 {
        shown += &term.until("\x1b[J");
    }
    term.send("q");
    term.until("A> ");
    let frames: Vec<&str> = shown.split("\x1b[J").skip(1).collect();
    for frame in &frames[..frames.len() - 1] {
        // A frame's rows, then the next frame's move up over them (CSI n F).
        let (rows, next) = frame.split_once("\x1b[").expect("the next frame moves up");
        let up: usize = next
            .split_once('F')
            .and_then(|(n, _)| n.parse().ok())
            .unwrap_or_else(|| panic!("a move up in {next:?}"));
        let rows: Vec<&str> = rows.split("\r\n").collect();
        assert_eq!(
            up,
            rows.len() - 1,
            "moved up over the rows drawn: {frame:?}"
        );
        for row in rows {
            assert!(
                row.chars().count() <= 60,
                "wider than the terminal: {row:?}"
            );
        }
    }
    term.send(":quit\r");
    assert_eq!(term.exit_code(), 0);
}

/// Text as a terminal shows it: control sequences (CSI … letter) taken out.
fn visible(text: &str) -> String {
    let mut out = String::new();
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        if c == '\x1b' {
            if chars.next() == Some('[') {
                for c in chars.by_ref() {
                    if c.is_ascii_alphabetic() || c == '~' {
                        break;
                    }
                }
            }
            continue;
        }
        out.push(c);
    }
    out
}

#[test]
fn tables_and_help_fit_a_narrow_terminal() {
    let mut term = Terminal::spawn_sized(&[], Some(60));
    term.until("A> ");
    for (command, last) in [
        (":params max\r", "max_encoder_deviation"),
        (":help\r", "More:"),
        (":help MVP\r", "usable in"),
        (":help ascii_mode\r", "echo:"),
        (":help io\r", "sources."),
        (":help GIO\r", "table."),
    ] {
        term.send(command);
        let shown = term.until(last) + term.until("A> ").as_str();
        let shown = visible(&shown);
        for line in shown.split(['\r', '\n']) {
            assert!(line.chars().count() <= 60, "{command:?}: {line:?}");
        }
        // Nothing was cut: a continuation line starts under its column.
        assert!(shown.contains(last), "{shown}");
    }
    term.send(":quit\r");
    assert_eq!(term.exit_code(), 0);
}

#[test]
fn ctrl_c_in_a_watch_stops_the_motor() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    let mut term = Terminal::spawn(&["--tcp", &sim.first]);
    term.until("A> ");
    term.send("ROR 0, 50000\r");
    term.until("ok, value 50000");
    term.send(":watch actual_speed\r");
    term.until("any key stops");
    term.send("\x03");
    term.until("stopped motor 0");
    term.send("GAP target_speed, 0\r");
    term.until("target_speed = 0 ");
    term.send(":quit\r");
    assert_eq!(term.exit_code(), 0);
    assert!(term.cooked());
}

#[test]
fn watch_without_a_terminal_points_to_record() {
    let out = super::expect(&["--sim", "-c", ":watch actual_position"], 2);
    assert!(crate::util::stderr(&out).contains(":watch needs a terminal"));
}
