//! A 2-wire RS-485 adapter that hands back every byte sent (`tmclsh sim --adapter-echo`):
//! identification, every TMCL echo mode, binary, SMD4 and the scan through it, the echo found at
//! open and said once; and an echo that differs from what was sent (a hostile device) is line
//! noise, never a value.

use crate::sim::Sim;

use super::{Act, BOTH, Fake, Run, on, run_script, tmclsh, with};

/// What tmclsh says when it finds the echo.
const FOUND: &str = "the adapter echoes what it sends (2-wire RS-485?): stripping it";

fn at(sim: &Sim, args: &[&str]) -> Run {
    let flag = if sim.first.starts_with("/dev/") {
        "--port"
    } else {
        "--tcp"
    };
    let mut all = vec![flag.to_string(), sim.first.clone()];
    all.extend(args.iter().map(|a| a.to_string()));
    tmclsh(&all)
}

fn found_once(run: &Run, what: &str) {
    assert_eq!(
        run.stderr.matches(FOUND).count(),
        1,
        "{what}: the echo is announced once\n{}",
        run.stderr
    );
}

#[test]
fn every_echo_mode_identifies_and_answers_through_an_echoing_adapter() {
    let pty = Sim::start(&["--pty", "--adapter-echo"]);
    let tcp = Sim::start(&["--listen", "127.0.0.1:0", "--adapter-echo"]);
    // Paced like a serial line: the module's character echo must not mix with the adapter's.
    let paced = Sim::start(&["--pty", "--adapter-echo", "--baud", "19200"]);
    let mut value = 1000;
    for (sim, baud) in [(&pty, &[][..]), (&tcp, &[]), (&paced, &["--baud", "19200"])] {
        for mode in ["char", "line", "none"] {
            let what = format!("{mode} echo on {}", sim.first);
            value += 1;
            let set = format!("SAP 4, 0, {value}");
            let args = [baud, &["--echo", mode, "-v", "-c", &set, "-c", "GAP 4, 0"]].concat();
            let run = at(sim, &args);
            run.expect(0, &what);
            let answer = format!("BA 100 {value}");
            assert_eq!(run.lines(), [&answer, &answer], "{what}");
            assert!(
                run.stderr
                    .contains("TMCM-142, firmware 142V1.06, profile tmcm-142"),
                "{what}: identified\n{}",
                run.stderr
            );
            found_once(&run, &what);
        }
    }
}

#[test]
fn binary_requests_get_their_replies_not_their_echoes() {
    let sim = Sim::start(&["--pty", "--adapter-echo", "--modules", "5:tmcm-6214"]);
    // A binary-only module: identification, then SAP 4, 5, 1000 — whose echo, taken for the
    // reply, read as status 4, "invalid value".
    for strip in [&[][..], &["--local-echo", "on"], &["--local-echo", "off"]] {
        let what = format!("tmcm-6214 {strip:?}");
        let args = [
            strip,
            &["-m", "5", "-c", "SAP 4, 5, 1000", "-c", "GAP 4, 5"],
        ]
        .concat();
        let run = at(&sim, &args);
        run.expect(0, &what);
        assert_eq!(run.lines(), ["BE 100 1000", "BE 100 1000"], "{what}");
        if strip.is_empty() {
            found_once(&run, &what);
        }
        if strip.contains(&"off") {
            assert!(
                run.stderr.contains("the request itself, handed back"),
                "{what}: the echo is set aside without stripping\n{}",
                run.stderr
            );
        }
    }
    let sim = Sim::start(&["--pty", "--adapter-echo"]);
    let run = at(&sim, &["--binary", "-c", "SAP 4, 0, 7", "-c", "GAP 4, 0"]);
    run.expect(0, "--binary");
    assert_eq!(run.lines(), ["BA 100 7", "BA 100 7"]);
    found_once(&run, "--binary");
}

#[test]
fn without_stripping_identification_is_not_fooled_by_the_echo() {
    // The echo of 136 read as its answer was '????????' and no profile, or a wrong one.
    let sim = Sim::start(&["--pty", "--adapter-echo"]);
    let run = at(
        &sim,
        &["--local-echo", "off", "-v", "--binary", "-c", "GAP 4, 0"],
    );
    run.expect(0, "stripping off");
    assert_eq!(run.lines(), ["BA 100 1000000"]);
    assert!(
        run.stderr.contains("firmware 142V1.06") && !run.stderr.contains(FOUND),
        "{}",
        run.stderr
    );
}

