//! Recordings: parameters sampled at a fixed interval, with the time of each sample, written to
//! CSV as they are taken (a crash loses at most one line) and kept for `:plot`.
//!
//! ```text
//! time_ms,actual_position,actual_speed
//! 0,0,0
//! 100,1250,25000
//! ```
//!
//! `time_ms` counts from the first sample; each row's values were read one after the other
//! starting at that time. Integers are written as they are, real numbers always with a decimal
//! point (`1000.0`, an SMD4's MOTOR:VACT in Hz), text as it is (an SMD4's flag words).

use std::io::{self, Write};
use std::time::Duration;

use crate::clock::Clock;
use crate::session::{SessionError, interrupt};

use super::device::{ParamDevice, ParamRef};
use super::value::ParamValue;

/// Sampled values of some parameters over time.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// The parameter names, one per column.
    pub columns: Vec<String>,
    /// The samples, in time order.
    pub samples: Vec<Sample>,
}

/// The values of every column at one time.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Milliseconds since the first sample.
    pub time_ms: u64,
    /// One value per column.
    pub values: Vec<ParamValue>,
}

/// What to sample, how often, for how long.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The parameters, one column each.
    pub params: Vec<ParamRef>,
    /// Time between the starts of two samples.
    pub interval: Duration,
    /// Sampling stops once this much time has passed (`None`: until `stop` says so).
    pub duration: Option<Duration>,
}

/// Samples `plan.params` from `device` until the duration has passed or `stop()` returns true,
/// handing each sample to `sink` as it is taken. Time comes from `clock` (waits are sliced so
/// Ctrl-C is noticed). A refused read or a lost link ends the recording with the error; the
/// samples taken so far are in the sink.
pub fn record(
    device: &mut dyn ParamDevice,
    plan: &Plan,
    clock: &dyn Clock,
    stop: &mut dyn FnMut() -> bool,
    sink: &mut dyn FnMut(&Sample) -> io::Result<()>,
) -> Result<Recording, SessionError> {
    let columns: Vec<String> = plan.params.iter().map(|p| p.name.clone()).collect();
    let mut samples = Vec::new();
    let start = clock.now();
    let mut due = Duration::ZERO;
    let interval = plan.interval.max(Duration::from_millis(1));
    loop {
        let elapsed = clock.now().saturating_sub(start);
        if plan.duration.is_some_and(|d| elapsed > d) || stop() {
            break;
        }
        let mut values = Vec::with_capacity(plan.params.len());
        for param in &plan.params {
            values.push(device.read(param)?.value);
        }
        let sample = Sample {
            time_ms: elapsed.as_millis() as u64,
            values,
        };
        sink(&sample)?;
        samples.push(sample);
        due += interval;
        let now = clock.now().saturating_sub(start);
        if due < now {
            // Reading took longer than the interval: skip to the next slot of the grid.
            let slots = now.as_nanos().div_ceil(interval.as_nanos());
            due = interval * u32::try_from(slots).unwrap_or(u32::MAX);
        }
        wait_until(clock, start + due)?;
    }
    Ok(Recording { columns, samples })
}

/// Waits on `clock` until `when`, in slices that notice Ctrl-C.
fn wait_until(clock: &dyn Clock, when: Duration) -> Result<(), SessionError> {
    loop {
        if interrupt::pending() {
            return Err(SessionError::Interrupted);
        }
        let now = clock.now();
        if now >= when {
            return Ok(());
        }
        clock.wait((when - now).min(interrupt::SLICE));
    }
}

/// The CSV header line (without line ending).
pub fn csv_header(columns: &[String]) -> String {
    let mut line = String::from(CSV_TIME);
    for c in columns {
        line.push(',');
        line.push_str(c);
    }
    line
}

/// The first column of every recording: how a file tmclsh wrote is recognised.
pub const CSV_TIME: &str = "time_ms";

/// One CSV data line (without line ending).
pub fn csv_row(sample: &Sample) -> String {
    let mut line = sample.time_ms.to_string();
    for v in &sample.values {
        line.push(',');
        line.push_str(&v.to_csv());
    }
    line
}

impl Recording {
    /// The whole recording as CSV.
    pub fn to_csv(&self) -> String {
        let mut text = csv_header(&self.columns);
        text.push('\n');
        for s in &self.samples {
            text.push_str(&csv_row(s));
            text.push('\n');
        }
        text
    }

