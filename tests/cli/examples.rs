//! The examples say what the tool does: every example in `scripts/` runs as its own header says
//! to try it on the simulator (the documentation's examples: `doc_examples.rs`).

use std::process::{Command, Stdio};

use crate::sim::Sim;
use crate::util::{bin, code, repo, stderr, stdout};

/// The reply timeout the example lines run with (`TMCLSH_TIMEOUT`, so a line's own `--timeout`
/// still wins). These runs prove the examples work, not how fast a reply comes: the default
/// 1000 ms was overrun once by a `tmclsh sim` process over a pty on a machine loaded ~10 on 2
/// cores.
const LOADED_MACHINE_TIMEOUT_MS: &str = "10000";

/// The command lines under "On the simulator" at the top of an example file.
fn simulator_lines(text: &str) -> Vec<Vec<String>> {
    let mut lines = text
        .lines()
        .skip_while(|l| !l.starts_with("// On the simulator"));
    lines.next();
    lines
        .map_while(|l| l.strip_prefix("//   tmclsh "))
        .map(|l| l.split_whitespace().map(String::from).collect())
        .collect()
}

#[test]
fn every_example_runs_on_the_simulator_as_its_header_says() {
    let mut checked = 0;
    let mut files: Vec<_> = std::fs::read_dir(repo().join("scripts"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        let lines = simulator_lines(&text);
        assert!(
            !lines.is_empty(),
            "{}: no \"On the simulator\" lines to try it with",
            file.display()
        );
        let mut port = None;
        for words in lines {
            if words[0] == "sim" {
                let args: Vec<&str> = words[1..].iter().map(String::as_str).collect();
                port = Some(Sim::start(&args));
                continue;
            }
            let args: Vec<String> = words
                .iter()
                .map(|w| match (w.as_str(), &port) {
                    ("PORT", Some(sim)) => sim.first.clone(),
                    _ => w.clone(),
                })
                .collect();
            let out = Command::new(bin())
                .args(&args)
                .current_dir(repo())
                .stdin(Stdio::null())
                .env("NO_COLOR", "1")
                .env("TMCLSH_TIMEOUT", LOADED_MACHINE_TIMEOUT_MS)
                .output()
                .unwrap();
            assert_eq!(
                code(&out),
                0,
                "{}: tmclsh {}\n{}{}",
                file.display(),
                args.join(" "),
                stdout(&out),
                stderr(&out)
            );
            checked += 1;
        }
    }
    assert!(checked >= 6, "only {checked} example lines found");
}
