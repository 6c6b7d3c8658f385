//! Every command example in README.md and docs/ is run, so none can rot. The convention (also at
//! the top of TESTING.md's "Examples in the documentation"):
//!
//! - Commands go in fenced ```` ```console ```` blocks; a line starting `$ ` is a command, run by
//!   `sh -c` in a scratch directory holding a copy of `scripts/`, with the built `tmclsh` first on
//!   `PATH`, stdin empty, `NO_COLOR` set, and a home, data and configuration directory of its own.
//!   It must exit 0, or the code a trailing `# exit N` gives. The lines up to the next `$ ` are
//!   its stdout, exactly; a line `…` alone stands for any number of lines; a command shown with
//!   no lines after it has its stdout unchecked.
//! - `tmclsh sim …` is started, must print its pty or address, and is ended with the block.
//! - Words after `console` in the fence say more: `output-varies` (the output shown depends on
//!   the machine or the moment: only the exit code is checked); `hardware` (a module on a port:
//!   each serial device, `usb:` name or `--tcp` address is replaced by a `tmclsh sim` of the
//!   command's `--protocol` and `--profile`, or of `module=PROFILE` given after `hardware`, and
//!   only the exit code is checked); `repl` (a session
//!   typed into the interactive shell in a pseudo-terminal: after `$ tmclsh`, a line `P> TEXT`
//!   waits for the prompt `P> ` and types TEXT, `⇥` being Tab; any other line must appear);
//!   `no-run` (cargo commands, which build the tree: checked to name subcommands, aliases, bench
//!   targets and profiles the tree has).
//! - A block of another kind (`sh`, `text`, none) must not hold a `$ ` line or start a line with
//!   `tmclsh `, so no command example escapes the runner.
//! - A `tmclsh …` code span in the prose is read by the real binary's parser (`tmclsh ARGS
//!   --help`), placeholders such as SHELL, MS and N filled in, `[optional parts]` left out.

use std::io::Read;
use std::os::unix::process::CommandExt;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::repl::{repl, type_in};
use crate::util::{bin, repo, tempdir};

/// How long one example may run: a hang guard, not a timing assertion.
const PATIENCE: Duration = Duration::from_secs(180);

/// A fenced block of a documentation file.
#[derive(Debug)]
struct Block {
    /// `FILE:LINE` of the opening fence.
    place: String,
    /// The info string's words: the language first.
    info: Vec<String>,
    /// The lines inside, without the fence's indentation.
    lines: Vec<String>,
}

impl Block {
    fn is(&self, attribute: &str) -> bool {
        self.info.iter().skip(1).any(|w| w == attribute)
    }
}

/// README.md and every file of docs/.
fn documents() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(repo().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    files.sort();
    files.insert(0, repo().join("README.md"));
    files
}

/// The fenced blocks of `text`, named after `file`.
fn blocks_of(file: &str, text: &str) -> Vec<Block> {
    let mut blocks = Vec::new();
    let mut lines = text.lines().enumerate();
    while let Some((at, line)) = lines.next() {
        let Some(info) = line.trim_start().strip_prefix("```") else {
            continue;
        };
        let indent = line.len() - line.trim_start().len();
        let lines = lines
            .by_ref()
            .map(|(_, l)| l)
            .take_while(|l| l.trim() != "```")
            .map(|l| l.get(indent..).unwrap_or("").to_string())
            .collect();
        blocks.push(Block {
            place: format!("{file}:{}", at + 1),
            info: info.split_whitespace().map(String::from).collect(),
            lines,
        });
    }
    blocks
}

fn all_blocks() -> Vec<Block> {
    documents()
        .iter()
        .flat_map(|path| {
            let name = path.strip_prefix(repo()).unwrap().display().to_string();
            blocks_of(&name, &std::fs::read_to_string(path).unwrap())
        })
        .collect()
}

fn console_blocks(kind: Option<&str>) -> Vec<Block> {
    let kinds = ["output-varies", "hardware", "repl", "no-run"];
    all_blocks()
        .into_iter()
        .filter(|b| b.info.first().is_some_and(|l| l == "console"))
        .filter(|b| match kind {
            Some(kind) => b.is(kind),
            None => !kinds.iter().any(|k| k != &"output-varies" && b.is(k)),
        })
        .collect()
}

/// One `$ ` line of a console block and what follows it.
#[derive(Debug)]
struct Example {
    command: String,
    exit: i32,
    /// The stdout shown, `None` when the block shows none.
    output: Option<Vec<String>>,
}

