//! Row 7: the fault soak at full size — every cell of the matrix {drop, corrupt, delay past the
//! timeout, all three} × {TMCL char, line and no echo, SMD4 with and without `--address`, TMCL
//! binary} with
//! 20,000 reads of known values at 1 % faults, through `tmclsh run` over a pty to `tmclsh sim`
//! (the harness of the fast soak in `cargo test`, `tests/soak/harness.rs`). The row counts silent
//! wrong values, which must be none; the section below the table has every cell's counts.
//!
//! `cargo bench --bench e2e -- --soak` measures this alone and rewrites only its row and section
//! of `BENCHMARKS.md`.

use std::fmt::Write as _;
use std::time::{Duration, Instant};

use crate::local::thousands;
use crate::proc::tmclsh;
use crate::report::Row;
use crate::soak_harness::{Counts, Fault, Plan, Target, run_cell};

/// The name the row starts with (a partial run finds its line by it).
pub const ROW_PREFIX: &str = "7. Fault soak";

/// The heading of the section with every cell.
pub const HEADING: &str = "## Fault soak";

/// One measured cell.
pub struct Cell {
    pub target: Target,
    pub fault: Fault,
    pub counts: Counts,
    pub took: Duration,
}

/// The plan of every cell: `reads` per cell, 1 % faults, `--timeout 100`, delays of 150 ms.
pub fn plan(reads: u64) -> Plan {
    Plan {
        reads,
        rate: 0.01,
        timeout_ms: 100,
        delay_ms: 150,
        seed: 12,
    }
}

/// The name the late replies' row starts with.
pub const LIMIT_ROW_PREFIX: &str = "8. Late replies";

/// The heading of the late replies' section.
pub const LIMIT_HEADING: &str = "## Late replies";

/// The fault cells of row 8: replies late past the resync window alone, with drops and
/// corruption beside them, and with drops alone (a late reply then comes while the answer to
/// the request after a dropped one is awaited, and no answer follows it at once).
pub const LIMIT_FAULTS: [Fault; 3] = [Fault::Delay, Fault::All, Fault::DropDelay];

/// The plan of the limit's cells: as row 7's, but delayed replies come later than the resync
/// window after the timeout. With `--timeout 100` the window is 100 ms, so the line is trusted
/// again 200 ms after the request and the next request is sent; a reply held back 250 ms comes
/// in the middle of the wait for the next one.
pub fn limit_plan(reads: u64) -> Plan {
    Plan {
        delay_ms: 250,
        ..plan(reads)
    }
}

/// Runs the matrix: the configurations side by side (each waits on its timeouts most of the
/// time), the fault kinds of one configuration one after the other.
pub fn measure(plan: &Plan) -> Vec<Cell> {
    measure_faults(plan, &Fault::ALL)
}

