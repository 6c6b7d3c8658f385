//! The examples say what the tool does: every example in `scripts/` runs as its own header says
//! to try it on the simulator (the documentation's examples: `doc_examples.rs`).

use std::process::{Command, Stdio};

use crate::sim::Sim;
use crate::util::{bin, code, repo, stderr, stdout};

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
