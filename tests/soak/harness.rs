//! The fault soak: reads of known values through the path users take — a Rhai script run by
//! `tmclsh run` over a pseudo-terminal to `tmclsh sim` — while the simulator drops, corrupts or
//! delays replies at a seeded rate. Every read ends one of three ways: the true value, a failure
//! the script caught (counted by kind), or a value that differs from the truth although the call
//! returned normally: a **silent wrong value**.
//!
//! Shared by the fast soak in `cargo test` and the full one in `cargo bench --bench e2e`; it needs
//! only the path of a `tmclsh` binary.

use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

/// How long the simulator may take to answer a console line or print its pty.
const PATIENCE: Duration = Duration::from_secs(30);

/// The configurations of the matrix: the three TMCL echo modes (global parameter 67), TMCL binary
/// direct mode, and the SMD4 drive with and without an address.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// TMCL, character echo (GP67 = 0).
    TmclChar,
    /// TMCL, line echo (GP67 = 0x10).
    TmclLine,
    /// TMCL, no echo (GP67 = 0x20, the usual RS-485 set-up).
    TmclNone,
    /// SMD4 without `--address`.
    Smd4,
    /// SMD4 with `--address 7` (the drive in addressing mode).
    Smd4Addressed,
    /// TMCL binary direct mode (`--binary`): reply frames name module and command, not the
    /// request's type or bank.
    TmclBinary,
}

impl Target {
    /// Every configuration, in table order (binary last: the cells before it keep their seeds).
    pub const ALL: [Target; 6] = [
        Target::TmclChar,
        Target::TmclLine,
        Target::TmclNone,
        Target::Smd4,
        Target::Smd4Addressed,
        Target::TmclBinary,
    ];

    /// The row label.
    pub fn name(self) -> &'static str {
        match self {
            Target::TmclChar => "TMCL char echo",
            Target::TmclLine => "TMCL line echo",
            Target::TmclNone => "TMCL no echo",
            Target::Smd4 => "SMD4",
            Target::Smd4Addressed => "SMD4 --address 7",
            Target::TmclBinary => "TMCL binary",
        }
    }

    fn smd4(self) -> bool {
        matches!(self, Target::Smd4 | Target::Smd4Addressed)
    }

    /// The client flags that select this configuration.
    fn client_args(self) -> Vec<&'static str> {
        match self {
            Target::Smd4 => vec!["--protocol", "smd4"],
            Target::Smd4Addressed => vec!["--protocol", "smd4", "--address", "7"],
            Target::TmclBinary => vec!["--binary"],
            _ => vec!["--stay-ascii"],
        }
    }
}

/// The injected faults of a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// Replies dropped.
    Drop,
    /// One byte of a reply changed.
    Corrupt,
    /// Replies held back past the client's timeout.
    Delay,
    /// All three, each at the rate.
    All,
    /// Replies dropped, and others held back: the late replies come when the reply to the
    /// request after a dropped one is awaited (not in [`Fault::ALL`]: its own cells).
    DropDelay,
}

impl Fault {
    /// Every fault kind, in table order.
    pub const ALL: [Fault; 4] = [Fault::Drop, Fault::Corrupt, Fault::Delay, Fault::All];

    /// The column label.
    pub fn name(self) -> &'static str {
        match self {
            Fault::Drop => "drop",
            Fault::Corrupt => "corrupt",
            Fault::Delay => "delay",
            Fault::All => "all three",
            Fault::DropDelay => "drop + delay",
        }
    }

    fn corrupts(self) -> bool {
        matches!(self, Fault::Corrupt | Fault::All)
    }

    /// The console commands that switch it on.
    fn commands(self, plan: &Plan) -> Vec<String> {
        let rate = plan.rate;
        let drop = format!("drop {rate}");
        let corrupt = format!("corrupt {rate}");
        let delay = format!("delay {rate} {}", plan.delay_ms);
        match self {
            Fault::Drop => vec![drop],
            Fault::Corrupt => vec![corrupt],
            Fault::Delay => vec![delay],
            Fault::All => vec![drop, corrupt, delay],
            Fault::DropDelay => vec![drop, delay],
        }
    }
}

