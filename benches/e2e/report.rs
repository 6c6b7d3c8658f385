//! The table, on the terminal and as `BENCHMARKS.md`.

use std::fmt::Write as _;

use crate::cases::Case;
use crate::machine::Machine;

/// One line of the table.
pub struct Row {
    pub name: String,
    pub measured: String,
    /// The peer or the limit it is compared with.
    pub reference: String,
    pub ratio: String,
    pub target: String,
    /// Whether the target was met; `None` where there is no target or it could not be judged.
    pub met: Option<bool>,
}

impl Row {
    fn verdict(&self) -> &'static str {
        match self.met {
            Some(true) => "met",
            Some(false) => "MISSED",
            None => "—",
        }
    }

    fn cells(&self) -> [&str; 6] {
        [
            &self.name,
            &self.measured,
            &self.reference,
            &self.ratio,
            &self.target,
            self.verdict(),
        ]
    }
}

const HEADER: [&str; 6] = [
    "row",
    "tmclsh",
    "compared with",
    "ratio",
    "target",
    "verdict",
];

/// The table as aligned plain text.
pub fn text(rows: &[Row]) -> String {
    let mut widths = HEADER.map(|h| h.chars().count());
    for row in rows {
        for (w, cell) in widths.iter_mut().zip(row.cells()) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let line = |cells: [&str; 6]| {
        let mut out = String::new();
        for (cell, w) in cells.iter().zip(widths) {
            let _ = write!(out, "{cell:<w$}  ");
        }
        out.trim_end().to_string() + "\n"
    };
    let mut out = line(HEADER);
    for row in rows {
        out.push_str(&line(row.cells()));
    }
    out
}

/// Everything that goes into `BENCHMARKS.md`.
pub struct Run<'a> {
    pub date: String,
    pub command: &'a str,
    pub machine: &'a Machine,
    pub load_before: String,
    pub load_after: String,
    pub rows: &'a [Row],
    pub pure: &'a [Case],
}

/// `BENCHMARKS.md`.
pub fn markdown(run: &Run) -> String {
    let mut md = String::new();
    let m = run.machine;
    let _ = write!(
        md,
        "# Benchmarks\n\n\
         Measured on {date} by\n\n```sh\n{command}\n```\n\n\
         which runs every row below side by side and writes this file; nothing in it is edited by \
         hand. `cargo bench` runs it together with the pure-part benchmark \
         (`cargo bench --bench pure`), whose numbers are repeated at the end.\n\n\
         ## Machine\n\n\
         | | |\n|---|---|\n\
         | CPU | {cpu} |\n| cores | {cores} |\n| kernel | {kernel} |\n| toolchain | {rustc} |\n\
         | peer | {python} |\n\
         | load average (1, 5, 15 min) before / after | {before} / {after} |\n\n",
        date = run.date,
        command = run.command,
        cpu = m.cpu,
        cores = m.cores,
        kernel = m.kernel,
        rustc = m.rustc,
        python = m
            .python
            .as_deref()
            .unwrap_or("python3 with pyserial not available: peer rows skipped"),
        before = run.load_before,
        after = run.load_after,
    );
    md.push_str("## Results\n\n");
    md.push_str(&table_row(&HEADER));
    md.push_str("|---|---:|---|---|---|---|\n");
    for row in run.rows {
        md.push_str(&table_row(&row.cells()));
    }
    md.push('\n');
    md.push_str(&pure_section(run.pure));
    md.push_str(METHOD);
    md.push_str(&notes(run.rows));
    md
}

/// The heading of the pure parts' section.
pub const PURE_HEADING: &str = "## Pure parts";

/// The pure parts' section: its heading and table.
pub fn pure_section(pure: &[Case]) -> String {
    let mut md =
        format!("{PURE_HEADING}\n\n| operation | ns/op (median of batches) |\n|---|---:|\n");
    for case in pure {
        let _ = writeln!(md, "| {} | {:.1} |", case.name, case.ns);
    }
    md
}

