//! `-c` lines and piped stdin: the reply line as received on stdout, and the exit codes — 0,
//! 1 for an error code (decoded on stderr), 2 for a line refused before sending (and nothing
//! sent), 3 for a drive that stays silent.

use tmclsh::dialect::smd4::protocol::{ErrorCode, Smd4Spec};

use super::{BOTH, Drive, Via, assert_exit, lines};

/// What SYS:FW answers on the simulated drive (its data value).
fn firmware() -> String {
    let spec = Smd4Spec::builtin();
    let fw = spec.commands.get("SYS:FW").unwrap();
    fw.sim_value
        .clone()
        .expect("the simulated firmware version is data")
}

/// A current as the drive rounds it: k · max/levels A (31 steps of 1.044 A).
pub fn rounded_current(amps: f64) -> f64 {
    let spec = Smd4Spec::builtin().commands.get("MOTOR:IR").unwrap();
    let arg = spec.arg.as_ref().unwrap();
    let step = arg.max.unwrap() / f64::from(arg.levels.unwrap());
    (amps / step).round() * step
}

/// A float as the drive writes it by default: 4 decimals, a signed two-digit exponent.
pub fn scientific(x: f64) -> String {
    let text = format!("{x:.4E}");
    let (mantissa, exponent) = text.split_once('E').unwrap();
    let exponent: i32 = exponent.parse().unwrap();
    format!(
        "{mantissa}E{}{:02}",
        if exponent < 0 { '-' } else { '+' },
        exponent.abs()
    )
}

