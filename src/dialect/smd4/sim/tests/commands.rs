//! Every command of the table, the error codes, couplings, gating, latching, modes and bake.

use super::Bench;
use crate::dialect::smd4::protocol::{Eflags, ReplyShape, Sflags, Smd4Spec, Value};

#[test]
fn every_command_of_the_table_answers() {
    for spec in Smd4Spec::builtin().commands.iter() {
        let name = &spec.mnemonic;
        if spec.readable {
            let reply = Bench::new().reply(name);
            assert!(reply.is_ok(), "{name} -> {}", reply.raw);
            match &spec.reply {
                ReplyShape::UserReal => assert!(reply.user_real().is_some(), "{name}"),
                ReplyShape::MultiLine => assert!(!reply.lines.is_empty(), "{name}"),
                ReplyShape::Value | ReplyShape::Named | ReplyShape::Literal(_) => {
                    assert_eq!(reply.data.len(), 1, "{name} -> {}", reply.raw)
                }
                ReplyShape::None => {}
            }
        }
        if let (true, Some(arg)) = (spec.writable, &spec.arg) {
            let value = spec
                .default
                .clone()
                .or_else(|| arg.choices.first().map(|c| c.value.clone()))
                .or_else(|| arg.min.map(|m| m.to_string()))
                .unwrap_or_else(|| "1".into());
            let line = format!("{name},{value}");
            let reply = Bench::new().reply(&line);
            assert!(reply.is_ok(), "{line} -> {}", reply.raw);
        }
        if !spec.readable && spec.arg.is_none() {
            let mut bench = Bench::new();
            let text = bench.send(name);
            match name.as_str() {
                "SYS:PROG" | "SYS:RESET" => assert_eq!(text, "", "{name} sends no reply"),
                // Bake only runs in bake mode (mode 3); the drive starts in Remote (1).
                "BAKE:RUN" => assert_eq!(bench.error(name), -6),
                _ => assert!(bench.reply(name).is_ok(), "{name} -> {text}"),
            }
        }
    }
}

#[test]
fn error_codes_for_bad_requests() {
    let mut b = Bench::new();
    assert_eq!(b.error("MOTOR:NOPE"), -103);
    assert_eq!(b.error("AMAX"), -103);
    assert_eq!(b.error("MOTOR:RUNV"), -3);
    assert_eq!(b.error("LIMIT:POL"), -3);
    assert_eq!(b.error("MOTOR:VMAX,1,2"), -102);
    assert_eq!(b.error("SYS:CLR,1"), -102);
    assert_eq!(b.error("MOTOR:T,5"), -102);
    assert_eq!(b.error("MOTOR:VMAX,fast"), -101);
    assert_eq!(b.error("MOTOR:RUNA,1.5"), -101);
    assert_eq!(b.error("MOTOR:VMAX,20000"), -2);
    assert_eq!(b.error("MOTOR:RES,100"), -2);
    assert_eq!(b.error("MOTOR:RUNV,x"), -2);
    // The document's own VSTART,0 example is below the documented minimum.
    assert_eq!(b.error("MOTOR:VSTART,0"), -2);
    for malformed in ["", "1ABC", "@", "MOTOR:RUNV +", "SYS:FW\u{7f}"] {
        assert_eq!(
            b.send(malformed),
            "0x0888,0x0000,-104 (Packet error)",
            "{malformed:?}"
        );
    }
    let long = "X".repeat(2000);
    assert!(b.send(&long).ends_with("-104 (Packet error)"));
    assert_eq!(
        b.data("SYS:FW"),
        ["24044.12"],
        "still answering after garbage"
    );
}

