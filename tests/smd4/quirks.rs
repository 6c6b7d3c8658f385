//! The client against each quirk switch of the simulated SMD4: the reply line comes out as the
//! drive spelled it, values are read right whatever the spelling (a script checks them), and an
//! error code is decoded and exits 1 in every spelling.

use tmclsh::dialect::smd4::protocol::{ErrorCode, Smd4Spec};

use super::lines::{rounded_current, scientific};
use super::{Drive, Via, assert_exit, lines};

/// The lines every quirk run sends; the last one fails with −1 because the motor runs.
const LINES: [&str; 6] = [
    "SYS:FW",
    "MOTOR:VMAX,2000",
    "MOTOR:IR,0.5",
    "MOTOR:PACT,1000",
    "MOTOR:RUNV,+",
    "MOTOR:RES,16",
];

/// Reads every value back in a script: user/real pairs, a rounded current (expected in
/// args[0]), a position, the flags, and an error code as a value.
const CHECK: &str = r#"
let r = reply("MOTOR:VMAX,2000");
assert_eq(r.error, ());
assert_eq(r.values, [2000.0, 2000.0]);
assert_eq(parse_number(send("MOTOR:VMAX")[1]), 2000.0);
// Replies carry 4 or 5 decimals.
assert_near(reply("MOTOR:IR,0.5").values[0], parse_float(args[0]), 0.00005);
send("MOTOR:PACT,1000");
assert_eq(reply("MOTOR:PACT").values, [1000.0]);
assert(flags().standby, "standing still");
send("MOTOR:RUNV,+");
let e = reply("MOTOR:RES,16");
assert_eq(e.error, -1);
assert(!e.ok, "an error code is not ok");
send("MOTOR:STOP");
wait_standby(10000);
print("values read");
"#;

fn firmware() -> String {
    Smd4Spec::builtin()
        .commands
        .get("SYS:FW")
        .unwrap()
        .sim_value
        .clone()
        .unwrap()
}

fn rounded(amps: f64) -> f64 {
    rounded_current(amps)
}

/// One quirk: simulator switches, client flags, console setup, and the reply lines the quirk
/// spells differently from the default (index into [`LINES`], expected text).
struct Quirk<'a> {
    via: Via,
    sim: &'a [&'a str],
    client: &'a [&'a str],
    setup: &'a [&'a str],
    spelled: Vec<(usize, String)>,
    current: f64,
}

fn check(quirk: Quirk) {
    let mut drive = Drive::start(quirk.via, quirk.sim);
    for command in quirk.setup {
        drive.console(command);
    }
    let mut args: Vec<&str> = quirk.client.to_vec();
    for line in LINES {
        args.extend(["-c", line]);
    }
    let out = drive.run(&args);
    assert_exit(&out, 1);
    let got = lines(&out);
    assert_eq!(got.len(), LINES.len(), "{got:?}");
    for (index, text) in &quirk.spelled {
        assert_eq!(&got[*index], text, "reply to {}", LINES[*index]);
    }
    let stop = ErrorCode::StopMotorFirst;
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(&format!(
            "error {} ({}): {}",
            stop.code(),
            stop.name(),
            stop.meaning()
        )),
        "decoded in every spelling: {err}"
    );
    assert!(err.contains("with MOTOR:STOP"), "{err}");
    drive.console_until("motor", |m| m.contains("standby 1"));

    let dir = crate::util::tempdir();
    let script = dir.join("check.rhai");
    std::fs::write(&script, CHECK).unwrap();
    let current = quirk.current.to_string();
    let mut args: Vec<&str> = quirk.client.to_vec();
    args.extend(["--", current.as_str()]);
    let out = drive.script(&script, &args);
    assert_exit(&out, 0);
    assert_eq!(lines(&out), ["values read"]);
}

fn fw_line(prefix: &str) -> String {
    format!("{prefix}0x0888,0x0000,{}", firmware())
}

#[test]
fn flag_words_in_lower_case() {
    check(Quirk {
        via: Via::Pty,
        sim: &["--flag-case", "lower"],
        client: &[],
        setup: &["limit pos 1"],
        spelled: vec![(0, format!("0x088c,0x0000,{}", firmware()))],
        current: rounded(0.5),
    });
}

#[test]
fn five_float_decimals() {
    check(Quirk {
        via: Via::Tcp,
        sim: &["--float-decimals", "5"],
        client: &[],
        setup: &[],
        spelled: vec![(1, "0x0888,0x0000,2.00000E+03,2.00000E+03".into())],
        current: rounded(0.5),
    });
}

#[test]
fn floats_without_the_e() {
    check(Quirk {
        via: Via::Pty,
        sim: &["--float-missing-e"],
        client: &[],
        setup: &[],
        spelled: vec![
            (1, "0x0888,0x0000,2.0000+03,2.0000+03".into()),
            (
                2,
                format!(
                    "0x0888,0x0000,{}",
                    scientific(rounded(0.5)).replace('E', "")
                ),
            ),
        ],
        current: rounded(0.5),
    });
}

#[test]
fn errors_spelled_with_a_comma() {
    let stop = ErrorCode::StopMotorFirst;
    check(Quirk {
        via: Via::Tcp,
        sim: &["--error-spelling", "comma"],
        client: &[],
        setup: &[],
        spelled: vec![(5, format!("0x0808,0x0000,{},{}", stop.code(), stop.name()))],
        current: rounded(0.5),
    });
}

