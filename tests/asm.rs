//! `tmclsh asm` and `tmclsh disasm`: the real binary on real files.

use crate::util::{code, repo, run, stderr, stdout, tempdir};

fn test2() -> String {
    repo().join("scripts/test2.tmc").display().to_string()
}

#[test]
fn asm_list_shows_address_bytes_and_source_of_test2() {
    let out = run(&["asm", &test2(), "--list"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stderr(&out), "");
    let text = stdout(&out);
    let row = |needle: &str| {
        text.lines()
            .find(|l| l.contains(needle))
            .unwrap_or_else(|| panic!("no line with {needle:?} in\n{text}"))
            .to_string()
    };
    assert!(text.starts_with("addr  bytes"), "{text}");
    assert!(row("ROL 0, 500000").starts_with("0000  02 00 00 00 07 A1 20"));
    assert!(row("Loop: MVP ABS, 0, 1000000").starts_with("0008  04 00 00 00 0F 42 40"));
    assert!(row("MVP ABS, 0, -1000000").starts_with("0010  04 00 00 FF F0 BD C0"));
    assert!(row("JA Loop").starts_with("0012  16 00 00 00 00 00 08"));
    assert!(
        row("//A simple example").starts_with(' '),
        "comment lines have no bytes"
    );
    assert!(
        text.trim_end()
            .ends_with("13 instructions of 2048 (91 bytes)"),
        "{text}"
    );
}

#[test]
fn asm_without_output_only_checks_and_reports() {
    let dir = tempdir();
    let source = dir.join("check.tmc");
    std::fs::copy(test2(), &source).unwrap();
    let out = run(&["asm", source.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(
        stdout(&out),
        format!("{}: 13 instructions of 2048 (91 bytes)\n", source.display())
    );
    let files: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(files.len(), 1, "nothing written besides the source");
}

#[test]
fn asm_to_bin_then_disasm_then_asm_gives_identical_bytes() {
    let dir = tempdir();
    let first = dir.join("first.bin");
    let out = run(&["asm", &test2(), "-o", first.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let bytes = std::fs::read(&first).unwrap();
    assert_eq!(bytes.len(), 7 + 13 * 7);
    assert_eq!(bytes[..7], [b'T', b'M', b'C', b'L', 1, 0, 13]);
    assert_eq!(bytes[7..14], [2, 0, 0, 0x00, 0x07, 0xA1, 0x20]); // ROL 0, 500000

    let out = run(&["disasm", first.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let source = stdout(&out);
    assert!(
        source.contains("\nL8:\n    MVP ABS, 0, 1000000\n"),
        "{source}"
    );
    assert!(source.contains("    JA L8\n"), "{source}");
    assert!(source.contains("WAIT TICKS, 0, 500"), "{source}");
    let disassembled = dir.join("again.tmc");
    std::fs::write(&disassembled, source).unwrap();

    let second = dir.join("second.bin");
    let out = run(&[
        "asm",
        disassembled.to_str().unwrap(),
        "--output",
        second.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(std::fs::read(&second).unwrap(), bytes);
}

#[test]
fn source_errors_are_listed_with_file_line_column_and_exit_2() {
    let dir = tempdir();
    let source = dir.join("bad.tmc");
    std::fs::write(
        &source,
        "// three mistakes\nLoop: MVPP ABS, 0, 10\n  JA Lop\n  WAIT TICK, 0, 5\n  129 1, 0, 0\n",
    )
    .unwrap();
    let output = dir.join("bad.bin");
    let out = run(&[
        "asm",
        source.to_str().unwrap(),
        "-o",
        output.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), 2);
    assert_eq!(stdout(&out), "");
    let name = source.display();
    assert_eq!(
        stderr(&out),
        format!(
            "{name}:2:7: error: unknown command 'MVPP'; did you mean MVP?\n\
             {name}:3:6: error: unknown label 'Lop'; did you mean Loop?\n\
             {name}:4:8: error: 'TICK' is not a keyword of WAIT; use TICKS, POS, REFSW, LIMSW, RFS\n\
             {name}:5:3: error: 129 — run application — is a direct-mode control function and cannot be stored in a program\n\
             tmclsh: {name}: 4 errors, nothing assembled\n"
        )
    );
    assert!(
        !output.exists(),
        "no program file is written for a broken source"
    );
}

#[test]
fn warnings_go_to_stderr_and_the_program_is_still_written() {
    let dir = tempdir();
    let source = dir.join("warn.tmc");
    std::fs::write(&source, "GAP 200, 0\nSTOP\n").unwrap();
    let output = dir.join("warn.bin");
    let out = run(&[
        "asm",
        source.to_str().unwrap(),
        "-o",
        output.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stderr(&out)
            .contains("warn.tmc:1:5: warning: axis parameter 200 is not in the TMCM-142 profile"),
        "{}",
        stderr(&out)
    );
    assert_eq!(
        std::fs::read(&output).unwrap()[7..],
        [6, 200, 0, 0, 0, 0, 0, 28, 0, 0, 0, 0, 0, 0]
    );
}

#[test]
fn unreadable_or_wrong_files_are_refused_with_exit_2() {
    let dir = tempdir();
    let missing = dir.join("missing.tmc");
    let out = run(&["asm", missing.to_str().unwrap()]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains(&format!("cannot read {}", missing.display())),
        "{}",
        stderr(&out)
    );

    let out = run(&["disasm", &test2()]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("not a tmclsh program file"),
        "{}",
        stderr(&out)
    );

    let truncated = dir.join("truncated.bin");
    std::fs::write(&truncated, b"TMCL\x01\x00\x02\x03\x00\x00\x00\x00\x00\x00").unwrap();
    let out = run(&["disasm", truncated.to_str().unwrap()]);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("announces 2 instructions (14 bytes) but 7 bytes follow"),
        "{}",
        stderr(&out)
    );

    let out = run(&["asm", truncated.to_str().unwrap()]);
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("is an assembled program file, not source"));
}

#[test]
fn disasm_writes_invalid_instructions_with_a_warning() {
    let dir = tempdir();
    let file = dir.join("memory.bin");
    // MST 0, then a stored control function (as a damaged memory image might hold).
    std::fs::write(
        &file,
        b"TMCL\x01\x00\x02\x03\x00\x00\x00\x00\x00\x00\x81\x01\x00\x00\x00\x00\x00",
    )
    .unwrap();
    let out = run(&["disasm", file.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("    MST 0\n    129 1, 0, 0 "),
        "{}",
        stdout(&out)
    );
    assert!(
        stderr(&out)
            .contains("warning: instruction 1 is not valid in a program: 129 — run application —"),
        "{}",
        stderr(&out)
    );
}