#[test]
fn currents_round_to_31_steps_and_couple() {
    let mut b = Bench::new();
    let level = |k: f64| k * 1.044 / 31.0;
    // 1 A is not a level: the nearest is 30 * 1.044 / 31 = 1.0103 A (the example echoes 1.0000).
    assert_eq!(b.data("MOTOR:IR,1"), ["1.0103E+00"]);
    assert!((b.number("MOTOR:IR") - level(30.0)).abs() < 1e-4);
    // IA below IR is accepted and leaves IR alone.
    b.send("MOTOR:IA,0.5");
    assert!((b.number("MOTOR:IA") - level(15.0)).abs() < 1e-4);
    assert!((b.number("MOTOR:IR") - level(30.0)).abs() < 1e-4);
    // IR set above IA raises IA to IR.
    b.send("MOTOR:IA,1.044");
    b.send("MOTOR:IR,0.5");
    assert!(
        (b.number("MOTOR:IA") - 1.044).abs() < 1e-4,
        "IA stays when IR is below it"
    );
    b.send("MOTOR:IA,0.2");
    b.send("MOTOR:IR,0.8");
    assert!((b.number("MOTOR:IR") - level(24.0)).abs() < 1e-4);
    assert!(
        (b.number("MOTOR:IA") - level(24.0)).abs() < 1e-4,
        "IA raised to IR"
    );
    b.send("MOTOR:IH,0.1");
    assert!((b.number("MOTOR:IH") - level(3.0)).abs() < 1e-4);
    b.send("MOTOR:IH,0");
    assert_eq!(b.number("MOTOR:IH"), 0.0);
}

#[test]
fn start_and_stop_frequencies_drag_each_other() {
    let mut b = Bench::new();
    assert_eq!(
        b.reply("MOTOR:VSTART,300").user_real(),
        Some((300.0, 300.0))
    );
    assert_eq!(
        b.reply("MOTOR:VSTOP").user_real(),
        Some((300.0, 300.0)),
        "VSTOP raised"
    );
    b.send("MOTOR:VSTOP,50");
    assert_eq!(
        b.reply("MOTOR:VSTART").user_real(),
        Some((50.0, 50.0)),
        "VSTART lowered"
    );
    // VMAX is never adjusted, nor adjusts them.
    b.send("MOTOR:VSTART,600");
    b.send("MOTOR:VMAX,500");
    assert_eq!(b.reply("MOTOR:VMAX").user_real(), Some((500.0, 500.0)));
    assert_eq!(b.reply("MOTOR:VSTART").user_real(), Some((600.0, 600.0)));
}

#[test]
fn standby_is_required_for_res_mode_jsmode_pact_prel() {
    let mut b = Bench::new();
    b.send("MOTOR:RUNV,+");
    b.at(0.5);
    assert!(!b.standby());
    for line in [
        "MOTOR:RES,128",
        "SYS:MODE,0",
        "SYS:JSMODE,1",
        "MOTOR:PACT,0",
        "MOTOR:PREL,0",
    ] {
        assert_eq!(b.error(line), -1, "{line}");
    }
    assert_eq!(
        b.data("MOTOR:RES"),
        ["256"],
        "value unchanged, reads allowed"
    );
    assert_eq!(b.data("SYS:MODE"), ["1 (Remote)"]);
    b.send("MOTOR:ESTOP");
    b.send("SYS:CLR");
    assert!(b.standby());
    assert_eq!(b.data("MOTOR:RES,128"), ["128"]);
    assert_eq!(b.data("SYS:MODE,0"), ["0 (Step/direction)"]);
    assert_eq!(b.data("SYS:JSMODE,1"), ["1"]);
    assert_eq!(b.data("MOTOR:PACT,7"), ["7.00"]);
    assert_eq!(b.data("MOTOR:PREL,3"), ["3.00"]);
}

#[test]
fn estop_latches_its_flag_until_clr_and_refuses_motion() {
    let mut b = Bench::new();
    b.send("MOTOR:RUNV,+");
    b.at(1.0);
    let reply = b.reply("MOTOR:ESTOP");
    assert!(reply.eflags.is_set(Eflags::EMERGENCY_STOP));
    assert!(reply.sflags.standby());
    let position = b.number("MOTOR:PACT");
    b.at(5.0);
    assert_eq!(b.number("MOTOR:PACT"), position, "halted where it was");
    assert!(
        b.sim.eflags().is_set(Eflags::EMERGENCY_STOP),
        "still latched later"
    );
    for line in [
        "MOTOR:RUNV,+",
        "MOTOR:RUNA,10",
        "MOTOR:RUNR,10",
        "MOTOR:RUNH,-",
    ] {
        assert_eq!(b.error(line), -7, "{line}");
    }
    assert_eq!(b.reply("SYS:CLR").eflags.0, 0);
    assert!(b.reply("MOTOR:RUNV,+").is_ok());
}

