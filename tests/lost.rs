//! Lost and found: a USB adapter pulled out and plugged back, played by `tmclsh sim --link PATH`
//! and its console's `unplug SECS` (the pty closes; a new one, on another number, comes back
//! behind the same symlink). The REPL notices the loss at its idle prompt and reconnects; lines
//! typed meanwhile are not sent without a yes; a `-c` run exits 3 at once, and with
//! `--reconnect` sends an interrupted read again but never a motion. Messages are checked in
//! order, never times.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Instant;

use crate::repl::repl;
use crate::sim::{PATIENCE, Sim};
use crate::util::{bin, tempdir};

/// A simulator behind a stable symlink in a fresh directory.
fn linked() -> (Sim, PathBuf) {
    let link = tempdir().join("ttyUSB-by-id");
    let sim = Sim::start(&["--pty", "--link", link.to_str().unwrap()]);
    (sim, link)
}

/// Unplugs the adapter for `secs`; returns the new pty's path once it is back.
fn unplug(sim: &mut Sim, secs: &str) -> String {
    let answer = sim.console(&format!("unplug {secs}"));
    assert!(answer.starts_with("ok unplugged"), "{answer}");
    let back = sim.line();
    back.strip_prefix("pty ")
        .unwrap_or_else(|| panic!("the pty came back: {back}"))
        .to_string()
}

/// Unplugs the adapter while the module is silent and lets it talk again before the pty comes
/// back after `secs`: the request in flight is cut short whether or not the simulator had read it
/// yet (sent is not yet received), and the module answers what is sent after the reconnect.
fn unplug_while_silent(sim: &mut Sim, secs: &str) -> String {
    let answer = sim.console(&format!("unplug {secs}"));
    assert!(answer.starts_with("ok unplugged"), "{answer}");
    assert_eq!(sim.console("silent off"), "ok talking");
    let back = sim.line();
    back.strip_prefix("pty ")
        .unwrap_or_else(|| panic!("the pty came back: {back}"))
        .to_string()
}

