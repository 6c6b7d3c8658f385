//! Serial ports: `tmclsh ports` shows what USB adapters say about themselves, `--port
//! usb:VID:PID[:SERIAL]` finds the adapter whatever its device file, and the REPL waits for a port
//! that is not there yet. Adapters cannot be plugged in on demand, so a made-up sysfs tree (read
//! from TMCLSH_TEST_SYSFS, by release builds too) stands for them, its device files symlinks to
//! simulators' pseudo-terminals.

#![cfg(target_os = "linux")]

use std::io::Write;
use std::os::unix::fs::symlink;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

use rexpect::session::spawn_command;

use crate::sim::Sim;
use crate::util::{bin, code, stderr, stdout, tempdir};

/// A sysfs tree with adapters plugged in.
struct Machine {
    root: PathBuf,
}

impl Machine {
    fn new() -> Machine {
        let root = tempdir();
        for dir in [
            "sys/class/tty",
            "sys/bus/usb",
            "sys/bus/usb-serial",
            "sys/bus/pnp",
            "dev",
        ] {
            std::fs::create_dir_all(root.join(dir)).unwrap();
        }
        // A virtual terminal has no device: not a serial port.
        std::fs::create_dir_all(root.join("sys/class/tty/tty0")).unwrap();
        std::fs::write(root.join("dev/tty0"), "").unwrap();
        Machine { root }
    }

    /// An FTDI-style adapter: the tty's device is the usb-serial port under the interface.
    fn usb_serial(&self, name: &str, ids: (&str, &str), serial: Option<&str>, device: &Path) {
        let usb = self.root.join(format!("sys/devices/usb1/{name}"));
        let interface = usb.join("1-0:1.0");
        let port = interface.join(name);
        std::fs::create_dir_all(&port).unwrap();
        std::fs::write(usb.join("idVendor"), format!("{}\n", ids.0)).unwrap();
        std::fs::write(usb.join("idProduct"), format!("{}\n", ids.1)).unwrap();
        if let Some(serial) = serial {
            std::fs::write(usb.join("serial"), format!("{serial}\n")).unwrap();
        }
        std::fs::write(usb.join("product"), "FT232R USB UART\n").unwrap();
        std::fs::write(usb.join("manufacturer"), "FTDI\n").unwrap();
        symlink(self.root.join("sys/bus/usb"), interface.join("subsystem")).unwrap();
        symlink(self.root.join("sys/bus/usb-serial"), port.join("subsystem")).unwrap();
        let class = self.root.join("sys/class/tty").join(name);
        std::fs::create_dir_all(&class).unwrap();
        symlink(&port, class.join("device")).unwrap();
        symlink(device, self.root.join("dev").join(name)).unwrap();
    }

    /// The latency timer of the FTDI adapter `name`, as `ftdi_sio` shows it.
    fn latency(&self, name: &str, ms: u32) {
        let port = self
            .root
            .join(format!("sys/devices/usb1/{name}/1-0:1.0/{name}"));
        std::fs::write(port.join("latency_timer"), format!("{ms}\n")).unwrap();
        let devices = self.root.join("sys/bus/usb-serial/devices");
        std::fs::create_dir_all(&devices).unwrap();
        let _ = std::fs::remove_file(devices.join(name));
        symlink(&port, devices.join(name)).unwrap();
    }

    /// A UUCP lock file for `name` naming `pid`.
    fn lock(&self, name: &str, pid: u32) -> PathBuf {
        let dir = self.root.join("var/lock");
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join(format!("LCK..{name}"));
        std::fs::write(&file, format!("{pid:>10}\n")).unwrap();
        file
    }

