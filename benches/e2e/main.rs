//! `cargo bench --bench e2e`: every row of the benchmark measured side by side in one run, printed
//! as one table and written to `BENCHMARKS.md` with the machine, the method and the date.
//!
//! `cargo bench --bench e2e -- --quick` runs fewer transactions and repetitions and only prints:
//! for trying a change, not for publishing. `-- --soak` runs only the fault soak (row 7) and
//! rewrites only its row and section; `-- --limit` likewise for late replies (row 8);
//! `-- --latency` for the latency timer rows (row 9), `-- --reconnect` for the reconnect time
//! (row 10, its row only), `-- --hot` for the hot path (row 11) and the in-process rate (row 3;
//! `-- --hot --no-in-process` leaves it out), `-- --in-process` for the in-process rate and the
//! pure parts alone, `-- --wire` for wire efficiency (row 1).
//! With `-- --reads N` the soak's and late replies' cells make N reads each instead of 20,000
//! (the table says how many). Linux only: it uses ptys, wait4 and /proc.

#[cfg(target_os = "linux")]
#[path = "../pure/cases.rs"]
mod cases;
#[cfg(target_os = "linux")]
mod host;
#[cfg(target_os = "linux")]
mod hot;
#[cfg(target_os = "linux")]
mod latency;
#[cfg(target_os = "linux")]
mod local;
#[cfg(target_os = "linux")]
mod machine;
#[cfg(target_os = "linux")]
mod proc;
#[cfg(target_os = "linux")]
mod relink;
#[cfg(target_os = "linux")]
mod report;
#[cfg(target_os = "linux")]
mod soak;
#[cfg(target_os = "linux")]
#[path = "../../tests/soak/harness.rs"]
mod soak_harness;
#[cfg(target_os = "linux")]
mod wire;

#[cfg(target_os = "linux")]
use std::path::PathBuf;
#[cfg(target_os = "linux")]
use std::time::SystemTime;

#[cfg(target_os = "linux")]
const COMMAND: &str = "cargo bench --bench e2e";

/// How much of everything a run does.
#[cfg(target_os = "linux")]
struct Plan {
    wire: Vec<wire::Line>,
    host_n: u32,
    host_reps: usize,
    /// Row 11: short repetitions, many of them, so each compares runs made close together.
    hot_n: u32,
    hot_reps: usize,
    in_process_n: u32,
    in_process_reps: usize,
    start_up_runs: usize,
    memory_n: u32,
    soak_reads: u64,
    latency_n: u32,
    latency_reps: usize,
    reconnects: usize,
}

#[cfg(target_os = "linux")]
impl Plan {
    fn full() -> Plan {
        Plan {
            wire: vec![
                wire::Line {
                    baud: 9600,
                    n: 1000,
                    reps: 1,
                },
                wire::Line {
                    baud: 115_200,
                    n: 1000,
                    reps: 5,
                },
            ],
            host_n: 10_000,
            host_reps: 7,
            hot_n: 2000,
            hot_reps: 31,
            in_process_n: 100_000,
            in_process_reps: 5,
            start_up_runs: 51,
            memory_n: 100_000,
            soak_reads: 20_000,
            latency_n: 200,
            latency_reps: 3,
            reconnects: 7,
        }
    }

