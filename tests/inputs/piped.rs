//! Piped stdin: CR, LF and CRLF each end a line; a line that is not UTF-8, too long or full of
//! control characters is refused with its number (exit 2, nothing sent), in a message that is
//! short and escaped; memory stays flat under an endless line.

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

use super::run_piped;
use crate::sim::Sim;
use crate::util::bin;

#[test]
fn cr_alone_lf_and_crlf_each_end_a_line_even_mixed_in_one_file() {
    let input = b"SAP 4, 0, 7\rGAP 4, 0\r\nSAP 4, 0, 8\n\rGAP 4, 0\r\r\nGGP 2, 2\n# done\rGAP 5, 0";
    let out = run_piped(&["--sim"], input.to_vec());
    assert_eq!(out.code, 0, "{}", out.stderr());
    assert_eq!(
        out.stdout.lines().collect::<Vec<_>>(),
        [
            "BA 100 7",
            "BA 100 7",
            "BA 100 8",
            "BA 100 8",
            "BA 100 0",
            "BA 100 100000"
        ]
    );
    // A CR-only file that fails names the line an editor shows.
    let out = run_piped(
        &["--sim"],
        b"GAP 4, 0\rGAP 4, 0\rGAP nope, 0\rGAP 4, 0\r".to_vec(),
    );
    assert_eq!(out.code, 2);
    assert!(
        out.stderr().starts_with("tmclsh: line 3 (GAP nope, 0): "),
        "{}",
        out.stderr()
    );
    assert_eq!(out.stdout.lines().count(), 2);
}

#[test]
fn a_line_that_is_not_utf8_is_refused_with_its_number() {
    let out = run_piped(
        &["--sim"],
        b"GAP 4, 0\r\nGAP \xFF\xFE4, 0\r\nSAP 4, 0, 9\r\n".to_vec(),
    );
    assert_eq!(out.code, 2);
    assert_eq!(
        out.stdout, "BA 100 1000000\n",
        "the run stops at the bad line"
    );
    assert_eq!(
        out.stderr(),
        "tmclsh: line 2: not valid UTF-8 (byte 0xFF at column 5); nothing sent\n"
    );
}

#[test]
fn control_characters_are_escaped_in_messages() {
    let out = run_piped(&["--sim"], b"GAP 4,\x1b]0;owned\x07 0\n".to_vec());
    assert_eq!(out.code, 2);
    assert!(
        !out.stderr.iter().any(|&b| b == 0x1b || b == 0x07),
        "raw control bytes reached the terminal: {:?}",
        out.stderr()
    );
    assert!(
        out.stderr()
            .starts_with("tmclsh: line 1 (GAP 4,\\x1B]0;owned\\x07 0): "),
        "{}",
        out.stderr()
    );
    // A -c line too.
    let out = run_piped(&["--sim", "-c", "GAP 4, 0\u{1b}[2J"], Vec::new());
    assert_eq!(out.code, 2);
    assert!(!out.stderr.contains(&0x1b), "{:?}", out.stderr());
    assert!(out.stderr().contains("\\x1B[2J"), "{}", out.stderr());
}

#[test]
fn a_one_megabyte_line_gets_a_short_message() {
    let mut input = b"GAP 4, 0\n".to_vec();
    input.extend(std::iter::repeat_n(b'x', 1 << 20));
    input.extend_from_slice(b"\nSAP 4, 0, 9\n");
    let out = run_piped(&["--sim"], input);
    assert_eq!(out.code, 2);
    assert_eq!(out.stdout, "BA 100 1000000\n");
    assert_eq!(
        out.stderr(),
        "tmclsh: line 2: longer than the 4096 bytes a line may have; nothing sent\n"
    );
    // The same from -c (an argument holds at most 128 KiB).
    let long = "x".repeat(100_000);
    let out = run_piped(&["--sim", "-c", "GAP 4, 0", "-c", &long], Vec::new());
    assert_eq!(out.code, 2);
    assert!(out.stderr.len() < 200, "{}", out.stderr().len());
}

#[test]
fn memory_stays_flat_under_an_endless_line() {
    let mut sim = Sim::start(&["--pty"]);
    let mut child = Command::new(bin())
        .args(["--port", &sim.first, "--timeout", "60000"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("tmclsh runs");
    let mut stdin = child.stdin.take().unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    stdin.write_all(b"GAP 4, 0\n").unwrap();
    let mut reply = String::new();
    stdout.read_line(&mut reply).unwrap();
    assert_eq!(reply, "BA 100 1000000\n", "the session is up");
    // The next line waits for a reply that does not come, while the reader takes in 64 MiB with
    // no line end: a reader that kept whole lines would hold all of it.
    assert!(sim.console("silent on").starts_with("ok"));
    stdin.write_all(b"GAP 4, 0\n").unwrap();
    stdin.write_all(&vec![b'7'; 64 << 20]).unwrap();
    let peak = crate::hostile::high_water_mark(child.id()).expect("tmclsh's own status");
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(peak < 40 * 1024, "peak RSS {peak} KiB for a 64 MiB line");
}
