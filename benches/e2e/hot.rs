//! Row 11, the hot path (`-- --hot` runs only it and row 3): the same `GAP 1, 0` loop over a pty
//! to the unpaced simulator against what lies under it, measured in one run with no load added
//! and with a busy loop added on the other core. Under tmclsh are the bare pty round trip (no
//! program) and the simulator's own turnaround, which a bare client measures: it writes each
//! request and reads its echo and reply with nothing else, so tmclsh's ratio to that client is
//! what tmclsh adds. System calls per transaction are counted with strace, which load does not
//! change, for TMCL ASCII and binary, SMD4 and TMCL over slcan.

use std::fs::{File, OpenOptions};
use std::io::{Read, Write};
use std::process::Command;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use crate::host::pty_floor;
use crate::proc::{Sim, median, repo_file, run, runs, tmclsh};
use crate::report::Row;

/// The prefix every row of this part starts with.
pub const PREFIX: &str = "11. Hot path";

/// What one round trip of the bare client sends and reads (character echo, the default).
const REQUEST: &[u8] = b"AGAP 1, 0\r";
const ANSWER: &[u8] = b"AGAP 1, 0\rBA 100 0\r";

/// Measures the rows: `n` transactions per run, `reps` repetitions of each program in turns.
pub fn measure(n: u32, reps: usize) -> Vec<Row> {
    let mut rows = Vec::new();
    for loaded in [false, true] {
        let busy = loaded.then(Busy::start);
        rows.push(round_trips(n, reps, loaded));
        drop(busy);
    }
    rows.push(paced(PACED_N, reps.min(3)));
    for session in SESSIONS {
        rows.push(syscalls(&session));
    }
    rows
}

/// tmclsh, the bare client on the simulator and the bare pty, in turns within each repetition,
/// so that every ratio compares runs made under the same conditions: the machine is shared and
/// its state drifts within seconds. Short repetitions keep the three runs close together, and
/// every other repetition runs them in reverse order so that a drift does not always favour
/// whichever runs first.
fn round_trips(n: u32, reps: usize, loaded: bool) -> Row {
    let sim = Sim::start(&[]);
    let bare_sim = Sim::start(&[]);
    let mut client = BareClient::open(&bare_sim.path);
    let (mut ours, mut bare, mut floor) = (vec![0.0; reps], vec![0.0; reps], vec![0.0; reps]);
    for rep in 0..reps {
        let mut steps: [&mut dyn FnMut(); 3] = [
            &mut || ours[rep] = tmclsh_loop_us(&sim.path, n, "tmclsh run (unpaced pty)"),
            &mut || bare[rep] = client.loop_us(n),
            &mut || floor[rep] = pty_floor(n) * 1e6,
        ];
        if rep % 2 == 1 {
            steps.reverse();
        }
        for step in steps {
            step();
        }
    }
    let within = |f: fn(f64, f64, f64) -> f64| -> Vec<f64> {
        (0..reps).map(|i| f(ours[i], bare[i], floor[i])).collect()
    };
    let ratio = median(&within(|us, bare, _| us / bare));
    let turnaround = median(&within(|_, bare, floor| bare - floor));
    let (us, bare, floor) = (median(&ours), median(&bare), median(&floor));
    let state = if loaded {
        "a busy loop added on the other core"
    } else {
        "no load added"
    };
    Row {
        name: format!("{PREFIX}, {state} (N = {n} a repetition, {reps} repetitions, medians)"),
        measured: format!("tmclsh {us:.1} µs/tx"),
        reference: format!(
            "bare client on the simulator {bare:.1} µs/tx; bare pty {floor:.1} µs; the \
             simulator's turnaround (bare client less bare pty within a repetition) {turnaround:.1} µs"
        ),
        ratio: format!(
            "{ratio:.2}× the bare client (median of the {reps} ratios within a repetition)"
        ),
        target: "≤ 1.25×".into(),
        met: Some(ratio <= 1.25),
    }
}

/// µs per transaction of tmclsh's loop of `n` over the pty at `port`, timed by the script.
fn tmclsh_loop_us(port: &str, n: u32, what: &str) -> f64 {
    let done = run(Command::new(tmclsh())
        .arg("run")
        .arg(repo_file(GAP_LOOP))
        .args(["--port", port, "--", &n.to_string()]))
    .expect_success(what);
    done.number(0) / f64::from(n) * 1e6
}

/// Transactions of the paced row: 115200 baud, a transaction takes about 2 ms.
const PACED_N: u32 = 500;