/// One row as a line of the markdown table.
/// `markdown` with the rows whose name starts with `prefix` replaced by `lines`, where the first
/// of them stood, or added at the end of the results table.
pub fn splice_rows(markdown: &str, prefix: &str, lines: &[String]) -> String {
    let start = format!("| {prefix}");
    let mut kept: Vec<String> = Vec::new();
    let mut at = None;
    for line in markdown.lines() {
        if line.starts_with(&start) {
            at.get_or_insert(kept.len());
        } else {
            kept.push(line.to_string());
        }
    }
    let at = at.unwrap_or_else(|| {
        let header = kept
            .iter()
            .position(|l| l.starts_with("| row |"))
            .expect("BENCHMARKS.md has a results table");
        kept[header..]
            .iter()
            .position(|l| !l.starts_with('|'))
            .map_or(kept.len(), |i| header + i)
    });
    for (i, line) in lines.iter().enumerate() {
        kept.insert(at + i, line.trim_end().to_string());
    }
    kept.join("\n") + "\n"
}

/// The section under `heading` (its first line) replaced by `section`, or added before the pure
/// parts.
pub fn splice_section(markdown: &str, heading: &str, section: &str) -> String {
    let mut lines: Vec<String> = markdown.lines().map(str::to_string).collect();
    let section_lines: Vec<String> = section.trim_end().lines().map(str::to_string).collect();
    match lines.iter().position(|l| l == heading) {
        Some(start) => {
            let end = lines[start + 1..]
                .iter()
                .position(|l| l.starts_with("## "))
                .map_or(lines.len(), |i| start + 1 + i);
            lines.splice(start..end, section_lines.into_iter().chain([String::new()]));
        }
        None => {
            let at = lines
                .iter()
                .position(|l| l == "## Pure parts")
                .unwrap_or(lines.len());
            lines.splice(at..at, section_lines.into_iter().chain([String::new()]));
        }
    }
    lines.join("\n") + "\n"
}

pub fn markdown_line(row: &Row) -> String {
    table_row(&row.cells())
}

fn table_row(cells: &[&str]) -> String {
    format!("| {} |\n", cells.join(" | "))
}

const METHOD: &str = "
## Method

All rows use the release binary cargo builds for the benchmark. Transactions are `GAP 1, 0`
(`gap(1, 0)` in `benches/e2e/gap_loop.rhai`), timed inside the script around the loop, so process
start-up and entering ASCII mode are not counted. Times are medians over repetitions; the
programs compared run in turns within each repetition, and ratios are the median of the ratios
within the repetitions, so that a busy (or idle) spell of the machine hits both sides alike.

1. **Wire efficiency**: `tmclsh run` against `tmclsh sim --pty --baud B`, echo mode set with
   `sgp(67, 0, …)`. The limit of one transaction is the bytes that must pass one after the other
   on an 8N1 line, 10 bits per byte, full duplex, the simulator answering at once: with `R` the
   request and its CR (`AGAP 1, 0␍`, 10 bytes) and `P` the reply and its CR (`BA 100 0␍`, 9
   bytes), no echo `R + P`, line echo `R + R + P` (the echoed line and its CR come after the
   request), character echo `R + 1 + P` (each character is echoed while the next is on its way in;
   only the echo of the final CR follows the request). Efficiency = limit / measured.
2. **Host overhead**: the same loop over a pty to `tmclsh sim --pty` without pacing, against
   `benches/peers/pyserial_loop.py` doing the same transactions on the same simulator: it enters
   ASCII mode with command 139, reads the echo and the reply line and checks status and value,
   reading each line with `read_until(b\"\\r\")` as pyserial's documentation shows (the peer of the
   target) and, in the row below, tuned to read whatever has arrived (`in_waiting`). CPU per
   transaction: tmclsh's user + system time (wait4) of the loop minus a run without
   transactions; the peer's `time.process_time()` over its loop. The floor row is a bare pty
   round trip (two threads, 10 bytes one way, 19 back): what the kernel costs before any program
   does anything.
3. **In-process**: the same script on the built-in simulator (no OS I/O): parse, Rhai, session
   and simulator.
4. **Start-up**: `tmclsh -c \"GAP 1, 0\"` on the built-in simulator, spawn to exit, against
   `python3 -c \"import serial\"`, the least a Python tool must do; runs alternate. The row
   below it is the size of that binary on disk, as the release profile in `Cargo.toml` builds it.
5. **Memory**: peak resident set size (wait4 `ru_maxrss`) of the loop with `--log` at N and at
   N/10; flat means under 5 % growth.
6. **Transcript cost**: row 2 with `--log FILE`, run right before or after (in turns) each of
   row 2's runs; CPU as in row 2.
7. **Fault soak**: reads of known values under injected faults; its own section above has the
   method and every cell's counts.
