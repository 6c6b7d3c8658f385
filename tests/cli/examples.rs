//! The examples say what the tool does: every example in `scripts/` runs as its own header says
//! to try it on the simulator, and the README's checked examples show what tmclsh prints.

use std::process::{Command, Stdio};

use crate::repl::{repl, type_in};
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

/// The README's blocks that follow `marker`, their lines with the fence's indentation removed.
fn readme_blocks(marker: &str) -> Vec<Vec<String>> {
    let readme = std::fs::read_to_string(repo().join("README.md")).unwrap();
    let mut blocks = Vec::new();
    let mut rest = readme.as_str();
    while let Some(at) = rest.find(marker) {
        rest = &rest[at + marker.len()..];
        let mut lines = rest.lines().skip(1);
        let fence = lines.next().expect("a block follows the marker");
        let indent = fence.len() - fence.trim_start().len();
        assert_eq!(fence.trim(), "```text", "{marker}");
        let block: Vec<String> = lines
            .take_while(|l| l.trim() != "```")
            .map(|l| l.get(indent..).unwrap_or("").to_string())
            .collect();
        blocks.push(block);
    }
    assert!(!blocks.is_empty(), "no README block marked {marker}");
    blocks
}

/// Splits a command line at spaces, keeping "double-quoted words" whole.
fn words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut quoted = false;
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ' ' if !quoted => {
                if !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
            }
            c => word.push(c),
        }
    }
    if !word.is_empty() {
        words.push(word);
    }
    words
}

#[test]
fn the_readme_commands_print_what_the_readme_shows() {
    for block in readme_blocks("<!-- example: run by the test suite on the built-in simulator") {
        let mut at = 0;
        while at < block.len() {
            let line = block[at].strip_prefix("$ tmclsh ").expect("a command line");
            let expected: Vec<&str> = block[at + 1..]
                .iter()
                .map(String::as_str)
                .take_while(|l| !l.starts_with("$ "))
                .collect();
            at += 1 + expected.len();
            let out = Command::new(bin())
                .args(words(line))
                .current_dir(repo())
                .stdin(Stdio::null())
                .env("NO_COLOR", "1")
                .output()
                .unwrap();
            let printed = stdout(&out);
            assert_eq!(
                printed.lines().collect::<Vec<_>>(),
                expected,
                "tmclsh {line}\n{}",
                stderr(&out)
            );
        }
    }
}

/// Text as rexpect shows it: it reads bytes as Latin-1.
fn latin1(text: &str) -> String {
    text.bytes().map(char::from).collect()
}

#[test]
fn the_readme_shell_session_is_what_the_repl_shows() {
    for block in readme_blocks("<!-- example: typed into the REPL by the test suite") {
        assert_eq!(block[0], "$ tmclsh");
        let (mut p, _) = repl(&[]);
        // The harness has seen the banner's first word, "tmclsh", already.
        let banner = block[1].strip_prefix("tmclsh").expect("the banner");
        p.exp_string(&latin1(banner)).unwrap();
        for line in &block[2..] {
            match line.split_once("> ") {
                Some((prompt, typed)) if prompt.len() <= 8 && !prompt.contains(' ') => {
                    p.exp_string(&format!("{prompt}> ")).unwrap();
                    for (i, part) in typed.split('⇥').enumerate() {
                        if i > 0 {
                            type_in(&mut p, "\t");
                        }
                        type_in(&mut p, part);
                    }
                    type_in(&mut p, "\r");
                }
                _ => {
                    p.exp_string(&latin1(line))
                        .unwrap_or_else(|e| panic!("README line {line:?}: {e}"));
                }
            }
        }
        p.send_control('d').unwrap();
        p.exp_eof().unwrap();
    }
}
