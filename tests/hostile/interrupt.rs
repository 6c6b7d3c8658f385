//! Ctrl-C while a slow reply is awaited, in the REPL on a pseudo-terminal.

use std::process::Command;

use rexpect::session::spawn_command;

use crate::util::{bin, tempdir};

use super::{Act, Fake, Via, await_request, on, same};

#[test]
fn ctrl_c_while_a_reply_is_awaited_stops_the_motor_at_once_and_leaves_nothing_behind() {
    // The device answers GAP 1 only together with the next request: a reply that keeps
    // tmclsh waiting as long as its (long) timeout allows.
    let fake = Fake::tmcl(Via::Pty, on("GAP 1, 0", 1, || Act::HoldUntilNext(same)));
    let data = tempdir();
    let mut command = Command::new(bin());
    command
        .args(fake.args())
        .args(["--timeout", "60000"])
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("XDG_DATA_HOME", &data)
        .env("HOME", &data);
    // rexpect's own timeout is the hang guard: far below the 60 s the reply would take.
    let mut p =
        spawn_command(command, Some(crate::util::EXPECT_MS)).expect("tmclsh starts in a pty");
    p.exp_string("A> ").unwrap();
    p.send_line("ROL 0, 1000").unwrap();
    p.exp_string("ok").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 1, 0").unwrap();
    await_request(&fake, "GAP 1, 0");
    p.send_control('c').unwrap();
    let (_, stopped) = p
        .exp_regex(r"interrupted: stopped motor 0 of module 1 \(A\) with MST\r\n")
        .unwrap();
    assert!(!stopped.is_empty());
    let before_prompt = p.exp_string("A> ").unwrap();
    assert!(
        !before_prompt.contains("MST"),
        "one message for one stop: {before_prompt:?}"
    );
    p.send_line("GAP 4, 0").unwrap();
    let answer = p
        .exp_string("max_positioning_speed = 1000000 usteps/t")
        .unwrap();
    assert!(
        !answer.contains("ignored") && !answer.contains("AGAP 1, 0"),
        "nothing left over from the interrupted request: {answer:?}"
    );
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
    let requests = fake.requests.lock().unwrap().clone();
    let msts = requests.iter().filter(|r| r.contains("MST")).count();
    assert_eq!(msts, 1, "one MST for one Ctrl-C: {requests:?}");
}
