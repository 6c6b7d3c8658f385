//! ASCII mode over a real pty: entered with 139, in each echo mode of GP 67.

use tmclsh::dialect::tmcl::protocol::Status;

use super::{Port, Sim};

fn enter_ascii(port: &mut Port, echo_bits: i32) {
    assert_eq!(port.transact(1, 9, 67, 0, echo_bits).status, Status::Ok);
    assert_eq!(port.transact(1, 139, 0, 0, 0).status, Status::Ok);
}

#[test]
fn character_echo_over_the_pty() {
    let sim = Sim::start(&["--pty"]);
    let mut port = sim.pty();
    enter_ascii(&mut port, 0);
    port.send(b"A");
    assert_eq!(port.read_n(1), b"A", "echoed as typed");
    port.send(b"GAX\x08P 4, 0\r");
    let got = port.read_until(|b| b.ends_with(b"1000000\r"));
    assert_eq!(got, b"GAX\x08 \x08P 4, 0\rBA 100 1000000\r");
}

#[test]
fn line_echo_over_the_pty() {
    let sim = Sim::start(&["--pty"]);
    let mut port = sim.pty();
    enter_ascii(&mut port, 0x10);
    port.send(b"AGAP 4, 0\r");
    let got = port.read_until(|b| b.ends_with(b"1000000\r"));
    assert_eq!(got, b"AGAP 4, 0\rBA 100 1000000\r");
}

#[test]
fn no_echo_and_bin_over_the_pty() {
    let sim = Sim::start(&["--pty"]);
    let mut port = sim.pty();
    enter_ascii(&mut port, 0x20);
    port.send(b"ASAP 1, 0, -5000\r");
    assert_eq!(port.read_line(), "BA 100 -5000\r");
    port.send(b"AGAP 1, 0\r");
    assert_eq!(port.read_line(), "BA 100 -5000\r", "the manual's example");
    port.send(b"AJA 3\r");
    assert_eq!(port.read_line(), "BA 2 3\r");
    port.send(b"ABIN\r");
    assert_eq!(port.read_line(), "BA 100 0\r");
    assert_eq!(port.transact(1, 6, 1, 0, 0).value, -5000, "binary again");
}

#[test]
fn chosen_line_endings_and_a_silent_139() {
    let sim = Sim::start(&[
        "--pty",
        "--no-reply-to-139",
        "--reply-end",
        "crlf",
        "--echo-end",
        "none",
    ]);
    let mut port = sim.pty();
    assert_eq!(port.transact(1, 9, 67, 0, 0x10).status, Status::Ok);
    port.send(&super::frame(1, 139, 0, 0, 0));
    port.send(b"AGAP 4, 0\r");
    let got = port.read_until(|b| b.ends_with(b"\r\n"));
    assert_eq!(
        got, b"AGAP 4, 0BA 100 1000000\r\n",
        "no binary reply before the text"
    );
}
