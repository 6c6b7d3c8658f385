//! A module power-cycled under an open session (`reset` on the simulator's console): in ASCII
//! mode it restarts in binary mode, and tmclsh must notice it, say so, enter ASCII mode again and
//! carry on; a binary-only session carries on as it was. RAM settings are back to their stored
//! values afterwards.

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

use crate::repl::type_in;
use crate::sim::Sim;
use crate::util::{bin, tempdir, terminal};

const RESTARTED: &str = "module 1 (A) restarted in binary mode; re-entering ASCII mode; RAM settings are back to their stored values";

#[test]
fn the_repl_notices_a_module_restarted_in_binary_mode_and_carries_on() {
    let mut sim = Sim::start(&["--pty"]);
    let mut p = terminal(&["--port", &sim.first, "--timeout", "400"], &[]);
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "SAP 4, 0, 1234\r");
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "GAP 4, 0\r");
    p.exp_string("1234").unwrap();
    p.exp_string("A> ").unwrap();
    assert!(sim.console("reset").contains("restarted in binary mode"));
    // The first line after the restart goes unanswered: the module is in binary mode.
    type_in(&mut p, "GAP 4, 0\r");
    p.exp_string(RESTARTED).unwrap();
    p.exp_string("no reply from module 1 (A)").unwrap();
    p.exp_string("was not repeated").unwrap();
    p.exp_string("A> ").unwrap();
    // The next is answered in ASCII mode, with the stored value.
    type_in(&mut p, "GAP 4, 0\r");
    p.exp_string("1000000").unwrap();
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "exit\r");
    p.exp_eof().unwrap();
}

#[test]
fn a_script_notices_a_module_restarted_and_its_next_read_is_answered() {
    let mut sim = Sim::start(&["--pty"]);
    let dir = tempdir();
    let script = dir.join("reads.rhai");
    std::fs::create_dir(dir.join("logs")).unwrap();
    std::fs::write(
        &script,
        r#"
sap(4, 0, 1234);
print("ready");
let failed = false;
for i in 0..400 {
    try { gap(4, 0); } catch (e) { print(`failed with exit ${e.exit}`); failed = true; break; }
    sleep(25);
}
print(`after: ${gap(4, 0)}`);
"#,
    )
    .unwrap();
    let mut child = Command::new(bin())
        .args(["--port", &sim.first, "--timeout", "400", "--log"])
        .arg(dir.join("logs"))
        .arg("run")
        .arg(&script)
        .env("XDG_DATA_HOME", &dir)
        .env("XDG_CONFIG_HOME", &dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut out = BufReader::new(child.stdout.take().unwrap());
    let mut line = String::new();
    out.read_line(&mut line).unwrap();
    assert_eq!(line.trim(), "ready");
    assert!(sim.console("reset 1").contains("module 1 restarted"));
    let output = child.wait_with_output().unwrap();
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut out, &mut rest).unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{rest}\n{stderr}");
    assert_eq!(
        rest.lines().collect::<Vec<_>>(),
        ["failed with exit 3", "after: 1000000"],
        "{stderr}"
    );
    assert!(stderr.contains(RESTARTED), "{stderr}");
    // The transcript records the restart too.
    let logs: Vec<_> = std::fs::read_dir(dir.join("logs")).unwrap().collect();
    assert_eq!(logs.len(), 1);
    let transcript = std::fs::read_to_string(logs[0].as_ref().unwrap().path()).unwrap();
    assert!(transcript.contains(RESTARTED), "{transcript}");
}

#[test]
fn a_binary_session_carries_on_after_a_restart_with_stored_values() {
    let mut sim = Sim::start(&["--pty"]);
    let mut p = terminal(&["--port", &sim.first, "--binary", "--timeout", "400"], &[]);
    p.exp_string("> ").unwrap();
    type_in(&mut p, "SAP 4, 0, 1234\r");
    p.exp_string("> ").unwrap();
    assert!(sim.console("reset").contains("restarted in binary mode"));
    type_in(&mut p, "GAP 4, 0\r");
    p.exp_string("1000000").unwrap();
    p.exp_string("> ").unwrap();
    type_in(&mut p, "exit\r");
    p.exp_eof().unwrap();
}

#[test]
fn no_barrier_is_owed_after_a_restart_and_the_echo_stays_as_set() {
    // Without an echo an unanswered line owes a barrier before the next one; after a restart
    // nothing sent before can be answered, so the next line goes out by itself. The echo set
    // with --echo stays: SGP 67 writes the EEPROM too (in the simulator, as bank 0's interface
    // settings on the modules), so the restarted module has it already.
    let mut sim = Sim::start(&["--pty"]);
    let data = tempdir();
    let log = data.join("session.log");
    let log_arg = log.to_str().unwrap();
    let args = [
        "--port",
        &sim.first,
        "--timeout",
        "400",
        "--echo",
        "none",
        "--log",
        log_arg,
    ];
    let mut p = terminal(&args, &[]);
    p.exp_string("A> ").unwrap();
    assert!(sim.console("reset").contains("restarted in binary mode"));
    type_in(&mut p, "GAP 4, 0\r");
    p.exp_string(RESTARTED).unwrap();
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "GGP 67, 0\r");
    p.exp_string("32").unwrap();
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "exit\r");
    p.exp_eof().unwrap();
    let transcript = std::fs::read_to_string(&log).unwrap();
    let after = &transcript[transcript.find(RESTARTED).expect("restart noted")..];
    assert!(!after.contains("barrier:"), "{after}");
    assert!(!after.contains("set again"), "{after}");
}