/// How a cell is run.
#[derive(Debug, Clone)]
pub struct Plan {
    /// Reads of known values.
    pub reads: u64,
    /// Probability of each injected fault per reply.
    pub rate: f64,
    /// The client's `--timeout`.
    pub timeout_ms: u64,
    /// How long a delayed reply is held back (past the timeout).
    pub delay_ms: u64,
    /// Seed of the faults and of the order of the reads.
    pub seed: u64,
}

/// What happened to the reads of one cell.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Counts {
    /// Reads made.
    pub reads: u64,
    /// Reads that returned the true value.
    pub ok: u64,
    /// Failures reported as a timeout (exit 3, "no reply").
    pub timeout: u64,
    /// Failures reported as line noise or an unusable reply (exit 3, other messages).
    pub noise: u64,
    /// Failures reported as a device error (exit 1). No read of the soak can fail on the device,
    /// so each of these is a damaged reply taken for a refusal.
    pub device: u64,
    /// Failures with any other exit code.
    pub other: u64,
    /// Values returned normally that differ from the truth: must be 0.
    pub silent_wrong: u64,
    /// Values returned normally that are the truth with one digit (or the sign) changed into
    /// another, still a well-formed number, in a cell that corrupts bytes: see
    /// [`one_digit_changed`]. Neither protocol carries a checksum in its ASCII form, so no client
    /// can tell these from the truth; they are counted apart from [`Counts::silent_wrong`]. The
    /// known values differ pairwise in at least three characters, so a reply to another request
    /// never lands here.
    pub undetectable: u64,
    /// Runs of the script that ended before their reads were done (the session could not
    /// open); the remaining reads were made by a new run.
    pub restarts: u64,
    /// Faults the simulator injected (its console's `faults`).
    pub injected: Injected,
    /// The first few silent wrong values, for the failure message.
    pub examples: Vec<String>,
    /// The seed the cell ran with.
    pub seed: u64,
    /// A hash of every read's outcome in order (FNV-1a): equal for two runs that went alike.
    pub digest: u64,
}

/// The simulator's own count of what it injected.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Injected {
    /// Replies judged.
    pub replies: u64,
    /// Replies dropped.
    pub dropped: u64,
    /// Replies corrupted.
    pub corrupted: u64,
    /// Replies delayed.
    pub delayed: u64,
}

impl Counts {
    /// Failures reported, of every kind.
    pub fn failures(&self) -> u64 {
        self.timeout + self.noise + self.device + self.other
    }

    /// Adds another cell's counts.
    pub fn add(&mut self, other: &Counts) {
        self.reads += other.reads;
        self.ok += other.ok;
        self.timeout += other.timeout;
        self.noise += other.noise;
        self.device += other.device;
        self.other += other.other;
        self.silent_wrong += other.silent_wrong;
        self.undetectable += other.undetectable;
        self.restarts += other.restarts;
        self.injected.replies += other.injected.replies;
        self.injected.dropped += other.injected.dropped;
        self.injected.corrupted += other.injected.corrupted;
        self.injected.delayed += other.injected.delayed;
        self.examples.extend(other.examples.iter().cloned());
    }

    /// One line: every count, for test output and failure messages.
    pub fn summary(&self) -> String {
        format!(
            "reads {} ok {} timeout {} noise {} device {} other {} silent-wrong {} \
             undetectable {} restarts {} (seed {}, injected: {} replies, {} dropped, {} corrupted, \
             {} delayed)",
            self.reads,
            self.ok,
            self.timeout,
            self.noise,
            self.device,
            self.other,
            self.silent_wrong,
            self.undetectable,
            self.restarts,
            self.seed,
            self.injected.replies,
            self.injected.dropped,
            self.injected.corrupted,
            self.injected.delayed,
        )
    }
}

