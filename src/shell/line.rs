//! `:line`: the state of the link, to tell a line problem from a module problem — the rate the
//! driver set, the modem lines, an FTDI adapter's latency timer, RS-485 direction, echo
//! stripping, what was sent and received, and the driver's framing and overrun counters.

use std::io::{self, Write};

use crate::dialect::DialectSession;
use crate::link::LineState;

/// Writes the state of `session`'s link, one fact a row.
pub(super) fn write_line_state(
    session: &mut dyn DialectSession,
    out: &mut dyn Write,
) -> io::Result<()> {
    let wire = &mut session.core_mut().wire;
    let link = wire.link.describe();
    let state = wire.link.line_state();
    let (requests, replies) = (wire.tally.requests, wire.tally.replies);
    let echo = wire.echo_state();
    for (name, value) in rows(&link, &state, echo, requests, replies) {
        let line = format!("{name:<12} {value}");
        writeln!(out, "{}", crate::escape::escape_control(&line))?;
    }
    Ok(())
}

/// The rows of `:line`.
fn rows(
    link: &str,
    s: &LineState,
    echo: &str,
    requests: u64,
    replies: u64,
) -> Vec<(&'static str, String)> {
    let none = |what: &str| format!("none ({what})");
    let rate = match (s.rate, s.asked_rate) {
        (Some(rate), Some(asked)) => {
            format!("{rate} baud (asked for {asked}; the driver set this)")
        }
        (Some(rate), None) => format!("{rate} baud, as read back from the driver"),
        (None, _) => none("not a serial port"),
    };
    let modem = s
        .modem
        .map(|m| m.describe())
        .unwrap_or_else(|| none("a pseudo-terminal or not a serial port"));
    let latency = match s.latency {
        Some(t) if t > crate::link::line::latency::LOW => format!(
            "{} ms: each reply may wait that long in the adapter (see docs/real-line.md)",
            t.as_millis()
        ),
        Some(t) => format!("{} ms", t.as_millis()),
        None => none("not an FTDI adapter"),
    };
    let errors = match s.counters {
        Some(c) => format!(
            "{} framing, {} overrun, {} parity, {} break, {} buffer overrun (the driver's, since \
             the port was set up; {} bytes received, {} sent by the UART)",
            c.frame, c.overrun, c.parity, c.brk, c.buf_overrun, c.rx, c.tx
        ),
        None => none("this port keeps no counters"),
    };
    let mut rows = vec![
        ("link", link.to_string()),
        ("rate", rate),
        ("modem lines", modem),
        ("latency", latency),
        ("RS-485", s.rs485.clone().unwrap_or_else(|| "off".into())),
        ("echo strip", echo.to_string()),
        (
            "sent",
            traffic(s.bytes_out, requests, "request", "requests"),
        ),
        ("received", traffic(s.bytes_in, replies, "reply", "replies")),
        ("errors", errors),
    ];
    rows.extend(s.notes.iter().map(|note| ("note", note.clone())));
    rows
}

/// `18 bytes in 2 requests`, or the requests alone where the link does not count bytes.
fn traffic(bytes: Option<u64>, n: u64, one: &str, many: &str) -> String {
    let noun = if n == 1 { one } else { many };
    match bytes {
        Some(bytes) => format!(
            "{} in {n} {noun}",
            crate::count::counted(bytes as usize, "byte")
        ),
        None => format!("{n} {noun}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::link::line::{Counters, ModemLines};

    #[test]
    fn a_serial_port_shows_each_part_and_a_pty_says_what_it_lacks() {
        let serial = LineState {
            rate: Some(9600),
            modem: Some(ModemLines {
                dtr: true,
                ..ModemLines::default()
            }),
            latency: Some(std::time::Duration::from_millis(16)),
            counters: Some(Counters {
                frame: 2,
                ..Counters::default()
            }),
            bytes_out: Some(18),
            bytes_in: Some(9),
            ..LineState::default()
        };
        let shown = rows("serial /dev/ttyUSB0 at 9600 baud", &serial, "off", 2, 1);
        let row = |name: &str| shown.iter().find(|(n, _)| *n == name).unwrap().1.clone();
        assert_eq!(row("rate"), "9600 baud, as read back from the driver");
        assert!(row("modem lines").starts_with("DTR on, RTS off"));
        assert!(row("latency").starts_with("16 ms: each reply may wait"));
        assert!(row("errors").starts_with("2 framing, 0 overrun"));
        assert_eq!(row("sent"), "18 bytes in 2 requests");
        assert_eq!(row("received"), "9 bytes in 1 reply");
        let pty = rows(
            "serial /dev/pts/3 at 9600 baud",
            &LineState::default(),
            "off",
            0,
            0,
        );
        assert!(
            pty.iter()
                .any(|(n, v)| *n == "modem lines" && v.starts_with("none ("))
        );
    }
}