/// Waits until `file` holds `text` (the transcript shows a request on its way) while `child`
/// runs.
fn wait_for(file: &Path, text: &str, child: &mut Child) -> String {
    let deadline = Instant::now() + PATIENCE;
    loop {
        let now = std::fs::read_to_string(file).unwrap_or_default();
        if now.contains(text) {
            return now;
        }
        if let Some(status) = child.try_wait().unwrap() {
            let mut stderr = String::new();
            let _ = child.stderr.take().unwrap().read_to_string(&mut stderr);
            panic!("tmclsh ended ({status}) before {text:?}: {stderr}\n{now}");
        }
        assert!(Instant::now() < deadline, "no {text:?} in {now}");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

/// `tmclsh --port LINK ARGS` with a transcript, stdin piped, stdout and stderr captured.
fn spawn(link: &Path, log: &Path, args: &[&str]) -> Child {
    Command::new(bin())
        .arg("--port")
        .arg(link)
        .arg("--log")
        .arg(log)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Piped lines: a first read answered, then the module falls silent and `line` goes out; it is
/// on its way (in the transcript) when this returns.
fn piped_until_in_flight(
    sim: &mut Sim,
    link: &Path,
    log: &Path,
    args: &[&str],
    line: &str,
) -> Child {
    piped_after(sim, link, log, args, ("GAP 1, 0", "BA 100 0\n"), line)
}

/// [`piped_until_in_flight`] with a `first` line and what it prints.
fn piped_after(
    sim: &mut Sim,
    link: &Path,
    log: &Path,
    args: &[&str],
    first: (&str, &str),
    line: &str,
) -> Child {
    let mut child = spawn(link, log, args);
    let mut stdin = child.stdin.take().unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    writeln!(stdin, "{}", first.0).unwrap();
    let mut printed = String::new();
    stdout.read_line(&mut printed).unwrap();
    assert_eq!(printed, first.1);
    assert_eq!(sim.console("silent on"), "ok silent");
    // The line may already be in the transcript (the first line): wait for one more.
    let before = std::fs::read_to_string(log).unwrap_or_default();
    let sent = before.matches(&format!("tx \"{line}")).count()
        + before.matches(&format!("tx \"A{line}")).count();
    writeln!(stdin, "{line}").unwrap();
    drop(stdin);
    let deadline = Instant::now() + PATIENCE;
    loop {
        let now = wait_for(log, line, &mut child);
        let count = now.matches(&format!("tx \"{line}")).count()
            + now.matches(&format!("tx \"A{line}")).count();
        if count > sent {
            break;
        }
        assert!(Instant::now() < deadline, "{line} not sent: {now}");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.stdout = Some(stdout.into_inner());
    child
}

#[test]
fn unplugged_the_adapter_comes_back_on_a_new_number_behind_the_link() {
    let (mut sim, link) = linked();
    let first = sim.first.clone();
    assert_eq!(std::fs::read_link(&link).unwrap(), Path::new(&first));
    let mut port = sim.pty();
    port.send(b"\x01\x8b\x00\x00\x00\x00\x00\x00\x8c");
    assert!(
        crate::sim::decode(&port.read_n(9)).status.is_success(),
        "in ASCII mode"
    );
    let answer = sim.console("unplug 0.5");
    assert!(answer.starts_with("ok unplugged"), "{answer}");
    // The client sees its port vanish: a read ends with an error or EOF.
    assert!(port.try_read_until(|_| false).is_err());
    let back = sim.line();
    let second = back.strip_prefix("pty ").expect("a new pty").to_string();
    assert_ne!(second, first, "a new number");
    assert_eq!(std::fs::read_link(&link).unwrap(), Path::new(&second));
    // The module kept its state: it is still in ASCII mode from the 139 sent before.
    let mut port = crate::sim::Port::Serial(crate::sim::open_serial(link.to_str().unwrap()));
    port.send(b"AGAP 1, 0\r");
    let reply = port.read_line();
    assert!(reply.ends_with("BA 100 0\r"), "{reply:?}");
}

#[test]
fn the_idle_repl_sees_the_loss_and_reconnects_and_asks_before_sending_what_was_typed() {
    let (mut sim, link) = linked();
    let log = tempdir().join("repl.log");
    let (mut p, _) = repl(&[
        "--port",
        link.to_str().unwrap(),
        "--log",
        log.to_str().unwrap(),
    ]);
    p.exp_string("A> ").unwrap();
    p.send_line("SAP 1, 0, 321").unwrap();
    p.exp_string("ok").unwrap();
    p.exp_string("A> ").unwrap();
    // Idle at the prompt: the adapter goes away for long enough to type a line.
    let answer = sim.console("unplug 3");
    assert!(answer.starts_with("ok unplugged"), "{answer}");
    p.exp_string("link lost").unwrap();
    p.exp_string("waiting for serial").unwrap();
    p.send_line("ROR 0, 500").unwrap();
    let back = sim.line();
    assert!(back.starts_with("pty "), "{back}");
    p.exp_string("reconnected").unwrap();
    p.exp_string("typed while the link was away (not sent):")
        .unwrap();
    p.exp_string("ROR 0, 500").unwrap();
    p.exp_string("send them now? [y/N]").unwrap();
    p.send_line("").unwrap();
    p.exp_string("not sent").unwrap();
    p.exp_string("A> ").unwrap();
    assert!(
        sim.console("motor").contains("velocity 0"),
        "the motor was started"
    );
    // The session carries on, on the new pty, with the module's state kept.
    p.send_line("GAP 1, 0").unwrap();
    p.exp_string("actual_position = 321 usteps").unwrap();
    p.send_line(":quit").unwrap();
    p.exp_eof().unwrap();
    let text = std::fs::read_to_string(&log).unwrap();
    for said in [
        "link lost",
        "waiting for the link",
        "link reopened",
        "reconnected",
        "not sent: ROR 0, 500",
    ] {
        assert!(text.contains(said), "{said:?} in {text}");
    }
}

#[test]
fn a_lost_link_mid_request_ends_a_c_run_with_exit_3_at_once() {
    let (mut sim, link) = linked();
    let log = tempdir().join("c.log");
    // Every reply held back for a while: the request is on its way when the adapter goes.
    assert!(sim.console("delay 1 1500").starts_with("ok"));
    let mut child = spawn(&link, &log, &["--timeout", "60000", "-c", "GAP 1, 0"]);
    wait_for(&log, "GAP 1, 0", &mut child);
    unplug(&mut sim, "0.2");
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("link lost"), "{stderr}");
    assert!(stderr.contains("--reconnect WAIT"), "a hint: {stderr}");
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(text.contains("GAP 1, 0 to module 1 (A)"), "{text}");
}

#[test]
fn with_reconnect_an_interrupted_read_is_sent_again_and_answered() {
    let (mut sim, link) = linked();
    let log = tempdir().join("read.log");
    assert!(sim.console("input 3 1").starts_with("ok"));
    let child = piped_until_in_flight(
        &mut sim,
        &link,
        &log,
        &["--timeout", "60000", "--reconnect", "20s"],
        "GIO 3, 0",
    );
    // The reply held back is dropped; once back, the module answers again.
    unplug_while_silent(&mut sim, "1");
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(String::from_utf8_lossy(&out.stdout), "BA 100 1\n");
    assert!(stderr.contains("reconnected"), "{stderr}");
    let text = std::fs::read_to_string(&log).unwrap();
    for said in [
        "request cut short by the lost link",
        "GIO 3, 0 to module 1 (A)",
        "waiting up to 20 s",
        "reconnected",
        "sent again after the reconnect",
    ] {
        assert!(text.contains(said), "{said:?} in {text}");
    }
}

#[test]
fn with_reconnect_an_interrupted_motion_is_not_sent_again() {
    let (mut sim, link) = linked();
    let log = tempdir().join("motion.log");
    let child = piped_until_in_flight(
        &mut sim,
        &link,
        &log,
        &["--timeout", "60000", "--reconnect", "20s"],
        "ROR 0, 500",
    );
    // Sent is not yet received: the simulator must have run it (its reply silenced) before it
    // talks again, or the reply would come and nothing would be cut short.
    let deadline = Instant::now() + PATIENCE;
    while !sim.console("motor").contains("reached 0") {
        assert!(
            Instant::now() < deadline,
            "ROR 0, 500 never reached the module"
        );
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    unplug_while_silent(&mut sim, "1");
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("never sent again"), "{stderr}");
    // It reached the module before the link went: the run stopped it on its way out.
    assert!(sim.console("motor").contains("velocity 0"), "{stderr}");
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(!text.contains("sent again after the reconnect"), "{text}");
}

#[test]
fn an_smd4_read_cut_short_is_sent_again_with_reconnect() {
    let link = tempdir().join("smd4-by-id");
    let mut sim = Sim::start(&[
        "--pty",
        "--protocol",
        "smd4",
        "--link",
        link.to_str().unwrap(),
    ]);
    let log = tempdir().join("smd4.log");
    let vmax = "0x0888,0x0000,1.0000E+03,1.0000E+03\n";
    let child = piped_after(
        &mut sim,
        &link,
        &log,
        &[
            "--protocol",
            "smd4",
            "--timeout",
            "60000",
            "--reconnect",
            "20s",
        ],
        ("MOTOR:VMAX", vmax),
        "MOTOR:VMAX",
    );
    unplug_while_silent(&mut sim, "1");
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(String::from_utf8_lossy(&out.stdout), vmax);
    let text = std::fs::read_to_string(&log).unwrap();
    assert!(text.contains("sent again after the reconnect"), "{text}");
}

#[test]
fn a_script_catches_the_error_of_a_motion_cut_short() {
    let (mut sim, link) = linked();
    let dir = tempdir();
    let script = dir.join("cut.rhai");
    // The pause only gives the test time to silence the module before the motion goes out.
    std::fs::write(
        &script,
        "print(`ready ${gap(1, 0)}`);\nsleep(3000);\ntry {\n    ror(0, 500);\n} catch (e) {\n    \
         print(`caught: ${e}`);\n}\nprint(`position ${gap(1, 0)}`);\n",
    )
    .unwrap();
    let log = dir.join("script.log");
    let mut child = Command::new(bin())
        .args([
            "--port",
            link.to_str().unwrap(),
            "--log",
            log.to_str().unwrap(),
        ])
        .args(["--timeout", "60000", "--reconnect", "20s", "run"])
        .arg(&script)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut ready = String::new();
    stdout.read_line(&mut ready).unwrap();
    assert_eq!(ready, "ready 0\n");
    assert_eq!(sim.console("silent on"), "ok silent");
    wait_for(&log, "ROR 0, 500", &mut child);
    unplug_while_silent(&mut sim, "1");
    child.stdout = Some(stdout.into_inner());
    let out = child.wait_with_output().unwrap();
    let printed = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        printed.contains("caught: ") && printed.contains("never sent again"),
        "{printed}{stderr}"
    );
    assert!(
        printed.contains("position "),
        "the script went on: {printed}{stderr}"
    );
}

#[test]
fn another_module_behind_the_port_after_the_outage_is_said() {
    let (mut first, link) = linked();
    let second = Sim::start(&["--pty", "--profile", "tmcm-1140"]);
    let (mut p, _) = repl(&["--port", link.to_str().unwrap()]);
    p.exp_string("A> ").unwrap();
    // The first adapter goes for good; another one, with another module, takes its name.
    let answer = first.console("unplug 600");
    assert!(answer.starts_with("ok unplugged"), "{answer}");
    p.exp_string("link lost").unwrap();
    std::os::unix::fs::symlink(&second.first, &link).unwrap();
    p.exp_string("now answers as TMCM-1140").unwrap();
    p.exp_string("reconnected").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 1, 0").unwrap();
    p.exp_string("actual_position = 0").unwrap();
    p.send_line(":quit").unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_line_typed_after_giving_up_the_wait_is_not_sent_and_the_wait_starts_again() {
    let (mut sim, link) = linked();
    let (mut p, _) = repl(&["--port", link.to_str().unwrap()]);
    p.exp_string("A> ").unwrap();
    assert!(sim.console("unplug 600").starts_with("ok unplugged"));
    p.exp_string("waiting for serial").unwrap();
    p.send_control('c').unwrap();
    p.exp_string("stopped waiting").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("ROR 0, 500").unwrap();
    p.exp_string("`ROR 0, 500` was not sent: the link is still away")
        .unwrap();
    p.exp_string("waiting for serial").unwrap();
    p.send_control('c').unwrap();
    p.exp_string("stopped waiting").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line(":quit").unwrap();
    p.exp_eof().unwrap();
}
