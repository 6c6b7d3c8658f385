//! Hostile replies through the real binary: a drive on a real pseudo-terminal whose answers to
//! chosen requests are replaced by scripted bytes — garbled digits, extra items, NaN and huge
//! numbers, another drive's prefix, terminal escape sequences — while every other request reaches
//! the simulated drive behind it. A reply that is not the command's declared answer fails with
//! exit 3 and a "line noise:" message, never a value; nothing the device sends reaches stdout or
//! stderr unescaped; and the next command gets its own answer.

use std::net::TcpListener;
use std::process::Output;
use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use tmclsh::clock::SystemClock;
use tmclsh::dialect::smd4::protocol::{Expectation, Smd4Spec, check_reply, parse_reply};
use tmclsh::dialect::smd4::sim::{Smd4Sim, Smd4SimOptions};
use tmclsh::dialect::tmcl::protocol::{CommandFrame, Instruction};
use tmclsh::dialect::tmcl::sim::{Bus, BusOptions};
use tmclsh::sim::Device;
use tmclsh::sim::inprocess::SharedDevice;
use tmclsh::sim::serve::{Server, wake_pair};

use crate::sim::PATIENCE;
use crate::smd4::{BOTH, Via, assert_exit, client};
use crate::util::tempdir;

/// A device that answers chosen request lines with scripted bytes, once each, and passes every
/// other line on to a real simulated device.
struct Scripted {
    /// The byte that ends a request line (LF for SMD4's CR LF, CR for TMCL).
    end: u8,
    /// Request line (without its line end) and the bytes sent instead of the device's answer.
    rules: Vec<(String, Vec<u8>)>,
    inner: Box<dyn Device>,
    line: Vec<u8>,
    out: Vec<u8>,
}

impl Device for Scripted {
    fn receive(&mut self, now: Duration, bytes: &[u8]) {
        for &b in bytes {
            self.line.push(b);
            if b != self.end {
                continue;
            }
            let line = std::mem::take(&mut self.line);
            let text = String::from_utf8_lossy(&line);
            let text = text.trim_end_matches(['\r', '\n']);
            match self.rules.iter().position(|(request, _)| request == text) {
                Some(i) => self.out.extend(self.rules.remove(i).1),
                None => self.inner.receive(now, &line),
            }
        }
    }

    fn poll_output(&mut self, now: Duration, out: &mut Vec<u8>) {
        out.append(&mut self.out);
        self.inner.poll_output(now, out);
    }

    fn next_due(&self, now: Duration) -> Option<Duration> {
        if self.out.is_empty() {
            self.inner.next_due(now)
        } else {
            Some(now)
        }
    }
}

/// Serves `device` from a thread with the simulator's own server, on a new pseudo-terminal or on
/// loopback TCP; returns the client's flags that reach it.
fn serve(device: Scripted, via: Via) -> [String; 2] {
    let device: SharedDevice = Arc::new(Mutex::new(device));
    let (waker, wake) = wake_pair().expect("a wake pair");
    let mut server = Server::new(device, Arc::new(SystemClock::new()), wake, Box::new(|_| {}));
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _waker = waker;
        let _ = match via {
            Via::Pty => server.serve_pty(&mut |path| {
                let _ = tx.send(["--port".to_string(), path.display().to_string()]);
            }),
            Via::Tcp => {
                let listener = TcpListener::bind("127.0.0.1:0").expect("a loopback port");
                let address = listener.local_addr().unwrap().to_string();
                let _ = tx.send(["--tcp".to_string(), address]);
                server.serve_tcp(&listener)
            }
        };
    });
    rx.recv_timeout(PATIENCE).expect("the device is served")
}

/// A simulated SMD4 behind `rules`, on a pseudo-terminal; the connection flags of a client.
fn smd4_drive(rules: &[(&str, &[u8])]) -> Vec<String> {
    smd4_drive_via(Via::Pty, rules)
}