/// Runs one cell of the matrix with the `tmclsh` at `bin` and returns its counts.
pub fn run_cell(bin: &Path, target: Target, fault: Fault, plan: &Plan) -> Counts {
    let dir = scratch_dir();
    let mut sim = Sim::start(bin, target);
    let truth = set_up(bin, &sim.pty, target, &dir);
    let seed = cell_seed(plan.seed, target, fault);
    assert!(
        sim.console(&format!("seed {seed}")).starts_with("ok "),
        "the simulator takes a seed"
    );
    for command in fault.commands(plan) {
        let answer = sim.console(&command);
        assert!(answer.starts_with("ok "), "{command}: {answer}");
    }
    let script = dir.join("soak.rhai");
    std::fs::write(&script, soak_script(target, &truth)).unwrap();
    let mut counts = Counts {
        digest: 0xCBF2_9CE4_8422_2325,
        ..Counts::default()
    };
    let max_restarts = 20 + plan.reads / 20;
    while counts.reads < plan.reads {
        let remaining = (plan.reads - counts.reads).to_string();
        let order_seed = (seed.wrapping_mul(1_000_003) + counts.reads) % (1 << 31);
        let output = run_script(bin, &sim.pty, target, &script)
            .args(["--timeout", &plan.timeout_ms.to_string()])
            .args(["--", &remaining, &order_seed.to_string()])
            .output()
            .expect("tmclsh runs");
        let before = counts.reads;
        tally_output(
            &mut counts,
            &String::from_utf8_lossy(&output.stdout),
            &truth,
            target,
            fault.corrupts(),
        );
        if !output.status.success() || counts.reads == before {
            counts.restarts += 1;
            assert!(
                output.status.code() == Some(3) && counts.restarts <= max_restarts,
                "{} / {}: the script keeps ending early (exit {:?}): {}",
                target.name(),
                fault.name(),
                output.status.code(),
                String::from_utf8_lossy(&output.stderr)
            );
        }
    }
    counts.injected = sim.injected();
    counts.seed = seed;
    sim.quit();
    let _ = std::fs::remove_dir_all(&dir);
    counts
}

/// The seed of one cell: the plan's, plus the cell's place in the matrix, so that cells do not
/// share their fault pattern and each can be replayed alone.
pub fn cell_seed(base: u64, target: Target, fault: Fault) -> u64 {
    let row = Target::ALL.iter().position(|t| *t == target).unwrap_or(0) as u64;
    let column = match Fault::ALL.iter().position(|f| *f == fault) {
        Some(column) => column as u64,
        // Past every row of the matrix.
        None => return base.wrapping_add(100 + row),
    };
    base.wrapping_add(row * Fault::ALL.len() as u64 + column)
}

/// Counts every read the soak script printed in `stdout` (its `soak` lines; others are ignored).
pub fn tally_output(
    counts: &mut Counts,
    stdout: &str,
    truth: &[String],
    target: Target,
    corrupts: bool,
) {
    for line in stdout.lines() {
        tally(counts, line, truth, target, corrupts);
    }
}

/// Counts one line of the soak script's output.
fn tally(counts: &mut Counts, line: &str, truth: &[String], target: Target, corrupts: bool) {
    let mut words = line.splitn(4, ' ');
    if words.next() != Some("soak") {
        return;
    }
    let outcome = words.next().unwrap_or_default();
    let index: usize = words
        .next()
        .and_then(|w| w.parse().ok())
        .expect("the soak script names the value it read");
    let rest = words.next().unwrap_or_default();
    counts.reads += 1;
    for byte in line.bytes().chain([b'\n']) {
        counts.digest = (counts.digest ^ u64::from(byte)).wrapping_mul(0x100_0000_01B3);
    }
    match outcome {
        "ok" if rest == truth[index] => counts.ok += 1,
        // A binary frame carries a checksum: no corrupted byte is undetectable there.
        "ok" if corrupts
            && target != Target::TmclBinary
            && one_digit_changed(rest, &truth[index]) =>
        {
            counts.undetectable += 1
        }
        "ok" if corrupts
            && target.smd4()
            && SMD4_TEXT.contains(&SMD4_VALUES[index].0)
            && one_character_changed(rest, &truth[index]) =>
        {
            counts.undetectable += 1
        }
        "ok" => {
            counts.silent_wrong += 1;
            if counts.examples.len() < 5 {
                counts.examples.push(format!(
                    "read {index} returned {rest} (truth {})",
                    truth[index]
                ));
            }
        }
        _ => {
            let (exit, message) = rest.split_once(' ').unwrap_or((rest, ""));
            match exit {
                "1" => counts.device += 1,
                "3" if message.contains("no reply") => counts.timeout += 1,
                "3" => counts.noise += 1,
                _ => counts.other += 1,
            }
        }
    }
}

