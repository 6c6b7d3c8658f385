//! Recordings, charts and the live watch of a simulated SMD4: in-process on a manual clock shared
//! by the drive and the recorder (positions and speeds of the trapezoid at exact times, the
//! standby flag in the flag words), the real binary over TCP on the wall clock (shape only, no
//! timing asserted), and `:watch` in the REPL on a pseudo-terminal.

use std::sync::Arc;
use std::time::Duration;

use tmclsh::clock::{Clock, ManualClock};
use tmclsh::commission::record::{self, Plan, Recording};
use tmclsh::commission::{ParamDevice, ParamValue, Tolerance};
use tmclsh::dialect::session::DialectSession;
use tmclsh::dialect::smd4::protocol::{Sflags, Smd4Spec};
use tmclsh::dialect::smd4::session::Smd4Session;
use tmclsh::dialect::smd4::sim::Smd4Sim;
use tmclsh::session::SessionOptions;
use tmclsh::sim::inprocess::SimLink;

use super::arg;
use super::repl::Terminal;
use crate::smd4::{Drive, Via, assert_exit};
use crate::util::tempdir;

/// Where a move of `distance` steps from standstill is after `t` seconds, and how fast: it starts
/// at `v0` (VSTART), accelerates at `a` to `v` (VMAX), cruises, decelerates at `a` to `v0`
/// (VSTOP) and stops — the ramp the SMD4 document describes.
fn trapezoid(distance: f64, v0: f64, v: f64, a: f64, t: f64) -> (f64, f64) {
    let ramp = (v - v0) / a;
    let ramp_distance = v0 * ramp + a * ramp * ramp / 2.0;
    let braking = ramp + (distance - 2.0 * ramp_distance) / v;
    let end = braking + ramp;
    if t <= ramp {
        (v0 * t + a * t * t / 2.0, v0 + a * t)
    } else if t <= braking {
        (ramp_distance + v * (t - ramp), v)
    } else if t < end {
        let dt = t - braking;
        (
            distance - ramp_distance + v * dt - a * dt * dt / 2.0,
            v - a * dt,
        )
    } else {
        (distance, 0.0)
    }
}

#[test]
fn samples_follow_a_move_exactly_on_a_shared_manual_clock() {
    let clock = Arc::new(ManualClock::new());
    let drive = Smd4Sim::new(tmclsh::dialect::smd4::sim::Smd4SimOptions::default());
    let link = SimLink::new(Box::new(drive), clock.clone());
    let mut session = Smd4Session::open(
        Box::new(link),
        SessionOptions::default(),
        tmclsh::dialect::smd4::session::Smd4SessionOptions::default(),
        None,
    )
    .unwrap();
    // 100 Hz start and stop, 1000 Hz/s both ways, 1000 Hz: 2000 steps take 2.81 s.
    for line in [
        "MOTOR:VSTART,100",
        "MOTOR:VSTOP,100",
        "MOTOR:AMAX,1000",
        "MOTOR:DMAX,1000",
        "MOTOR:VMAX,1000",
        "MOTOR:RUNA,2000",
    ] {
        assert!(session.execute(line).unwrap().ok(), "{line}");
    }
    let plan = Plan {
        params: ["MOTOR:PACT", "VACT", "SYS:FLAGS"]
            .iter()
            .map(|n| session.find(n).unwrap())
            .collect(),
        interval: Duration::from_millis(100),
        duration: Some(Duration::from_millis(3200)),
    };
    let clock_ref: &dyn Clock = clock.as_ref();
    let mut rows = Vec::new();
    let recording = record::record(&mut session, &plan, clock_ref, &mut || false, &mut |s| {
        rows.push(record::csv_row(s));
        Ok(())
    })
    .unwrap();
    assert_eq!(recording.columns, ["MOTOR:PACT", "MOTOR:VACT", "SYS:FLAGS"]);
    assert_eq!(recording.samples.len(), 33);
    let digits = Tolerance::Digits(Smd4Spec::builtin().snapshot.float_digits);
    for sample in &recording.samples {
        let t = sample.time_ms as f64 / 1000.0;
        let (position, speed) = trapezoid(2000.0, 100.0, 1000.0, 1000.0, t);
        let got = sample.values[0].as_f64().unwrap();
        // PACT is reported with two decimals.
        assert!(
            (got - position).abs() <= 0.005 + 1e-9,
            "at {t} s: position {got}, the trapezoid says {position}"
        );
        assert!(
            digits.same(&sample.values[1], &speed.into()),
            "at {t} s: speed {:?}, the trapezoid says {speed}",
            sample.values[1]
        );
        let ParamValue::Text(flags) = &sample.values[2] else {
            panic!("flag words are text: {:?}", sample.values[2]);
        };
        let sflags = u16::from_str_radix(&flags[2..6], 16).unwrap();
        assert_eq!(
            Sflags(sflags).standby(),
            speed == 0.0,
            "at {t} s: {flags} with speed {speed}"
        );
    }
    assert!(rows[5].starts_with("500,"), "{}", rows[5]);
    assert!(
        rows[5].contains(".0,"),
        "reals keep their point in the CSV: {}",
        rows[5]
    );
}

