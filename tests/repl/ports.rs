//! The I/O ports in the REPL, from the profile's port map: `:help io`, the hint of a typed port,
//! Tab after GIO/SIO, and a GIO reply under the port's name — on the TMCM-142 and on a module
//! with another map.

use super::{repl, type_in};

#[test]
fn help_io_lists_the_ports_and_gio_shows_them_while_typing_and_in_the_reply() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    p.send_line(":help io").unwrap();
    p.exp_string("I/O ports of the TMCM-142").unwrap();
    p.exp_string("0/7       *  IN7      input       11  digital input, opto-isolated")
        .unwrap();
    p.exp_string("2/2       *  OUT_2    output      22  user output")
        .unwrap();
    p.exp_string("does not confirm the row").unwrap();
    p.exp_string("A> ").unwrap();
    // The hint names the port once the bank is typed; Enter sends it, and the reply is named.
    type_in(&mut p, "GIO 7,0");
    p.exp_string("IN7, digital input, opto-isolated, active low")
        .unwrap();
    type_in(&mut p, "\r");
    p.exp_regex("IN7 = [01]\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    // An analog input reads the ADC, under its own name.
    p.send_line("GIO 0, 1").unwrap();
    p.exp_regex("IN0_A/D = [0-9]+\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn tab_after_gio_offers_the_ports_and_an_unknown_port_s_hint_is_why() {
    let (mut p, _) = repl(&[]);
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "GIO \t");
    p.exp_string("7, 0 (IN7)").unwrap();
    p.exp_string("2, 2 (OUT_2)").unwrap();
    type_in(&mut p, "6, 0\r");
    p.exp_regex("IN6 = [01]\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    // One port of one bank: Tab completes it with its bank, and Enter sends it.
    type_in(&mut p, "GIO 8\t");
    p.exp_string("IN8, digital input").unwrap();
    type_in(&mut p, "\r");
    p.exp_regex("IN8 = [01]\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    // SIO offers the outputs only: port 1 is OUT_1 of bank 2.
    type_in(&mut p, "SIO 1\t");
    p.exp_string("OUT_1, user output, pin 9").unwrap();
    type_in(&mut p, "1\r");
    p.exp_string("OUT_1 set to 1\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line("GIO 1, 2").unwrap();
    p.exp_string("OUT_1 = 1\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    // No bank has port 9: the hint says so before Enter, and Enter refuses it.
    type_in(&mut p, "GIO 9");
    p.exp_string("has no I/O port 9 in any bank").unwrap();
    type_in(&mut p, ", 0\r");
    p.exp_string("error: the TMCM-142 has no I/O port 9 in any bank")
        .unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn another_module_s_ports_come_from_its_own_profile() {
    let (mut p, _) = repl(&["--profile", "tmcm-1141"]);
    p.exp_string("A> ").unwrap();
    p.send_line(":help ports").unwrap();
    p.exp_string("I/O ports of the TMCM-1141").unwrap();
    p.exp_string("1/0       *  ADC0  input      analog input, 0..4095")
        .unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line(":help SIO").unwrap();
    p.exp_string("Outputs on this TMCM-1141: bank 2 ports 0, 1 (OUT0, OUT1, digital output)")
        .unwrap();
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "GIO 4,");
    p.exp_string("IN3, digital input").unwrap();
    type_in(&mut p, "0\r");
    p.exp_regex("IN3 = [01]\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    type_in(&mut p, "GIO 0, \t");
    p.exp_string("1 (ADC0)").unwrap();
    p.exp_string("2 (OUT0)").unwrap();
    type_in(&mut p, "1\r");
    p.exp_regex("ADC0 = [0-9]+\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn a_profile_without_a_port_map_says_so() {
    let (mut p, _) = repl(&["--profile", "generic"]);
    p.exp_string("A> ").unwrap();
    p.send_line(":help io").unwrap();
    p.exp_string("The generic profile has no port map").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line(":help GIO").unwrap();
    p.exp_string("usable in").unwrap();
    p.exp_string("has no port map").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn on_a_bus_each_module_s_ports_are_its_own() {
    let sim = crate::sim::Sim::start(&["--pty", "--modules", "1:tmcm-142,2:tmcm-6110"]);
    let mut p = crate::util::terminal(&["--port", &sim.first], &[]);
    p.exp_string("A> ").unwrap();
    // A line addressed to module 2 is read back under module 2's port names.
    p.send_line("BGIO 8, 1").unwrap();
    p.exp_regex("VIN = [0-9]+\r\n").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line(":target 2").unwrap();
    p.exp_string("TMCM-6110").unwrap();
    p.exp_string("B> ").unwrap();
    p.send_line(":help io").unwrap();
    p.exp_string("I/O ports of the TMCM-6110").unwrap();
    p.exp_string("1/8       *  VIN   input      analog input, 0..4095")
        .unwrap();
    p.exp_string("B> ").unwrap();
    type_in(&mut p, "GIO 8, 1");
    p.exp_string("VIN, analog input, 0..4095").unwrap();
    type_in(&mut p, "\r");
    p.exp_regex("VIN = [0-9]+\r\n").unwrap();
    p.exp_string("B> ").unwrap();
    p.send_line(":target 1").unwrap();
    p.exp_string("TMCM-142").unwrap();
    p.exp_string("A> ").unwrap();
    p.send_line(":help GIO").unwrap();
    p.exp_string("Ports on this TMCM-142: bank 0 ports 3..8")
        .unwrap();
    p.exp_string("A> ").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}