    fn quick() -> Plan {
        Plan {
            wire: vec![
                wire::Line {
                    baud: 9600,
                    n: 20,
                    reps: 1,
                },
                wire::Line {
                    baud: 115_200,
                    n: 200,
                    reps: 1,
                },
            ],
            host_n: 2000,
            host_reps: 1,
            hot_n: 500,
            hot_reps: 3,
            in_process_n: 20_000,
            in_process_reps: 1,
            start_up_runs: 11,
            memory_n: 100_000,
            soak_reads: 1000,
            latency_n: 50,
            latency_reps: 1,
            reconnects: 3,
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn main() {
    eprintln!("the end-to-end benchmark runs on Linux only (ptys, wait4, /proc)");
}

#[cfg(target_os = "linux")]
fn main() {
    // cargo passes `--bench`; anything else but `--quick` is ignored.
    let quick = std::env::args().any(|a| a == "--quick");
    let mut plan = if quick { Plan::quick() } else { Plan::full() };
    if let Some(reads) = reads_flag() {
        plan.soak_reads = reads;
    }
    let soak_plan = soak::plan(plan.soak_reads);
    let date = || humantime::format_rfc3339_seconds(SystemTime::now()).to_string();
    let limit_plan = soak::limit_plan(plan.soak_reads);
    if std::env::args().any(|a| a == "--limit") {
        eprintln!("e2e: late replies only");
        let cells = soak::measure_faults(&limit_plan, &soak::LIMIT_FAULTS);
        let row = soak::limit_row(&cells, &limit_plan);
        let section = soak::limit_section(&cells, &limit_plan, &date());
        show_and_write(&row, &section, quick, "late replies", soak::splice_limit);
        return;
    }
    if std::env::args().any(|a| a == "--latency") {
        eprintln!("e2e: the latency timer rows only");
        let load_before = machine::load();
        let rows = latency::measure(plan.latency_n, plan.latency_reps);
        println!("{}", report::text(&rows));
        let load_after = machine::load();
        println!("load average before / after: {load_before} / {load_after}");
        if !quick {
            edit_benchmarks("the latency rows", |old| {
                let lines: Vec<String> = rows.iter().map(report::markdown_line).collect();
                let new = latency::splice(old, &lines);
                let section = latency::section(&date(), &load_before, &load_after);
                report::splice_section(&new, latency::HEADING, &section)
            });
        }
        return;
    }
    if std::env::args().any(|a| a == "--wire") {
        eprintln!("e2e: wire efficiency only (the 9600 baud runs take a while)");
        let load_before = machine::load();
        let rows = wire::measure(&plan.wire);
        println!("{}", report::text(&rows));
        let load_after = machine::load();
        println!("load average before / after: {load_before} / {load_after}");
        if !quick {
            edit_benchmarks("the row 1 lines", |old| {
                let (lateness, lines) = rows.split_last().expect("the timer lateness row");
                let lines: Vec<String> = lines.iter().map(report::markdown_line).collect();
                let new = report::splice_rows(old, wire::PREFIX, &lines);
                let new = report::splice_rows(
                    &new,
                    wire::LATENESS_PREFIX,
                    &[report::markdown_line(lateness)],
                );
                let section = wire::section(&date(), &load_before, &load_after);
                report::splice_section(&new, wire::HEADING, &section)
            });
        }
        return;
    }
    if std::env::args().any(|a| a == "--hot") {
        // `--no-in-process`: row 11 alone, row 3 left as it is.
        let row3 = !std::env::args().any(|a| a == "--no-in-process");
        eprintln!("e2e: the hot path (row 11) and, unless --no-in-process, the in-process rate");
        let load_before = machine::load();
        let in_process = row3.then(|| local::in_process(plan.in_process_n, plan.in_process_reps));
        let hot = hot::measure(plan.hot_n, plan.hot_reps);
        if let Some(row) = &in_process {
            println!("{}", report::text(std::slice::from_ref(row)));
        }
        println!("{}", report::text(&hot));
        let load_after = machine::load();
        println!("load average before / after: {load_before} / {load_after}");
        if !quick {
            edit_benchmarks("the hot path rows", |old| {
                let mut new = old.to_string();
                if let Some(row) = &in_process {
                    let row3 = [report::markdown_line(row)];
                    new = report::splice_rows(&new, "3. In-process", &row3);
                }
                let lines: Vec<String> = hot.iter().map(report::markdown_line).collect();
                let new = report::splice_rows(&new, hot::PREFIX, &lines);
                let section = hot::section(&date(), &load_before, &load_after);
                report::splice_section(&new, hot::HEADING, &section)
            });
        }
        return;
    }
    if std::env::args().any(|a| a == "--in-process") {
        eprintln!("e2e: the in-process rate and the pure parts only");
        let in_process = local::in_process(plan.in_process_n, plan.in_process_reps);
        let pure = cases::run();
        println!("{}", report::text(std::slice::from_ref(&in_process)));
        print_pure(&pure);
        if !quick {
            edit_benchmarks("row 3 and the pure parts", |old| {
                let row3 = [report::markdown_line(&in_process)];
                let new = report::splice_rows(old, "3. In-process", &row3);
                let section = report::pure_section(&pure);
                report::splice_section(&new, report::PURE_HEADING, &section)
            });
        }
        return;
    }
    if std::env::args().any(|a| a == "--reconnect") {
        eprintln!("e2e: the reconnect time only");
        let scratch = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("e2e");
        std::fs::create_dir_all(&scratch).expect("scratch directory");
        let row = relink::measure(plan.reconnects, &scratch);
        println!("{}", report::text(std::slice::from_ref(&row)));
        if quick {
            eprintln!("e2e: --quick: BENCHMARKS.md is left as it is");
            return;
        }
        edit_benchmarks("the reconnect row", |old| {
            relink::splice(old, &report::markdown_line(&row))
        });
        return;
    }
    if std::env::args().any(|a| a == "--soak") {
        eprintln!("e2e: fault soak only");
        let cells = soak::measure(&soak_plan);
        let row = soak::row(&cells, &soak_plan);
        let section = soak::section(&cells, &soak_plan, &date());
        show_and_write(&row, &section, quick, "the fault soak", soak::splice);
        return;
    }
    let scratch = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("e2e");
    std::fs::create_dir_all(&scratch).expect("scratch directory");
    let machine = machine::Machine::probe();
    let python = machine.python.is_some();
    let load_before = machine::load();

    let step = |what: &str| eprintln!("e2e: {what}");
    step("pure parts");
    let pure = cases::run();
    step("in-process, start-up, memory");
    let in_process = local::in_process(plan.in_process_n, plan.in_process_reps);
    let start_up = local::start_up(plan.start_up_runs, python);
    let size = local::size();
    let memory = local::memory(plan.memory_n, &scratch);
    step("host overhead and transcript cost over an unpaced pty");
    let mut host = host::measure(&host::Plan {
        n: plan.host_n,
        reps: plan.host_reps,
        python,
        scratch: scratch.clone(),
    });
    step("wire efficiency over paced ptys (the 9600 baud runs take a while)");
    let mut rows = wire::measure(&plan.wire);
    let transcript = host.pop().expect("the transcript row");
    rows.append(&mut host);
    rows.extend([in_process, start_up, size, memory, transcript]);
    step("latency timers");
    let latency_rows = latency::measure(plan.latency_n, plan.latency_reps);
    step("fault soak (a few minutes at full size)");
    let soak_cells = soak::measure(&soak_plan);
    rows.push(soak::row(&soak_cells, &soak_plan));
    step("late replies: replies later than the resync window (a few minutes)");
    let limit_cells = soak::measure_faults(&limit_plan, &soak::LIMIT_FAULTS);
    let limit_row = soak::limit_row(&limit_cells, &limit_plan);
    step("the hot path: round trips with and without load, system calls");
    let hot_rows = hot::measure(plan.hot_n, plan.hot_reps);
    step("the reconnect time: an adapter unplugged under an idle REPL");
    let relink_row = relink::measure(plan.reconnects, &scratch);
    let load_after = machine::load();
    let date = date();
    let soak_section = soak::section(&soak_cells, &soak_plan, &date);
    let limit_section = soak::limit_section(&limit_cells, &limit_plan, &date);
    let hot_section = hot::section(&date, &load_before, &load_after);
    let wire_section = wire::section(&date, &load_before, &load_after);
    let latency_section = latency::section(&date, &load_before, &load_after);

    let soak_line = report::markdown_line(rows.last().expect("the soak row"));
    let limit_line = report::markdown_line(&limit_row);
    rows.push(limit_row);
    rows.extend(latency_rows);
    rows.push(relink_row);
    rows.extend(hot_rows);
    println!("{}", report::text(&rows));
    print_pure(&pure);
    println!("load average before / after: {load_before} / {load_after}");
    if quick {
        eprintln!("e2e: --quick: BENCHMARKS.md is left as it is");
        return;
    }
    let markdown = report::markdown(&report::Run {
        date,
        command: COMMAND,
        machine: &machine,
        load_before,
        load_after,
        rows: &rows,
        pure: &pure,
    });
    let markdown = soak::splice(&markdown, &soak_line, &soak_section);
    let markdown = soak::splice_limit(&markdown, &limit_line, &limit_section);
    let markdown = report::splice_section(&markdown, hot::HEADING, &hot_section);
    let markdown = report::splice_section(&markdown, wire::HEADING, &wire_section);
    let markdown = report::splice_section(&markdown, latency::HEADING, &latency_section);
    let path = proc::repo_file("BENCHMARKS.md");
    std::fs::write(&path, markdown).expect("write BENCHMARKS.md");
    eprintln!("e2e: wrote {}", path.display());
}

/// `--reads N`: the soak's reads per cell.
#[cfg(target_os = "linux")]
fn reads_flag() -> Option<u64> {
    let args: Vec<String> = std::env::args().collect();
    let at = args.iter().position(|a| a == "--reads")?;
    let reads = args.get(at + 1).and_then(|n| n.parse().ok());
    Some(reads.expect("--reads takes a number of reads per cell"))
}

#[cfg(target_os = "linux")]
/// Prints a soak's row and section, and writes them into BENCHMARKS.md with `splice` unless the
/// run was `--quick`.
fn show_and_write(
    row: &report::Row,
    section: &str,
    quick: bool,
    what: &str,
    splice: fn(&str, &str, &str) -> String,
) {
    println!("{}", report::text(std::slice::from_ref(row)));
    println!("{section}");
    if quick {
        eprintln!("e2e: --quick: BENCHMARKS.md is left as it is");
        return;
    }
    edit_benchmarks(what, |old| {
        splice(old, &report::markdown_line(row), section)
    });
}

/// Rewrites BENCHMARKS.md with `edit`, which splices `what` (named in the message) into it.
#[cfg(target_os = "linux")]
fn edit_benchmarks(what: &str, edit: impl FnOnce(&str) -> String) {
    let path = proc::repo_file("BENCHMARKS.md");
    let old = std::fs::read_to_string(&path).expect("read BENCHMARKS.md");
    std::fs::write(&path, edit(&old)).expect("write BENCHMARKS.md");
    eprintln!("e2e: wrote {what} into {}", path.display());
}

/// The pure parts' timings, as `cargo bench --bench pure` prints them.
#[cfg(target_os = "linux")]
fn print_pure(pure: &[cases::Case]) {
    println!("{:<66} {:>12}", "pure part", "ns/op");
    for case in pure {
        println!("{:<66} {:>12.1}", case.name, case.ns);
    }
}
