//! SYS:FLAGS in the REPL, against the built-in simulated drive: `:help SYS:FLAGS` lists the bits
//! of both flag words from `data/smd4.toml`, and a read shows the two words with what they mean,
//! not the fixed item `1` the protocol document's example adds without explaining it (`:raw`
//! still shows the line as received).

use tmclsh::dialect::smd4::protocol::Smd4Spec;

use crate::util::terminal;

#[test]
fn help_lists_the_flag_bits_and_a_read_shows_the_words_it_reads() {
    let mut p = terminal(&["--protocol", "smd4"], &[]);
    p.exp_string("smd4> ").unwrap();
    p.send_line(":help SYS:FLAGS").unwrap();
    p.exp_string("does not explain it").unwrap();
    // Every named bit of both words, in order, as the data names it.
    let spec = Smd4Spec::builtin();
    p.exp_string("Status (SFLAGS").unwrap();
    for bit in spec.sflags.bits().iter().filter(|b| b.name != "Reserved") {
        p.exp_string(&format!("{:>4}  {}", bit.bit, bit.name))
            .unwrap();
    }
    p.exp_string("Errors (EFLAGS").unwrap();
    for bit in spec.eflags.bits().iter().filter(|b| b.name != "Reserved") {
        p.exp_string(&format!("{:>4}  {}", bit.bit, bit.name))
            .unwrap();
    }
    p.exp_string("Reserved, reading 0: status bits 5, 6, 13, 14, 15")
        .unwrap();
    // A read: the two words and their bits, starting the line — no leading `1`.
    p.send_line("SYS:FLAGS").unwrap();
    let (_, read) = p
        .exp_regex(r"\n0x[0-9A-F]{4}, 0x0000 \(status: [^;\r]*Standby[^;\r]*; errors: none\)\r\n")
        .unwrap();
    assert!(!read.contains(", 1"), "{read:?}");
    // An emergency stop latches EFLAGS bit 5, which the next read names.
    p.send_line("MOTOR:ESTOP").unwrap();
    p.exp_string("ok").unwrap();
    p.send_line("SYS:FLAGS").unwrap();
    p.exp_regex(r"\n0x[0-9A-F]{4}, 0x0020 \(status: [^;\r]*; errors: Emergency Stop\)\r\n")
        .unwrap();
    // The line as received keeps the item.
    p.send_line(":raw").unwrap();
    p.exp_string("raw output on").unwrap();
    p.send_line("SYS:FLAGS").unwrap();
    p.exp_regex(r"\n0x[0-9A-F]{4},0x0020,1\r\n").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn the_value_of_sys_flags_is_its_two_words() {
    let out = crate::util::run(&[
        "--sim",
        "--protocol",
        "smd4",
        "--value",
        "-c",
        "SYS:FLAGS",
        "-c",
        "MOTOR:ESTOP",
        "-c",
        "SYS:FLAGS",
    ]);
    assert_eq!(crate::util::code(&out), 0, "{}", crate::util::stderr(&out));
    let text = crate::util::stdout(&out);
    let values: Vec<&str> = text.lines().collect();
    // The words as the drive writes them; MOTOR:ESTOP has no data; then bit 5 latched.
    assert_eq!(values.len(), 3, "{text}");
    assert!(
        values[0].starts_with("0x") && values[0].ends_with(",0x0000"),
        "{text}"
    );
    assert_eq!(values[1], "", "{text}");
    assert!(values[2].ends_with(",0x0020"), "{text}");
    assert_eq!(values[0].split(',').count(), 2, "{text}");
}