/// Whether `got` is `truth` with one character changed into a reply no parser can tell from a
/// true one: a digit into another digit, or a leading sign into a digit or back, leaving a finite
/// number without a leading zero (hexadecimal digits in a UUID). Anything else — a changed
/// separator, exponent or dash, a truncation, a leading zero — a careful client can refuse.
pub fn one_digit_changed(got: &str, truth: &str) -> bool {
    if got.len() != truth.len() {
        return false;
    }
    let mut differing = got
        .bytes()
        .zip(truth.bytes())
        .enumerate()
        .filter(|(_, (g, t))| g != t);
    let (Some((at, (g, t))), None) = (differing.next(), differing.next()) else {
        return false;
    };
    // The items as the script prints them: ["1.2340E+03", "1.2340E+03"] or a bare number.
    let items: Vec<&str> = got
        .trim_matches(|c| c == '[' || c == ']')
        .split(", ")
        .map(|item| item.trim_matches('"'))
        .collect();
    if items.len() == 1 && is_uuid(items[0]) {
        return is_uuid(truth.trim_matches(|c| matches!(c, '[' | ']' | '"')))
            && g.is_ascii_hexdigit()
            && t.is_ascii_hexdigit();
    }
    let sign_or_digit = |c: u8| c.is_ascii_digit() || c == b'-';
    let at_start = at == 0 || matches!(got.as_bytes()[at - 1], b'"' | b'[');
    let well_formed = items.iter().all(|item| {
        let unsigned = item.strip_prefix('-').unwrap_or(item);
        let leading_zero = unsigned.len() > 1
            && unsigned.starts_with('0')
            && unsigned.as_bytes()[1].is_ascii_digit();
        item.parse::<f64>().is_ok_and(f64::is_finite) && !leading_zero
    });
    well_formed
        && if at_start {
            sign_or_digit(g) && sign_or_digit(t)
        } else {
            g.is_ascii_digit() && t.is_ascii_digit()
        }
}

/// Whether `got` is `truth` with one printable character changed into another printable one:
/// all a client can see of a corrupted byte in a text item no grammar constrains (see
/// [`SMD4_TEXT`]). Both are compared as the items hold them, not as the script prints them (a
/// backslash or quote is printed escaped).
pub fn one_character_changed(got: &str, truth: &str) -> bool {
    let (got, truth) = (unescape(got), unescape(truth));
    let printable = |c: u8| c.is_ascii_graphic() && c != b',';
    let mut differing = got.iter().zip(truth.iter()).filter(|(g, t)| g != t);
    got.len() == truth.len()
        && matches!(
            (differing.next(), differing.next()),
            (Some((&g, &t)), None) if printable(g) && printable(t)
        )
}

/// A printed string item as the item holds it: `\\` and `\"` are one character each.
fn unescape(printed: &str) -> Vec<u8> {
    let mut out = Vec::with_capacity(printed.len());
    let mut bytes = printed.bytes();
    while let Some(b) = bytes.next() {
        match b {
            b'\\' => out.extend(bytes.next()),
            _ => out.push(b),
        }
    }
    out
}

/// `8-4-4-4-12` hexadecimal digits.
fn is_uuid(text: &str) -> bool {
    text.len() == 36
        && text.bytes().enumerate().all(|(i, b)| match i {
            8 | 13 | 18 | 23 => b == b'-',
            _ => b.is_ascii_hexdigit(),
        })
}

/// Characters that differ between `a` and `b`, right-aligned, the shorter padded with `0`.
fn distance(a: &str, b: &str) -> usize {
    let width = a.len().max(b.len());
    let pad = |s: &str| format!("{s:0>width$}").into_bytes();
    pad(a)
        .iter()
        .zip(pad(b).iter())
        .filter(|(x, y)| x != y)
        .count()
}

