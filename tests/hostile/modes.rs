//! Mode changes on a slow line and host addresses outside A..Z, against the real simulator.

use crate::sim::Sim;

use super::tmclsh;

fn on(sim: &Sim, args: &[&str]) -> super::Run {
    let mut all = vec!["--port".to_string(), sim.first.clone()];
    all.extend(args.iter().map(|a| a.to_string()));
    tmclsh(&all)
}

#[test]
fn mode_changes_wait_as_long_as_a_slow_line_needs() {
    // At 600 baud the nine bytes of 139 and of its reply take 300 ms on the wire.
    let sim = Sim::start(&["--pty", "--baud", "600"]);
    let slow = ["--baud", "600", "--timeout", "3000"];
    let run = on(
        &sim,
        &[
            &slow[..],
            &["-c", "GAP 4, 0", "-c", ":bin", "-c", "GAP 4, 0"],
        ]
        .concat(),
    );
    run.expect(0, "600 baud");
    assert_eq!(
        run.lines(),
        [
            "BA 100 1000000",
            "module 1 (A) is in binary direct mode: lines go out as binary frames; :ascii returns",
            "BA 100 1000000"
        ],
        "{}",
        run.stderr
    );
    assert!(run.stderr.is_empty(), "nothing unexpected: {}", run.stderr);
}

#[test]
fn a_module_that_may_be_in_binary_mode_gets_no_ascii_resync_bytes() {
    // BIN without a reply: the module is in binary mode afterwards, where a CR would shift the
    // next frame. Each run ends with BIN (the module was found in binary mode), and the next
    // run's 139 frame must still be understood.
    let sim = Sim::start(&["--pty", "--baud", "600", "--no-reply-to-bin"]);
    for round in 0..3 {
        let run = on(
            &sim,
            &["--baud", "600", "--timeout", "3000", "-c", "GAP 4, 0"],
        );
        run.expect(0, &format!("run {round}"));
        assert_eq!(
            run.lines(),
            ["BA 100 1000000"],
            "run {round}: {}",
            run.stderr
        );
    }
}

#[test]
fn any_host_address_is_read_in_replies() {
    // GP 76 takes 0..255; the module starts its replies with the byte 0x40 + address.
    let sim = Sim::start(&["--pty"]);
    for host in [0u8, 26, 27, 150, 200, 224, 255] {
        let run = on(
            &sim,
            &["-c", &format!("SGP 76, 0, {host}"), "-c", "GAP 4, 0"],
        );
        run.expect(0, &format!("host {host}"));
        let replies = run.lines();
        assert_eq!(replies.len(), 2, "host {host}: {}", run.stderr);
        assert!(
            replies[1].ends_with("A 100 1000000"),
            "host {host}: {:?}",
            replies[1]
        );
        // A new session reads the module with that host address from its first reply on.
        let run = on(&sim, &["-c", "GAP 4, 0"]);
        run.expect(0, &format!("host {host}, new session"));
        let first = run.stdout.chars().next().unwrap();
        let host_char = char::from(0x40u8.wrapping_add(host));
        if !host_char.is_control() {
            assert_eq!(first, host_char, "host {host}: {}", run.stdout);
        }
        assert!(
            run.stdout.trim_end().ends_with("A 100 1000000"),
            "host {host}"
        );
    }
    let run = on(&sim, &["-c", "SGP 76, 0, 2"]);
    run.expect(0, "back to B");
}
