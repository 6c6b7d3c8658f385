//! `help`, `?`, `exit`, `quit` and `clear` do what everyone expects, at the prompt and in piped
//! input; `:help exit` says how to leave.

use crate::repl::{repl, type_in};
use crate::util::{code, run_with_stdin, stderr, stdout, tempdir};

#[test]
fn at_the_prompt_the_words_do_their_helpers() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line("help").unwrap();
    p.exp_string("Helper commands:").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("? exit").unwrap();
    p.exp_string("Leave with :quit, quit or exit").unwrap();
    p.exp_string("Exit codes: 0 success").unwrap();
    p.exp_string("A> ").unwrap();
    // The line editor clears the screen: cursor home, then erase.
    type_in(&mut p, "clear\r");
    p.exp_string("\x1b[H").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("max_positioning_speed").unwrap();
    // Typed before the prompt, a line is flushed when the line editor takes the terminal.
    p.exp_string("A> ").unwrap();
    p.send_line("exit").unwrap();
    p.exp_eof().unwrap();
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line("QUIT").unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn in_piped_input_help_prints_quit_ends_and_clear_is_skipped() {
    let out = run_with_stdin(&["--sim"], "help GAP\nclear\nGAP 4, 0\nexit\nGAP 5, 0\n");
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("get axis parameter (command 6)"), "{text}");
    assert!(text.contains("BA 100 1000000"), "{text}");
    assert!(
        !text.contains("BA 100 5"),
        "lines after exit are not run: {text}"
    );
    assert!(
        stderr(&out).contains("clear: there is no screen to clear"),
        "{}",
        stderr(&out)
    );
}

/// What the transcript `log` says was sent, one line per `tx`.
fn sent(log: &std::path::Path) -> Vec<String> {
    let text = std::fs::read_to_string(log).unwrap();
    text.lines()
        .filter(|l| l.split_whitespace().nth(1) == Some("tx"))
        .map(str::to_string)
        .collect()
}

#[test]
fn exit_or_quit_with_words_after_them_leaves_at_the_prompt_and_sends_nothing() {
    for (protocol, command, reply, word) in [
        ("tmcl", "GAP 4, 0", "max_positioning_speed", "exit now"),
        ("smd4", "MOTOR:VMAX", "1000 Hz requested", "quit please"),
    ] {
        let log = tempdir().join("t.log");
        let (mut p, _) = repl(&["--protocol", protocol, "--log", log.to_str().unwrap()]);
        p.exp_string("> ").unwrap();
        p.send_line(command).unwrap();
        p.exp_string(reply).unwrap();
        p.exp_string("> ").unwrap();
        p.send_line(word).unwrap();
        p.exp_eof().unwrap();
        let sent = sent(&log).join("\n");
        assert!(sent.contains(command), "{sent}");
        let typed = word.split(' ').next().unwrap();
        assert!(!sent.to_ascii_lowercase().contains(typed), "{sent}");
    }
}

#[test]
fn in_piped_input_exit_with_words_after_it_leaves_as_at_the_prompt() {
    for (protocol, before, after) in [
        ("tmcl", "GAP 4, 0", "GAP 5, 0"),
        ("smd4", "MOTOR:VMAX", "MOTOR:AMAX"),
    ] {
        for word in ["exit now", "QUIT please", "exit 1"] {
            let log = tempdir().join("t.log");
            let args = [
                "--sim",
                "--protocol",
                protocol,
                "--log",
                log.to_str().unwrap(),
            ];
            let out = run_with_stdin(&args, &format!("{before}\n{word}\n{after}\n"));
            // Leaving is not a failure, and `exit 1` is no exit code.
            assert_eq!(code(&out), 0, "{word}: {}", stderr(&out));
            assert!(!stderr(&out).contains("unknown"), "{}", stderr(&out));
            let sent = sent(&log).join("\n");
            assert!(sent.contains(before), "{sent}");
            assert!(
                !sent.contains(after),
                "lines after {word} are not run: {sent}"
            );
            let typed = word.split(' ').next().unwrap().to_ascii_lowercase();
            assert!(!sent.to_ascii_lowercase().contains(&typed), "{sent}");
        }
    }
}