/// The known values: set them fault-free, read them back, and check that every pair differs
/// in at least three characters (so [`Counts::undetectable`] can never hold a reply to another
/// request). Returns the truth, as the soak script prints it, by index.
fn set_up(bin: &Path, pty: &str, target: Target, dir: &Path) -> Vec<String> {
    if target == Target::Smd4Addressed {
        let out = Command::new(bin)
            .args([
                "--port",
                pty,
                "--protocol",
                "smd4",
                "-c",
                "COMS:SERIAL:SLAVEADDR,7",
            ])
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let script = dir.join("setup.rhai");
    std::fs::write(&script, setup_script(target)).unwrap();
    let out = run_script(bin, pty, target, &script).output().unwrap();
    assert!(
        out.status.success(),
        "{} set-up: {}",
        target.name(),
        String::from_utf8_lossy(&out.stderr)
    );
    let truth: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| l.strip_prefix("truth "))
        .map(|l| l.split_once(' ').expect("index and value").1.to_string())
        .collect();
    let expected = if target.smd4() {
        SMD4_VALUES.len()
    } else {
        tmcl_values().len()
    };
    assert_eq!(truth.len(), expected, "every known value read back");
    if !target.smd4() {
        let set: Vec<String> = tmcl_values().iter().map(i32::to_string).collect();
        assert_eq!(truth, set, "the values read back are the values set");
    }
    for (i, a) in truth.iter().enumerate() {
        for b in &truth[i + 1..] {
            assert!(
                distance(a, b) >= 3,
                "known values {a} and {b} are too alike"
            );
        }
    }
    truth
}

/// The 56 user variables' known values (TMCL bank 2): from one to ten digits, half of them
/// negative, drawn from a fixed generator and kept when at least three characters away from
/// every value kept before.
pub fn tmcl_values() -> Vec<i32> {
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state >> 11
    };
    let mut values: Vec<i32> = Vec::new();
    while values.len() < 56 {
        let digits = 1 + (next() % 10) as u32;
        let magnitude = (next() % 10u64.pow(digits)).min(i32::MAX as u64) as i32;
        let value = if next() % 2 == 0 {
            magnitude
        } else {
            -magnitude
        };
        let text = value.to_string();
        if values.iter().all(|v| distance(&v.to_string(), &text) >= 3) {
            values.push(value);
        }
    }
    values
}

/// SMD4 settings set to known values (the read-only ones as the simulator fixes them).
const SMD4_VALUES: [(&str, Option<&str>); 13] = [
    ("MOTOR:PACT", Some("-3705418")),
    ("MOTOR:VMAX", Some("9163.5")),
    ("MOTOR:AMAX", Some("2471.25")),
    ("MOTOR:DMAX", Some("13058")),
    ("MOTOR:VSTART", Some("57.75")),
    ("MOTOR:VSTOP", Some("612.5")),
    ("MOTOR:THIGH", Some("4890")),
    ("MOTOR:TZW", Some("2.15")),
    ("MOTOR:PDDEL", Some("0.65")),
    ("BAKE:T", Some("173")),
    ("COMS:SERIAL:RS485DEL", Some("806")),
    ("SYS:FW", None),
    ("SYS:UUID", None),
];

/// The settings whose reply item the SMD4 document declares a STRING with no format: the
/// firmware version. A byte of it corrupted into another printable character is a well-formed
/// reply (`24A44.12` for `24044.12`), as undetectable as a digit changed in a number.
const SMD4_TEXT: [&str; 1] = ["SYS:FW"];

fn setup_script(target: Target) -> String {
    let mut script = String::new();
    if target.smd4() {
        for (i, (mnemonic, value)) in SMD4_VALUES.iter().enumerate() {
            if let Some(value) = value {
                script.push_str(&format!("send(\"{mnemonic},{value}\");\n"));
            }
            script.push_str(&format!("print(`truth {i} ${{send(\"{mnemonic}\")}}`);\n"));
        }
    } else {
        let gp67 = match target {
            Target::TmclLine => Some(0x10),
            Target::TmclNone => Some(0x20),
            Target::TmclBinary => None,
            _ => Some(0),
        };
        if let Some(gp67) = gp67 {
            script.push_str(&format!("sgp(67, 0, {gp67});\n"));
        }
        for (i, value) in tmcl_values().iter().enumerate() {
            script.push_str(&format!("sgp({i}, 2, {value});\n"));
        }
        for i in 0..tmcl_values().len() {
            script.push_str(&format!("print(`truth {i} ${{ggp({i}, 2)}}`);\n"));
        }
    }
    script
}

