//! Each dialect recalls its own lines: a TMCL session never offers `SYS:FW`, and the one history
//! file of earlier versions is split between the dialects.

use crate::repl::{repl_at, type_in};
use crate::util::tempdir;

/// Arrow up, then Enter: runs the line history recalls.
fn recall_last(p: &mut rexpect::session::PtySession) {
    type_in(p, "\x1b[A");
    type_in(p, "\r");
}

#[test]
fn a_tmcl_session_recalls_tmcl_lines_after_an_smd4_session() {
    let data = tempdir();
    let mut p = repl_at(&[], &data);
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("max_positioning_speed").unwrap();
    p.exp_string("A> ").unwrap();
    // Ctrl-D leaves without adding a line to the history.
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();

    let mut p = repl_at(&["--protocol", "smd4"], &data);
    p.exp_string("smd4> ").unwrap();
    p.send_line("SYS:FW").unwrap();
    p.exp_string("smd4> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();

    // The SMD4 line came last, but a TMCL session recalls its own.
    let mut p = repl_at(&[], &data);
    p.exp_string("A> ").unwrap();
    recall_last(&mut p);
    p.exp_string("max_positioning_speed = 1000000").unwrap();
    p.send_line(":quit").unwrap();
    p.exp_eof().unwrap();

    let mut p = repl_at(&["--protocol", "smd4"], &data);
    p.exp_string("smd4> ").unwrap();
    recall_last(&mut p);
    p.exp_string("SYS:FW").unwrap();
    p.send_line(":quit").unwrap();
    p.exp_eof().unwrap();

    let dir = data.join("tmclsh");
    let tmcl = std::fs::read_to_string(dir.join("history-tmcl")).unwrap();
    let smd4 = std::fs::read_to_string(dir.join("history-smd4")).unwrap();
    assert!(
        tmcl.contains("GAP 4, 0") && !tmcl.contains("SYS:FW"),
        "{tmcl}"
    );
    assert!(
        smd4.contains("SYS:FW") && !smd4.contains("GAP 4, 0"),
        "{smd4}"
    );
}

#[test]
fn the_shared_history_of_earlier_versions_is_split() {
    let data = tempdir();
    let dir = data.join("tmclsh");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("history"), "#V2\nGAP 4, 0\nMOTOR:RUNA\n").unwrap();
    let mut p = repl_at(&[], &data);
    p.exp_string("A> ").unwrap();
    recall_last(&mut p);
    p.exp_string("max_positioning_speed = 1000000").unwrap();
    p.send_line(":quit").unwrap();
    p.exp_eof().unwrap();
    let tmcl = std::fs::read_to_string(dir.join("history-tmcl")).unwrap();
    assert!(!tmcl.contains("MOTOR:RUNA"), "{tmcl}");
}
