//! SMD4 drives (no echo, with and without `--address`) under a hostile line, on a pty and on TCP.

use std::time::Duration;

use super::{Act, BOTH, Corruption, Fake, on, replace_last, run_script, same, tmclsh, with};

/// Long enough that a late reply, due half a timeout after it, lands well inside the wait for a
/// quiet line on a loaded machine (the late-reply tests depend on that window, ±300 ms).
const TIMEOUT: Duration = Duration::from_millis(1000);
const TIMEOUT_ARG: &str = "1000";

/// First MOTOR:AMAX (5000) meets the misbehaviour; MOTOR:VMAX (1000) must get its own answer.
const FIRST_FAILS_SECOND_ANSWERS: &str = r#"
try { print(send("MOTOR:AMAX")); } catch (e) { print("failed"); }
print(send("MOTOR:VMAX")[0]);
"#;

/// As in `tmcl.rs`: the -c run on one device, the script run on another.
fn fails_then_recovers(device: impl Fn() -> Fake, address: &[&str], message: &str, what: &str) {
    let mut args = vec!["--protocol", "smd4", "--timeout", TIMEOUT_ARG];
    args.extend_from_slice(address);
    let fake = &device();
    let run = tmclsh(&with(fake, &[&args[..], &["-c", "MOTOR:AMAX"]].concat()));
    run.expect(3, what);
    assert!(run.stdout.is_empty(), "{what}: no value: {}", run.stdout);
    assert!(run.stderr.contains(message), "{what}: {}", run.stderr);
    let fake = &device();
    let run = run_script(fake, FIRST_FAILS_SECOND_ANSWERS, &args);
    run.expect(0, what);
    assert_eq!(
        run.lines().first(),
        Some(&"failed"),
        "{what}: {}",
        run.stderr
    );
    let second = run
        .lines()
        .get(1)
        .map(|l| l.to_string())
        .unwrap_or_default();
    assert!(
        second == "1.0000E+03",
        "{what}: the second request's own answer: {second} ({})",
        run.stderr
    );
}

/// With `--address 1` the simulated drive (address 1) answers with its `@1,` prefix.
const ADDRESSINGS: [&[&str]; 2] = [&[], &["--address", "1"]];

#[test]
fn a_reply_later_than_the_quiet_wait_is_discarded_before_a_barrier() {
    // MOTOR:AMAX's reply comes only when the next line goes out, however long the line was
    // quiet: that line is the barrier (refused with -103), and the reply before its refusal is
    // discarded instead of being taken for MOTOR:VMAX's (both are two reals).
    for via in BOTH {
        for address in ADDRESSINGS {
            let what = format!("{via:?} {address:?}");
            let fake = Fake::smd4(via, on("MOTOR:AMAX", 1, || Act::HoldUntilNext(same)));
            let mut args = vec!["--protocol", "smd4", "--timeout", TIMEOUT_ARG];
            args.extend_from_slice(address);
            let run = run_script(&fake, FIRST_FAILS_SECOND_ANSWERS, &args);
            run.expect(0, &what);
            assert_eq!(
                run.lines(),
                ["failed", "1.0000E+03"],
                "{what}: {}",
                run.stderr
            );
        }
    }
}

#[test]
fn a_late_reply_is_never_taken_for_the_next_request() {
    for via in BOTH {
        for address in ADDRESSINGS {
            let device = || Fake::smd4(via, on("MOTOR:AMAX", 1, || Act::Late(TIMEOUT * 3 / 2)));
            fails_then_recovers(
                device,
                address,
                "no reply from",
                &format!("{via:?} {address:?}"),
            );
        }
    }
}

fn cr_in_value(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"5.0000E+03\r\n", b"5.00\r00E+03\r\n")
}

fn trailing_data(answer: &[u8]) -> Vec<u8> {
    [answer, b"0x0888,0x0000,1\r\n"].concat()
}

/// The last digit corrupted into CR: the value cut short, and a line end more after it.
fn last_digit_cr(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"5.0000E+03\r\n", b"5.0000E+0\r\r\n")
}

/// The CR corrupted into a digit: appended to the value, the line ended by the LF alone.
fn cr_into_digit(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"5.0000E+03\r\n", b"5.0000E+034\n")
}

#[test]
fn a_corrupted_reply_is_line_noise_never_a_value() {
    let cases: [(&str, Corruption); 4] = [
        ("a CR inside the value", cr_in_value),
        ("data after the reply", trailing_data),
        ("the last digit turned into CR", last_digit_cr),
        ("the CR turned into a digit", cr_into_digit),
    ];
    for via in BOTH {
        for address in ADDRESSINGS {
            for (what, corrupt) in cases {
                let device = || Fake::smd4(via, on("MOTOR:AMAX", 1, move || Act::Map(corrupt)));
                fails_then_recovers(device, address, "line noise", &format!("{via:?} {what}"));
            }
        }
    }
}