#[test]
fn external_enable_and_faults_disable_the_motor() {
    let mut b = Bench::new();
    assert!(b.reply("SYS:FW").sflags.is_set(Sflags::EXTERNAL_ENABLE));
    b.send("SYS:EXTEN,1");
    b.send("MOTOR:RUNV,+");
    b.at(1.0);
    b.sim.set_external_enable(b.now, false);
    assert!(b.sim.eflags().is_set(Eflags::EXTERNAL_DISABLE));
    assert!(b.standby(), "disabling stops the motor at once");
    assert_eq!(b.error("MOTOR:RUNV,+"), -7);
    assert!(
        b.reply("SYS:CLR").eflags.is_set(Eflags::EXTERNAL_DISABLE),
        "cause persists"
    );
    b.sim.set_external_enable(b.now, true);
    assert_eq!(b.reply("SYS:CLR").eflags.0, 0);
    // With EXTEN = 0 the input is ignored.
    b.send("SYS:EXTEN,0");
    b.sim.set_external_enable(b.now, false);
    assert_eq!(b.sim.eflags().0, 0);
    b.send("MOTOR:RUNV,-");
    b.at(2.0);
    b.sim.inject_fault(b.now, Eflags::TEMP_OPEN);
    assert!(b.standby());
    assert_eq!(b.reply("SYS:FW").eflags.0, 0x0002);
    assert_eq!(b.error("MOTOR:RUNV,-"), -7);
}

#[test]
fn modes_and_bake() {
    let mut b = Bench::new();
    b.send("SYS:MODE,0");
    assert_eq!(b.error("MOTOR:RUNV,+"), -6, "motion needs remote mode");
    assert_eq!(b.error("BAKE:RUN"), -6);
    b.send("SYS:MODE,4");
    assert_eq!(b.error("MOTOR:RUNV,+"), -6);
    b.send("SYS:MODE,3");
    b.at(10.0);
    let reply = b.reply("BAKE:RUN");
    assert!(reply.sflags.is_set(Sflags::BAKING));
    b.at(10.0 + 3725.0);
    assert_eq!(
        b.reply("BAKE:ELAPSED").data[0].value,
        Value::Hms {
            hours: 1,
            minutes: 2,
            seconds: 5
        }
    );
    assert!(
        !b.reply("MOTOR:STOP").sflags.is_set(Sflags::BAKING),
        "stop ends the bake"
    );
    b.at(5000.0);
    assert_eq!(b.data("BAKE:ELAPSED"), ["1:02:05"], "elapsed time kept");
    b.send("BAKE:RUN");
    b.send("SYS:MODE,1");
    assert!(
        !b.reply("SYS:FW").sflags.is_set(Sflags::BAKING),
        "leaving bake mode ends it"
    );
}

#[test]
fn network_settings_follow_dhcp() {
    let mut b = Bench::new();
    assert_eq!(b.data("COMS:NET:IP"), ["10.0.97.70"]);
    // The document's example: with DHCP on, setting the gateway returns the assigned one.
    assert_eq!(b.data("COMS:NET:GATEWAY,192.168.1.1"), ["10.0.96.1"]);
    let ipconf = b.reply("COMS:NET:IPCONF");
    assert!(
        ipconf.lines.iter().any(|l| l.ends_with(":10.0.97.70")),
        "{:?}",
        ipconf.lines
    );
    assert!(ipconf.lines.last().unwrap().ends_with(":Enabled"));
    b.send("COMS:NET:DHCP,0");
    assert_eq!(
        b.data("COMS:NET:GATEWAY"),
        ["192.168.1.1"],
        "the value set is kept"
    );
    assert_eq!(b.data("COMS:NET:IP"), ["192.168.0.100"]);
    let ipconf = b.reply("COMS:NET:IPCONF");
    assert!(
        ipconf.lines[3].ends_with(":192.168.1.1"),
        "{:?}",
        ipconf.lines
    );
    assert!(ipconf.lines[4].ends_with(":Disabled"));
}

