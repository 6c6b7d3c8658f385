//! `help`, `?`, `exit`, `quit` and `clear` do what everyone expects, at the prompt and in piped
//! input; `:help exit` says how to leave.

use crate::repl::{repl, type_in};
use crate::util::{code, run_with_stdin, stderr, stdout};

#[test]
fn at_the_prompt_the_words_do_their_helpers() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line("help").unwrap();
    p.exp_string("Helper commands:").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("? exit").unwrap();
    p.exp_string("Leave with :quit (or quit, exit) or Ctrl-D")
        .unwrap();
    p.exp_string("Exit codes: 0 success").unwrap();
    p.exp_string("A> ").unwrap();
    // The line editor clears the screen: cursor home, then erase.
    type_in(&mut p, "clear\r");
    p.exp_string("\x1b[H").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("max_positioning_speed").unwrap();
    p.send_line("exit").unwrap();
    p.exp_eof().unwrap();
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line("QUIT").unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn in_piped_input_help_prints_quit_ends_and_clear_is_skipped() {
    let out = run_with_stdin(&[], "help GAP\nclear\nGAP 4, 0\nexit\nGAP 5, 0\n");
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