fn examples(block: &Block) -> Vec<Example> {
    let mut examples: Vec<Example> = Vec::new();
    for line in &block.lines {
        if let Some(command) = line.strip_prefix("$ ") {
            let exit = command
                .rsplit_once("# exit ")
                .map(|(_, n)| n.trim().parse().expect("# exit N takes a number"))
                .unwrap_or(0);
            examples.push(Example {
                command: command.to_string(),
                exit,
                output: None,
            });
        } else {
            let example = examples
                .last_mut()
                .unwrap_or_else(|| panic!("{}: output before any `$ ` command", block.place));
            example
                .output
                .get_or_insert_with(Vec::new)
                .push(line.clone());
        }
    }
    assert!(
        !examples.is_empty(),
        "{}: a console block with no `$ ` command",
        block.place
    );
    examples
}

/// Shell words of a command line, quotes removed (enough for the examples: no escapes).
fn words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut word: Option<String> = None;
    let mut quote = None;
    for c in line.chars() {
        match (c, quote) {
            ('"' | '\'', None) => {
                quote = Some(c);
                word.get_or_insert_with(String::new);
            }
            (q, Some(open)) if q == open => quote = None,
            ('#', None) if word.is_none() => break,
            (' ', None) => words.extend(word.take()),
            (c, _) => word.get_or_insert_with(String::new).push(c),
        }
    }
    words.extend(word);
    words
}

/// Where a block's commands run: a scratch directory with `scripts/`, and `tmclsh` on `PATH`.
struct Scratch {
    dir: PathBuf,
    path: String,
    home: PathBuf,
}

impl Scratch {
    fn new() -> Scratch {
        let root = tempdir();
        let dir = root.join("work");
        let tools = root.join("bin");
        let home = root.join("home");
        for d in [&dir.join("scripts"), &tools, &home] {
            std::fs::create_dir_all(d).unwrap();
        }
        for entry in std::fs::read_dir(repo().join("scripts")).unwrap() {
            let entry = entry.unwrap();
            std::fs::copy(entry.path(), dir.join("scripts").join(entry.file_name())).unwrap();
        }
        std::os::unix::fs::symlink(bin(), tools.join("tmclsh")).unwrap();
        let path = format!(
            "{}:{}",
            tools.display(),
            std::env::var("PATH").unwrap_or_default()
        );
        Scratch { dir, path, home }
    }

    /// `sh -c COMMAND` here, in its own process group (so a hung one is ended whole); stdin
    /// empty, or a pipe kept open (a simulator's console).
    fn spawn(&self, command: &str, console: bool) -> Child {
        let mut sh = Command::new("sh");
        sh.arg("-c")
            .arg(command)
            .current_dir(&self.dir)
            .stdin(if console {
                Stdio::piped()
            } else {
                Stdio::null()
            })
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .env("PATH", &self.path)
            .env("HOME", &self.home)
            .env("XDG_CONFIG_HOME", self.home.join(".config"))
            .env("XDG_DATA_HOME", self.home.join(".local/share"))
            .env("NO_COLOR", "1")
            .process_group(0);
        for (name, _) in std::env::vars() {
            if name.starts_with("TMCLSH_") {
                sh.env_remove(name);
            }
        }
        sh.spawn().expect("sh runs")
    }

    /// Runs COMMAND to its end: (exit code, stdout, stderr).
    fn run(&self, command: &str) -> (i32, String, String) {
        let mut child = self.spawn(command, false);
        let out = reader(child.stdout.take().unwrap());
        let err = reader(child.stderr.take().unwrap());
        let deadline = Instant::now() + PATIENCE;
        let status = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break status;
            }
            if Instant::now() > deadline {
                end_group(&child);
                panic!("`{command}` did not end within {PATIENCE:?}");
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        let code = status.code().unwrap_or(-1);
        (code, out.join().unwrap(), err.join().unwrap())
    }

