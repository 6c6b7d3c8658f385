//! Multi-line replies (SYS:FLAGSV, COMS:NET:IPCONF) have no end marker: the client collects
//! lines until the line goes quiet. Over the pty and TCP, with the default gap and with a custom
//! `--quiet-gap` on a paced line where the lines dribble in; the next command still gets its own
//! reply, with nothing left over.

use tmclsh::dialect::smd4::protocol::Smd4Spec;

use super::{BOTH, Drive, assert_exit, lines};

/// SYS:FLAGSV of a drive with these flag words, as the listing in the data describes it.
fn flagsv(sflags: u16, eflags: u16) -> Vec<String> {
    let spec = Smd4Spec::builtin();
    let mut expected = vec![format!("{sflags:#06X},{eflags:#06X},").replace("0X", "0x")];
    expected.push("-------Status flags------".into());
    expected.extend(spec.sflags.listing(sflags));
    expected.push("-------Error flags-------".into());
    expected.extend(spec.eflags.listing(eflags));
    expected
}

/// COMS:NET:IPCONF with DHCP on: the simulated lease.
fn ipconf(sflags: u16) -> Vec<String> {
    let sim = &Smd4Spec::builtin().sim;
    vec![
        format!("{sflags:#06X},0x0000,").replace("0X", "0x"),
        "Ethernet interface:".into(),
        format!("IPv4 Address. . . . . . . . . . . :{}", sim.dhcp_ip),
        format!("Subnet Mask . . . . . . . . . . .:{}", sim.dhcp_netmask),
        format!("Default Gateway . . . . . . . :{}", sim.dhcp_gateway),
        "DHCP State. . . . . . . . . . . . :Enabled".into(),
    ]
}

fn firmware_line(sflags: u16) -> String {
    let fw = Smd4Spec::builtin().commands.get("SYS:FW").unwrap();
    format!("{sflags:#06X},0x0000,{}", fw.sim_value.clone().unwrap()).replace("0X", "0x")
}

#[test]
fn multi_line_replies_end_when_the_line_goes_quiet() {
    for via in BOTH {
        // The default gap with the reply written at once; a custom one on a line paced at 19200
        // baud, where the lines dribble in. (A gap shorter than a stall of the simulator would
        // cut a reply short: that is the documented limit of ending replies by silence.)
        for (gap, sim) in [(None, &[][..]), (Some("500"), &["--baud", "19200"][..])] {
            let mut drive = Drive::start(via, sim);
            drive.console("limit neg 1");
            let mut args = vec![];
            if let Some(ms) = gap {
                args.extend(["--quiet-gap", ms]);
            }
            args.extend(["-c", "SYS:FLAGSV", "-c", "COMS:NET:IPCONF", "-c", "SYS:FW"]);
            let out = drive.run(&args);
            assert_exit(&out, 0);
            // Limit negative (bit 1) on top of external enable, standby and boost.
            let sflags = 0x088A;
            let mut expected = flagsv(sflags, 0);
            expected.extend(ipconf(sflags));
            expected.push(firmware_line(sflags));
            assert_eq!(lines(&out), expected, "{via:?}, gap {gap:?}");
            assert!(
                out.stderr.is_empty(),
                "nothing left over or ignored: {}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
    }
}

#[test]
fn a_multi_line_command_that_fails_ends_at_its_first_line() {
    let drive = Drive::start(super::Via::Pty, &[]);
    let out = drive.run(&["--no-validate", "-c", "SYS:FLAGSV,1", "-c", "SYS:FW"]);
    assert_exit(&out, 1);
    let code = tmclsh::dialect::smd4::protocol::ErrorCode::ArgumentCount;
    assert_eq!(
        lines(&out),
        [format!("0x0888,0x0000,{} ({})", code.code(), code.name())]
    );
}
