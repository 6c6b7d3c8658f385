//! TMCL in ASCII mode (character, line and no echo) under a hostile line, on a pty and on TCP.

use std::time::Duration;

use super::{Act, BOTH, Corruption, Fake, on, replace_last, run_script, tmclsh, with};

/// The reply timeout of every run here.
/// Long enough that a late reply, due half a timeout after it, lands well inside the wait for a
/// quiet line on a loaded machine (the late-reply tests depend on that window, ±300 ms).
const TIMEOUT: Duration = Duration::from_millis(1000);
const TIMEOUT_ARG: &str = "1000";

/// A script whose first request meets the misbehaviour and whose second must get its own
/// answer: GAP 4 is 1000000 on a fresh module, GAP 1 is 0.
const FIRST_FAILS_SECOND_ANSWERS: &str = r#"
try { print(gap(4, 0)); } catch (e) { print("failed"); }
print(gap(1, 0));
"#;

/// Two identical requests; GAP 1 is 0 on a fresh module.
const IDENTICAL: &str = r#"
try { print(gap(1, 0)); } catch (e) { print("failed"); }
print(gap(1, 0));
"#;

fn set_echo(fake: &Fake, echo: &str) {
    let run = tmclsh(&with(fake, &["-c", &format!(":echo {echo}")]));
    run.expect(0, "setting the echo");
}

/// On a device from `device`, the -c run fails with exit 3 and `message`; on another, the
/// script run fails the first request and answers the second with its own value. (Two devices:
/// what one run leaves on the line is not the next run's business.)
fn fails_then_recovers(device: impl Fn() -> Fake, message: &str, what: &str) {
    fails_then_recovers_at(device, "9600", message, what);
}

/// As [`fails_then_recovers`], with the line's baud rate.
fn fails_then_recovers_at(device: impl Fn() -> Fake, baud: &str, message: &str, what: &str) {
    let options = ["--timeout", TIMEOUT_ARG, "--baud", baud];
    let fake = &device();
    let run = tmclsh(&with(fake, &[&options[..], &["-c", "GAP 4, 0"]].concat()));
    run.expect(3, what);
    assert!(run.stdout.is_empty(), "{what}: no value: {}", run.stdout);
    assert!(run.stderr.contains(message), "{what}: {}", run.stderr);
    let fake = &device();
    let run = run_script(fake, FIRST_FAILS_SECOND_ANSWERS, &options);
    run.expect(0, what);
    let requests = fake.requests.lock().unwrap().clone();
    // The device's rule matches ASCII lines only: a session that went on in binary frames never
    // met it, and its first answer proves nothing. Say so rather than fail on the value.
    assert!(
        requests.iter().any(|r| r.contains("GAP 4, 0")),
        "{what}: the request never reached the device as an ASCII line (the session went on \
         in binary?): {}\nrequests: {requests:?}",
        run.stderr
    );
    assert_eq!(
        run.lines(),
        ["failed", "0"],
        "{what}: {}\nrequests: {requests:?}",
        run.stderr
    );
}

#[test]
fn a_late_reply_is_never_taken_for_the_next_request_in_any_echo_mode() {
    for via in BOTH {
        for echo in ["char", "line", "none"] {
            // Later than the timeout, within the wait for a quiet line that follows it.
            let device = || {
                let fake = Fake::tmcl(via, on("GAP 4, 0", 1, || Act::Late(TIMEOUT * 3 / 2)));
                set_echo(&fake, echo);
                fake
            };
            fails_then_recovers(device, "no reply from module 1 (A) within 1000 ms", echo);
        }
    }
}

/// The answer with its value replaced: a reply nobody asked for.
fn stale(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b" 0\r", b" 777777\r")
}

