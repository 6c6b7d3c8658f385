//! Serial ports: `tmclsh ports` shows what USB adapters say about themselves, `--port
//! usb:VID:PID[:SERIAL]` finds the adapter whatever its device file, and the REPL waits for a port
//! that is not there yet. Adapters cannot be plugged in on demand, so a made-up sysfs tree (read
//! by debug builds from TMCLSH_TEST_SYSFS) stands for them, its device files symlinks to
//! simulators' pseudo-terminals.

#![cfg(target_os = "linux")]

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
            "FT232R",
            "USB",
            "UART",
            "(FTDI)"
        ]
    );
    assert_eq!(row("ttyUSB1")[1..4], ["USB", "2e8a:000a", "-"]);
    assert_eq!(row("ttyS0")[1..], ["other", "-", "-"]);
    assert!(
        !text.contains("tty0 "),
        "a virtual terminal is no serial port:\n{text}"
    );
    assert!(text.contains("--port usb:0403:6001:A50285BI"), "{text}");
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