#[test]
fn errors_spelled_bare() {
    check(Quirk {
        via: Via::Pty,
        sim: &["--error-spelling", "bare"],
        client: &[],
        setup: &[],
        spelled: vec![(
            5,
            format!("0x0808,0x0000,{}", ErrorCode::StopMotorFirst.code()),
        )],
        current: rounded(0.5),
    });
}

#[test]
fn errors_spelled_with_parentheses_by_default() {
    let stop = ErrorCode::StopMotorFirst;
    check(Quirk {
        via: Via::Tcp,
        sim: &[],
        client: &[],
        setup: &[],
        spelled: vec![
            (0, fw_line("")),
            (1, "0x0888,0x0000,2.0000E+03,2.0000E+03".into()),
            (2, format!("0x0888,0x0000,{}", scientific(rounded(0.5)))),
            (3, "0x0888,0x0000,1000.00".into()),
            (4, "0x0808,0x0000".into()),
            (
                5,
                format!("0x0808,0x0000,{} ({})", stop.code(), stop.name()),
            ),
        ],
        current: rounded(0.5),
    });
}

#[test]
fn currents_echoed_unrounded() {
    check(Quirk {
        via: Via::Pty,
        sim: &["--no-current-rounding"],
        client: &[],
        setup: &[],
        spelled: vec![(2, "0x0888,0x0000,5.0000E-01".into())],
        current: 0.5,
    });
}

#[test]
fn positions_in_scientific_notation() {
    check(Quirk {
        via: Via::Tcp,
        sim: &["--scientific-positions"],
        client: &[],
        setup: &[],
        spelled: vec![(3, format!("0x0888,0x0000,{}", scientific(1000.0)))],
        current: rounded(0.5),
    });
}

#[test]
fn only_attached_prefixes_with_the_default_client() {
    check(Quirk {
        via: Via::Pty,
        sim: &["--prefix-only", "attached"],
        client: &["--address", "1"],
        setup: &[],
        spelled: vec![(0, fw_line("@1,"))],
        current: rounded(0.5),
    });
}

#[test]
fn only_comma_prefixes_with_prefix_comma() {
    check(Quirk {
        via: Via::Tcp,
        sim: &["--prefix-only", "comma"],
        client: &["--address", "1", "--prefix-comma"],
        setup: &[],
        spelled: vec![(0, fw_line("@1,"))],
        current: rounded(0.5),
    });
}

#[test]
fn replies_without_the_address_prefix() {
    check(Quirk {
        via: Via::Pty,
        sim: &["--no-reply-prefix"],
        client: &["--address", "1"],
        setup: &[],
        spelled: vec![(0, fw_line(""))],
        current: rounded(0.5),
    });
}

#[test]
fn a_prefix_form_the_drive_does_not_understand_is_a_packet_error() {
    let packet = ErrorCode::PacketError;
    for (via, only, client) in [
        (Via::Pty, "comma", &["--address", "1"][..]),
        (
            Via::Tcp,
            "attached",
            &["--address", "1", "--prefix-comma"][..],
        ),
    ] {
        let mut drive = Drive::start(via, &["--prefix-only", only]);
        let mut args = client.to_vec();
        args.extend(["-c", "SYS:FW"]);
        let out = drive.run(&args);
        assert_exit(&out, 1);
        assert_eq!(
            lines(&out),
            [format!(
                "0x0888,0x0000,{} ({})",
                packet.code(),
                packet.name()
            )]
        );
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(&packet.meaning()), "{err}");
        assert!(
            drive.console("flags").ends_with("addressing 0"),
            "a malformed packet does not switch to addressing mode"
        );
    }
}

#[test]
fn wait_time_reported_in_milliseconds() {
    let drive = Drive::start(Via::Pty, &["--tzw-reply-ms"]);
    let out = drive.run(&["-c", "MOTOR:TZW,0.5", "-c", "MOTOR:TZW"]);
    assert_exit(&out, 0);
    let ms = format!("0x0888,0x0000,{}", scientific(500.0));
    assert_eq!(lines(&out), [ms.clone(), ms]);
}

#[test]
fn real_values_on_a_frequency_grid() {
    let grid: f64 = 12e6 / 16_777_216.0 / 256.0;
    let real = (10.0 / grid).round() * grid;
    let drive = Drive::start(Via::Tcp, &["--real-value-grid", &grid.to_string()]);
    let out = drive.run(&["-c", "MOTOR:VSTOP,10"]);
    assert_exit(&out, 0);
    assert_eq!(
        lines(&out),
        [format!(
            "0x0888,0x0000,{},{}",
            scientific(10.0),
            scientific(real)
        )]
    );
    let script = crate::util::tempdir().join("real.rhai");
    std::fs::write(
        &script,
        "let r = reply(\"MOTOR:VSTOP\");\n\
         assert_eq(r.values[0], 10.0);\n\
         assert_near(r.values[1], parse_float(args[0]), 0.00005);\n\
         assert(r.values[1] != r.values[0], \"the real value differs\");\n",
    )
    .unwrap();
    let real = real.to_string();
    assert_exit(&drive.script(&script, &["--", &real]), 0);
}