#[test]
fn with_an_echo_even_an_identical_request_takes_only_the_reply_after_its_own_echo() {
    for via in BOTH {
        for echo in ["char", "line"] {
            // Echo and reply of the first request come only when the second has been sent,
            // later than any wait for quiet could cover.
            let fake = Fake::tmcl(via, on("GAP 1, 0", 1, || Act::HoldUntilNext(stale)));
            set_echo(&fake, echo);
            let run = run_script(&fake, IDENTICAL, &["--timeout", TIMEOUT_ARG]);
            run.expect(0, echo);
            assert_eq!(
                run.lines(),
                ["failed", "0"],
                "{via:?} {echo}: {}",
                run.stderr
            );
        }
    }
}

#[test]
fn without_an_echo_a_reply_later_than_the_quiet_wait_is_discarded_before_a_barrier() {
    // With echo off nothing in a reply names its request, and this one comes only after the
    // line has been quiet for the resync window, when the next line goes out: that line is the
    // barrier (`AGAP 1, 255`, refused with status 4), and the late reply before its refusal is
    // discarded, not taken by the next request.
    for via in BOTH {
        let fake = Fake::tmcl(via, on("GAP 1, 0", 1, || Act::HoldUntilNext(stale)));
        set_echo(&fake, "none");
        let log = crate::util::tempdir().join(format!("barrier-{via:?}.log"));
        let log_arg = log.to_str().unwrap();
        let run = run_script(
            &fake,
            IDENTICAL,
            &["--timeout", TIMEOUT_ARG, "--log", log_arg],
        );
        run.expect(0, "echo off");
        assert_eq!(run.lines(), ["failed", "0"], "{via:?}: {}", run.stderr);
        let transcript = std::fs::read_to_string(&log).unwrap();
        let _ = std::fs::remove_file(&log);
        assert!(
            transcript.contains("barrier: AGAP 1, 255 to module 1 (A)")
                && transcript.contains("777777"),
            "{via:?}: the barrier and the late reply it discarded are in the transcript:\n{transcript}"
        );
    }
}

/// The reply's value cut short by a byte corrupted into CR: `1000000` read as `100`.
fn cr_in_value(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"1000000\r", b"100\r0000\r")
}

fn trailing_data(answer: &[u8]) -> Vec<u8> {
    [answer, b"143\r"].concat()
}

/// The last digit corrupted into a line end: `100000`, then the reply's own CR.
fn last_digit_cr(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"1000000\r", b"100000\r\r")
}

fn last_digit_lf(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"1000000\r", b"100000\n\r")
}

/// The last digit corrupted into 0xA0, which Latin-1 reads as a no-break space.
fn last_digit_nbsp(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"1000000\r", b"100000\xA0\r")
}

/// The first digit corrupted into a sign: `-000000` parses, but no module writes it.
fn digit_into_sign(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"1000000\r", b"-000000\r")
}

fn unknown_status(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"BA 100 ", b"BA 150 ")
}

fn status_cut_short(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"BA 100 1000000\r", b"BA 1\r00 1000000\r")
}

#[test]
fn a_corrupted_reply_is_line_noise_never_a_value_nor_a_refusal() {
    let cases: [(&str, Corruption, &str); 8] = [
        ("a CR inside the value", cr_in_value, "line noise"),
        ("data after the reply", trailing_data, "line noise"),
        ("the last digit turned into CR", last_digit_cr, "line noise"),
        ("the last digit turned into LF", last_digit_lf, "line noise"),
        (
            "a digit turned into a sign",
            digit_into_sign,
            "not a valid reply",
        ),
        (
            "the last digit turned into a no-break space",
            last_digit_nbsp,
            "not a valid reply",
        ),
        ("an unknown status", unknown_status, "not a valid reply"),
        (
            "a CR inside the status",
            status_cut_short,
            "not a valid reply",
        ),
    ];
    for via in BOTH {
        for (what, corrupt, message) in cases {
            let device = || Fake::tmcl(via, on("GAP 4, 0", 1, move || Act::Map(corrupt)));
            fails_then_recovers(device, message, &format!("{via:?}: {what}"));
        }
    }
}