    /// Starts `tmclsh sim ARGS` here; it must print its pty or address.
    fn sim(&self, args: &[&str]) -> Result<Sim, String> {
        let command = format!("exec tmclsh sim {}", shell_quoted(args));
        let mut child = self.spawn(&command, true);
        let stdout = child.stdout.take().unwrap();
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut line = String::new();
            let _ = std::io::BufRead::read_line(&mut std::io::BufReader::new(stdout), &mut line);
            let _ = tx.send(line);
        });
        let err = reader(child.stderr.take().unwrap());
        let mut sim = Sim {
            child,
            first: String::new(),
        };
        match rx.recv_timeout(PATIENCE) {
            Ok(line) if !line.trim().is_empty() => {
                sim.first = line.trim().to_string();
                Ok(sim)
            }
            _ => {
                drop(sim);
                Err(format!(
                    "`{command}` printed no pty or address: {}",
                    err.join().unwrap()
                ))
            }
        }
    }
}

/// A `tmclsh sim` a block started, ended with it.
struct Sim {
    child: Child,
    /// The pty path or TCP address it printed.
    first: String,
}

impl Drop for Sim {
    fn drop(&mut self) {
        end_group(&self.child);
        let _ = self.child.wait();
    }
}

fn shell_quoted(args: &[&str]) -> String {
    args.iter()
        .map(|a| format!("'{}'", a.replace('\'', "'\\''")))
        .collect::<Vec<_>>()
        .join(" ")
}

fn reader(mut pipe: impl Read + Send + 'static) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        let _ = pipe.read_to_end(&mut bytes);
        String::from_utf8_lossy(&bytes).into_owned()
    })
}

/// Ends the process group of our own child `sh` (the shell and what it started).
fn end_group(child: &Child) {
    let group = nix::unistd::Pid::from_raw(child.id() as i32);
    let _ = nix::sys::signal::killpg(group, nix::sys::signal::Signal::SIGKILL);
}

/// Whether `printed` is what the block shows, `…` standing for any run of lines.
fn matches(shown: &[String], printed: &[&str]) -> bool {
    match shown.split_first() {
        None => printed.is_empty(),
        Some((first, rest)) if first == "…" => {
            (0..=printed.len()).any(|skip| matches(rest, &printed[skip..]))
        }
        Some((first, rest)) => printed
            .split_first()
            .is_some_and(|(p, more)| p == first && matches(rest, more)),
    }
}

/// `tmclsh sim ARGS` as the block starts it: the words after `sim`.
fn sim_args(words: &[String]) -> Option<Vec<&str>> {
    match words {
        [tmclsh, sim, rest @ ..] if tmclsh == "tmclsh" && sim == "sim" => {
            Some(rest.iter().map(String::as_str).collect())
        }
        _ => None,
    }
}

/// Runs one console block's commands as the convention says; the failures, described.
fn run_block(block: &Block, hardware: bool) -> Vec<String> {
    let scratch = Scratch::new();
    let compare = !block.is("output-varies") && !hardware;
    let mut failures = Vec::new();
    let mut sims = Vec::new();
    for example in examples(block) {
        let words = words(&example.command);
        if let Some(args) = sim_args(&words) {
            // Started as the block says: it prints its pty or address, or the start fails.
            match scratch.sim(&args) {
                Ok(sim) => sims.push(sim),
                Err(e) => failures.push(format!("{}: {e}", block.place)),
            }
            continue;
        }
        let (command, _stand_in) = if hardware {
            match stand_in(&scratch, block, &example.command, &words) {
                Ok(stood_in) => stood_in,
                Err(e) => {
                    failures.push(format!("{}: {e}", block.place));
                    continue;
                }
            }
        } else {
            (example.command.clone(), None)
        };
        let (code, out, err) = scratch.run(&command);
        let printed: Vec<&str> = out.lines().collect();
        let output_ok = match (&example.output, compare) {
            (Some(shown), true) => matches(shown, &printed),
            _ => true,
        };
        if code != example.exit || !output_ok {
            failures.push(format!(
                "{}: `{}` exited {code} (expected {}){}\n--- stdout\n{out}--- stderr\n{err}",
                block.place,
                command,
                example.exit,
                if output_ok {
                    ""
                } else {
                    ", and its stdout is not what the block shows"
                },
            ));
        }
    }
    drop(sims);
    failures
}