#[test]
fn floods_end_at_the_deadline_in_bounded_memory() {
    let floods: [(&str, &[u8]); 3] = [
        ("junk lines", b"junk \x1b]0;title\x07 junk\r\n"),
        ("digits without a line end", b"1234567890"),
        ("replies of another drive", b"@7,0x0888,0x0000,5\r\n"),
    ];
    for via in BOTH {
        for (what, unit) in floods {
            let device = || {
                Fake::smd4(
                    via,
                    on("MOTOR:AMAX", 1, move || Act::Flood {
                        answer: false,
                        unit: unit.to_vec(),
                        // Past the deadline (the flood starts only once the request is
                        // sent), and over well inside the next request's resync, which waits
                        // for a quiet line for at most one more timeout: a loaded machine that
                        // serves the flood late still leaves it most of a second.
                        lasting: TIMEOUT + TIMEOUT / 10,
                    }),
                )
            };
            fails_then_recovers(device, &["--address", "1"], "no reply from", what);
        }
    }
}

#[test]
fn an_endless_multi_line_reply_still_obeys_the_deadline() {
    for via in BOTH {
        // Line after line, never a quiet gap: only the deadline ends it.
        let device = || {
            Fake::smd4(
                via,
                on("SYS:FLAGSV", 1, || Act::Trickle {
                    answer: true,
                    unit: b"[X]Standby\r\n".to_vec(),
                    every: Duration::from_millis(2),
                    // Past the deadline, and over well inside the next request's barrier wait,
                    // however slowly a loaded machine serves the trickle.
                    lasting: TIMEOUT * 5 / 4,
                }),
            )
        };
        let fake = device();
        let args = ["--protocol", "smd4", "--timeout", TIMEOUT_ARG];
        let run = tmclsh(&with(&fake, &[&args[..], &["-c", "SYS:FLAGSV"]].concat()));
        run.expect(3, "endless reply");
        assert!(run.stdout.is_empty(), "{}", run.stdout);
        assert!(
            run.stderr
                .contains("line noise: the reply to SYS:FLAGSV did not end in time"),
            "{}",
            run.stderr
        );
        let script = r#"
try { print(send("SYS:FLAGSV")); } catch (e) { print("failed"); }
print(send("MOTOR:VMAX")[0]);
"#;
        let run = run_script(&device(), script, &args);
        run.expect(0, "after an endless reply");
        assert_eq!(run.lines(), ["failed", "1.0000E+03"], "{}", run.stderr);
    }
}

fn foreign_first(answer: &[u8]) -> Vec<u8> {
    [b"@3,0x0888,0x0000,7.0000E+03,7.0000E+03\r\n", answer].concat()
}

#[test]
fn a_multi_line_reply_flooding_past_64_kib_is_cut_off() {
    for via in BOTH {
        let fake = Fake::smd4(
            via,
            on("SYS:FLAGSV", 1, || Act::Flood {
                answer: true,
                unit: b"[X]Standby\r\n".to_vec(),
                lasting: TIMEOUT / 2,
            }),
        );
        let run = tmclsh(&with(
            &fake,
            &[
                "--protocol",
                "smd4",
                "--timeout",
                TIMEOUT_ARG,
                "-c",
                "SYS:FLAGSV",
            ],
        ));
        run.expect(3, "flooding reply");
        assert!(
            run.stderr
                .contains("line noise: the reply to SYS:FLAGSV is longer than 64 KiB"),
            "{}",
            run.stderr
        );
    }
}

#[test]
fn a_reply_from_another_drive_is_reported_not_taken() {
    for via in BOTH {
        let fake = Fake::smd4(via, on("MOTOR:AMAX", 1, || Act::Map(foreign_first)));
        let run = tmclsh(&with(
            &fake,
            &["--protocol", "smd4", "--address", "1", "-c", "MOTOR:AMAX"],
        ));
        run.expect(0, "foreign reply");
        assert_eq!(run.lines(), ["@1,0x0888,0x0000,5.0000E+03,5.0000E+03"]);
        assert!(
            run.stderr
                .contains("ignored a reply from drive @3 while waiting for drive @1"),
            "{}",
            run.stderr
        );
    }
}

#[test]
fn a_hang_up_halfway_through_a_reply_is_a_lost_link() {
    for via in BOTH {
        let fake = Fake::smd4(via, on("MOTOR:AMAX", 1, || Act::HangUp(12)));
        let run = tmclsh(&with(
            &fake,
            &["--protocol", "smd4", "-c", "MOTOR:AMAX", "-c", "MOTOR:VMAX"],
        ));
        run.expect(3, "hang-up");
        assert!(run.stdout.is_empty(), "{}", run.stdout);
        assert!(run.stderr.contains("link lost"), "{}", run.stderr);
    }
}