/// The soak: `args[0]` reads in an order drawn from `args[1]`; each read prints
/// `soak ok INDEX VALUE` or `soak err INDEX EXIT MESSAGE`.
fn soak_script(target: Target, truth: &[String]) -> String {
    let reader = if target.smd4() {
        let names: Vec<String> = SMD4_VALUES
            .iter()
            .map(|(m, _)| format!("\"{m}\""))
            .collect();
        format!(
            "let names = [{}];\nfn read(names, i) {{ send(names[i]) }}\n",
            names.join(", ")
        )
    } else {
        "let names = [];\nfn read(names, i) { ggp(i, 2) }\n".to_string()
    };
    script_reading(&reader, truth.len())
}

/// The soak's loop over `values` known values with the given `reader`: Rhai that defines
/// `names` and `fn read(names, i)`, the read of value `i`.
pub fn script_reading(reader: &str, values: usize) -> String {
    format!(
        "{reader}\
         let n = parse_int(args[0]);\n\
         let x = parse_int(args[1]);\n\
         let k = {};\n\
         for j in 0..n {{\n\
         \x20   x = (x * 1103515245 + 12345) % 2147483648;\n\
         \x20   let i = (x / 65536) % k;\n\
         \x20   try {{\n\
         \x20       let value = read(names, i);\n\
         \x20       print(`soak ok ${{i}} ${{value}}`);\n\
         \x20   }} catch (e) {{\n\
         \x20       print(`soak err ${{i}} ${{e.exit}} ${{e}}`);\n\
         \x20   }}\n\
         }}\n",
        values
    )
}

/// `tmclsh run SCRIPT --port PTY` with the target's flags.
fn run_script(bin: &Path, pty: &str, target: Target, script: &Path) -> Command {
    let mut command = Command::new(bin);
    command
        .arg("run")
        .arg(script)
        .args(["--port", pty])
        .args(target.client_args())
        .stdin(Stdio::null())
        .env("NO_COLOR", "1");
    command
}

fn scratch_dir() -> PathBuf {
    fresh_dir("tmclsh-soak")
}

/// A new, empty directory `PREFIX-PID-N` in the system temp dir. Process ids wrap (a container's
/// `pid_max` may be 32768), so a name an earlier run left is skipped, never reused.
pub fn fresh_dir(prefix: &str) -> PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    loop {
        let dir = std::env::temp_dir().join(format!(
            "{prefix}-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        match std::fs::create_dir(&dir) {
            Ok(()) => return dir,
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => panic!("cannot create {}: {e}", dir.display()),
        }
    }
}

/// A `tmclsh sim` on a pty, steered through its console.
struct Sim {
    child: Child,
    stdin: ChildStdin,
    lines: Receiver<String>,
    pty: String,
}

impl Sim {
    fn start(bin: &Path, target: Target) -> Sim {
        let protocol = if target.smd4() { "smd4" } else { "tmcl" };
        let mut child = Command::new(bin)
            .args(["sim", "--pty", "--protocol", protocol])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("tmclsh sim starts");
        let stdin = child.stdin.take().unwrap();
        let stdout = child.stdout.take().unwrap();
        let (tx, lines) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let Ok(line) = line else { break };
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        let mut sim = Sim {
            child,
            stdin,
            lines,
            pty: String::new(),
        };
        sim.pty = sim.line();
        sim
    }

    fn line(&mut self) -> String {
        self.lines
            .recv_timeout(PATIENCE)
            .expect("tmclsh sim answered in time")
    }

    fn console(&mut self, command: &str) -> String {
        writeln!(self.stdin, "{command}").unwrap();
        self.stdin.flush().unwrap();
        self.line()
    }

    /// The console's `faults`: `ok seed S replies R dropped D corrupted C delayed L`.
    fn injected(&mut self) -> Injected {
        let answer = self.console("faults");
        let words: Vec<&str> = answer.split_whitespace().collect();
        let field = |name: &str| -> u64 {
            words
                .iter()
                .position(|w| *w == name)
                .and_then(|i| words.get(i + 1))
                .and_then(|w| w.parse().ok())
                .unwrap_or_else(|| panic!("no {name} in '{answer}'"))
        };
        Injected {
            replies: field("replies"),
            dropped: field("dropped"),
            corrupted: field("corrupted"),
            delayed: field("delayed"),
        }
    }

    fn quit(mut self) {
        let _ = writeln!(self.stdin, "quit");
        let _ = self.stdin.flush();
        let _ = self.child.wait();
    }
}

impl Drop for Sim {
    fn drop(&mut self) {
        // Our own child, by its id.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