    /// A multi-port adapter (an FT4232H): one USB device, a tty per interface.
    fn multi_port(&self, names: &[&str], serial: &str, device: &Path) {
        let usb = self.root.join("sys/devices/usb1/1-2");
        for (i, name) in names.iter().enumerate() {
            let interface = usb.join(format!("1-2:1.{i}"));
            let port = interface.join(name);
            std::fs::create_dir_all(&port).unwrap();
            std::fs::write(interface.join("bInterfaceNumber"), format!("{i:02x}\n")).unwrap();
            symlink(self.root.join("sys/bus/usb"), interface.join("subsystem")).unwrap();
            symlink(self.root.join("sys/bus/usb-serial"), port.join("subsystem")).unwrap();
            let class = self.root.join("sys/class/tty").join(name);
            std::fs::create_dir_all(&class).unwrap();
            symlink(&port, class.join("device")).unwrap();
            symlink(device, self.root.join("dev").join(name)).unwrap();
        }
        std::fs::write(usb.join("idVendor"), "0403\n").unwrap();
        std::fs::write(usb.join("idProduct"), "6011\n").unwrap();
        std::fs::write(usb.join("serial"), format!("{serial}\n")).unwrap();
        std::fs::write(usb.join("product"), "Quad RS232-HS\n").unwrap();
    }

    /// A udev link to `name` under `dev/serial/DIR`, relative as udev writes it.
    fn stable(&self, dir: &str, link: &str, name: &str) -> String {
        let dir = self.root.join("dev/serial").join(dir);
        std::fs::create_dir_all(&dir).unwrap();
        symlink(format!("../../{name}"), dir.join(link)).unwrap();
        dir.join(link).to_string_lossy().into_owned()
    }

    /// A placeholder ttyS port: serial8250 reserves it, no UART behind it (type 0).
    fn placeholder(&self, name: &str) {
        self.builtin(name);
        std::fs::write(
            self.root.join("sys/class/tty").join(name).join("type"),
            "0\n",
        )
        .unwrap();
    }

    /// A built-in port (pnp).
    fn builtin(&self, name: &str) {
        let device = self.root.join(format!("sys/devices/pnp0/{name}"));
        std::fs::create_dir_all(&device).unwrap();
        symlink(self.root.join("sys/bus/pnp"), device.join("subsystem")).unwrap();
        let class = self.root.join("sys/class/tty").join(name);
        std::fs::create_dir_all(&class).unwrap();
        symlink(&device, class.join("device")).unwrap();
        std::fs::write(self.root.join("dev").join(name), "").unwrap();
    }

    fn dev(&self, name: &str) -> String {
        self.root
            .join("dev")
            .join(name)
            .to_string_lossy()
            .into_owned()
    }

    fn run(&self, args: &[&str]) -> Output {
        Command::new(bin())
            .args(args)
            .env("TMCLSH_TEST_SYSFS", &self.root)
            .env("NO_COLOR", "1")
            .stdin(Stdio::null())
            .output()
            .unwrap()
    }
}

