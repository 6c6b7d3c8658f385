//! The addressing state machine: sticky once a prefixed packet arrives, broadcasts executed
//! silently, everything else ignored silently; back to normal on restart.

use super::Bench;

#[test]
fn normal_mode_answers_unprefixed_packets() {
    let mut b = Bench::new();
    assert_eq!(b.send("SYS:FW"), "0x0888,0x0000,24044.12");
    assert!(b.send("").ends_with("-104 (Packet error)"));
    assert!(!b.sim.addressing_mode());
}

#[test]
fn the_first_prefixed_packet_switches_to_addressing_mode_for_good() {
    let mut b = Bench::new();
    assert_eq!(b.send("@1SYS:FW"), "@1,0x0888,0x0000,24044.12");
    assert!(b.sim.addressing_mode());
    assert_eq!(b.send("SYS:FW"), "", "unprefixed packets are now ignored");
    assert_eq!(b.send("@1"), "", "malformed packets too");
    assert_eq!(b.send("garbage!"), "");
    assert_eq!(b.send("@2SYS:FW"), "", "other addresses are ignored");
    assert_eq!(
        b.send("@300SYS:FW"),
        "",
        "out-of-range addresses are ignored"
    );
    assert_eq!(
        b.send("@1,SYS:FW"),
        "@1,0x0888,0x0000,24044.12",
        "both prefix forms"
    );
    assert_eq!(
        b.send("@1MOTOR:NOPE"),
        "@1,0x0888,0x0000,-103 (Invalid Mnemonic)"
    );
}

#[test]
fn broadcasts_execute_without_reply() {
    let mut b = Bench::new();
    assert_eq!(b.send("@0SYS:IDENT,1"), "");
    assert!(
        b.sim.addressing_mode(),
        "a broadcast also switches the mode"
    );
    assert_eq!(
        b.send("@1SYS:IDENT"),
        "@1,0x0898,0x0000,1",
        "executed (and Ident flag set)"
    );
}

#[test]
fn a_packet_for_another_drive_switches_silently() {
    let mut b = Bench::new();
    assert_eq!(b.send("@7SYS:IDENT,1"), "");
    assert!(b.sim.addressing_mode());
    assert_eq!(b.send("@1SYS:IDENT"), "@1,0x0888,0x0000,0", "not executed");
}

#[test]
fn the_own_address_is_slaveaddr_and_restart_leaves_addressing_mode() {
    let mut b = Bench::new();
    assert_eq!(b.send("@1COMS:SERIAL:SLAVEADDR,5"), "@1,0x0888,0x0000,5");
    assert_eq!(b.send("@1SYS:FW"), "");
    assert_eq!(b.send("@5SYS:FW"), "@5,0x0888,0x0000,24044.12");
    b.send("@5STORE");
    assert_eq!(b.send("@5SYS:RESET"), "");
    assert!(!b.sim.addressing_mode(), "restart ends addressing mode");
    assert_eq!(b.send("SYS:FW"), "0x0888,0x0000,24044.12");
    assert_eq!(
        b.send("@5SYS:FW"),
        "@5,0x0888,0x0000,24044.12",
        "stored address kept"
    );
    b.sim.power_cycle(b.now);
    assert_eq!(b.send("SYS:FW"), "0x0888,0x0000,24044.12");
}

#[test]
fn bytes_may_arrive_split_or_pipelined() {
    let mut b = Bench::new();
    assert_eq!(b.raw(b"SYS:"), "");
    assert_eq!(b.raw(b"FW\r"), "");
    assert_eq!(b.raw(b"\n"), "0x0888,0x0000,24044.12\r\n");
    assert_eq!(
        b.raw(b"SYS:IDENT,1\r\nSYS:IDENT\r\n"),
        "0x0898,0x0000,1\r\n0x0898,0x0000,1\r\n"
    );
    assert_eq!(
        b.raw(b"sys:fw\n"),
        "0x0898,0x0000,24044.12\r\n",
        "LF alone, any case"
    );
}
