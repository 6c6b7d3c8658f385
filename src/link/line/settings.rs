//! The line settings a user gives (`--dtr`, `--rts`, `--rs485`, `--rs485-delay`,
//! `--keep-latency`, or their keys in `tmclsh.toml`), parsed and checked without touching a port.

use std::fmt;
use std::str::FromStr;
use std::time::Duration;

/// A modem line's setting.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Modem {
    /// Raised on opening.
    On,
    /// Lowered on opening.
    Off,
    /// Left as found, on opening and on closing (HUPCL cleared, as picocom's `--noreset`): a
    /// board that resets on DTR is not reset by tmclsh starting or ending.
    Keep,
}

/// A setting tmclsh cannot read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SettingError {
    /// Not one of the words of a modem line.
    #[error("'{0}' is not a modem line setting: on, off or keep")]
    Modem(String),
    /// Not a delay.
    #[error(
        "'{0}' is not an RS-485 delay: milliseconds before sending (and after, the same unless \
         given as BEFORE,AFTER), at most 1000"
    )]
    Delay(String),
}

impl FromStr for Modem {
    type Err = SettingError;

    fn from_str(text: &str) -> Result<Modem, SettingError> {
        match text.trim().to_ascii_lowercase().as_str() {
            "on" | "1" | "high" => Ok(Modem::On),
            "off" | "0" | "low" => Ok(Modem::Off),
            "keep" => Ok(Modem::Keep),
            _ => Err(SettingError::Modem(text.to_string())),
        }
    }
}

impl fmt::Display for Modem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Modem::On => "on",
            Modem::Off => "off",
            Modem::Keep => "keep",
        })
    }
}

/// RS-485 direction: RTS raised while the host sends, with delays around it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Rs485 {
    /// RTS raised this long before the first byte.
    pub before: Duration,
    /// RTS held this long after the last byte has left.
    pub after: Duration,
}

/// The longest delay accepted (the kernel's own limit for `delay_rts_*_send`).
const MAX_DELAY_MS: u64 = 1000;

impl Rs485 {
    /// `MS` (both delays) or `BEFORE,AFTER`, in milliseconds.
    pub fn parse_delay(text: &str) -> Result<Rs485, SettingError> {
        let bad = || SettingError::Delay(text.to_string());
        let ms = |s: &str| {
            s.trim()
                .parse::<u64>()
                .ok()
                .filter(|ms| *ms <= MAX_DELAY_MS)
                .map(Duration::from_millis)
                .ok_or_else(bad)
        };
        match text.split_once(',') {
            Some((before, after)) => Ok(Rs485 {
                before: ms(before)?,
                after: ms(after)?,
            }),
            None => {
                let both = ms(text)?;
                Ok(Rs485 {
                    before: both,
                    after: both,
                })
            }
        }
    }

    /// The kernel's `struct serial_rs485` flags for this mode: enabled, RTS high during a send
    /// and low after it (`SER_RS485_*`, include/uapi/linux/serial.h).
    pub fn kernel_flags(&self) -> u32 {
        const ENABLED: u32 = 1 << 0;
        const RTS_ON_SEND: u32 = 1 << 1;
        ENABLED | RTS_ON_SEND
    }

    /// The kernel's delay fields, in milliseconds.
    pub fn kernel_delays(&self) -> (u32, u32) {
        let ms = |d: Duration| u32::try_from(d.as_millis()).unwrap_or(u32::MAX);
        (ms(self.before), ms(self.after))
    }
}

/// Everything the user set about the line; the default leaves the port as opening it does.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct LineOptions {
    /// DTR, unless left to the system.
    pub dtr: Option<Modem>,
    /// RTS, unless left to the system (or driven for RS-485).
    pub rts: Option<Modem>,
    /// RS-485 direction control.
    pub rs485: Option<Rs485>,
    /// Leave an FTDI adapter's latency timer as it is.
    pub keep_latency: bool,
}

impl LineOptions {
    /// Whether anything asks for the modem lines.
    pub fn wants_modem_lines(&self) -> bool {
        self.dtr.is_some() || self.rts.is_some() || self.rs485.is_some()
    }

    /// The options in the words of the command line, for a note that they could not be applied.
    pub fn named(&self) -> Vec<String> {
        let mut named = Vec::new();
        if let Some(dtr) = self.dtr {
            named.push(format!("--dtr {dtr}"));
        }
        if let Some(rts) = self.rts {
            named.push(format!("--rts {rts}"));
        }
        if self.rs485.is_some() {
            named.push("--rs485".into());
        }
        named
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modem_settings_are_read_in_any_case() {
        assert_eq!("on".parse::<Modem>(), Ok(Modem::On));
        assert_eq!("OFF".parse::<Modem>(), Ok(Modem::Off));
        assert_eq!(" keep".parse::<Modem>(), Ok(Modem::Keep));
        let err = "up".parse::<Modem>().unwrap_err();
        assert!(err.to_string().contains("on, off or keep"), "{err}");
        for m in [Modem::On, Modem::Off, Modem::Keep] {
            assert_eq!(m.to_string().parse::<Modem>(), Ok(m));
        }
    }

    #[test]
    fn rs485_delays_are_one_value_or_two() {
        let ms = Duration::from_millis;
        assert_eq!(
            Rs485::parse_delay("2").unwrap(),
            Rs485 {
                before: ms(2),
                after: ms(2)
            }
        );
        assert_eq!(
            Rs485::parse_delay("0,5").unwrap(),
            Rs485 {
                before: ms(0),
                after: ms(5)
            }
        );
        for bad in ["", "-1", "1,", "x", "1001", "1,2,3"] {
            assert!(Rs485::parse_delay(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn the_kernel_mode_is_enabled_with_rts_high_while_sending() {
        let mode = Rs485::parse_delay("1,3").unwrap();
        // SER_RS485_ENABLED | SER_RS485_RTS_ON_SEND; RTS_AFTER_SEND (4) clear: low afterwards.
        assert_eq!(mode.kernel_flags(), 0b011);
        assert_eq!(mode.kernel_delays(), (1, 3));
    }

    #[test]
    fn options_name_themselves_as_written() {
        let options = LineOptions {
            dtr: Some(Modem::Keep),
            rts: None,
            rs485: Some(Rs485::default()),
            keep_latency: false,
        };
        assert!(options.wants_modem_lines());
        assert_eq!(options.named(), ["--dtr keep", "--rs485"]);
        assert!(!LineOptions::default().wants_modem_lines());
    }
}