#[test]
fn ports_shows_ids_serial_number_and_product() {
    let machine = Machine::new();
    let nowhere = machine.root.join("nowhere");
    std::fs::write(&nowhere, "").unwrap();
    machine.usb_serial("ttyUSB0", ("0403", "6001"), Some("A50285BI"), &nowhere);
    machine.usb_serial("ttyUSB1", ("2e8a", "000A"), None, &nowhere);
    machine.builtin("ttyS0");
    let out = machine.run(&["ports"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let row = |name: &str| -> Vec<String> {
        let line = text
            .lines()
            .find(|l| l.starts_with(&machine.dev(name)))
            .unwrap_or_else(|| panic!("{name} not listed:\n{text}"));
        line.split_whitespace().map(String::from).collect()
    };
    assert_eq!(
        row("ttyUSB0")[1..],
        [
            "USB",
            "0403:6001",
            "A50285BI",
            "0",
            "-",
            "FT232R",
            "USB",
            "UART",
            "(FTDI)"
        ]
    );
    assert_eq!(row("ttyUSB1")[1..4], ["USB", "2e8a:000a", "-"]);
    assert_eq!(row("ttyS0")[1..], ["other", "-", "-", "-", "-"]);
    assert!(
        !text.contains("tty0 "),
        "a virtual terminal is no serial port:\n{text}"
    );
    assert!(text.contains("--port usb:0403:6001:A50285BI"), "{text}");
}

#[test]
fn ports_shows_stable_names_interfaces_and_latency_and_hides_placeholders() {
    let sim = Sim::start(&["--pty"]);
    let machine = Machine::new();
    machine.usb_serial(
        "ttyUSB0",
        ("0403", "6001"),
        Some("A1"),
        Path::new(&sim.first),
    );
    machine.latency("ttyUSB0", 16);
    let by_id = machine.stable("by-id", "usb-FTDI_FT232R_USB_UART_A1-if00-port0", "ttyUSB0");
    let by_path = machine.stable("by-path", "pci-0000:00:14.0-usb-0:1:1.0-port0", "ttyUSB0");
    machine.multi_port(
        &["ttyUSB1", "ttyUSB2", "ttyUSB3", "ttyUSB4"],
        "FT4232A",
        Path::new(&sim.first),
    );
    machine.builtin("ttyS0");
    machine.placeholder("ttyS1");
    machine.placeholder("ttyS2");
    let out = machine.run(&["ports"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let lines: Vec<&str> = text.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with(&machine.dev("ttyUSB0")))
        .unwrap_or_else(|| panic!("{text}"));
    let row: Vec<&str> = lines[at].split_whitespace().collect();
    assert_eq!(row[4..7], ["0", "16", "ms"], "{text}");
    // The stable names under their port.
    assert_eq!(lines[at + 1], format!("  also {by_id}"), "{text}");
    assert_eq!(lines[at + 2], format!("  also {by_path}"), "{text}");
    let interface = |name: &str| -> String {
        let line = lines
            .iter()
            .find(|l| l.starts_with(&machine.dev(name)))
            .unwrap();
        line.split_whitespace().nth(4).unwrap().to_string()
    };
    assert_eq!(interface("ttyUSB3"), "2");
    assert!(text.contains(&machine.dev("ttyS0")), "{text}");
    assert!(!text.contains(&machine.dev("ttyS1")), "{text}");
    assert!(text.contains("2 placeholder ports hidden"), "{text}");
    assert!(text.contains("FTDI latency timer above 2 ms"), "{text}");
    let out = machine.run(&["ports", "--all"]);
    let text = stdout(&out);
    assert!(text.contains(&machine.dev("ttyS1")), "{text}");
    assert!(text.contains("placeholder: no UART behind it"), "{text}");

    // One port of the quad adapter by its interface; the adapter alone is ambiguous.
    let out = machine.run(&["--port", "usb:0403:6011:FT4232A:2", "-c", "GAP 1, 0", "-v"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = machine.run(&["--port", "usb:0403:6011", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("(serial FT4232A, interface 3)"), "{err}");
    assert!(err.contains("e.g. usb:0403:6011:FT4232A:0"), "{err}");
    // A stable name is a port like any other.
    let out = machine.run(&["--port", &by_id, "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}

#[test]
fn a_usb_name_finds_its_adapter_or_says_why_not() {
    let sim = Sim::start(&["--pty"]);
    let other = Sim::start(&["--pty", "--modules", "2"]);
    let machine = Machine::new();
    machine.usb_serial(
        "ttyUSB0",
        ("0403", "6001"),
        Some("A1"),
        Path::new(&sim.first),
    );
    machine.usb_serial(
        "ttyUSB1",
        ("0403", "6001"),
        Some("B2"),
        Path::new(&other.first),
    );
    machine.usb_serial("ttyUSB2", ("10c4", "ea60"), None, Path::new(&other.first));

    let out = machine.run(&[
        "--port",
        "usb:0403:6001:A1",
        "-c",
        "SAP 1, 0, 42",
        "-c",
        "GAP 1, 0",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).ends_with("BA 100 42\n"), "{}", stdout(&out));
    // Upper-case hex, and the only adapter of its kind needs no serial number.
    let out = machine.run(&["--port", "usb:10C4:EA60", "--module", "2", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));

    let out = machine.run(&["--port", "usb:0403:6001", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("usb:0403:6001 matches 2 ports"), "{err}");
    assert!(
        err.contains("(serial A1)") && err.contains("(serial B2)"),
        "{err}"
    );
    assert!(err.contains("e.g. usb:0403:6001:A1"), "{err}");

    let out = machine.run(&["--port", "usb:0403:6001:C3", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(stderr(&out).contains("no USB adapter usb:0403:6001:C3 is plugged in"));

    let out = machine.run(&["--port", "usb:ftdi", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("usb:VID:PID"), "{}", stderr(&out));
    // A subcommand resolves it the same way (after reading its file, which must be a snapshot).
    let snapshot = tempdir().join("min.toml");
    std::fs::write(&snapshot, "[module]\nname = \"TMCM-142\"\n").unwrap();
    let out = machine.run(&[
        "snapshot",
        "diff",
        snapshot.to_str().unwrap(),
        "--port",
        "usb:dead:beef",
    ]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
}

#[test]
fn a_high_latency_timer_is_explained_once_with_its_fix() {
    let sim = Sim::start(&["--pty"]);
    let machine = Machine::new();
    machine.usb_serial(
        "ttyUSB0",
        ("0403", "6001"),
        Some("A1"),
        Path::new(&sim.first),
    );
    let port = machine.dev("ttyUSB0");
    let lines = [
        "--port", &port, "--baud", "115200", "-c", "GAP 1, 0", "-c", "GAP 2, 0",
    ];

    // 16 ms, the default: the low-latency flag cannot be set on the pty behind the made-up
    // adapter, the timer read again is still 16 ms, so the cost and the fix are given, once.
    machine.latency("ttyUSB0", 16);
    let log = machine.root.join("session.log");
    let mut logged = lines.to_vec();
    logged.extend(["--log", log.to_str().unwrap()]);
    let out = machine.run(&logged);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let err = stderr(&out);
    assert_eq!(err.matches("latency timer, 16 ms").count(), 1, "{err}");
    // The transcript has it too: a log shared later explains itself.
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(transcript.contains("latency timer, 16 ms"), "{transcript}");
    assert!(err.contains("1.6 ms on the wire at 115200 baud"), "{err}");
    assert!(
        err.contains("echo 1 > /sys/bus/usb-serial/devices/ttyUSB0/latency_timer"),
        "{err}"
    );
    assert!(err.contains("ATTR{latency_timer}=\"1\""), "{err}");
    assert!(stdout(&out).ends_with("BA 100 0\n"), "{}", stdout(&out));

    // --keep-latency leaves it alone and says nothing of it.
    let mut kept = lines.to_vec();
    kept.push("--keep-latency");
    let out = machine.run(&kept);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(!stderr(&out).contains("latency"), "{}", stderr(&out));

    // A timer already at 1 ms costs nothing worth a word.
    machine.latency("ttyUSB0", 1);
    let out = machine.run(&lines);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(!stderr(&out).contains("latency"), "{}", stderr(&out));
}

#[test]
fn line_shows_the_rate_the_timer_and_what_the_pty_lacks() {
    let sim = Sim::start(&["--pty"]);
    let machine = Machine::new();
    machine.usb_serial("ttyUSB0", ("0403", "6001"), None, Path::new(&sim.first));
    machine.latency("ttyUSB0", 16);
    let port = machine.dev("ttyUSB0");
    let out = machine.run(&[
        "--port",
        &port,
        "--keep-latency",
        "-c",
        "GAP 1, 0",
        "-c",
        ":line",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let row = |name: &str| -> String {
        text.lines()
            .find_map(|l| l.strip_prefix(name))
            .unwrap_or_else(|| panic!("no {name} row:\n{text}"))
            .trim()
            .to_string()
    };
    assert_eq!(row("rate"), "9600 baud, as read back from the driver");
    assert!(row("modem lines").starts_with("none ("), "{text}");
    assert!(row("latency").starts_with("16 ms: "), "{text}");
    assert_eq!(row("echo strip"), "off");
    // Identification, ASCII mode and the typed line: every request answered.
    let sent = row("sent");
    let received = row("received");
    let requests = sent
        .split(" in ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap();
    let replies = received
        .split(" in ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap();
    assert_eq!(requests, replies, "{text}");
    assert!(
        sent.ends_with(" requests") && received.ends_with(" replies"),
        "{text}"
    );
}

#[test]
fn a_port_held_by_another_program_names_it() {
    let sim = Sim::start(&["--pty"]);
    let machine = Machine::new();
    // Another tmclsh reading lines from a pipe: it holds the port until its input ends.
    let mut holder = Command::new(bin())
        .args(["--port", &sim.first])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let pid = holder.id();
    let mut input = holder.stdin.take().unwrap();
    let mut output = std::io::BufReader::new(holder.stdout.take().unwrap());
    writeln!(input, "GAP 1, 0").unwrap();
    let mut answer = String::new();
    std::io::BufRead::read_line(&mut output, &mut answer).unwrap();
    assert_eq!(answer, "BA 100 0\n", "the holder has the port open");
    let out = machine.run(&["--port", &sim.first, "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains(&format!("in use by PID {pid} (")), "{err}");
    assert!(err.contains("--port"), "the holder's command line: {err}");
    assert!(!err.contains("plugged in"), "{err}");
    drop(input);
    assert!(holder.wait().unwrap().success());
}

#[test]
fn a_live_uucp_lock_refuses_the_port_and_a_stale_one_is_noted() {
    let sim = Sim::start(&["--pty"]);
    let machine = Machine::new();
    machine.usb_serial("ttyUSB0", ("0403", "6001"), None, Path::new(&sim.first));
    let port = machine.dev("ttyUSB0");
    // This test's own process: alive, and not the tmclsh that opens the port.
    let file = machine.lock("ttyUSB0", std::process::id());
    let out = machine.run(&["--port", &port, "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.contains(&format!("locked by PID {} (", std::process::id())),
        "{err}"
    );
    assert!(err.contains(&file.display().to_string()), "{err}");
    // A PID no process has (above the kernel's pid_max).
    machine.lock("ttyUSB0", 4_194_305);
    let out = machine.run(&["--port", &port, "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stderr(&out).contains("stale lock file"), "{}", stderr(&out));
}

/// The REPL on `port`, its environment clean.
fn repl_on(machine: &Machine, port: &str) -> rexpect::session::PtySession {
    let home = tempdir();
    let mut command = Command::new(bin());
    command
        .args(["--port", port])
        .env("TMCLSH_TEST_SYSFS", &machine.root)
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("XDG_DATA_HOME", &home)
        .env("XDG_CONFIG_HOME", &home)
        .env("HOME", &home);
    spawn_command(command, Some(crate::util::EXPECT_MS)).unwrap()
}

#[test]
fn the_repl_waits_for_a_port_to_appear() {
    let sim = Sim::start(&["--pty"]);
    let machine = Machine::new();
    let late = machine.dev("ttyLATE");
    let mut p = repl_on(&machine, &late);
    p.exp_string(&format!("waiting for {late}")).unwrap();
    symlink(&sim.first, &late).unwrap();
    p.exp_string(&format!("{late} is there")).unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("max_positioning_speed = 1000000").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();

    // A usb: name waits for its adapter the same way.
    let mut p = repl_on(&machine, "usb:0403:6001");
    p.exp_string("waiting for usb:0403:6001").unwrap();
    machine.usb_serial("ttyUSB0", ("0403", "6001"), None, Path::new(&sim.first));
    p.exp_string("usb:0403:6001 is there").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn ctrl_c_gives_up_waiting_and_a_run_never_waits() {
    let machine = Machine::new();
    let missing = machine.dev("ttyNEVER");
    let mut p = repl_on(&machine, &missing);
    p.exp_string(&format!("waiting for {missing}")).unwrap();
    p.send_control('c').unwrap();
    p.exp_string("gave up waiting").unwrap();
    p.exp_eof().unwrap();
    match p.process().wait().unwrap() {
        rexpect::process::WaitStatus::Exited(_, code) => assert_eq!(code, 130),
        other => panic!("{other:?}"),
    }
    let out = machine.run(&["--port", &missing, "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 3, "{}", stderr(&out));
    assert!(!stdout(&out).contains("waiting"));
}

#[test]
fn probe_names_the_module_on_each_port_and_says_which_are_silent() {
    let six = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    let elsewhere = Sim::start(&["--pty", "--modules", "5"]);
    let machine = Machine::new();
    machine.usb_serial(
        "ttyUSB0",
        ("0403", "6001"),
        Some("A1"),
        Path::new(&six.first),
    );
    machine.usb_serial(
        "ttyUSB1",
        ("0403", "6001"),
        Some("B2"),
        Path::new(&elsewhere.first),
    );
    // A device file that is no serial port: it cannot be opened as one.
    let nowhere = machine.root.join("nowhere");
    std::fs::write(&nowhere, "").unwrap();
    machine.usb_serial("ttyUSB2", ("0403", "6001"), Some("C3"), &nowhere);
    let out = machine.run(&["ports", "--probe"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let answer = |name: &str| -> String {
        let prefix = format!("{}: ", machine.dev(name));
        text.lines()
            .find_map(|l| l.strip_prefix(&prefix))
            .unwrap_or_else(|| panic!("{name} not probed:\n{text}"))
            .to_string()
    };
    assert_eq!(answer("ttyUSB0"), "TMCM-6110 (6110V131), in binary mode");
    assert_eq!(answer("ttyUSB1"), "no module answered");
    assert!(answer("ttyUSB2").starts_with("not probed: "), "{text}");
    // Without --probe nothing is probed.
    let out = machine.run(&["ports"]);
    assert!(!stdout(&out).contains("probing"), "{}", stdout(&out));

    // A built-in port is probed only when named: what is wired to it may not expect bytes.
    let builtin = machine.dev("ttyS0");
    symlink(&six.first, &builtin).unwrap();
    std::fs::create_dir_all(machine.root.join("sys/devices/pnp0/ttyS0")).unwrap();
    symlink(
        machine.root.join("sys/bus/pnp"),
        machine.root.join("sys/devices/pnp0/ttyS0/subsystem"),
    )
    .unwrap();
    std::fs::create_dir_all(machine.root.join("sys/class/tty/ttyS0")).unwrap();
    symlink(
        machine.root.join("sys/devices/pnp0/ttyS0"),
        machine.root.join("sys/class/tty/ttyS0/device"),
    )
    .unwrap();
    let out = machine.run(&["ports", "--probe"]);
    assert!(
        !stdout(&out).contains(&format!("{builtin}: ")),
        "{}",
        stdout(&out)
    );
    let out = machine.run(&["ports", "--probe", &builtin]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(
        text.contains(&format!("{builtin}: TMCM-6110 (6110V131)")),
        "{text}"
    );
    assert!(
        !text.contains(&format!("{}: ", machine.dev("ttyUSB0"))),
        "{text}"
    );
}

#[test]
fn a_usb_name_is_looked_up_again_when_the_adapter_comes_back_under_another_name() {
    let mut sim = Sim::start(&["--pty"]);
    let machine = Machine::new();
    machine.usb_serial(
        "ttyUSB0",
        ("0403", "6001"),
        Some("A50285BI"),
        Path::new(&sim.first),
    );
    let mut p = repl_on(&machine, "usb:0403:6001");
    p.exp_string("A> ").unwrap();
    // Pulled out: its tty goes from the tree, then from the line.
    for gone in ["sys/class/tty/ttyUSB0", "sys/devices/usb1/ttyUSB0"] {
        std::fs::remove_dir_all(machine.root.join(gone)).unwrap();
    }
    std::fs::remove_file(machine.root.join("dev/ttyUSB0")).unwrap();
    assert!(sim.console("unplug 0.5").starts_with("ok unplugged"));
    p.exp_string("link lost").unwrap();
    let back = sim.line();
    let path = back.strip_prefix("pty ").expect("a new pty");
    // Plugged back in: the kernel names it ttyUSB1.
    machine.usb_serial(
        "ttyUSB1",
        ("0403", "6001"),
        Some("A50285BI"),
        Path::new(path),
    );
    p.exp_string("reconnected: serial usb:0403:6001 (").unwrap();
    p.exp_string("ttyUSB1) at 9600 baud").unwrap();
    p.send_line("GAP 4, 0").unwrap();
    p.exp_string("max_positioning_speed = 1000000").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn ports_marks_known_slcan_adapters_as_can() {
    let machine = Machine::new();
    let nowhere = machine.root.join("nowhere");
    std::fs::write(&nowhere, "").unwrap();
    machine.usb_serial("ttyACM0", ("16d0", "117e"), None, &nowhere);
    machine.usb_serial("ttyUSB0", ("0403", "6001"), None, &nowhere);
    let out = machine.run(&["ports"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    let line = |name: &str| {
        text.lines()
            .find(|l| l.starts_with(&machine.dev(name)))
            .unwrap_or_else(|| panic!("{name} not listed:\n{text}"))
            .to_string()
    };
    let can = line("ttyACM0");
    assert!(can.contains(" CAN "), "{can}");
    assert!(can.contains("CANable 2.0 (slcan firmware)"), "{can}");
    assert!(
        can.contains(&format!("--can slcan:{}", machine.dev("ttyACM0"))),
        "{can}"
    );
    assert!(line("ttyUSB0").contains(" USB "), "{text}");
}