fn smd4_drive_via(via: Via, rules: &[(&str, &[u8])]) -> Vec<String> {
    let device = Scripted {
        end: b'\n',
        rules: own(rules),
        inner: Box::new(Smd4Sim::new(Smd4SimOptions::default())),
        line: Vec::new(),
        out: Vec::new(),
    };
    let mut flags = vec!["--protocol".to_string(), "smd4".to_string()];
    flags.extend(serve(device, via));
    flags.extend(["--timeout".to_string(), "500".to_string()]);
    flags
}

/// A simulated TMCM-142 already in ASCII mode (char echo) behind `rules`; the connection flags
/// of a client that neither enters nor leaves ASCII mode.
fn tmcl_module(rules: &[(&str, &[u8])]) -> Vec<String> {
    let mut bus = Bus::new(
        tmclsh::dialect::tmcl::profile::Profile::builtin(),
        BusOptions::default(),
    );
    let enter = CommandFrame {
        address: 1,
        instruction: Instruction::new(139, 0, 0, 0),
    };
    bus.receive(Duration::ZERO, &enter.encode());
    bus.poll_output(Duration::ZERO, &mut Vec::new());
    let device = Scripted {
        end: b'\r',
        rules: own(rules),
        inner: Box::new(bus),
        line: Vec::new(),
        out: Vec::new(),
    };
    let mut flags = serve(device, Via::Pty).to_vec();
    flags.extend(["--no-enter".to_string(), "--stay-ascii".to_string()]);
    flags
}

