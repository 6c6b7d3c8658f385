//! The interactive shell: rustyline with history, completion, hints and highlighting; decoded,
//! coloured replies; Ctrl-C stops a command (and the motor) in flight, and at the idle prompt stops
//! the motors while something this session started may still move; SIGTERM and SIGHUP, at the
//! prompt or during a command, stop them and end the shell; a lost link is waited for and
//! reopened with history and settings intact.

pub mod complete;
pub mod editor;
mod history;
mod outage;
#[cfg(unix)]
mod watch;

use std::io::{IsTerminal, Write};

use crossterm::style::Stylize;
use rustyline::error::ReadlineError;
use rustyline::history::DefaultHistory;
use rustyline::{CompletionType, Config, Editor};

use crate::escape::escape_control;
use crate::exit::Exit;
use crate::session::{SessionError, interrupt};
use crate::shell::words::{Everyday, everyday, only_remark};
use crate::shell::{Flow, Shell};

use editor::ReplHelper;

/// Whether output may be coloured: a terminal, and NO_COLOR unset.
pub fn color_enabled() -> bool {
    std::env::var_os("NO_COLOR").is_none() && std::io::stdout().is_terminal()
}

/// Runs the REPL until `:quit` or Ctrl-D; the session is closed (modules restored) at the end.
pub fn run(shell: &mut Shell, banner: &str) -> Exit {
    let color = color_enabled();
    let config = Config::builder()
        .completion_type(CompletionType::List)
        // One Tab lists what an ambiguous word may become (`MOTOR:` and its commands).
        .completion_show_all_if_ambiguous(true)
        .auto_add_history(true)
        .history_ignore_space(true)
        .max_history_size(5000)
        .map(|b| b.build())
        .unwrap_or_default();
    let mut editor: Editor<ReplHelper, DefaultHistory> = match Editor::with_config(config) {
        Ok(editor) => editor,
        Err(e) => {
            eprintln!("tmclsh: cannot start the line editor: {e}");
            return Exit::Link;
        }
    };
    editor.set_helper(Some(ReplHelper::new(shell.session_ref().grammar(), color)));
    let dialect = shell.session_ref().dialect();
    history::load(&mut editor, dialect);
    let mut out = std::io::stdout();
    let _ = writeln!(out, "{banner}");
    let _ = writeln!(
        out,
        "Type :help for help, Tab to complete, Ctrl-D to leave."
    );
    // The REPL always waits for a lost link, asking before it sends what was typed meanwhile.
    shell.session().core_mut().options.reconnect = None;
    let mut exit = Exit::Success;
    loop {
        // SIGTERM or SIGHUP, during a command or at the prompt: the session ends here.
        if let Some(signal) = interrupt::terminated() {
            terminate(shell, signal.name());
            exit = Exit::Terminated(signal.number() as u8);
            break;
        }
        // What the last command changed (TMCL :bin) shows in completion and validation.
        if let Some(helper) = editor.helper_mut() {
            helper.grammar = shell.session_ref().grammar();
        }
        #[cfg(unix)]
        let watch = shell
            .session_ref()
            .watch_link()
            .and_then(watch::LinkWatch::start);
        let line = {
            let _prompting = interrupt::Prompting::start();
            editor.readline(&shell.prompt())
        };
        #[cfg(unix)]
        let lost = watch.as_ref().is_some_and(watch::LinkWatch::lost);
        #[cfg(not(unix))]
        let lost = false;
        #[cfg(unix)]
        drop(watch);
        if interrupt::terminated().is_some() {
            continue;
        }
        if lost && matches!(line, Err(ReadlineError::Interrupted)) {
            interrupt::take();
            let why = format!("{} went away", shell.session().describe());
            outage::lost(shell, &why, None, color, &mut out);
            continue;
        }
        match line {
            Ok(text) => {
                let flow = match everyday(&text) {
                    Some(Everyday::Clear) => {
                        let _ = editor.clear_screen();
                        Flow::Continue
                    }
                    Some(Everyday::Helper(line)) => handle(shell, &line, color, &mut out),
                    None => handle(shell, text.trim(), color, &mut out),
                };
                if flow == Flow::Quit {
                    break;
                }
            }
            // Ctrl-C at the prompt: the panic key while something this session started may
            // still move; otherwise it only clears the line.
            Err(ReadlineError::Interrupted) => {
                if shell.session_ref().may_be_moving() {
                    interrupt::take();
                    stop_target(shell, &mut out);
                }
            }
            Err(ReadlineError::Eof) => break,
            // The terminal is gone (a read fails with EIO once it hangs up, with or without the
            // SIGHUP): the same as a hang-up.
            Err(e) => {
                terminate(shell, &format!("the terminal failed ({e})"));
                exit = Exit::Terminated(interrupt::Termination::Hup.number() as u8);
                break;
            }
        }
    }
    // A hang-up may end the editor's read before its signal is seen.
    if let (Exit::Success, Some(signal)) = (exit, interrupt::terminated()) {
        terminate(shell, signal.name());
        exit = Exit::Terminated(signal.number() as u8);
    }
    history::save(&mut editor, dialect);
    // `:quit` or Ctrl-D with a motor turning: said, as `:stop` says it of a program's motion.
    if exit == Exit::Success && shell.session_ref().may_be_moving() {
        for warning in shell.session().turning_at_exit() {
            let _ = writeln!(out, "warning: {}", escape_control(&warning));
        }
    }
    for message in shell.session().close() {
        let _ = writeln!(out, "{}", escape_control(&message));
    }
    exit
}

