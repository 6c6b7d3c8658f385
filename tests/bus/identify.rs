//! Identification on a shared bus: back-to-back sessions to an ASCII module and a binary-only
//! one, what another program left on the line, a host-address clash that garbles every answer to
//! 136 (refused with its cause, never sent 139 on a guess), and `:target` switching.

use super::{bus_sim, on, sent};
use crate::util::{code, run_with_stdin, stderr, stdout, tempdir};

#[test]
fn back_to_back_snapshots_of_an_ascii_and_a_binary_only_module_identify_each() {
    let sim = bus_sim(&[]);
    let dir = tempdir();
    let (a, b) = (dir.join("a.toml"), dir.join("b.toml"));
    let log = dir.join("b.log");
    let out = on(&sim, &["-m", "2", "snapshot", "save", a.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = on(
        &sim,
        &[
            "-m",
            "3",
            "--log",
            log.to_str().unwrap(),
            "snapshot",
            "save",
            b.to_str().unwrap(),
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("of the TMCM-6214 at address 3"),
        "{}",
        stdout(&out)
    );
    let log = std::fs::read_to_string(&log).unwrap();
    assert!(!sent(&log).iter().any(|l| l.contains("(139)")), "{log}");
    // Twenty more pairs of sessions, each module identified every time.
    for round in 0..20 {
        for (module, name) in [("2", "TMCM-6110"), ("3", "TMCM-6214")] {
            let out = on(&sim, &["-v", "-m", module, "-c", "GAP 1, 0"]);
            assert_eq!(code(&out), 0, "round {round}: {}", stderr(&out));
            assert!(
                stderr(&out).contains(&format!("{name}, firmware")),
                "round {round}: {}",
                stderr(&out)
            );
        }
    }
}

#[test]
fn a_module_at_the_host_address_garbling_136_is_named_and_nothing_is_guessed() {
    // Module 2 sits at the host address 2 on a line where every module hears the others: it
    // answers module 3's reply to 136 as a request to itself, every time.
    let sim = bus_sim(&["--shared-line"]);
    let dir = tempdir();
    let log = dir.join("b.log");
    let b = dir.join("b.toml");
    let out = on(
        &sim,
        &[
            "-m",
            "2",
            "snapshot",
            "save",
            dir.join("a.toml").to_str().unwrap(),
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = on(
        &sim,
        &[
            "-m",
            "3",
            "--log",
            log.to_str().unwrap(),
            "snapshot",
            "save",
            b.to_str().unwrap(),
        ],
    );
    let err = stderr(&out);
    assert_eq!(code(&out), 3, "{err}");
    for said in [
        "module 3 (C) is not identified",
        "a reply from module 2 (B)",
        "host address",
        "--profile NAME",
        "--binary",
    ] {
        assert!(err.contains(said), "{said}: {err}");
    }
    assert!(!b.exists());
    let log = std::fs::read_to_string(&log).unwrap();
    let sent = sent(&log);
    // Asked twice, then nothing more: no 139, no request.
    assert_eq!(sent.len(), 2, "{log}");
    assert!(
        sent.iter().all(|l| l.contains("136 to module 3 (C)")),
        "{log}"
    );
    // Told what it is, the session goes on in binary frames without asking it into ASCII mode.
    let again = dir.join("c.log");
    let out = on(
        &sim,
        &[
            "-m",
            "3",
            "--binary",
            "--log",
            again.to_str().unwrap(),
            "-c",
            "GGP 0, 0",
        ],
    );
    let log = std::fs::read_to_string(&again).unwrap();
    assert!(!log.contains("(139)"), "{log}");
    assert!(stderr(&out).contains("not identified"), "{}", stderr(&out));
}

#[test]
fn what_another_program_left_on_the_line_is_waited_out_before_the_first_frame() {
    let sim = bus_sim(&[]);
    let dir = tempdir();
    let log = dir.join("left.log");
    {
        let mut port = sim.pty();
        // A request to module 1 whose reply nobody reads, then half a frame to module 3.
        port.send(&[1, 6, 1, 0, 0, 0, 0, 0, 8]);
        port.send(&[3, 6, 1, 0]);
    }
    let out = on(
        &sim,
        &[
            "-v",
            "-m",
            "3",
            "--log",
            log.to_str().unwrap(),
            "-c",
            "GAP 1, 0",
        ],
    );
    let log = std::fs::read_to_string(&log).unwrap();
    assert_eq!(code(&out), 0, "{}\n{log}", stderr(&out));
    assert!(
        stderr(&out).contains("TMCM-6214, firmware"),
        "{}",
        stderr(&out)
    );
    assert_eq!(stdout(&out).trim_end(), "BC 100 0");
}

#[test]
fn switching_between_an_ascii_and_a_binary_only_module_keeps_both_working() {
    let sim = bus_sim(&[]);
    let dir = tempdir();
    let log = dir.join("switch.log");
    let mut input = String::new();
    for _ in 0..20 {
        input.push_str(":target 2\nGAP 1, 0\n:target 3\nGAP 1, 0\nBGAP 1, 0\nAGAP 1, 0\n");
    }
    let out = run_with_stdin(
        &["--port", &sim.first, "--log", log.to_str().unwrap()],
        &input,
    );
    let log = std::fs::read_to_string(&log).unwrap();
    assert_eq!(code(&out), 0, "{}\n{log}", stderr(&out));
    let replies = stdout(&out)
        .lines()
        .filter(|l| l.ends_with(" 100 0"))
        .count();
    assert_eq!(replies, 80, "{}", stdout(&out));
    // The binary-only module never asked into ASCII mode, each module asked once what it is.
    let sent = sent(&log);
    assert!(
        !sent.iter().any(|l| l.contains("(139) to module 3")),
        "{log}"
    );
    for module in ["module 1 (A)", "module 2 (B)", "module 3 (C)"] {
        let asked = sent
            .iter()
            .filter(|l| l.contains(&format!("136 to {module} in binary")))
            .count();
        assert_eq!(asked, 1, "{module}: {log}");
    }
}