/// Wire efficiency at 115200 baud split between the simulator and tmclsh: the bare client on a
/// paced simulator shows how near the limit the simulator's own timer lets any client come.
fn paced(n: u32, reps: usize) -> Row {
    let sim = Sim::start(&["--baud", "115200"]);
    let bare_sim = Sim::start(&["--baud", "115200"]);
    let mut client = BareClient::open(&bare_sim.path);
    let (mut ours, mut bare) = (vec![], vec![]);
    for _ in 0..reps {
        ours.push(tmclsh_loop_us(&sim.path, n, "tmclsh run (paced pty)"));
        bare.push(client.loop_us(n));
    }
    let (us, bare) = (median(&ours), median(&bare));
    // Character echo: the request, the echo of its CR, the reply, 10 bits a byte.
    let limit = (REQUEST.len() + 1 + ANSWER.len() - REQUEST.len()) as f64 * 10.0 / 115_200.0 * 1e6;
    Row {
        name: format!(
            "{PREFIX}: wire efficiency at 115200 baud, character echo (N = {n}, {})",
            runs(reps)
        ),
        measured: format!(
            "tmclsh {:.3} ms/tx, {:.1} % of the limit; of it, {:.3} ms is the wait for a byte \
             glued to the reply",
            us / 1e3,
            limit / us * 100.0,
            glued_byte_wait_us() / 1e3
        ),
        reference: format!(
            "bare client {:.3} ms/tx, {:.1} % of the limit {:.3} ms",
            bare / 1e3,
            limit / bare * 100.0,
            limit / 1e3
        ),
        ratio: format!("{:.2}× the bare client", us / bare),
        target: "≥ 97 % of what the simulator allows".into(),
        met: Some(bare / us >= 0.97),
    }
}

/// tmclsh's wait after a reply on a paced line, in µs: as long as the next byte of the same
/// transmission would take, 1.25 byte times (the pace of character echo at 115200 baud is one
/// byte time), and 50 µs for the sender's lateness (`settle_time` in `src/session/wire/trust.rs`).
/// The value a corrupted byte cut short is only known to be whole once that wait has passed, so
/// it cannot move into the next request's drain: the value would be returned by then.
fn glued_byte_wait_us() -> f64 {
    10.0 / 115_200.0 * 1e6 * 1.25 + 50.0
}

/// A session whose system calls are counted: its name, the simulator's arguments, the loop
/// script and tmclsh's arguments besides the link.
struct Session {
    name: &'static str,
    sim: &'static [&'static str],
    script: &'static str,
    client: &'static [&'static str],
}

/// Every kind of session a loop can run: TMCL in both modes, SMD4, TMCL over slcan.
const SESSIONS: [Session; 4] = [
    Session {
        name: "TMCL ASCII",
        sim: &[],
        script: GAP_LOOP,
        client: &[],
    },
    Session {
        name: "TMCL binary",
        sim: &[],
        script: GAP_LOOP,
        client: &["--binary"],
    },
    Session {
        name: "SMD4",
        sim: &["--protocol", "smd4"],
        script: "benches/e2e/smd4_loop.rhai",
        client: &["--protocol", "smd4"],
    },
    Session {
        name: "TMCL over slcan",
        sim: &["--slcan"],
        script: GAP_LOOP,
        client: &[],
    },
];

const GAP_LOOP: &str = "benches/e2e/gap_loop.rhai";

/// System calls of tmclsh per transaction: strace's count for a loop of N less one of none.
fn syscalls(session: &Session) -> Row {
    const N: u32 = 1000;
    let sim = Sim::start(session.sim);
    // An slcan adapter is reached with --can, every other simulator as a serial port.
    let link = if session.sim.contains(&"--slcan") {
        ["--can".to_string(), format!("slcan:{}", sim.path)]
    } else {
        ["--port".to_string(), sim.path.clone()]
    };
    let count = |n: u32| -> Option<f64> {
        let out = std::env::temp_dir().join(format!("tmclsh-strace-{}", std::process::id()));
        let status = Command::new("strace")
            .args(["-f", "-c", "-o"])
            .arg(&out)
            .arg(tmclsh())
            .arg("run")
            .args(session.client)
            .arg(repo_file(session.script))
            .args(&link)
            .args(["--", &n.to_string()])
            .stdout(std::process::Stdio::null())
            .status()
            .ok()?;
        let text = std::fs::read_to_string(&out).ok()?;
        let _ = std::fs::remove_file(&out);
        let total = text.lines().find(|l| l.trim_end().ends_with("total"))?;
        let calls = total.split_whitespace().nth(3)?.parse::<f64>().ok()?;
        status.success().then_some(calls)
    };
    let name = format!(
        "{PREFIX}: system calls per transaction, {} (strace -f -c)",
        session.name
    );
    let per = count(N)
        .zip(count(0))
        .map(|(n, none)| (n - none) / f64::from(N));
    let Some(per) = per else {
        return Row {
            name,
            measured: "skipped (strace not found or refused)".into(),
            reference: "—".into(),
            ratio: "—".into(),
            target: "one wait".into(),
            met: None,
        };
    };
    Row {
        name,
        measured: format!("{per:.2}"),
        reference: "look, write, wait (poll), read".into(),
        ratio: "—".into(),
        target: "one wait, ≤ 4".into(),
        met: Some(per <= 4.05),
    }
}