8. **Late replies**: the soak's delay cells with replies later than the resync window;
   its own section above has the method and every cell's counts.
9. **Latency timer**: row 1's loop without echo at 115200 baud through `tmclsh sim --pty --baud
   115200 --latency MS`, which holds the bytes it sends until MS pass or 62 wait, as an FTDI
   adapter does, against the same simulator without `--latency` (started first, in the same
   run). 16 ms is an untouched adapter's timer (what tmclsh's notice on opening says it costs
   where the low-latency flag does not lower it); 1 ms is the timer the flag sets.
10. **Reconnect**: `tmclsh --port LINK` at its idle prompt on a pseudo-terminal of its own, with
    `tmclsh sim --pty --link LINK`; the console's `unplug S` (S from 0.25 s up, a different
    outage each run, so the replug falls at different points of the pauses between tries) closes
    the pty and serves a new one behind LINK after S. Timed from the simulator's `pty PATH` line
    (the new pty is there) to the REPL's `reconnected` (136, 139 and GGP 67 sent again). Only this
    row: `cargo bench --bench e2e -- --reconnect`.
11. **Hot path**: tmclsh against a bare client on the simulator and the bare pty, with and
    without a busy loop added, at 115200 baud against the bare client on a paced simulator, and
    system calls per transaction; its own section above has the method and the conditions.
";

/// The sentence that says when rows were measured and how busy the machine was.
pub fn measured_under(rows: &str, date: &str, load_before: &str, load_after: &str) -> String {
    format!(
        "{rows}, measured on {date} with load averages (1, 5, 15 min) {load_before} before and \
         {load_after} after: the machine is shared with other work, so the times include waits \
         for a CPU that an idle machine would not have."
    )
}

/// What the reader should know about targets that were missed.
fn notes(rows: &[Row]) -> String {
    let missed = |prefix: &str| {
        rows.iter()
            .any(|r| r.name.starts_with(prefix) && r.met == Some(false))
    };
    let mut out = String::from("\n## Notes\n\n");
    let mut any = false;
    if missed("1.") {
        any = true;
        out.push_str(
            "- **Wire efficiency below 97 %**: the simulator delivers every byte at its wire time \
             (nanosecond ppoll timeouts, timer slack 1 ns) and tmclsh sends the next request as \
             soon as it has read the reply's last byte, so each transaction loses what it takes \
             the last byte to reach the client after its wire time and the next request to reach \
             the simulator: the simulator's timed wake-up for that byte (timer lateness row), \
             the trip through the pty to tmclsh, tmclsh's turn-around (row 2's CPU) and the trip \
             back, each trip a kernel worker and a process to wake. Between the bytes of a paced \
             line the CPUs fall idle, and on this virtual machine waking an idle CPU costs about \
             what the timer lateness row shows, several times per transaction; any wait for a \
             CPU while other work runs (load average above) comes on top. At 115200 baud a \
             transaction lasts 1.6–2.5 ms, so 97 % leaves 50–75 µs for all of that; at 9600 baud \
             ten times as much.\n",
        );
    }
    if missed("2.") {
        any = true;
        out.push_str(
            "- **Host overhead**: compare with the pty floor row. Most of a transaction is the \
             kernel moving the bytes through the pty and waking the two processes (a kernel \
             worker and a process on each side); tmclsh and the simulator add the difference \
             shown there, and the CPU column is what tmclsh itself spends, mostly in its four \
             system calls per transaction. The floor depends on whether the CPUs were idle: on \
             this virtual machine a wake-up from idle costs about what the timer lateness row \
             shows, so an otherwise idle machine has a higher floor than a busy one. The same \
             floor is in the pyserial loop's time, so the ratio cannot exceed the peer's time \
             divided by the floor, however little tmclsh spends.\n",
        );
    }
    if missed("6.") {
        any = true;
        out.push_str(
            "- **Transcript cost above 20 %**: each transcript line is one write(2), two per \
             transaction, so that a crash loses nothing.\n",
        );
    }
    for row in rows.iter().filter(|r| r.met == Some(false)) {
        if !["1.", "2.", "6."].iter().any(|p| row.name.starts_with(p)) {
            any = true;
            let _ = writeln!(
                out,
                "- **{}** missed its target ({}) in this run.",
                row.name, row.target
            );
        }
    }
    if !any {
        out.push_str("Every target was met in this run.\n");
    }
    out
}
