//! An FTDI adapter's latency timer. The chip holds what it received from the line until the
//! timer runs out (16 ms by default) or a USB packet is full, so every reply waits up to 16 ms
//! in the adapter: at 115200 baud a request and its reply take under 2 ms on the wire. Linux
//! shows the timer in sysfs (`/sys/bus/usb-serial/devices/ttyUSBn/latency_timer`, milliseconds,
//! written only by root); the serial driver's low-latency flag (`ASYNC_LOW_LATENCY`, what
//! `setserial low_latency` and pyserial's `set_low_latency_mode` set, no root needed) lowers it
//! to 1 ms on the kernels whose `ftdi_sio` honours it, so tmclsh sets the flag and reads the
//! timer again; where it stays high it says once what that costs and how to fix it.

use std::path::{Path, PathBuf};
use std::time::Duration;

use super::sysfs;

/// At or below this the timer costs nothing worth a word.
pub const LOW: Duration = Duration::from_millis(2);

/// The latency timer file of the tty behind `path` under the tree `root`, if it has one (only
/// `ftdi_sio` ports do).
pub fn timer_file(root: &Path, path: &Path) -> Option<PathBuf> {
    sysfs::tty_names(path)
        .into_iter()
        .map(|name| {
            root.join("sys/bus/usb-serial/devices")
                .join(name)
                .join("latency_timer")
        })
        .find(|file| file.is_file())
}

/// The timer in `file`.
pub fn read(file: &Path) -> Option<Duration> {
    std::fs::read_to_string(file)
        .ok()?
        .trim()
        .parse::<u64>()
        .ok()
        .map(Duration::from_millis)
}

/// What became of the timer when the port was opened.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Outcome {
    /// Low already.
    Low(Duration),
    /// Lowered by the low-latency flag.
    Lowered {
        /// Before.
        from: Duration,
        /// After.
        to: Duration,
    },
    /// Left alone (`--keep-latency`).
    Kept(Duration),
    /// Still high after the flag was set, or the flag could not be set (`why`).
    High {
        /// The timer.
        timer: Duration,
        /// Why the flag did not help: the error of the ioctl, if it failed.
        why: Option<String>,
    },
}

/// Decides, from the timer found, whether to set the low-latency flag (`lower`, which returns
/// the ioctl's error), and reads the timer again after it (`reread`).
pub fn settle(
    found: Duration,
    keep: bool,
    lower: impl FnOnce() -> std::io::Result<()>,
    reread: impl FnOnce() -> Option<Duration>,
) -> Outcome {
    if found <= LOW {
        return Outcome::Low(found);
    }
    if keep {
        return Outcome::Kept(found);
    }
    let why = lower().err().map(|e| e.to_string());
    match reread() {
        Some(now) if now <= LOW => Outcome::Lowered {
            from: found,
            to: now,
        },
        now => Outcome::High {
            timer: now.unwrap_or(found),
            why,
        },
    }
}

/// What a timer that stays high costs at `baud`, and the fix: the sysfs write now and a udev
/// rule for good. `tty` is the kernel's name of the port (`ttyUSB0`).
pub fn advice(tty: &str, timer: Duration, why: Option<&str>, baud: u32) -> String {
    let ms = timer.as_millis();
    // A binary request and its reply: 18 bytes of 10 bits.
    let wire = 18.0 * 10.0 * 1000.0 / f64::from(baud.max(1));
    let tried = match why {
        Some(why) => format!("setting the low-latency flag failed ({why})"),
        None => "the low-latency flag did not lower it on this kernel".into(),
    };
    format!(
        "the FTDI adapter {tty} holds every reply up to its latency timer, {ms} ms ({tried}); \
         a request and its reply take {wire:.1} ms on the wire at {baud} baud, so each waits up \
         to {ms} ms more. Fix it now (as root): echo 1 > \
         /sys/bus/usb-serial/devices/{tty}/latency_timer; for good, a udev rule in \
         /etc/udev/rules.d/99-ftdi-latency.rules: ACTION==\"add\", SUBSYSTEM==\"usb-serial\", \
         DRIVER==\"ftdi_sio\", ATTR{{latency_timer}}=\"1\" (--keep-latency leaves the timer alone)"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(n: u64) -> Duration {
        Duration::from_millis(n)
    }

    #[test]
    fn a_low_timer_is_not_touched() {
        let outcome = settle(
            ms(1),
            false,
            || panic!("not lowered"),
            || panic!("not read"),
        );
        assert_eq!(outcome, Outcome::Low(ms(1)));
        assert_eq!(
            settle(ms(2), false, || panic!(), || None),
            Outcome::Low(ms(2))
        );
    }

    #[test]
    fn keep_leaves_a_high_timer_alone() {
        let outcome = settle(ms(16), true, || panic!("not lowered"), || panic!());
        assert_eq!(outcome, Outcome::Kept(ms(16)));
    }

    #[test]
    fn the_flag_lowers_it_or_the_timer_read_again_says_it_did_not() {
        assert_eq!(
            settle(ms(16), false, || Ok(()), || Some(ms(1))),
            Outcome::Lowered {
                from: ms(16),
                to: ms(1)
            }
        );
        assert_eq!(
            settle(ms(16), false, || Ok(()), || Some(ms(16))),
            Outcome::High {
                timer: ms(16),
                why: None
            }
        );
        assert_eq!(
            settle(
                ms(16),
                false,
                || Err(std::io::Error::other("not a tty")),
                || None
            ),
            Outcome::High {
                timer: ms(16),
                why: Some("not a tty".into())
            }
        );
    }

    #[test]
    fn the_advice_gives_the_cost_and_both_fixes() {
        let text = advice("ttyUSB0", ms(16), None, 115_200);
        assert!(text.contains("16 ms"), "{text}");
        assert!(text.contains("1.6 ms on the wire at 115200 baud"), "{text}");
        assert!(
            text.contains("echo 1 > /sys/bus/usb-serial/devices/ttyUSB0/latency_timer"),
            "{text}"
        );
        assert!(
            text.contains(
                "ACTION==\"add\", SUBSYSTEM==\"usb-serial\", DRIVER==\"ftdi_sio\", \
                 ATTR{latency_timer}=\"1\""
            ),
            "{text}"
        );
    }

    #[cfg(unix)]
    #[test]
    fn the_timer_file_is_found_by_the_device_name_or_its_link_target() {
        let root = std::env::temp_dir().join(format!("tmclsh-latency-{}", std::process::id()));
        let dir = root.join("sys/bus/usb-serial/devices/ttyUSB3");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::create_dir_all(root.join("dev/serial/by-id")).unwrap();
        std::fs::write(dir.join("latency_timer"), "16\n").unwrap();
        std::fs::write(root.join("dev/ttyUSB3"), "").unwrap();
        let link = root.join("dev/serial/by-id/usb-FTDI_FT232R_A1-if00-port0");
        let _ = std::fs::remove_file(&link);
        std::os::unix::fs::symlink("../../ttyUSB3", &link).unwrap();
        for path in [root.join("dev/ttyUSB3"), link] {
            let file = timer_file(&root, &path).expect("found");
            assert_eq!(read(&file), Some(ms(16)));
        }
        assert_eq!(timer_file(&root, Path::new("/dev/ttyS0")), None);
        let _ = std::fs::remove_dir_all(&root);
    }
}