#[test]
fn flag_listing_is_multi_line_and_matches_the_words() {
    let mut b = Bench::new();
    b.send("SYS:IDENT,1");
    let reply = b.reply("SYS:FLAGSV");
    assert_eq!(reply.lines.len(), 34);
    assert_eq!(reply.lines[0], "-------Status flags------");
    assert_eq!(reply.lines[1 + 4], "[X]Ident");
    assert_eq!(reply.lines[1 + 7], "[X]Standby");
    assert_eq!(reply.lines[1 + 9], "[ ]TargetVelocityReached");
    assert_eq!(reply.lines[17], "-------Error flags-------");
    assert!(reply.sflags.is_set(Sflags::IDENT));
    assert_eq!(b.data("SYS:FLAGS"), ["1"], "as the document's example");
}

#[test]
fn queries_resets_and_programming_mode() {
    let mut b = Bench::new();
    assert_eq!(b.data("SYS:UUID"), ["f4562fb1-d002-11ee-b3e5-44b7d0c71675"]);
    assert_eq!(b.data("COMS:NET:MAC"), ["44:b7:d0:c7:16:75"]);
    assert_eq!(b.data("MOTOR:T"), ["25"]);
    assert_eq!(b.data("SYS:STORE"), Vec::<String>::new(), "alias of STORE");
    b.at(10.0);
    assert_eq!(b.data("SYS:UPTIME"), ["10000"]);
    b.send("MOTOR:VMAX,2000");
    b.send("MOTOR:RUNR,100");
    b.at(20.0);
    assert_eq!(b.send("SYS:RESET"), "");
    assert_eq!(b.data("SYS:UPTIME"), ["0"], "restarted");
    assert_eq!(
        b.reply("MOTOR:VMAX").user_real(),
        Some((1000.0, 1000.0)),
        "unsaved value lost"
    );
    assert_eq!(b.data("MOTOR:PACT"), ["0.00"]);
    assert_eq!(b.send("SYS:PROG"), "");
    assert_eq!(b.send("SYS:FW"), "", "programming mode answers nothing");
    b.sim.power_cycle(b.now);
    assert_eq!(b.data("SYS:FW"), ["24044.12"]);
}

#[test]
fn joystick_and_limit_polarity() {
    let mut b = Bench::new();
    b.sim.set_joystick(b.now, true);
    let reply = b.reply("SYS:MODE");
    assert!(reply.sflags.is_set(Sflags::JOYSTICK));
    assert_eq!(
        reply.data_strings(),
        ["2 (Joystick)"],
        "AUTOJS switches to joystick mode"
    );
    b.sim.set_joystick(b.now, false);
    b.send("SYS:MODE,1");
    b.send("SYS:AUTOJS,0");
    b.sim.set_joystick(b.now, true);
    assert_eq!(b.data("SYS:MODE"), ["1 (Remote)"]);
    // LIMIT:POL sets both polarities; an active-low input that is low is active.
    assert_eq!(b.data("LIMIT:POL,1"), ["1"]);
    assert_eq!(b.data("LIMIT:POL+"), ["1"]);
    assert_eq!(b.data("LIMIT:POL-"), ["1"]);
    let flags = b.reply("SYS:FW").sflags;
    assert!(flags.is_set(Sflags::LIMIT_POSITIVE) && flags.is_set(Sflags::LIMIT_NEGATIVE));
    b.sim
        .set_limit_input(b.now, super::super::Limit::Positive, true);
    let flags = b.reply("SYS:FW").sflags;
    assert!(!flags.is_set(Sflags::LIMIT_POSITIVE) && flags.is_set(Sflags::LIMIT_NEGATIVE));
}
