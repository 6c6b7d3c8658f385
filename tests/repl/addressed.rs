//! A line addressed to another module of a mixed bus (`tmclsh sim --modules
//! 1:tmcm-142,2:tmcm-6110`), as the REPL shows it while it is typed: Tab, the hint and the
//! highlighting read it with that module's profile — assumed to be the target's until the module
//! is identified, which the hint says — and a line to the target with the target's.

use std::process::Command;

use rexpect::session::{PtySession, spawn_command};

use super::type_in;
use crate::sim::Sim;
use crate::util::{bin, tempdir};

/// The red that marks an invalid line (crossterm's `red()`).
const RED: &str = "\x1b[38;5;9m";

/// The REPL on `port` (with `extra` flags) with colours on, so the highlighting can be read.
fn coloured_repl(port: &str, extra: &[&str]) -> PtySession {
    let data = tempdir();
    let mut command = Command::new(bin());
    command
        .args(["--port", port])
        .args(extra)
        .env_remove("NO_COLOR")
        .env("TERM", "xterm")
        .env("XDG_DATA_HOME", &data)
        .env("XDG_CONFIG_HOME", &data)
        .env("HOME", &data);
    let mut p = spawn_command(command, Some(crate::util::EXPECT_MS)).expect("tmclsh starts");
    p.exp_string("A> ").unwrap();
    p
}

/// Types `line` and returns its last redraw: the prompt, the line as highlighted and as much of
/// the hint as `hint` (a regex) asks for. Ctrl-U clears the line afterwards.
fn typed(p: &mut PtySession, line: &str, hint: &str) -> String {
    type_in(p, line);
    let pattern = format!(r"A> \S*{}\S*\s+\S+ {hint}", regex_escape(line));
    let (_, shown) = p.exp_regex(&pattern).unwrap();
    type_in(p, "\x15");
    shown
}

fn regex_escape(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '.' | '[' | ']' | '(' | ')' | '*' | '+' | '?' | '\\' | '|' | '^' | '$' => {
                format!("\\{c}")
            }
            c => c.to_string(),
        })
        .collect()
}

#[test]
fn a_line_to_another_module_is_completed_hinted_and_highlighted_with_its_profile() {
    let sim = Sim::start(&["--pty", "--modules", "1:tmcm-142,2:tmcm-6110"]);
    let mut p = coloured_repl(&sim.first, &[]);
    // Module 2 is not identified yet: taken for a TMCM-142 like the target, and the hint says
    // so; the line is not marked invalid, since the module decides once it is asked.
    let shown = typed(
        &mut p,
        "BGAP 4, 5",
        r"motor 5 does not exist: the TMCM-142 has one motor \(0\.\.0\); module 2 \(B\) not identified yet, taken for a TMCM-142",
    );
    assert!(!shown.contains(RED), "{shown:?}");
    // Sending it identifies module 2 and reads the reply with its profile.
    type_in(&mut p, "BGAP 4, 5\r");
    p.exp_string("max_positioning_speed = ").unwrap();
    p.exp_string("A> ").unwrap();
    // Now Tab offers the TMCM-6110's own parameters after B …
    type_in(&mut p, "BGAP chopper_\t");
    p.exp_string("chopper_blank_time (162)").unwrap();
    p.exp_string("chopper_off_time (167)").unwrap();
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "\x15");
    // … motor 5 is valid there, and the hint is the TMCM-6110's description of the parameter.
    let shown = typed(
        &mut p,
        "BGAP 4, 5",
        r"#4 max_positioning_speed \[0\.\.2047, RWE\]",
    );
    assert!(!shown.contains(RED), "{shown:?}");
    assert!(!shown.contains("not identified"), "{shown:?}");
    // Its ports are the TMCM-6110's map (VIN), which the TMCM-142 lacks.
    typed(&mut p, "BGIO 8, 1", "VIN, analog input");
    // The target is still a TMCM-142: the same line to it is invalid, with the reason.
    let shown = typed(
        &mut p,
        "AGAP 4, 5",
        r"motor 5 does not exist: the TMCM-142 has one motor",
    );
    assert!(
        shown.starts_with(&format!("A> {RED}AGAP 4, 5")),
        "{shown:?}"
    );
    let shown = typed(&mut p, "GAP 4, 5", r"motor 5 does not exist");
    assert!(shown.contains(RED), "{shown:?}");
    // And Tab without an address offers the target's parameters: none named chopper_.
    type_in(&mut p, "AGAP chopper_\t");
    p.exp_string("\x07").unwrap();
    type_in(&mut p, "\x15");
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_given_profile_reads_every_module_s_lines_before_and_after_it_answers() {
    let sim = Sim::start(&["--pty", "--modules", "1:tmcm-142,2:tmcm-6110"]);
    let mut p = coloured_repl(&sim.first, &["--profile", "tmcm-142"]);
    // The given profile is used for module 2 whatever it says: nothing is assumed, and the line
    // is invalid before it is sent …
    let shown = typed(
        &mut p,
        "BGAP 4, 5",
        r"motor 5 does not exist: the TMCM-142 has one motor \(0\.\.0\)\x1b",
    );
    assert!(
        shown.starts_with(&format!("A> {RED}BGAP 4, 5")),
        "{shown:?}"
    );
    assert!(!shown.contains("not identified"), "{shown:?}");
    // … refused when it is …
    type_in(&mut p, "BGAP 4, 5\r");
    p.exp_string("error: motor 5 does not exist").unwrap();
    p.exp_string("A> ").unwrap();
    // … and still offers no TMCM-6110 parameter once module 2 has answered.
    type_in(&mut p, "BGAP chopper_\t");
    p.exp_string("\x07").unwrap();
    type_in(&mut p, "\x15");
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}
