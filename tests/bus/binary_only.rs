//! Binary-only modules stay binary: 139 and a write of global parameter 67 (its ASCII start bit)
//! are refused before anything is sent, and a scan shows their echo as `binary`.

use super::{bus_sim, on, sent};
use crate::util::{code, run_with_stdin, stderr, stdout, tempdir};

#[test]
fn the_ascii_start_bit_and_139_are_refused_unsent_to_a_binary_only_module() {
    let sim = bus_sim(&[]);
    let dir = tempdir();
    for (n, line) in ["SGP 67, 0, 1", "STGP 67, 0", "139"]
        .into_iter()
        .enumerate()
    {
        let log = dir.join(format!("{n}.log"));
        let out = on(
            &sim,
            &["-m", "3", "--log", log.to_str().unwrap(), "-c", line],
        );
        assert_eq!(code(&out), 2, "{line}: {}", stderr(&out));
        let log = std::fs::read_to_string(&log).unwrap();
        let sent = sent(&log);
        assert!(
            sent.iter().all(|l| l.contains("136 to module 3 (C)")),
            "{line}: {log}"
        );
    }
    let out = on(&sim, &["-m", "3", "-c", "SGP 67, 0, 1"]);
    assert!(
        stderr(&out).contains("the TMCM-6214 has no ASCII interface"),
        "{}",
        stderr(&out)
    );
    // The same line to the TMCM-6110 beside it is its own business: sent and answered.
    let out = on(&sim, &["-m", "2", "-c", "SGP 67, 0, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    // In the shell, a refusal and the session goes on.
    let out = run_with_stdin(
        &["--port", &sim.first, "-m", "3", "--keep-going"],
        "SGP 67, 0, 1\nGAP 1, 0\n",
    );
    assert_eq!(stdout(&out).trim_end(), "BC 100 0", "{}", stderr(&out));
    assert!(
        stderr(&out).contains("has no ASCII interface"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_scan_shows_a_binary_only_module_s_echo_as_binary() {
    let sim = bus_sim(&[]);
    let out = on(&sim, &["scan", "--addresses", "1-3"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let row = |address: &str| {
        text.lines()
            .find(|l| l.split_whitespace().next() == Some(address))
            .unwrap_or_else(|| panic!("{address}: {text}"))
            .split_whitespace()
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    assert_eq!(row("3")[4], "binary", "{text}");
    assert_eq!(row("2")[4], "char", "{text}");
}
