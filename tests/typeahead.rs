//! Lines typed before the prompt asks for them: a paste of several lines, and lines typed while a
//! command still runs. Each must run, in order — a line the editor read ahead must not be dropped.

use crate::repl::repl;
use crate::util::tempdir;

/// Three lines in one write, as a terminal delivers a paste: the editor reads them in one go.
#[test]
fn a_pasted_block_of_lines_runs_every_line() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send("GGP 65,0\rGGP 66,0\rGGP 67,0\r").unwrap();
    p.flush().unwrap();
    p.exp_string("serial_baud_rate = 0").unwrap();
    p.exp_string("serial_address = 1").unwrap();
    p.exp_string("ascii_mode = 0").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

/// Lines typed while a script sleeps wait in the terminal and run after it, none lost.
#[test]
fn lines_typed_while_a_command_runs_all_run_after_it() {
    let dir = tempdir();
    let script = dir.join("pause.rhai");
    std::fs::write(&script, "sleep(300);\nprint(\"slept\");\n").unwrap();
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    let source = format!(":source {}\r", script.display());
    p.send(&source).unwrap();
    p.flush().unwrap();
    for line in ["GGP 65,0\r", "GGP 66,0\r", "GGP 67,0\r"] {
        p.send(line).unwrap();
        p.flush().unwrap();
    }
    p.exp_string("slept").unwrap();
    p.exp_string("serial_baud_rate = 0").unwrap();
    p.exp_string("serial_address = 1").unwrap();
    p.exp_string("ascii_mode = 0").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}