/// A hardware example's command with a simulator standing in for its module: every serial device
/// or `usb:` name is the pty of a `tmclsh sim` of the command's protocol and profile (or the
/// block's `module=PROFILE`), a `--tcp` address its TCP address.
fn stand_in(
    scratch: &Scratch,
    block: &Block,
    command: &str,
    words: &[String],
) -> Result<(String, Option<Sim>), String> {
    let mut args: Vec<&str> = Vec::new();
    if let Some(profile) = block.info.iter().find_map(|w| w.strip_prefix("module=")) {
        args.extend(["--profile", profile]);
    }
    for pair in words.windows(2) {
        if pair[0] == "--protocol" || pair[0] == "--profile" {
            args.extend([pair[0].as_str(), pair[1].as_str()]);
        }
    }
    let tcp = words
        .windows(2)
        .find(|p| p[0] == "--tcp")
        .map(|p| p[1].clone());
    if tcp.is_some() {
        args.extend(["--listen", "127.0.0.1:0"]);
    }
    let sim = scratch.sim(&args)?;
    let mut command = command.to_string();
    if let Some(address) = tcp {
        command = command.replace(&address, &sim.first);
    }
    for word in words {
        if ["/dev/tty", "/dev/serial/", "usb:"]
            .iter()
            .any(|p| word.starts_with(p))
        {
            command = command.replace(word.as_str(), &sim.first);
        }
    }
    Ok((command, Some(sim)))
}

fn report(failures: Vec<String>, ran: usize) {
    assert!(ran > 0, "no examples of this kind found");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_command_example_is_in_a_console_block() {
    let mut stray = Vec::new();
    for block in all_blocks() {
        if block.info.first().is_some_and(|l| l == "console") {
            continue;
        }
        if let Some(line) = block
            .lines
            .iter()
            .find(|l| l.starts_with("$ ") || l.starts_with("tmclsh "))
        {
            stray.push(format!("{}: `{line}`", block.place));
        }
    }
    assert!(
        stray.is_empty(),
        "command examples outside a ```console block (see tests/cli/doc_examples.rs):\n{}",
        stray.join("\n")
    );
}

#[test]
fn the_console_examples_print_what_they_show() {
    let blocks = console_blocks(None);
    let failures = blocks.iter().flat_map(|b| run_block(b, false)).collect();
    report(failures, blocks.len());
}

#[test]
fn the_hardware_examples_run_against_a_simulator_standing_in() {
    let blocks = console_blocks(Some("hardware"));
    let failures = blocks.iter().flat_map(|b| run_block(b, true)).collect();
    report(failures, blocks.len());
}

/// The `tmclsh …` code spans of the prose (outside fenced blocks), with their file.
fn prose_commands() -> Vec<(String, String)> {
    let mut spans = Vec::new();
    for path in documents() {
        let name = path.strip_prefix(repo()).unwrap().display().to_string();
        let text = std::fs::read_to_string(&path).unwrap();
        let mut prose = String::new();
        let mut fenced = false;
        for line in text.lines() {
            if line.trim_start().starts_with("```") {
                fenced = !fenced;
            } else if !fenced {
                prose.push_str(line);
                prose.push(' ');
            }
        }
        for (i, span) in prose.split('`').enumerate() {
            if i % 2 == 1 && span.starts_with("tmclsh ") {
                spans.push((name.clone(), span.to_string()));
            }
        }
    }
    spans
}

/// A prose command's words as the parser gets them: the placeholders a reader fills in given a
/// value of their kind, optional parts (`[-- ARGS...]`) and shell redirections left out.
fn filled_in(span: &str) -> Vec<String> {
    let mut out = Vec::new();
    for word in words(span).into_iter().skip(1) {
        if word.starts_with('>') || word.starts_with('|') {
            break;
        }
        if word.starts_with('[') || word.ends_with(']') || word == "ARGS..." {
            continue;
        }
        out.push(
            match word.as_str() {
                "SHELL" => "bash",
                "MS" | "N" => "1",
                other => other,
            }
            .to_string(),
        );
    }
    out
}

#[test]
fn every_command_in_the_prose_is_one_the_parser_takes() {
    // `tmclsh ARGS --help`: the real binary's parser reads ARGS (an unknown option, subcommand or
    // a value of the wrong kind is an error) and stops at --help before anything is opened.
    let spans = prose_commands();
    let mut refused = Vec::new();
    for (file, span) in &spans {
        let args = filled_in(span);
        let out = Command::new(bin())
            .args(&args)
            .arg("--help")
            .env("NO_COLOR", "1")
            .stdin(Stdio::null())
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        // A span naming an option of a command (`tmclsh asm -o`) lacks only its value.
        let names_an_option =
            args.last().is_some_and(|a| a.starts_with('-')) && err.contains("a value is required");
        if out.status.code() != Some(0) && !names_an_option {
            refused.push(format!(
                "{file}: `{span}`: {}",
                err.lines().next().unwrap_or("")
            ));
        }
    }
    assert!(
        spans.len() > 40,
        "only {} prose commands found",
        spans.len()
    );
    assert!(refused.is_empty(), "{}", refused.join("\n"));
}

#[test]
fn the_readme_lists_every_page_of_docs_and_its_links_lead_somewhere() {
    let readme = std::fs::read_to_string(repo().join("README.md")).unwrap();
    for page in documents().iter().skip(1) {
        let name = page.strip_prefix(repo()).unwrap().display().to_string();
        assert!(
            readme.contains(&format!("]({name})")),
            "README.md does not list {name}"
        );
    }
    // Links between the pages of docs/ (README.md lists pages still to be written as well).
    for page in documents().iter().skip(1) {
        let text = std::fs::read_to_string(page).unwrap();
        for link in text.split("](").skip(1) {
            let target = link.split([')', '#']).next().unwrap();
            if target.ends_with(".md") && !target.contains("://") {
                let path = page.parent().unwrap().join(target);
                assert!(
                    path.exists(),
                    "{}: link to {target}, which does not exist",
                    page.display()
                );
            }
        }
    }
}

/// Text as rexpect shows it: it reads bytes as Latin-1.
fn latin1(text: &str) -> String {
    text.bytes().map(char::from).collect()
}

#[test]
fn the_shell_sessions_are_what_the_repl_shows() {
    let blocks = console_blocks(Some("repl"));
    for block in &blocks {
        assert_eq!(block.lines[0], "$ tmclsh", "{}", block.place);
        let (mut p, _) = repl(&[]);
        // The harness has seen the banner's first word, "tmclsh", already.
        let banner = block.lines[1].strip_prefix("tmclsh").expect("the banner");
        p.exp_string(&latin1(banner)).unwrap();
        for line in &block.lines[2..] {
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
                        .unwrap_or_else(|e| panic!("{}: line {line:?}: {e}", block.place));
                }
            }
        }
        p.send_control('d').unwrap();
        p.exp_eof().unwrap();
    }
    assert!(!blocks.is_empty());
}

