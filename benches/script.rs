//! `cargo bench --bench script`: how a script's cost grows with the data it builds. A loop of N
//! `a.push(i)` through the real binary, for N doubling: linear growth keeps the time per push
//! flat (ratio ~1 per doubling); the quadratic growth of Rhai's data-size checks doubled it.
//! Start-up (N = 0) is subtracted; each size takes the median of five runs.

use std::process::Command;
use std::time::{Duration, Instant};

fn run(n: u64, dir: &std::path::Path) -> Duration {
    let script = dir.join(format!("push{n}.rhai"));
    std::fs::write(
        &script,
        format!("let a = [];\nfor i in 0..{n} {{ a.push(i); }}\nif a.len() != {n} {{ throw \"short\"; }}\n"),
    )
    .expect("the script is written");
    let mut times: Vec<Duration> = (0..5)
        .map(|_| {
            let start = Instant::now();
            let status = Command::new(env!("CARGO_BIN_EXE_tmclsh"))
                .arg("run")
                .arg(&script)
                .args(["--sim", "--max-operations", "0"])
                .status()
                .expect("tmclsh runs");
            assert!(status.success(), "the push loop of {n} succeeds");
            start.elapsed()
        })
        .collect();
    times.sort();
    times[2]
}

fn main() {
    let dir = std::env::temp_dir().join(format!("tmclsh-bench-script-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    let start_up = run(0, &dir);
    println!("start-up (N = 0): {:.1} ms", start_up.as_secs_f64() * 1e3);
    println!(
        "{:>10} {:>12} {:>12} {:>22}",
        "pushes", "ms", "ns/push", "ns/push vs N/2"
    );
    let mut last: Option<f64> = None;
    for n in [100_000u64, 200_000, 400_000, 800_000, 1_600_000] {
        let t = run(n, &dir).saturating_sub(start_up);
        let per = t.as_nanos() as f64 / n as f64;
        let ratio = last.map_or(String::from("-"), |l| format!("{:.2}", per / l));
        println!(
            "{n:>10} {:>12.1} {per:>12.1} {ratio:>22}",
            t.as_secs_f64() * 1e3
        );
        last = Some(per);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