/// SIGTERM, SIGHUP or a terminal gone (`why`): what this session set moving is stopped as after
/// a failure, and said so on stderr (the terminal may be gone); the caller ends the shell (exit
/// 143 or 129).
fn terminate(shell: &mut Shell, why: &str) {
    interrupt::take();
    let stopped = if shell.session_ref().may_be_moving() {
        shell.session().stop_motion()
    } else {
        Vec::new()
    };
    let mut err = std::io::stderr();
    let what = if stopped.is_empty() {
        "nothing this session started was moving".to_string()
    } else {
        "stopping what this session set moving".to_string()
    };
    let _ = writeln!(err, "tmclsh: {why}: leaving the shell; {what}");
    for line in stopped {
        let _ = writeln!(err, "tmclsh: {}", escape_control(&line));
    }
}

/// Runs one typed line and shows its outcome (also for `outage`, the lines typed while the link
/// was away and confirmed). What the session noticed while it waited for a
/// reply (bytes it discarded before the reply, a position event, a transcript that failed) is
/// shown before the reply or error it concerns.
fn handle(shell: &mut Shell, text: &str, color: bool, out: &mut dyn Write) -> Flow {
    if only_remark(text) {
        return Flow::Continue;
    }
    crate::crash::point("repl", text);
    interrupt::take();
    if text.starts_with(':') {
        let result = shell.helper(text, out);
        // A helper writes as it goes, and some redraw what they wrote (`:watch`, `:plot`, a
        // progress bar): a line put between would break the drawing, so its notices follow.
        show_notices(shell, color, out);
        return outcome(shell, text, result, color, out);
    }
    let result = shell.session().execute(text);
    show_notices(shell, color, out);
    let result = result.map(|reply| {
        let ok = reply.ok();
        let shown = if shell.raw {
            reply.shown
        } else {
            reply.decoded
        };
        // Escaped before it is coloured: the colour is ours, any other sequence is the device's.
        let shown = escape_control(&shown).into_owned();
        let shown = match (color, ok) {
            (false, _) => shown,
            (true, true) => shown.green().to_string(),
            (true, false) => shown.red().to_string(),
        };
        let _ = writeln!(out, "{}{shown}", stamp(shell));
        Flow::Continue
    });
    outcome(shell, text, result, color, out)
}

/// Writes the session's notices, one line each.
fn show_notices(shell: &mut Shell, color: bool, out: &mut dyn Write) {
    for notice in shell.session().take_notices() {
        let notice = escape_control(&notice).into_owned();
        let line = if color {
            notice.yellow().to_string()
        } else {
            notice
        };
        let _ = writeln!(out, "{line}");
    }
}

/// Ends a line: an error is shown, Ctrl-C stops the motors, a lost link is waited for.
fn outcome(
    shell: &mut Shell,
    text: &str,
    result: Result<Flow, SessionError>,
    color: bool,
    out: &mut dyn Write,
) -> Flow {
    match result {
        Ok(flow) => flow,
        Err(SessionError::Interrupted) => {
            interrupt::take();
            stop_target(shell, out);
            Flow::Continue
        }
        Err(SessionError::Lost(message)) => {
            outage::lost(shell, &message, Some(text), color, out);
            Flow::Continue
        }
        Err(e) => {
            let line = format!("error: {}", escape_control(&e.to_string()));
            let line = if color { line.red().to_string() } else { line };
            let _ = writeln!(out, "{}{line}", stamp(shell));
            Flow::Continue
        }
    }
}

/// The time of day before a reply when `:log time on` asked for it.
fn stamp(shell: &Shell) -> String {
    if shell.timestamps {
        format!("{} ", crate::shell::time_of_day())
    } else {
        String::new()
    }
}

/// After Ctrl-C: MST to every motor of the target module (MOTOR:STOP on an SMD4), and to every
/// module this session set moving.
fn stop_target(shell: &mut Shell, out: &mut dyn Write) {
    for line in shell.session().stop_target() {
        let _ = writeln!(out, "{}", escape_control(&line));
    }
}