    /// Reads a recording back from CSV (as written by tmclsh: a `time_ms` column, then values).
    pub fn from_csv(text: &str) -> Result<Recording, CsvError> {
        let mut lines = text.lines().filter(|l| !l.trim().is_empty());
        let header = lines.next().ok_or(CsvError::Empty)?;
        let mut names = header.split(',').map(str::trim);
        if names.next() != Some("time_ms") {
            return Err(CsvError::NoTime);
        }
        let columns: Vec<String> = names.map(String::from).collect();
        let mut samples = Vec::new();
        for (i, line) in lines.enumerate() {
            let row = i + 2;
            let cells: Vec<&str> = line.split(',').map(str::trim).collect();
            if cells.len() != columns.len() + 1 {
                return Err(CsvError::Width {
                    row,
                    cells: cells.len(),
                    header: columns.len() + 1,
                });
            }
            let time_ms = cells[0]
                .parse::<i64>()
                .map_err(|_| CsvError::NotAnInteger {
                    row,
                    cell: cells[0].to_string(),
                })?;
            let time_ms = u64::try_from(time_ms).map_err(|_| CsvError::NegativeTime { row })?;
            let values = cells[1..].iter().map(|c| ParamValue::from_csv(c)).collect();
            samples.push(Sample { time_ms, values });
        }
        Ok(Recording { columns, samples })
    }

    /// The (time in seconds, value) points of one column; samples whose value is not a number
    /// are left out.
    pub fn series(&self, column: usize) -> Vec<(f64, f64)> {
        self.samples
            .iter()
            .filter_map(|s| Some((s.time_ms as f64 / 1000.0, s.values[column].as_f64()?)))
            .collect()
    }

    /// Whether a column holds numbers (a chart can draw it).
    pub fn numeric(&self, column: usize) -> bool {
        self.samples
            .iter()
            .all(|s| s.values[column].as_f64().is_some())
    }
}

/// Why a text is not a recording tmclsh wrote.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CsvError {
    /// No line at all.
    #[error("the file is empty")]
    Empty,
    /// The header does not start with the time column.
    #[error("the first column is not time_ms")]
    NoTime,
    /// A row with more or fewer values than the header has columns.
    #[error("line {row} has {}, the header {header}", crate::count::counted(*cells, "value"))]
    Width {
        /// The line, from 1.
        row: usize,
        /// How many values it has.
        cells: usize,
        /// How many columns the header has.
        header: usize,
    },
    /// A time that is not a whole number.
    #[error("line {row}: '{cell}' is not an integer")]
    NotAnInteger {
        /// The line, from 1.
        row: usize,
        /// The time as written.
        cell: String,
    },
    /// A time before the recording started.
    #[error("line {row}: time is negative")]
    NegativeTime {
        /// The line, from 1.
        row: usize,
    },
}

/// The largest recording read back (`:plot FILE`): hours of samples, more than other files.
pub const READ_LIMIT: u64 = 64 << 20;

/// A CSV file being written sample by sample.
pub struct CsvFile {
    file: std::fs::File,
}

impl CsvFile {
    /// Creates (or replaces) the file and writes the header.
    pub fn create(path: &std::path::Path, columns: &[String]) -> Result<CsvFile, SessionError> {
        let file = crate::file::create(path)
            .map_err(|e| SessionError::Usage(format!("cannot write recording {e}")))?;
        CsvFile::start(file, columns)
    }

    /// Writes the header to an opened, empty file (a script's, opened through its sandbox).
    pub fn start(mut file: std::fs::File, columns: &[String]) -> Result<CsvFile, SessionError> {
        writeln!(file, "{}", csv_header(columns))?;
        Ok(CsvFile { file })
    }

    /// Appends one sample.
    pub fn append(&mut self, sample: &Sample) -> io::Result<()> {
        writeln!(self.file, "{}", csv_row(sample))
    }
}

#[cfg(test)]
mod tests {
    use super::super::device::StoreStep;
    use super::super::fake::FakeDevice;
    use super::super::value::Reading;
    use super::*;
    use crate::clock::ManualClock;

    fn plan(device: &FakeDevice, names: &[&str], interval_ms: u64, duration_ms: u64) -> Plan {
        Plan {
            params: names.iter().map(|n| device.param(n)).collect(),
            interval: Duration::from_millis(interval_ms),
            duration: Some(Duration::from_millis(duration_ms)),
        }
    }

    #[test]
    fn samples_are_taken_on_the_interval_grid_until_the_duration() {
        let mut device = FakeDevice::new();
        device.set("actual_position", 42);
        let clock = ManualClock::new();
        let plan = plan(&device, &["actual_position", "actual_speed"], 100, 500);
        let mut rows = Vec::new();
        let rec = record(&mut device, &plan, &clock, &mut || false, &mut |s| {
            rows.push(csv_row(s));
            Ok(())
        })
        .unwrap();
        let times: Vec<u64> = rec.samples.iter().map(|s| s.time_ms).collect();
        assert_eq!(times, [0, 100, 200, 300, 400, 500]);
        assert_eq!(rows[1], "100,42,0");
        assert_eq!(rec.columns, ["actual_position", "actual_speed"]);
    }

    /// A device whose reads take time on the manual clock and whose position follows it.
    struct Moving {
        inner: FakeDevice,
        clock: ManualClock,
        read_cost: Duration,
    }