/// Runs the configurations with each of `faults`, as [`measure`] does.
pub fn measure_faults(plan: &Plan, faults: &[Fault]) -> Vec<Cell> {
    let bin = tmclsh();
    let mut cells: Vec<Cell> = std::thread::scope(|scope| {
        let workers: Vec<_> = Target::ALL
            .into_iter()
            .map(|target| {
                let bin = &bin;
                scope.spawn(move || {
                    faults
                        .iter()
                        .map(|&fault| {
                            let start = Instant::now();
                            let counts = run_cell(bin, target, fault, plan);
                            eprintln!(
                                "e2e: soak {} / {}: {}",
                                target.name(),
                                fault.name(),
                                counts.summary()
                            );
                            Cell {
                                target,
                                fault,
                                counts,
                                took: start.elapsed(),
                            }
                        })
                        .collect::<Vec<Cell>>()
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("a soak worker"))
            .collect()
    });
    cells.sort_by_key(|c| {
        (
            Target::ALL.iter().position(|t| *t == c.target),
            // Cells outside the matrix (drop + delay) after its columns.
            Fault::ALL
                .iter()
                .position(|f| *f == c.fault)
                .unwrap_or(Fault::ALL.len()),
        )
    });
    cells
}

/// The row of the results table.
pub fn row(cells: &[Cell], plan: &Plan) -> Row {
    let mut total = Counts::default();
    for cell in cells {
        total.add(&cell.counts);
    }
    Row {
        name: format!(
            "{ROW_PREFIX}: 1 % faults, {} cells × {} reads of known values",
            cells.len(),
            thousands(plan.reads as f64)
        ),
        measured: format!("{} silent wrong", thousands(total.silent_wrong as f64)),
        reference: format!(
            "{} reads: {} ok, {} failures reported, {} one digit changed",
            thousands(total.reads as f64),
            thousands(total.ok as f64),
            thousands(total.failures() as f64),
            thousands(total.undetectable as f64)
        ),
        ratio: "—".into(),
        target: "0 silent wrong".into(),
        met: Some(total.silent_wrong == 0),
    }
}

/// The section with every cell's counts, its method and the date it was measured.
pub fn section(cells: &[Cell], plan: &Plan, date: &str) -> String {
    let mut md = format!("{HEADING}\n\n");
    let _ = write!(
        md,
        "Row 7, cell by cell, measured on {date}. Each cell is a fresh `tmclsh sim --pty` whose \
         faults are switched on through its console (`seed N`, then `drop`, `corrupt` or `delay` \
         at {rate} % each; \"all three\" has the three at once), after the known values were set \
         without faults: TMCL's 56 user variables (bank 2) set to values of one to ten digits, \
         half of them negative; the SMD4's positions, speeds, accelerations, times and counts \
         (13 settings, two of them fixed by the simulator). Any two known values differ in at \
         least three characters. A Rhai script (`tmclsh run --timeout {timeout} --stay-ascii` \
         for TMCL, `--binary` instead for TMCL binary) reads them {reads} times in a seeded order, catching every failure, and \
         prints what each read returned; delayed replies are held back {delay} ms, past the \
         timeout. A read returns the truth (ok), fails with a reported error (timeout and line \
         noise exit 3, a device error 1; no read here can fail on the device, so each device \
         error is a damaged reply taken for a refusal) or returns another value normally: \
         **silent wrong**. A digit corrupted into another digit (or a sign into a digit) leaves \
         a well-formed reply that no client can tell from the truth, since neither ASCII \
         protocol carries a checksum (a binary frame does); where an ASCII cell corrupts bytes and the value is the truth \
         with exactly one digit or sign changed and still a well-formed number, it is counted \
         as \"one digit changed\" instead; so is one printable character changed into another \
         in the firmware version, which the document declares a STRING of no format. \
         \"Restarts\" are runs whose \
         session could not open; a new run made the remaining reads. Replay a cell with its \
         seed: `tmclsh sim --seed N` or the console's `seed N`.\n\n",
        rate = plan.rate * 100.0,
        timeout = plan.timeout_ms,
        reads = thousands(plan.reads as f64),
        delay = plan.delay_ms,
    );
    md.push_str(
        "| configuration | faults | reads | ok | timeout | line noise | device error | other \
         | silent wrong | one digit changed | restarts | injected: dropped / corrupted / delayed \
         | seed | time |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n",
    );
    for cell in cells {
        let c = &cell.counts;
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | **{}** | {} | {} | {} / {} / {} | {} | {:.0} s |",
            cell.target.name(),
            cell.fault.name(),
            c.reads,
            c.ok,
            c.timeout,
            c.noise,
            c.device,
            c.other,
            c.silent_wrong,
            c.undetectable,
            c.restarts,
            c.injected.dropped,
            c.injected.corrupted,
            c.injected.delayed,
            c.seed,
            cell.took.as_secs_f64(),
        );
    }
    push_wrong_examples(&mut md, cells);
    md
}

/// Whether a configuration has no echo: TMCL with echo off and every SMD4 drive.
fn without_echo(target: Target) -> bool {
    !matches!(target, Target::TmclChar | Target::TmclLine)
}

/// Silent wrong values per 100 delayed replies, with one decimal.
fn per_hundred_late(counts: &Counts) -> String {
    match counts.injected.delayed {
        0 => "—".into(),
        late => format!("{:.1}", 100.0 * counts.silent_wrong as f64 / late as f64),
    }
}

/// Row 8 of the results table: silent wrong values for replies later than the resync window,
/// without an echo (where a barrier after each failure must keep them out) and with one.
pub fn limit_row(cells: &[Cell], plan: &Plan) -> Row {
    let mut no_echo = Counts::default();
    let mut echo = Counts::default();
    for cell in cells {
        if without_echo(cell.target) {
            no_echo.add(&cell.counts);
        } else {
            echo.add(&cell.counts);
        }
    }
    Row {
        name: format!(
            "{LIMIT_ROW_PREFIX}: replies {} ms late (past the resync window), {} cells × {} reads",
            plan.delay_ms,
            cells.len(),
            thousands(plan.reads as f64)
        ),
        measured: format!(
            "{} silent wrong for {} late replies without an echo (binary, no echo, SMD4)",
            thousands(no_echo.silent_wrong as f64),
            thousands(no_echo.injected.delayed as f64),
        ),
        reference: format!(
            "with an echo: {} silent wrong for {} late replies",
            thousands(echo.silent_wrong as f64),
            thousands(echo.injected.delayed as f64)
        ),
        ratio: "—".into(),
        target: "0 silent wrong".into(),
        met: Some(echo.silent_wrong + no_echo.silent_wrong == 0),
    }
}

/// The limit's section: its method and every cell's counts.
pub fn limit_section(cells: &[Cell], plan: &Plan, date: &str) -> String {
    let mut md = format!("{LIMIT_HEADING}\n\n");
    let _ = write!(
        md,
        "Row 8, measured on {date}: replies later than any quiet wait. The cells are row 7's, \
         with `delay` and \"all three\", and \"drop + delay\" (`drop` and `delay` at {rate} % \
         each), but a delayed reply is held back {delay} ms: past the client's timeout \
         ({timeout} ms) and the resync window after it (as long as the timeout), so the line has \
         been quiet long enough and the next request is on its way when the late reply comes. \
         The simulator keeps its replies in order, so the answer to that next request follows \
         the late one at once, as a module that answers late because it was busy would send it, \
         unless that answer is itself dropped or delayed. Without an echo (TMCL with echo off, \
         TMCL binary, SMD4) nothing in a reply names its request (a binary frame names its \
         command, not the type or bank): after a failure the next request is preceded by a \
         barrier, a read-only request whose reply no earlier request can send, and everything \
         before that reply is discarded (docs/guarantee.md); with an echo the reply must \
         follow the echo of its own request. \"Silent wrong per 100 late\" divides the silent \
         wrong values by the replies the simulator delayed.\n\n",
        rate = plan.rate * 100.0,
        delay = plan.delay_ms,
        timeout = plan.timeout_ms,
    );
    md.push_str(
        "| configuration | faults | reads | ok | timeout | line noise | device error | other \
         | silent wrong | silent wrong per 100 late | one digit changed | injected: dropped / \
         corrupted / delayed | seed | time |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n",
    );
    for cell in cells {
        let c = &cell.counts;
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | **{}** | {} | {} | {} / {} / {} | {} | {:.0} s |",
            cell.target.name(),
            cell.fault.name(),
            c.reads,
            c.ok,
            c.timeout,
            c.noise,
            c.device,
            c.other,
            c.silent_wrong,
            per_hundred_late(c),
            c.undetectable,
            c.injected.dropped,
            c.injected.corrupted,
            c.injected.delayed,
            c.seed,
            cell.took.as_secs_f64(),
        );
    }
    push_wrong_examples(&mut md, cells);
    md
}

/// The first silent wrong values of each cell that had any, as a list after a table.
fn push_wrong_examples(md: &mut String, cells: &[Cell]) {
    let wrong: Vec<String> = cells
        .iter()
        .filter(|c| !c.counts.examples.is_empty())
        .map(|c| {
            format!(
                "- {} / {}: {}",
                c.target.name(),
                c.fault.name(),
                c.counts.examples.join("; ")
            )
        })
        .collect();
    if !wrong.is_empty() {
        md.push_str("\nThe first silent wrong values of each cell (index, value, truth):\n\n");
        md.push_str(&wrong.join("\n"));
        md.push('\n');
    }
}

/// `BENCHMARKS.md` with the soak's row and section replaced by `row_line` and `section` (or
/// added: the row after the last row of the results table, the section before the pure parts),
/// everything else kept as it was.
pub fn splice(markdown: &str, row_line: &str, section: &str) -> String {
    splice_part(markdown, ROW_PREFIX, HEADING, row_line, section)
}

/// [`splice`] for the limit's row and section.
pub fn splice_limit(markdown: &str, row_line: &str, section: &str) -> String {
    splice_part(markdown, LIMIT_ROW_PREFIX, LIMIT_HEADING, row_line, section)
}

/// The row starting with `prefix` and the section under `heading` replaced or added.
fn splice_part(
    markdown: &str,
    prefix: &str,
    heading: &str,
    row_line: &str,
    section: &str,
) -> String {
    let mut lines: Vec<String> = markdown.lines().map(str::to_string).collect();
    let row_start = format!("| {prefix}");
    match lines.iter().position(|l| l.starts_with(&row_start)) {
        Some(i) => lines[i] = row_line.trim_end().to_string(),
        None => {
            let header = lines
                .iter()
                .position(|l| l.starts_with("| row |"))
                .expect("BENCHMARKS.md has a results table");
            let end = lines[header..]
                .iter()
                .position(|l| !l.starts_with('|'))
                .map_or(lines.len(), |i| header + i);
            lines.insert(end, row_line.trim_end().to_string());
        }
    }
    crate::report::splice_section(&(lines.join("\n") + "\n"), heading, section)
}
