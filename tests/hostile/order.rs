//! What the session notices while it waits for a reply — bytes it discarded before the reply, a
//! position event, another module's reply — appears on screen before the reply it concerns, in
//! the REPL, in `-c` runs (notices on stderr, replies on stdout, one terminal) and before the
//! `print` line of a script that shows the reply.

use rexpect::session::PtySession;

use crate::util::tempdir;

use super::{Act, Fake, Via, on, replace_last};

/// The module's answer to GAP 4, 0 as the REPL decodes it.
const DECODED: &str = "max_positioning_speed = 1000000 usteps/t";

/// Garbage, an event and another module's reply, all before the reply to the request.
fn litter(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"BA 100", b"\x07junk\rBA 128 0\rBC 100 5\rBA 100")
}

/// The notices the litter provokes.
const NOTICES: [&str; 3] = [
    "ignored unexpected data from the line",
    "module 1 (A): target position reached (event)",
    "ignored a reply from module 3 (C) while waiting for module 1 (A)",
];

fn start(args: &[String]) -> PtySession {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    crate::util::terminal(&args, &[])
}

fn assert_notices_in(text: &str, what: &str) {
    for notice in NOTICES {
        assert!(text.contains(notice), "{what}: {notice:?} in {text:?}");
    }
}

#[test]
fn in_the_repl_notices_come_before_the_reply_and_the_error_they_concern() {
    let fake = Fake::tmcl(
        Via::Pty,
        Box::new({
            let mut gap4 = on("GAP 4, 0", 1, || Act::Map(litter));
            let mut gap200 = on("GAP 200, 0", 1, || {
                Act::Map(|a| replace_last(a, b"BA ", b"\x07junk\rBA "))
            });
            move |line: &str| match line {
                l if l.contains("GAP 200") => gap200(l),
                l => gap4(l),
            }
        }),
    );
    let mut p = start(&fake.args());
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    let before = p.exp_string(DECODED).unwrap();
    assert_notices_in(&before, "before the reply");
    let after = p.exp_string("A> ").unwrap();
    assert!(
        !after.contains("ignored") && !after.contains("event"),
        "nothing after the reply: {after:?}"
    );
    p.send_line("GAP 200, 0").unwrap();
    let before = p.exp_string("error 3: wrong type").unwrap();
    assert!(
        before.contains("ignored unexpected data from the line"),
        "before the error: {before:?}"
    );
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn in_c_runs_stderr_notices_come_before_the_stdout_reply_in_every_output_form() {
    for (form, reply) in [
        (None, "BA 100 1000000"),
        (Some("--value"), "1000000"),
        (Some("--json"), "\"value\":1000000"),
    ] {
        let fake = Fake::tmcl(Via::Pty, on("GAP 4, 0", 1, || Act::Map(litter)));
        let mut args = fake.args();
        args.extend(form.map(String::from));
        args.extend(["-c".to_string(), "GAP 4, 0".to_string()]);
        let mut p = start(&args);
        let screen = p.exp_eof().unwrap();
        let at = screen
            .find(reply)
            .unwrap_or_else(|| panic!("{form:?}: {reply} in {screen:?}"));
        assert_notices_in(&screen[..at], &format!("{form:?}, before the reply"));
    }
}

#[test]
fn in_a_script_notices_come_before_the_print_that_shows_the_reply() {
    let fake = Fake::tmcl(Via::Pty, on("GAP 4, 0", 1, || Act::Map(litter)));
    let script = tempdir().join("order.rhai");
    std::fs::write(
        &script,
        "print(`speed ${gap(4, 0)}`);\nprint(`then ${gap(1, 0)}`);\n",
    )
    .unwrap();
    let mut args = vec!["run".to_string(), script.display().to_string()];
    args.extend(fake.args());
    let mut p = start(&args);
    let screen = p.exp_eof().unwrap();
    let at = screen
        .find("speed 1000000")
        .unwrap_or_else(|| panic!("the reply in {screen:?}"));
    assert_notices_in(&screen[..at], "before the print");
    assert!(screen[at..].contains("then 0"), "{screen:?}");
}