/// Whether Cargo.toml or .cargo/config.toml has `text`.
fn cargo_files_have(text: &str) -> bool {
    [repo().join("Cargo.toml"), repo().join(".cargo/config.toml")]
        .iter()
        .any(|f| std::fs::read_to_string(f).unwrap().contains(text))
}

#[test]
fn the_cargo_commands_name_what_the_tree_has() {
    let blocks = console_blocks(Some("no-run"));
    for block in &blocks {
        for example in examples(block) {
            let words = words(&example.command);
            assert_eq!(
                words[0], "cargo",
                "{}: only cargo commands go unrun",
                block.place
            );
            let builtin = ["run", "test", "build", "install", "bench", "deb"];
            assert!(
                builtin.contains(&words[1].as_str())
                    || cargo_files_have(&format!("\n{} = ", words[1])),
                "{}: `cargo {}` is neither cargo's nor an alias in .cargo/config.toml",
                block.place,
                words[1]
            );
            for pair in words.windows(2) {
                let needed = match pair[0].as_str() {
                    "--bench" => format!("name = \"{}\"", pair[1]),
                    "--profile" => format!("[profile.{}]", pair[1]),
                    "--path" => {
                        assert!(repo().join(&pair[1]).join("Cargo.toml").exists());
                        continue;
                    }
                    _ => continue,
                };
                assert!(
                    cargo_files_have(&needed),
                    "{}: `{}` names nothing in Cargo.toml",
                    block.place,
                    example.command
                );
            }
        }
    }
    assert!(!blocks.is_empty());
}

#[test]
fn the_runner_reads_its_convention() {
    let text =
        "x\n  ```console output-varies\n  $ tmclsh -c 'GAP 1, 0' # exit 3\n  a\n  …\n  ```\n";
    let blocks = blocks_of("t.md", text);
    assert_eq!(blocks[0].place, "t.md:2");
    assert!(blocks[0].is("output-varies"));
    let examples = examples(&blocks[0]);
    assert_eq!(examples[0].exit, 3);
    assert_eq!(words(&examples[0].command), ["tmclsh", "-c", "GAP 1, 0"]);
    let shown = examples[0].output.clone().unwrap();
    assert!(matches(&shown, &["a"]));
    assert!(matches(&shown, &["a", "b", "c"]));
    assert!(!matches(&shown, &["b"]));
    assert!(!matches(&["a".into()], &["a", "b"]));
}
