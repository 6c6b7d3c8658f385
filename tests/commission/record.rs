//! Recordings whose samples follow a simulated move: in-process on a manual clock shared by the
//! simulator and the recorder (exact positions at exact times), and the real binary over TCP on
//! the wall clock (shape only, no timing asserted), with its chart.

use std::sync::Arc;
use std::time::Duration;

use tmclsh::clock::{Clock, ManualClock};
use tmclsh::commission::ParamDevice;
use tmclsh::commission::record::{self, Plan, Recording};
use tmclsh::dialect::session::DialectSession;
use tmclsh::dialect::tmcl::profile::Profile;
use tmclsh::dialect::tmcl::session::TmclSession;
use tmclsh::dialect::tmcl::sim::Bus;
use tmclsh::session::SessionOptions;
use tmclsh::sim::inprocess::SimLink;

use super::{arg, expect};
use crate::sim::Sim;
use crate::util::{stdout, tempdir};

/// Where the trapezoid of a move of `distance` microsteps (from 0, at `v` pps and `a` pps²)
/// has the motor after `t` seconds.
fn trapezoid(distance: f64, v: f64, a: f64, t: f64) -> f64 {
    let ramp = v / a;
    let total = 2.0 * ramp + (distance - v * v / a) / v;
    if t <= ramp {
        a * t * t / 2.0
    } else if t <= total - ramp {
        v * ramp / 2.0 + v * (t - ramp)
    } else if t < total {
        let left = total - t;
        distance - a * left * left / 2.0
    } else {
        distance
    }
}

#[test]
fn samples_follow_a_move_exactly_on_a_shared_manual_clock() {
    let clock = Arc::new(ManualClock::new());
    let link = SimLink::new(Box::new(Bus::builtin()), clock.clone());
    let mut session = TmclSession::open(
        Box::new(link),
        Profile::builtin(),
        SessionOptions::default(),
        None,
    )
    .unwrap();
    // Speeds in pps (AP255 = 1): 8000 pps, 16000 pps²; 8000 steps take 1.5 s.
    for line in ["SAP 255, 0, 1", "SAP 4, 0, 8000", "SAP 5, 0, 16000"] {
        assert!(session.execute(line).unwrap().ok(), "{line}");
    }
    assert!(session.execute("MVP ABS, 0, 8000").unwrap().ok());
    let plan = Plan {
        params: vec![
            session.find("actual_position").unwrap(),
            session.find("actual_speed").unwrap(),
        ],
        interval: Duration::from_millis(100),
        duration: Some(Duration::from_millis(2000)),
    };
    let clock_ref: &dyn Clock = clock.as_ref();
    let recording = record::record(&mut session, &plan, clock_ref, &mut || false, &mut |_| {
        Ok(())
    })
    .unwrap();
    assert_eq!(recording.samples.len(), 21);
    for sample in &recording.samples {
        let t = sample.time_ms as f64 / 1000.0;
        let expected = trapezoid(8000.0, 8000.0, 16000.0, t);
        let position = sample.values[0].as_f64().unwrap();
        assert!(
            (position - expected).abs() <= 1.0,
            "at {t} s: position {position}, the trapezoid says {expected}"
        );
    }
    let speeds: Vec<i64> = recording
        .samples
        .iter()
        .map(|s| s.values[1].as_i64().unwrap())
        .collect();
    assert_eq!(speeds[5], 8000, "cruising at 0.5 s");
    assert_eq!(*speeds.last().unwrap(), 0, "stopped at the end");
    assert!(speeds[..5].windows(2).all(|w| w[0] <= w[1]), "{speeds:?}");
}

#[test]
fn record_and_plot_a_move_over_tcp() {
    let sim = Sim::start(&["--listen", "127.0.0.1:0"]);
    let dir = tempdir();
    let csv = dir.join("ramp.csv");
    let record = format!(
        ":record {} actual_position,actual_speed 20ms 400ms",
        arg(&csv)
    );
    let out = expect(
        &[
            "--tcp",
            &sim.first,
            "-c",
            "SAP unit_conversion_mode, 0, 1",
            "-c",
            "SAP max_positioning_speed, 0, 20000",
            "-c",
            "MVP ABS, 0, 100000",
            "-c",
            &record,
            "-c",
            ":plot",
            "-c",
            "MST 0",
        ],
        0,
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let recording = Recording::from_csv(&text).unwrap();
    assert_eq!(recording.columns, ["actual_position", "actual_speed"]);
    let n = recording.samples.len();
    assert!(n >= 2, "{text}");
    let times: Vec<u64> = recording.samples.iter().map(|s| s.time_ms).collect();
    assert!(times.windows(2).all(|w| w[0] < w[1]), "{times:?}");
    let positions: Vec<i64> = recording
        .samples
        .iter()
        .map(|s| s.values[0].as_i64().unwrap())
        .collect();
    assert!(positions.windows(2).all(|w| w[0] <= w[1]), "{positions:?}");
    assert!(positions.iter().all(|p| (0..=100_000).contains(p)));
    let shown = stdout(&out);
    assert!(
        shown.contains(&format!(
            "recorded {n} samples of actual_position, actual_speed"
        )),
        "{shown}"
    );
    let titles: Vec<&str> = shown.lines().filter(|l| l.starts_with("actual_")).collect();
    assert_eq!(titles, ["actual_position", "actual_speed"], "{shown}");
    assert!(
        shown.contains('⠀')
            || shown
                .chars()
                .any(|c| ('\u{2801}'..='\u{28FF}').contains(&c))
    );
}

#[test]
fn record_needs_a_duration_without_a_terminal_and_plot_needs_a_recording() {
    let out = expect(&["--sim", "-c", ":record x.csv actual_position 10ms"], 2);
    assert!(crate::util::stderr(&out).contains("needs a duration"));
    let out = expect(&["--sim", "-c", ":plot"], 2);
    assert!(crate::util::stderr(&out).contains("nothing recorded yet"));
    let out = expect(&["--sim", "-c", ":record x.csv no_such_param 10ms 1s"], 2);
    assert!(crate::util::stderr(&out).contains("unknown parameter 'no_such_param'"));
}

#[test]
fn a_bare_number_is_milliseconds_in_record_as_everywhere() {
    let dir = tempdir();
    let csv = dir.join("bare.csv");
    let record = format!(":record {} actual_position 20 150", arg(&csv));
    expect(&["--sim", "-c", &record], 0);
    let text = std::fs::read_to_string(&csv).unwrap();
    let recording = Recording::from_csv(&text).unwrap();
    let times: Vec<u64> = recording.samples.iter().map(|s| s.time_ms).collect();
    assert!(times.len() >= 2, "{text}");
    assert!(
        times.iter().all(|&t| t <= 150),
        "150 is 150 ms, 20 is 20 ms: {times:?}"
    );
    let out = expect(&["--sim", "-c", ":help time"], 0);
    assert!(
        stdout(&out).contains("a bare number of milliseconds (250 is 250ms), at most 7 days"),
        "{}",
        stdout(&out)
    );
}