#[test]
fn record_and_plot_a_move_over_tcp() {
    let drive = Drive::start(Via::Tcp, &[]);
    let dir = tempdir();
    let csv = dir.join("ramp.csv");
    let record = format!(
        ":record {} MOTOR:PACT,motor:vact,SYS:FLAGS 20ms 400ms",
        arg(&csv)
    );
    let out = drive.run(&[
        "-c",
        "MOTOR:RUNA,5000",
        "-c",
        &record,
        "-c",
        ":plot",
        "-c",
        "MOTOR:STOP",
    ]);
    assert_exit(&out, 0);
    let text = std::fs::read_to_string(&csv).unwrap();
    let recording = Recording::from_csv(&text).unwrap();
    assert_eq!(recording.columns, ["MOTOR:PACT", "MOTOR:VACT", "SYS:FLAGS"]);
    let n = recording.samples.len();
    assert!(n >= 2, "{text}");
    let times: Vec<u64> = recording.samples.iter().map(|s| s.time_ms).collect();
    assert!(times.windows(2).all(|w| w[0] < w[1]), "{times:?}");
    let column = |i: usize| -> Vec<f64> {
        recording
            .samples
            .iter()
            .map(|s| s.values[i].as_f64().unwrap())
            .collect()
    };
    let positions = column(0);
    assert!(positions.windows(2).all(|w| w[0] <= w[1]), "{positions:?}");
    assert!(positions.iter().all(|p| (0.0..=5000.0).contains(p)));
    let vmax: f64 = Smd4Spec::builtin()
        .commands
        .get("MOTOR:VMAX")
        .and_then(|c| c.default.as_deref()?.parse().ok())
        .unwrap();
    assert!(column(1).iter().all(|v| (0.0..=vmax).contains(v)), "{text}");
    assert!(
        recording
            .samples
            .iter()
            .all(|s| matches!(&s.values[2], ParamValue::Text(t) if t.starts_with("0x"))),
        "{text}"
    );
    let shown = String::from_utf8_lossy(&out.stdout);
    assert!(
        shown.contains(&format!(
            "recorded {n} samples of MOTOR:PACT, MOTOR:VACT, SYS:FLAGS"
        )),
        "{shown}"
    );
    let titles: Vec<&str> = shown.lines().filter(|l| l.starts_with("MOTOR:")).collect();
    assert_eq!(titles, ["MOTOR:PACT", "MOTOR:VACT"], "{shown}");
    assert!(
        shown.contains("SYS:FLAGS: not numbers, not drawn"),
        "{shown}"
    );
}

#[test]
fn record_refuses_what_cannot_be_read() {
    let drive = Drive::start(Via::Pty, &[]);
    for (line, error) in [
        (
            ":record x.csv MOTOR:RUNV 10ms 1s",
            "MOTOR:RUNV has no value to read (it starts a move)",
        ),
        (
            ":record x.csv SYS:FLAGSV 10ms 1s",
            "SYS:FLAGSV has no value to read (a multi-line listing",
        ),
        (
            ":record x.csv EN 10ms 1s",
            "'EN' could be LIMIT:EN or BOOST:EN",
        ),
        (
            ":record x.csv MOTOR:VMAXX 10ms 1s",
            "did you mean MOTOR:VMAX?",
        ),
    ] {
        let out = drive.run(&["-c", line]);
        assert_exit(&out, 2);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(error), "{line}: {err}");
    }
}

#[test]
fn watch_shows_values_labels_units_and_real_values_and_ctrl_c_stops_the_motor() {
    let mut drive = Drive::start(Via::Tcp, &["--manual-clock"]);
    let connection = drive.connection();
    let args: Vec<&str> = connection.iter().map(String::as_str).collect();
    let mut term = Terminal::spawn(&args);
    term.until("smd4> ");
    term.send(":watch MOTOR:VMAX,SYS:MODE,MOTOR:IR 50ms\r");
    let frame = term.until("MOTOR:IR");
    let frame = frame + term.until("A rms").as_str();
    assert!(frame.contains("the drive every 50 ms"), "{frame:?}");
    assert!(frame.contains("Hz (real 1000)"), "{frame:?}");
    assert!(frame.contains("1 (Remote)"), "{frame:?}");
    term.until("any key stops");
    term.send("q");
    term.until("smd4> ");

    term.send("MOTOR:RUNV,+\r");
    term.until("smd4> ");
    drive.console("advance 2s");
    term.send(":watch MOTOR:VACT\r");
    term.until("any key stops");
    term.send("\x03");
    term.until("MOTOR:STOP");
    term.until("smd4> ");
    drive.console("advance 5s");
    assert!(drive.motor().standby, "stopped");
    term.send(":quit\r");
    assert_eq!(term.exit_code(), 0);
    assert!(term.cooked(), "the terminal is back in line mode with echo");
}
