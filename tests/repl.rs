//! The REPL driven in a real pseudo-terminal (expect-style): completion of a parameter name, a
//! hint, decoded replies, Ctrl-C at the prompt and during a wait, history, Ctrl-D.

use std::process::Command;

use rexpect::session::{PtySession, spawn_command};

use crate::util::{bin, tempdir};

mod addressed;
mod leaving;
mod ports;

/// The REPL on the built-in simulator, with its own history directory.
pub(crate) fn repl(extra: &[&str]) -> (PtySession, std::path::PathBuf) {
    let data = tempdir();
    (repl_at(extra, &data), data)
}

/// The REPL on the built-in simulator with `data` as its home, data and config directory.
pub(crate) fn repl_at(extra: &[&str], data: &std::path::Path) -> PtySession {
    let mut command = Command::new(bin());
    command
        .args(extra)
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("XDG_DATA_HOME", data)
        .env("XDG_CONFIG_HOME", data)
        .env("HOME", data);
    let mut p =
        spawn_command(command, Some(crate::util::EXPECT_MS)).expect("tmclsh starts in a pty");
    p.exp_string("tmclsh").unwrap();
    p
}

/// Types text without Enter (rexpect buffers until flushed).
pub(crate) fn type_in(p: &mut PtySession, text: &str) {
    p.send(text).unwrap();
    p.flush().unwrap();
}

#[test]
fn banner_says_what_it_talks_to() {
    let (mut p, _) = repl(&[]);
    // rexpect reads bytes as Latin-1, so the banner's dashes are matched around.
    p.exp_string("simulated TMCM-142 (built-in)").unwrap();
    p.exp_string("use --port to talk to hardware").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn tab_completes_a_parameter_name_and_the_reply_is_decoded() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "SAP actual_pos");
    type_in(&mut p, "\t");
    type_in(&mut p, "0, -5000\r");
    p.exp_string("ok").unwrap();
    type_in(&mut p, "GAP actual_p\t0\r");
    p.exp_string("actual_position = -5000 usteps").unwrap();
    p.send_line("GAP 200, 0").unwrap();
    p.exp_string("error 3: wrong type").unwrap();
    p.send_line("SAP max_current, 0, 99").unwrap();
    p.exp_string("error: 99 is out of range for max_current")
        .unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_hint_shows_number_range_access_unit_and_description() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "SAP max_current, ");
    p.exp_string("#6 max_current [0..15, RWE] 1/15 of full scale")
        .unwrap();
    p.exp_string("Coil current while the motor moves.").unwrap();
    // Ctrl-C at the prompt clears the line instead of leaving. Typing ahead of the new prompt
    // would be flushed by the terminal, so wait for the line editor to end the old line first.
    p.send_control('c').unwrap();
    p.exp_string("\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("max_positioning_speed = 1000000 usteps/t")
        .unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn ctrl_c_during_a_wait_stops_the_rotating_motor() {
    let dir = tempdir();
    let script = dir.join("spin.rhai");
    std::fs::write(
        &script,
        "ror(0, 100000);\nprint(\"spinning\");\nsleep(60000);\n",
    )
    .unwrap();
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line(&format!(":source {}", script.display()))
        .unwrap();
    p.exp_string("spinning").unwrap();
    p.send_control('c').unwrap();
    p.exp_string("stopped motor 0 of module 1 (A) with MST")
        .unwrap();
    p.exp_string("interrupted").unwrap();
    p.exp_string("A> ").unwrap();
    // The motor decelerates with its ramp; it ends standing.
    let mut speed = String::new();
    for _ in 0..200 {
        p.send_line("GAP actual_speed, 0").unwrap();
        let (_, found) = p.exp_regex(r"actual_speed = -?\d+").unwrap();
        speed = found;
        if speed == "actual_speed = 0" {
            break;
        }
    }
    assert_eq!(speed, "actual_speed = 0");
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn helpers_work_and_history_is_kept_in_the_data_directory() {
    let (mut p, data) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line(":params max_c").unwrap();
    p.exp_string("max_current").unwrap();
    p.send_line(":bin").unwrap();
    p.exp_string("binary direct mode").unwrap();
    p.exp_string("A[bin]> ").unwrap();
    p.send_line("136 0").unwrap();
    p.exp_string("firmware version 142V1.06").unwrap();
    p.send_line(":quit").unwrap();
    p.exp_eof().unwrap();
    let history = std::fs::read_to_string(data.join("tmclsh").join("history-tmcl")).unwrap();
    assert!(history.contains("136 0"), "{history}");
}

#[test]
fn a_lost_link_is_waited_for_and_the_session_carries_on() {
    let mut sim = crate::sim::Sim::start(&["--listen", "127.0.0.1:0"]);
    let (mut p, _) = repl(&["--tcp", &sim.first.clone()]);
    p.exp_string("A> ").unwrap();
    p.send_line("SAP 1, 0, 321").unwrap();
    p.exp_string("ok").unwrap();
    assert!(sim.console("hangup").starts_with("ok"));
    p.send_line("GAP 1, 0").unwrap();
    p.exp_string("link lost").unwrap();
    p.exp_string("waiting for tcp").unwrap();
    p.exp_string("reconnected").unwrap();
    p.send_line("GAP 1, 0").unwrap();
    p.exp_string("actual_position = 321 usteps").unwrap();
    // History from before the loss is still there: arrow up recalls the last line.
    p.send("\x1b[A").unwrap();
    p.flush().unwrap();
    p.exp_string("GAP 1, 0").unwrap();
    p.send_control('c').unwrap();
    p.exp_string("\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}