#[test]
fn smd4_lines_and_scans_through_an_echoing_adapter() {
    let sim = Sim::start(&["--pty", "--protocol", "smd4", "--adapter-echo"]);
    let run = at(
        &sim,
        &["--protocol", "smd4", "-c", "MOTOR:AMAX", "-c", "MOTOR:VMAX"],
    );
    run.expect(0, "smd4");
    assert_eq!(run.lines().len(), 2, "{}", run.stdout);
    assert!(run.stdout.contains("E+"), "values: {}", run.stdout);
    found_once(&run, "smd4");
    let sim = Sim::start(&["--pty", "--adapter-echo", "--modules", "1,2,3"]);
    let run = at(&sim, &["scan", "--addresses", "1-4"]);
    run.expect(0, "scan");
    assert!(
        run.stdout.contains("3 modules answered"),
        "{}\n{}",
        run.stdout,
        run.stderr
    );
}

#[test]
fn an_echo_where_there_is_none_is_line_noise() {
    let sim = Sim::start(&["--pty"]);
    let run = at(&sim, &["--local-echo", "on", "--binary", "-c", "GAP 4, 0"]);
    run.expect(3, "--local-echo on without an echo");
    assert!(run.stdout.is_empty(), "no value: {}", run.stdout);
    assert!(
        run.stderr.contains("line noise: the adapter's echo"),
        "{}",
        run.stderr
    );
}

/// One byte of the echo changed: a collision on the line.
fn collided(echo: &[u8]) -> Vec<u8> {
    let mut echo = echo.to_vec();
    if let Some(b) = echo.iter_mut().find(|b| b.is_ascii_uppercase()) {
        *b = b'X';
    }
    echo
}

#[test]
fn an_echo_that_differs_is_line_noise_never_a_value() {
    for via in BOTH {
        for (dialect, first, line, args) in [
            (
                "smd4",
                "MOTOR:VMAX",
                "MOTOR:AMAX",
                &["--protocol", "smd4"][..],
            ),
            ("tmcl", "GAP 1, 0", "GAP 4, 0", &[][..]),
        ] {
            let what = format!("{dialect} {via:?}");
            // The first request finds the echo; the second one's is garbled.
            let device = || Fake::echoing(dialect, via, on(line, 1, || Act::GarbleEcho(collided)));
            let fake = device();
            let run = tmclsh(&with(&fake, &[args, &["-c", first, "-c", line]].concat()));
            run.expect(3, &what);
            assert_eq!(run.lines().len(), 1, "{what}: no value: {}", run.stdout);
            assert!(
                run.stderr
                    .contains("line noise: the adapter's echo of what was sent"),
                "{what}: {}",
                run.stderr
            );
            found_once(&run, &what);
            // The next request in the same run gets its own answer.
            let script = format!(
                "print(send(\"{first}\"));\n\
                 try {{ print(send(\"{line}\")); }} catch (e) {{ print(`failed ${{e.exit}}`); }}\n\
                 print(send(\"{first}\"));"
            );
            let run = run_script(&device(), &script, args);
            run.expect(0, &what);
            let lines = run.lines();
            assert_eq!(lines.len(), 3, "{what}: {}\n{}", run.stdout, run.stderr);
            assert_eq!(lines[1], "failed 3", "{what}: {}", run.stderr);
            assert_eq!(lines[0], lines[2], "{what}: its own answer");
        }
    }
}

#[test]
fn line_says_the_echo_is_stripped_once_it_is_found() {
    let echoing = Sim::start(&["--pty", "--adapter-echo"]);
    let plain = Sim::start(&["--pty"]);
    for (sim, expected) in [(&echoing, "on: "), (&plain, "off")] {
        let run = at(sim, &["-c", "GAP 4, 0", "-c", ":line"]);
        run.expect(0, &sim.first);
        let row = run
            .lines()
            .into_iter()
            .find_map(|l| l.strip_prefix("echo strip"))
            .unwrap_or_else(|| panic!("no echo strip row:\n{}", run.stdout))
            .trim()
            .to_string();
        assert!(row.starts_with(expected), "{}: {row}", sim.first);
    }
}
