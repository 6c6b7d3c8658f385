//! A link lost under the REPL, at the prompt or during a line: said at once, the port closed,
//! waited for with growing pauses (Ctrl-C stops waiting), found again by the name given, the
//! modules put back in their mode and asked again what they are, and "reconnected" said. Lines
//! typed meanwhile wait in the terminal; they are shown, and sent only after a yes: a motion
//! typed into a dead link must not start by itself when the link comes back.

use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};

use crate::escape::escape_control;
use crate::session::interrupt;
use crate::session::relink::Backoff;
use crate::shell::Shell;

/// The most typed input gathered from the terminal after an outage.
const MOST_TYPED: usize = 64 * 1024;

/// Set while the link is known to be away (a wait was given up with Ctrl-C): a line that fails
/// then was never sent.
static AWAY: AtomicBool = AtomicBool::new(false);

/// The link was lost (`why`); `cut_short` is the line that was under way, if one was.
pub(super) fn lost(
    shell: &mut Shell,
    why: &str,
    cut_short: Option<&str>,
    color: bool,
    out: &mut dyn Write,
) {
    let _ = writeln!(out, "link lost: {}", escape_control(why));
    if cut_short.is_none() {
        shell
            .session()
            .annotate(&format!("link lost while idle at the prompt: {why}"));
    }
    shell.session().lose_link(why);
    match cut_short {
        Some(line) if AWAY.load(Ordering::SeqCst) => {
            let _ = writeln!(
                out,
                "`{}` was not sent: the link is still away",
                escape_control(line)
            );
        }
        Some(line) => {
            let _ = writeln!(
                out,
                "`{}` was cut short: whether the module got it is unknown; it is not sent again",
                escape_control(line)
            );
            shell
                .session()
                .annotate(&format!("cut short by the lost link: {line}"));
        }
        None => {}
    }
    if wait(shell, color, out) {
        typed_meanwhile(shell, color, out);
    }
}

/// Waits until the link is back (true) or Ctrl-C (false).
fn wait(shell: &mut Shell, color: bool, out: &mut dyn Write) -> bool {
    let describe = shell.session().describe();
    let _ = writeln!(
        out,
        "waiting for {} to come back (Ctrl-C to stop waiting)…",
        escape_control(&describe)
    );
    shell
        .session()
        .annotate("waiting for the link to come back (Ctrl-C stops waiting)");
    let mut backoff = Backoff::default();
    loop {
        if interrupt::take() {
            let _ = writeln!(
                out,
                "stopped waiting; the next line is not sent but starts the wait again"
            );
            shell
                .session()
                .annotate("stopped waiting for the link (Ctrl-C)");
            AWAY.store(true, Ordering::SeqCst);
            return false;
        }
        if shell.session().reconnect().is_ok() {
            AWAY.store(false, Ordering::SeqCst);
            super::show_notices(shell, color, out);
            let _ = writeln!(
                out,
                "reconnected: {}",
                escape_control(&shell.session().describe())
            );
            return true;
        }
        // Anything said by a try that failed is stale once the next one runs.
        let _ = shell.session().take_notices();
        let _ = backoff.pause(None);
    }
}

/// Shows the lines typed while the link was away and sends them only after a yes.
fn typed_meanwhile(shell: &mut Shell, color: bool, out: &mut dyn Write) {
    let lines = pending_lines();
    if lines.is_empty() {
        return;
    }
    let _ = writeln!(out, "typed while the link was away (not sent):");
    for line in &lines {
        let _ = writeln!(out, "  {}", escape_control(line));
    }
    let _ = write!(out, "send them now? [y/N] ");
    let _ = out.flush();
    let mut answer = String::new();
    let _ = std::io::stdin().read_line(&mut answer);
    // Ctrl-C while asked is a no.
    let interrupted = interrupt::take();
    let yes = !interrupted && matches!(answer.trim().to_lowercase().as_str(), "y" | "yes");
    for line in &lines {
        let what = if yes { "sent after a yes" } else { "not sent" };
        shell
            .session()
            .annotate(&format!("typed while the link was away, {what}: {line}"));
    }
    if !yes {
        let _ = writeln!(out, "not sent");
        return;
    }
    for line in &lines {
        if super::handle(shell, line, color, out) == crate::shell::Flow::Quit {
            break;
        }
    }
}

/// The complete lines waiting in the terminal (typed and ended with Enter while nobody read).
#[cfg(unix)]
fn pending_lines() -> Vec<String> {
    use std::os::fd::AsFd;

    use nix::poll::{PollFd, PollFlags, PollTimeout, poll};

    let stdin = std::io::stdin();
    let mut bytes = Vec::new();
    while bytes.len() < MOST_TYPED {
        let mut fds = [PollFd::new(stdin.as_fd(), PollFlags::POLLIN)];
        let ready = matches!(poll(&mut fds, PollTimeout::ZERO), Ok(n) if n > 0)
            && fds[0]
                .revents()
                .is_some_and(|r| r.contains(PollFlags::POLLIN));
        if !ready {
            break;
        }
        let mut buf = [0u8; 4096];
        match nix::unistd::read(stdin.as_fd(), &mut buf) {
            Ok(0) | Err(_) => break,
            Ok(n) => bytes.extend_from_slice(&buf[..n]),
        }
    }
    String::from_utf8_lossy(&bytes)
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .map(String::from)
        .collect()
}

/// Without poll(2) the terminal is not looked at: typed lines reach the prompt as they are.
#[cfg(not(unix))]
fn pending_lines() -> Vec<String> {
    let _ = MOST_TYPED;
    Vec::new()
}