fn own(rules: &[(&str, &[u8])]) -> Vec<(String, Vec<u8>)> {
    rules
        .iter()
        .map(|(request, reply)| (request.to_string(), reply.to_vec()))
        .collect()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// No control character but the line feed in what tmclsh wrote, on either stream.
#[track_caller]
fn assert_nothing_raw(out: &Output) {
    for (name, bytes) in [("stdout", &out.stdout), ("stderr", &out.stderr)] {
        let raw: Vec<u8> = bytes
            .iter()
            .copied()
            .filter(|&b| (b < 0x20 && b != b'\n') || b == 0x7F)
            .collect();
        assert!(
            raw.is_empty(),
            "{name} carries {raw:02X?}: {:?}",
            text(bytes)
        );
    }
}

/// The SMD4 cases: a request and the hostile reply that replaces its answer, with what the
/// message must say.
const SMD4_NOISE: &[(&str, &[u8], &str)] = &[
    (
        "MOTOR:PACT",
        b"0x0888,0x0000,3.45O0E+03\r\n",
        "line noise: '3.45O0E+03' where one FLOAT item is due",
    ),
    (
        "MOTOR:VACT",
        b"0x0888,0x0000,1.0000E+03,1.0000E+03\r\n",
        "line noise: one FLOAT item due, 2 received",
    ),
    (
        "MOTOR:VACT",
        b"0x0888,0x0000,NaN\r\n",
        "line noise: 'NaN' where one FLOAT item is due",
    ),
    (
        "MOTOR:VMAX",
        b"0x0888,0x0000,inf,1.0000E+03\r\n",
        "line noise: 'inf' where one FLOAT item is due",
    ),
    (
        "MOTOR:VACT",
        b"0x0888,0x0000,1e999\r\n",
        "line noise: '1e999' where one FLOAT item is due",
    ),
    (
        "SYS:UPTIME",
        b"0x0888,0x0000,12345678901234567890123\r\n",
        "line noise: '12345678901234567890123' where one UINT item is due",
    ),
    // A byte turned into CR: the value is cut short, the rest is a line of its own.
    (
        "MOTOR:PACT",
        b"0x0888,0x0000,12\r34.00\r\n",
        // What follows the reply is seen before the reply's items are checked.
        "line noise: the reply \"0x0888,0x0000,12\" was followed by \"34.00\\r\\n\"",
    ),
    (
        "MOTOR:VMAX",
        b"0x0888,0x0000,-99999999999 (Invalid Mnemonic)\r\n",
        "line noise: error code -99999999999 out of range",
    ),
    (
        "SYS:FW",
        b"0x0888,0x0000,24044.12\x1b]0;owned\x07\x1b[2J\r\n",
        "line noise: a control or non-ASCII character, in the reply \"0x0888,0x0000,24044.12\\x1B]0;owned\\x07\\x1B[2J\"",
    ),
    (
        "SYS:FW",
        b"0x0888,0x0000,240\x0044.12\r\n",
        "line noise: a control or non-ASCII character",
    ),
    (
        "SYS:FLAGSV",
        b"@5,0x0888,0x0000,\r\n[X]Standby\r\n",
        "line noise: a reply from drive @5, but requests carry no address",
    ),
    (
        "SYS:FLAGSV",
        b"0x0888,0x0000,\r\n[X]Standby\x1b[2J\r\n",
        "line noise: a control or non-ASCII character in line 2",
    ),
];

/// The firmware version the simulated drive reports.
fn firmware() -> String {
    let spec = Smd4Spec::builtin().commands.get("SYS:FW").unwrap();
    spec.sim_value.clone().unwrap()
}

#[test]
fn smd4_noise_exits_3_with_no_value_and_nothing_raw() {
    for via in BOTH {
        for &(request, reply, message) in SMD4_NOISE {
            let drive = smd4_drive_via(via, &[(request, reply)]);
            let out = client(&drive, &["-c", request, "-c", "SYS:FW"], "");
            assert_exit(&out, 3);
            assert_nothing_raw(&out);
            assert!(
                out.stdout.is_empty(),
                "{request}: no value: {}",
                text(&out.stdout)
            );
            let stderr = text(&out.stderr);
            let first = format!("tmclsh: line 1 ({request}): {message}");
            assert!(stderr.starts_with(&first), "{via:?} {request}: {stderr}");
        }
    }
}

#[test]
fn after_noise_the_next_commands_get_their_own_answers() {
    let dir = tempdir();
    let cases = BOTH
        .into_iter()
        .flat_map(|via| SMD4_NOISE.iter().map(move |c| (via, c)));
    for (n, (via, &(request, reply, message))) in cases.enumerate() {
        let drive = smd4_drive_via(via, &[(request, reply)]);
        let script = dir.join(format!("noise{n}.rhai"));
        std::fs::write(
            &script,
            format!(
                "let failure = ();\n\
                 try {{ send(\"{request}\"); }} catch (e) {{ failure = e; }}\n\
                 print(\"caught: \" + failure.to_string());\n\
                 print(send(\"SYS:FW\")[0]);\n\
                 print(reply(\"{request}\").raw);\n\
                 throw failure;\n"
            ),
        )
        .unwrap();
        let mut args = vec!["run".to_string(), script.display().to_string()];
        args.extend(drive);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = client(&[], &args, "");
        assert_exit(&out, 3);
        assert_nothing_raw(&out);
        let stdout = text(&out.stdout);
        let lines: Vec<&str> = stdout.lines().collect();
        // A multi-line reply's lines follow its first line.
        assert!(lines.len() >= 3, "{request}: {stdout}");
        assert!(
            lines[0].starts_with(&format!("caught: {message}")),
            "{stdout}"
        );
        // The same drive, the same run: SYS:FW gets the firmware version, and the command asked
        // again gets a reply the check accepts, from the drive behind the script.
        assert_eq!(lines[1], firmware(), "{request}");
        let spec = Smd4Spec::builtin().commands.get(request).unwrap();
        let expect = Expectation::for_command(spec);
        let again = parse_reply(lines[2], &expect).unwrap();
        assert!(again.is_ok(), "{request}: {}", lines[2]);
        assert_eq!(check_reply(&again, &expect, None), Ok(()), "{}", lines[2]);
        assert!(text(&out.stderr).contains(message), "{}", text(&out.stderr));
    }
}

#[test]
fn a_reply_from_another_drive_is_never_taken() {
    // Without --address, and with another address than the reply's: ignored, said, timed out.
    for (address, request) in [(None, "MOTOR:PACT"), (Some("3"), "@3MOTOR:PACT")] {
        let mut drive = smd4_drive(&[(request, b"@5,0x0888,0x0000,1000.00\r\n")]);
        if let Some(address) = address {
            drive.extend(["--address".to_string(), address.to_string()]);
        }
        let out = client(&drive, &["-c", "MOTOR:PACT"], "");
        assert_exit(&out, 3);
        assert_nothing_raw(&out);
        assert!(out.stdout.is_empty(), "{}", text(&out.stdout));
        let stderr = text(&out.stderr);
        assert!(stderr.contains("ignored a reply from drive @5"), "{stderr}");
        let silent = match address {
            Some(a) => format!("no reply from drive @{a} within"),
            None => "no reply from the drive within".to_string(),
        };
        assert!(stderr.contains(&silent), "{stderr}");
    }
    // The drive's own prefix is ours.
    let drive = smd4_drive(&[("@5MOTOR:PACT", b"@5,0x0888,0x0000,1000.00\r\n")]);
    let out = client(&drive, &["--address", "5", "-c", "MOTOR:PACT"], "");
    assert_exit(&out, 0);
    assert_eq!(text(&out.stdout), "@5,0x0888,0x0000,1000.00\n");
}

#[test]
fn unvalidated_commands_are_held_to_printable_replies() {
    let drive = smd4_drive(&[("SYS:SECRET", b"0x0888,0x0000,\x1b]2;owned\x07\r\n")]);
    let out = client(&drive, &["--no-validate", "-c", "SYS:SECRET"], "");
    assert_exit(&out, 3);
    assert_nothing_raw(&out);
    assert!(
        text(&out.stderr).contains("\\x1B]2;owned\\x07"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn input_lines_are_escaped_in_messages() {
    let drive = smd4_drive(&[]);
    let out = client(&drive, &[], "SYS:FW\x1b[2J\x07\n");
    assert_exit(&out, 2);
    assert_nothing_raw(&out);
    assert!(
        text(&out.stderr).starts_with("tmclsh: line 1 (SYS:FW\\x1B[2J\\x07): "),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn tmcl_device_text_is_escaped_on_both_streams() {
    let module = tmcl_module(&[
        // An echo garbled into an escape sequence: line noise, quoted escaped.
        ("AGAP 1, 0", b"AGAP 1,\x1b0\rBA 100 5\r"),
        // A line of junk before the reply: a notice, quoted escaped, and the reply taken.
        ("AGAP 2, 0", b"AGAP 2, 0\r\x1b]0;owned\x07\x00\rBA 100 7\r"),
    ]);
    let out = client(&module, &["-c", "GAP 2, 0", "-c", "GAP 1, 0"], "");
    assert_exit(&out, 3);
    assert_nothing_raw(&out);
    assert_eq!(text(&out.stdout), "BA 100 7\n");
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("ignored unexpected data from the line: \"\\x1B]0;owned\\x07\\x00"),
        "{stderr}"
    );
    assert!(
        stderr.contains("line 2 (GAP 1, 0): line noise: module 1 (A) echoed 'AGAP 1,\\x1B0'"),
        "{stderr}"
    );
}

#[test]
fn transcripts_and_json_carry_no_raw_device_or_input_text() {
    let module = tmcl_module(&[
        ("AGAP 1, 0", b"AGAP 1,\x1b0\rBA 100 5\r"),
        (
            "AGAP 2, 0",
            b"AGAP 2, 0\r\x1b]0;owned\x07\x7f\x9b2J\rBA 100 7\r",
        ),
    ]);
    let log = tempdir().join("noise.log");
    let log_arg = log.display().to_string();
    let out = client(
        &module,
        &[
            "--log",
            &log_arg,
            "--json",
            "--keep-going",
            "-c",
            "GAP 2, 0",
            "-c",
            "GAP 1, 0",
            "-c",
            "GAP 3, 0\x7f\x1b[2J",
        ],
        "",
    );
    assert_exit(&out, 3);
    assert_nothing_raw(&out);
    let json = text(&out.stdout);
    assert!(json.contains("\\u007f"), "the input's DEL, escaped: {json}");
    let transcript = std::fs::read(&log).unwrap();
    let raw: Vec<u8> = transcript
        .iter()
        .copied()
        .filter(|&b| (b < 0x20 && b != b'\n') || b >= 0x7F)
        .collect();
    assert!(raw.is_empty(), "{raw:02X?} in {:?}", text(&transcript));
    let transcript = text(&transcript);
    assert!(
        transcript.contains("-- line noise: module 1 (A) echoed 'AGAP 1,\\x1B0'"),
        "the line noise note quotes the echo escaped: {transcript}"
    );
}

#[test]
fn a_flood_of_position_events_is_one_line_with_a_count() {
    let mut flood = b"AGAP 2, 0\r".to_vec();
    for _ in 0..200 {
        flood.extend_from_slice(b"BA 128 0\r");
    }
    flood.extend_from_slice(b"BA 100 7\r");
    let module = tmcl_module(&[("AGAP 2, 0", flood.as_slice())]);
    let out = client(&module, &["-c", "GAP 2, 0"], "");
    assert_exit(&out, 0);
    assert_eq!(text(&out.stdout), "BA 100 7\n");
    let stderr = text(&out.stderr);
    assert_eq!(
        stderr, "tmclsh: module 1 (A): target position reached (event) (and 199 more like it)\n",
        "one line, first the event, then the count"
    );
}

#[test]
fn tmcl_reply_lines_reach_stdout_escaped() {
    // Form feed and vertical tab count as white space after a reply; they are shown, escaped.
    let module = tmcl_module(&[("AGAP 3, 0", b"AGAP 3, 0\rBA 100 9\x0c\x0b\r")]);
    let out = client(&module, &["-c", "GAP 3, 0", "-c", "GAP 1, 0"], "");
    assert_nothing_raw(&out);
    match out.status.code() {
        Some(0) => assert_eq!(text(&out.stdout), "BA 100 9\\x0C\\x0B\nBA 100 0\n"),
        // Trailing bytes after a reply may instead count as line noise.
        _ => assert_exit(&out, 3),
    }
}

#[test]
fn script_print_escapes_what_it_is_given() {
    let dir = tempdir();
    let script = dir.join("print.rhai");
    std::fs::write(
        &script,
        "print(\"title\\x1b]0;owned\\x07 bell\\x07 cr\\rover\\nsecond line\");\n\
         debug(\"nul\\x00\");\n",
    )
    .unwrap();
    let out = client(&[], &["--sim", "run", &script.display().to_string()], "");
    assert_exit(&out, 0);
    assert_nothing_raw(&out);
    assert_eq!(
        text(&out.stdout),
        "title\\x1B]0;owned\\x07 bell\\x07 cr\\rover\nsecond line\n"
    );
    // Rhai hands `debug` its own escaped rendering ("nul\0"); nothing raw gets through either way.
    assert!(
        text(&out.stderr).contains("debug line 2"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn the_repl_shows_noise_escaped_and_goes_on() {
    use rexpect::session::spawn_command;

    let drive = smd4_drive(&[("SYS:FW", b"0x0888,0x0000,24044.12\x1b]0;owned\x07\r\n")]);
    let home = tempdir();
    let mut command = std::process::Command::new(crate::util::bin());
    command
        .args(&drive)
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("HOME", &home)
        .env("XDG_DATA_HOME", &home);
    let mut p =
        spawn_command(command, Some(crate::util::EXPECT_MS)).expect("tmclsh starts in a pty");
    let mut seen = p.exp_string("smd4> ").unwrap();
    p.send_line("SYS:FW").unwrap();
    seen += &p
        .exp_string("error: line noise: a control or non-ASCII character")
        .unwrap();
    seen += &p.exp_string("\\x1B]0;owned\\x07").unwrap();
    seen += &p.exp_string("smd4> ").unwrap();
    // The same session goes on: the next command gets the drive's own answer.
    p.send_line("SYS:FW").unwrap();
    seen += &p.exp_string(&firmware()).unwrap();
    seen += &p.exp_string("smd4> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
    assert!(!seen.contains("\x1b]0;owned"), "{seen:?}");
    assert!(!seen.contains('\x07'), "{seen:?}");
}