/// A client with nothing of its own: it enters ASCII mode once, then writes each request and
/// reads until its echo and reply are in.
struct BareClient {
    port: File,
}

impl BareClient {
    fn open(path: &str) -> BareClient {
        let port = OpenOptions::new()
            .read(true)
            .write(true)
            .open(path)
            .expect("open the simulator's pty");
        let mut termios = nix::sys::termios::tcgetattr(&port).expect("tcgetattr");
        nix::sys::termios::cfmakeraw(&mut termios);
        nix::sys::termios::tcsetattr(&port, nix::sys::termios::SetArg::TCSANOW, &termios)
            .expect("tcsetattr");
        let mut client = BareClient { port };
        // Command 139 to module 1, then its 9-byte binary reply.
        let enter = [1u8, 139, 0, 0, 0, 0, 0, 0, 140];
        client.port.write_all(&enter).expect("write 139");
        client.read_exactly(9);
        let mut first = Vec::new();
        client.port.write_all(REQUEST).expect("write a request");
        while first.len() < ANSWER.len() {
            let mut buf = [0u8; 64];
            let n = client.port.read(&mut buf).expect("read");
            first.extend_from_slice(&buf[..n]);
        }
        assert_eq!(first, ANSWER, "the simulator's echo and reply");
        client
    }

    fn read_exactly(&mut self, len: usize) {
        let mut buf = [0u8; 64];
        let mut got = 0;
        while got < len {
            got += self.port.read(&mut buf).expect("read the reply");
        }
    }

    /// µs per round trip over `n` of them.
    fn loop_us(&mut self, n: u32) -> f64 {
        let start = Instant::now();
        for _ in 0..n {
            self.port.write_all(REQUEST).expect("write a request");
            self.read_exactly(ANSWER.len());
        }
        start.elapsed().as_secs_f64() * 1e6 / f64::from(n)
    }
}

/// A thread spinning while it lives: load on the other core.
struct Busy {
    stop: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Busy {
    fn start() -> Busy {
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::spawn(move || {
            while !flag.load(Ordering::Relaxed) {
                std::hint::spin_loop();
            }
        });
        Busy {
            stop,
            thread: Some(thread),
        }
    }
}

impl Drop for Busy {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The heading of this part's section.
pub const HEADING: &str = "## Hot path";

/// The section that says how row 11 was measured and under what load.
pub fn section(date: &str, load_before: &str, load_after: &str) -> String {
    format!(
        "{HEADING}\n\n\
         Row 11, measured on {date} with load averages (1, 5, 15 min) {load_before} before and \
         {load_after} after: the machine is shared, so \"no load added\" is not an idle machine, \
         and \"a busy loop added\" adds a thread spinning in the benchmark's process for the \
         whole run. Each repetition runs, one after the other, `tmclsh run \
         benches/e2e/gap_loop.rhai` over a pty to `tmclsh sim --pty`, a bare client (the \
         benchmark itself: raw pty, 139 once, then each request written and its echo and reply \
         read, nothing checked) on a second simulator, and the bare pty round trip of row 2's \
         floor; every other repetition runs them in reverse order, so that a drift of the \
         machine's state does not always favour whichever runs first. The repetitions are short \
         (N transactions each, a fraction of a second for the three together) and many, \
         because the machine's state drifts within seconds: 7 repetitions of 10,000 gave \
         ratios between 1.00× and 1.65× from one run to the next and a negative turnaround. \
         The ratio is the median of the \
         ratios tmclsh / bare client within each repetition, and the simulator's turnaround the \
         median of bare client less bare pty within each repetition; the times shown are each \
         side's own median. The bare client's time is the floor plus the simulator's own \
         turnaround, so tmclsh's ratio to it is what tmclsh adds. The paced row does the same at 115200 baud: the bare client shows how \
         near the limit the simulator's timer lets any client come, and tmclsh is judged \
         against that. Of tmclsh's share, the wait for a byte glued to the reply is shown: a \
         reply whose last digit a corrupted byte turned into a line end looks whole until the \
         next byte time has passed, so the value is trusted only after that wait; it cannot move \
         into the next request's drain, which comes after the value was returned (the test \
         `what_follows_a_reply_on_a_paced_line_is_waited_for` holds it). System calls are strace's count (`strace -f -c`) of a loop of 1000 less \
         one of none, divided by 1000: a count that load does not change. They are counted for \
         each kind of session: TMCL in ASCII and in binary over a pty, SMD4 (`send(\"MOTOR:PACT\")` \
         in `benches/e2e/smd4_loop.rhai`) against `tmclsh sim --pty --protocol smd4`, and TMCL \
         over slcan (`--can slcan:PTY`) against `tmclsh sim --pty --slcan`. The same count at the \
         level of the link (sends, looks, waits) is pinned by a test (`tests/hot_path.rs`). \
         Only these rows and row 3: `cargo bench --bench e2e -- --hot`.\n"
    )
}