    impl ParamDevice for Moving {
        fn module_name(&self) -> String {
            self.inner.module_name()
        }
        fn address(&self) -> Option<u32> {
            Some(1)
        }
        fn who(&self) -> String {
            "module 1 (A)".into()
        }
        fn memory(&self) -> &'static str {
            "EEPROM"
        }
        fn firmware(&mut self) -> Option<String> {
            None
        }
        fn params(&self) -> Vec<ParamRef> {
            self.inner.params()
        }
        fn find(&self, name: &str) -> Result<ParamRef, crate::commission::ParamError> {
            self.inner.find(name)
        }
        fn read(&mut self, _: &ParamRef) -> Result<Reading, SessionError> {
            let t = self.clock.now().as_millis() as i64;
            self.clock.advance(self.read_cost);
            Ok(Reading::of(t * 10))
        }
        fn write(&mut self, p: &ParamRef, v: &ParamValue) -> Result<(), SessionError> {
            self.inner.write(p, v)
        }
        fn check_write(
            &self,
            _: &ParamRef,
            _: &ParamValue,
        ) -> Result<(), crate::commission::ParamError> {
            Ok(())
        }
        fn write_line(&self, p: &ParamRef, v: &ParamValue) -> String {
            self.inner.write_line(p, v)
        }
        fn store_steps(&self, params: &[&ParamRef]) -> Vec<StoreStep> {
            self.inner.store_steps(params)
        }
        fn store(&mut self, step: &StoreStep) -> Result<(), SessionError> {
            self.inner.store(step)
        }
    }

    #[test]
    fn slow_reads_keep_the_grid_and_skip_the_slots_they_missed() {
        let clock = ManualClock::new();
        let inner = FakeDevice::new();
        let plan = plan(&inner, &["actual_position"], 10, 100);
        let mut device = Moving {
            inner,
            clock: clock.clone(),
            read_cost: Duration::from_millis(25),
        };
        let rec = record(&mut device, &plan, &clock, &mut || false, &mut |_| Ok(())).unwrap();
        let times: Vec<u64> = rec.samples.iter().map(|s| s.time_ms).collect();
        assert_eq!(times, [0, 30, 60, 90]);
        let values: Vec<i64> = rec
            .samples
            .iter()
            .filter_map(|s| s.values[0].as_i64())
            .collect();
        assert_eq!(
            values,
            [0, 300, 600, 900],
            "each value is read at its sample time"
        );
    }

    #[test]
    fn a_stop_request_ends_an_open_ended_recording() {
        let mut device = FakeDevice::new();
        let clock = ManualClock::new();
        let mut plan = plan(&device, &["actual_position"], 50, 0);
        plan.duration = None;
        let mut calls = 0;
        let rec = record(
            &mut device,
            &plan,
            &clock,
            &mut || {
                calls += 1;
                calls > 3
            },
            &mut |_| Ok(()),
        )
        .unwrap();
        assert_eq!(rec.samples.len(), 3);
    }

    #[test]
    fn a_refused_read_ends_the_recording_with_the_error() {
        let mut device = FakeDevice::new();
        device.refuse_read.push("actual_speed".into());
        let clock = ManualClock::new();
        let plan = plan(&device, &["actual_speed"], 50, 1000);
        let error = record(&mut device, &plan, &clock, &mut || false, &mut |_| Ok(())).unwrap_err();
        assert!(matches!(error, SessionError::Device { .. }));
    }

    #[test]
    fn csv_round_trips_and_bad_files_are_refused_with_the_line() {
        let rec = Recording {
            columns: vec!["a".into(), "b".into()],
            samples: vec![
                Sample {
                    time_ms: 0,
                    values: vec![1.into(), (-2).into()],
                },
                Sample {
                    time_ms: 20,
                    values: vec![3.into(), 4.into()],
                },
            ],
        };
        let text = rec.to_csv();
        assert_eq!(text, "time_ms,a,b\n0,1,-2\n20,3,4\n");
        assert_eq!(Recording::from_csv(&text).unwrap(), rec);
        assert!(
            Recording::from_csv("time_ms,a\nx,1\n")
                .unwrap_err()
                .to_string()
                .contains("line 2: 'x'")
        );
        assert!(
            Recording::from_csv("t,a\n")
                .unwrap_err()
                .to_string()
                .contains("time_ms")
        );
        assert!(
            Recording::from_csv("time_ms,a\n0\n")
                .unwrap_err()
                .to_string()
                .contains("line 2 has 1")
        );
    }

    #[test]
    fn real_numbers_and_text_round_trip_and_only_numbers_are_charted() {
        let rec = Recording {
            columns: vec!["MOTOR:PACT".into(), "SYS:FLAGS".into()],
            samples: vec![Sample {
                time_ms: 0,
                values: vec![1000.0.into(), ParamValue::Text("0x0808 0x0000".into())],
            }],
        };
        let text = rec.to_csv();
        assert_eq!(
            text,
            "time_ms,MOTOR:PACT,SYS:FLAGS\n0,1000.0,0x0808 0x0000\n"
        );
        let back = Recording::from_csv(&text).unwrap();
        assert_eq!(back, rec);
        assert!(back.numeric(0) && !back.numeric(1));
        assert_eq!(back.series(1), []);
    }
}