#[test]
fn c_lines_print_each_reply_as_received() {
    for via in BOTH {
        let drive = Drive::start(via, &[]);
        let out = drive.run(&["-c", "SYS:FW", "-c", "MOTOR:VMAX,2000", "-c", "motor:vmax"]);
        assert_exit(&out, 0);
        assert_eq!(
            lines(&out),
            [
                format!("0x0888,0x0000,{}", firmware()),
                "0x0888,0x0000,2.0000E+03,2.0000E+03".to_string(),
                "0x0888,0x0000,2.0000E+03,2.0000E+03".to_string(),
            ],
            "{via:?}"
        );
        assert!(
            out.stderr.is_empty(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

#[test]
fn stdin_lines_print_each_reply_and_skip_comments() {
    for via in BOTH {
        let drive = Drive::start(via, &[]);
        let out = drive.run_with_stdin(&[], "# currents\nMOTOR:IR,0.5\n\nMOTOR:IA\nSYS:FW\n");
        assert_exit(&out, 0);
        let ir = scientific(rounded_current(0.5));
        assert_eq!(
            lines(&out),
            [
                format!("0x0888,0x0000,{ir}"),
                // IA follows IR upwards only; IR went down, IA stays at its default.
                format!("0x0888,0x0000,{}", scientific(rounded_current(1.044))),
                format!("0x0888,0x0000,{}", firmware()),
            ],
            "{via:?}"
        );
    }
}

#[test]
fn an_error_code_exits_1_with_the_decoded_error_on_stderr() {
    for via in BOTH {
        let mut drive = Drive::start(via, &[]);
        // Sent on purpose without validation, so the drive itself answers −103.
        let out = drive.run(&[
            "--no-validate",
            "-c",
            "SYS:FW",
            "-c",
            "MOTOR:NOPE",
            "-c",
            "SYS:FW",
        ]);
        assert_exit(&out, 1);
        let code = ErrorCode::InvalidMnemonic;
        assert_eq!(
            lines(&out),
            [
                format!("0x0888,0x0000,{}", firmware()),
                format!("0x0888,0x0000,{} ({})", code.code(), code.name()),
            ],
            "the run stops at the failing line"
        );
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("line 2 (MOTOR:NOPE)"), "{err}");
        assert!(err.contains(&code.meaning()), "{err}");

        // An action the drive fails: STORE on worn-out flash (−5).
        assert_eq!(drive.console("flash-failure on"), "STORE fails from now on");
        let out = drive.run(&["-c", "STORE"]);
        assert_exit(&out, 1);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("error -5"), "{err}");
        assert!(err.contains(&ErrorCode::ActionFailed.meaning()), "{err}");
        drive.console("flash-failure off");
        assert_exit(&drive.run(&["-c", "STORE"]), 0);
    }
}

#[test]
fn refused_lines_exit_2_name_the_problem_and_send_nothing() {
    let refused = [
        ("MOTOR:VMXA", "did you mean MOTOR:VMAX?"),
        ("LIMIT:POL", "cannot be read"),
        ("SYS:FW,1", "read-only"),
        ("MOTOR:VMAX,1,2", "takes one argument, got 2"),
        ("MOTOR:VMAX,fast", "expected FLOAT"),
        ("MOTOR:IR,5", "out of range"),
        ("MOTOR:RES,7", "use one of 8, 16, 32, 64, 128, 256"),
        ("MOTOR:RUNV,x", "use one of +, -"),
        ("@300SYS:FW", "address 300 is out of range"),
    ];
    for via in BOTH {
        let drive = Drive::logged(via, &[]);
        let log = crate::util::tempdir().join("transcript.log");
        for (line, problem) in refused {
            let out = drive.run(&["--log", log.to_str().unwrap(), "-c", "SYS:FW", "-c", line]);
            assert_exit(&out, 2);
            assert_eq!(lines(&out).len(), 1, "only SYS:FW was answered");
            let err = String::from_utf8_lossy(&out.stderr);
            assert!(err.contains(&format!("line 2 ({line})")), "{err}");
            assert!(err.contains(problem), "{line}: {err}");
        }
        let transcript = std::fs::read_to_string(&log).unwrap();
        let sent: Vec<&str> = transcript.lines().filter(|l| l.contains(" tx ")).collect();
        assert_eq!(sent.len(), refused.len(), "{transcript}");
        assert!(
            sent.iter().all(|l| l.contains("tx \"SYS:FW\\r\\n\"")),
            "{transcript}"
        );
        assert_eq!(
            drive.received(),
            vec!["SYS:FW".to_string(); refused.len()],
            "{via:?}: the drive saw only the good lines"
        );
    }
}

#[test]
fn a_silent_drive_exits_3_after_the_timeout() {
    for via in BOTH {
        let drive = Drive::logged(via, &["--silent-after", "0"]);
        let out = drive.run(&["--timeout", "200", "-c", "SYS:FW"]);
        assert_exit(&out, 3);
        assert!(lines(&out).is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("no reply from the drive within 200 ms"),
            "{err}"
        );
        let received = drive.received();
        assert_eq!(
            received.first().map(String::as_str),
            Some("SYS:FW"),
            "{via:?}: the request did go out"
        );
        // Then the TMCL probes that tell a TMCL module on the line, ended by a line end, and
        // nothing else.
        assert_eq!(received.len(), 2, "{via:?}: {received:?}");
        assert!(received[1].ends_with("AGGP 67, 0\\r"), "{received:?}");
    }
}

#[test]
fn flags_helper_prints_the_table_with_the_drive_s_flags() {
    let mut drive = Drive::start(Via::Tcp, &[]);
    drive.console("limit neg 1");
    drive.console("fault TempOver");
    let out = drive.run(&["-c", ":flags"]);
    assert_exit(&out, 0);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    let spec = Smd4Spec::builtin();
    assert!(text.starts_with("SFLAGS 0x088A\n"), "{text}");
    assert!(text.contains("\nEFLAGS 0x0004 "), "{text}");
    let marked: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with("[X]"))
        .collect();
    let named = |table: &tmclsh::dialect::smd4::protocol::FlagTable, bit: u8| {
        table
            .bits()
            .iter()
            .find(|b| b.bit == bit)
            .unwrap()
            .name
            .clone()
    };
    let expected = [
        named(&spec.sflags, 1),
        named(&spec.sflags, 3),
        named(&spec.sflags, 7),
        named(&spec.sflags, 11),
        named(&spec.eflags, 2),
    ];
    assert_eq!(marked.len(), expected.len(), "{text}");
    for (line, name) in marked.iter().zip(&expected) {
        assert!(line.ends_with(name.as_str()), "{line} / {name}");
    }
    assert!(text.contains("any set bit disables the motor"));
}