#[test]
fn what_follows_a_reply_on_a_paced_line_is_waited_for() {
    // The corrupted reply arrives a byte at a time, as from a serial line: the rest of the
    // value comes after the CR that cut it, and must still be seen. 8 ms a byte: 1200 baud.
    for via in BOTH {
        let device = || {
            Fake::tmcl(
                via,
                on("GAP 4, 0", 1, || Act::Paced {
                    at_once: b"AGAP 4, 0\r".to_vec(),
                    paced: b"BA 100 100\r0000\r".to_vec(),
                    gap: Duration::from_millis(8),
                }),
            )
        };
        fails_then_recovers_at(device, "1200", "line noise", &format!("{via:?}: paced"));
    }
}

#[test]
fn floods_end_at_the_deadline_in_bounded_memory_and_the_next_request_gets_its_answer() {
    let floods: [(&str, &[u8]); 3] = [
        ("junk lines", b"junk \x1b[2J junk\r\n"),
        ("digits without a line end", b"1234567890"),
        ("replies from another module", b"BC 100 5\r"),
    ];
    for via in BOTH {
        for (what, unit) in floods {
            let device = || {
                Fake::tmcl(
                    via,
                    on("GAP 4, 0", 1, move || Act::Flood {
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
            fails_then_recovers(
                device,
                "no reply from module 1 (A)",
                &format!("{via:?}: {what}"),
            );
        }
    }
}

fn foreign_first(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"BA 100", b"BC 100 5\rBA 100")
}

#[test]
fn a_reply_from_another_module_is_reported_not_taken() {
    for via in BOTH {
        let fake = Fake::tmcl(via, on("GAP 4, 0", 1, || Act::Map(foreign_first)));
        let run = tmclsh(&with(&fake, &["-c", "GAP 4, 0", "-c", "GAP 1, 0"]));
        run.expect(0, "foreign reply");
        assert_eq!(run.lines(), ["BA 100 1000000", "BA 100 0"]);
        assert!(
            run.stderr
                .contains("ignored a reply from module 3 (C) while waiting for module 1 (A)"),
            "{}",
            run.stderr
        );
    }
}

#[test]
fn a_hang_up_halfway_through_a_reply_is_a_lost_link() {
    for via in BOTH {
        let fake = Fake::tmcl(via, on("GAP 4, 0", 1, || Act::HangUp(14)));
        let run = tmclsh(&with(&fake, &["-c", "GAP 4, 0", "-c", "GAP 1, 0"]));
        run.expect(3, "hang-up");
        assert!(run.stdout.is_empty(), "{}", run.stdout);
        assert!(run.stderr.contains("link lost"), "{}", run.stderr);
        if via == super::Via::Tcp {
            // The device is back for the next connection, and answers it.
            let run = tmclsh(&with(&fake, &["-c", "GAP 4, 0"]));
            run.expect(0, "after the hang-up");
            assert_eq!(run.lines(), ["BA 100 1000000"]);
        }
    }
}

fn garbled_echo(answer: &[u8]) -> Vec<u8> {
    replace_last(answer, b"AGAP 4, 0", b"AGAP 4, 8")
}

#[test]
fn a_garbled_echo_reaches_the_transcript_as_line_noise() {
    for via in BOTH {
        let fake = Fake::tmcl(via, on("GAP 4, 0", 1, || Act::Map(garbled_echo)));
        let log = crate::util::tempdir().join("t.log");
        let run = tmclsh(&with(
            &fake,
            &["--log", log.to_str().unwrap(), "-c", "GAP 4, 0"],
        ));
        run.expect(3, "garbled echo");
        assert!(
            run.stderr
                .contains("line noise: module 1 (A) echoed 'AGAP 4, 8' for 'AGAP 4, 0'"),
            "{}",
            run.stderr
        );
        let text = std::fs::read_to_string(&log).unwrap();
        assert!(
            text.contains(r#" rx "AGAP 4, 8\r" ; garbled echo: line noise, discarded"#),
            "{text}"
        );
        assert!(
            text.contains(" -- line noise: module 1 (A) echoed 'AGAP 4, 8'"),
            "{text}"
        );
    }
}
