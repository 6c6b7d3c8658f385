//! The state of a link as `:line` shows it: what the link knows of itself (rate, modem lines,
//! latency timer, RS-485, byte counts, the driver's error counters). Each part is `None` where
//! the link has no such thing (a pty has no modem lines, TCP no rate).

use std::time::Duration;

/// A link's state at one moment.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct LineState {
    /// The bit rate set, as read back from the driver.
    pub rate: Option<u32>,
    /// The bit rate asked for, when the driver set another.
    pub asked_rate: Option<u32>,
    /// The modem lines, where the port has them.
    pub modem: Option<ModemLines>,
    /// An FTDI adapter's latency timer.
    pub latency: Option<Duration>,
    /// How RS-485 direction is driven, if it is.
    pub rs485: Option<String>,
    /// Bytes sent through the link since it was opened, where it counts them.
    pub bytes_out: Option<u64>,
    /// Bytes received, where it counts them.
    pub bytes_in: Option<u64>,
    /// The driver's counters (TIOCGICOUNT), where it keeps them.
    pub counters: Option<Counters>,
    /// What the link said of itself on opening (a rate the driver changed, modem lines a port
    /// lacks, a latency timer left high), for the transcript and `:line`.
    pub notes: Vec<String>,
}

/// The modem lines: outputs and inputs.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ModemLines {
    /// Data terminal ready (output).
    pub dtr: bool,
    /// Request to send (output).
    pub rts: bool,
    /// Clear to send (input).
    pub cts: bool,
    /// Data set ready (input).
    pub dsr: bool,
    /// Carrier detect (input).
    pub cd: bool,
}

/// The driver's error counters (`struct serial_icounter_struct`): since the port was
/// initialised, not since tmclsh opened it.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counters {
    /// Bytes received by the UART.
    pub rx: u64,
    /// Bytes sent by the UART.
    pub tx: u64,
    /// Framing errors: a byte without its stop bit (wrong rate, noise, a bus driven by two).
    pub frame: u64,
    /// Bytes lost because the UART was not read in time.
    pub overrun: u64,
    /// Parity errors.
    pub parity: u64,
    /// Breaks received.
    pub brk: u64,
    /// Bytes lost because the driver's buffer was full.
    pub buf_overrun: u64,
}

impl Counters {
    /// The errors that grew from `before` to `self`, in words (`3 framing errors, 1 overrun`);
    /// `None` when none did.
    pub fn moved_since(&self, before: &Counters) -> Option<String> {
        let grew = [
            (self.frame.saturating_sub(before.frame), "framing error"),
            (self.overrun.saturating_sub(before.overrun), "overrun"),
            (self.parity.saturating_sub(before.parity), "parity error"),
            (self.brk.saturating_sub(before.brk), "break"),
            (
                self.buf_overrun.saturating_sub(before.buf_overrun),
                "buffer overrun",
            ),
        ];
        let words: Vec<String> = grew
            .iter()
            .filter(|(n, _)| *n > 0)
            .map(|(n, noun)| crate::count::counted(*n as usize, noun))
            .collect();
        (!words.is_empty()).then(|| words.join(", "))
    }
}

impl ModemLines {
    /// `DTR on, RTS off; CTS off, DSR off, CD off`.
    pub fn describe(&self) -> String {
        let w = |b: bool| if b { "on" } else { "off" };
        format!(
            "DTR {}, RTS {}; CTS {}, DSR {}, CD {}",
            w(self.dtr),
            w(self.rts),
            w(self.cts),
            w(self.dsr),
            w(self.cd)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counters_say_which_errors_grew() {
        let before = Counters {
            frame: 2,
            ..Counters::default()
        };
        let after = Counters {
            frame: 5,
            overrun: 1,
            rx: 100,
            ..Counters::default()
        };
        assert_eq!(
            after.moved_since(&before).as_deref(),
            Some("3 framing errors, 1 overrun")
        );
        assert_eq!(before.moved_since(&before), None);
    }
}
