//! Why a serial port could not be opened, in words that say what to do: another program holds
//! it (named, from `holder.rs`), the user lacks the group that owns it (named), or no device is
//! behind the name. serialport reports EBUSY from `TIOCEXCL` as "no device", which is why the
//! text is read before the kind.

use std::path::Path;

use super::holder;

/// Why a port could not be opened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Cause {
    /// Another program holds it (TIOCEXCL: EBUSY; or its flock).
    Busy,
    /// No permission.
    Denied,
    /// No such device file, or no device behind it.
    Missing,
    /// Anything else.
    Other,
}

fn cause(error: &serialport::Error) -> Cause {
    let text = error.description.to_ascii_lowercase();
    if text.contains("busy") || text.contains("exclusive lock") || text.contains("shared lock") {
        return Cause::Busy;
    }
    // ENXIO, ENODEV: a device file with nothing behind it (an adapter just unplugged).
    if text.contains("no such device") {
        return Cause::Missing;
    }
    match error.kind() {
        serialport::ErrorKind::Io(std::io::ErrorKind::PermissionDenied) => Cause::Denied,
        serialport::ErrorKind::NoDevice
        | serialport::ErrorKind::Io(std::io::ErrorKind::NotFound) => Cause::Missing,
        _ => Cause::Other,
    }
}

/// The OS error with what usually fixes it.
pub(in crate::link) fn open_hint(path: &str, error: &serialport::Error) -> String {
    let hint = match cause(error) {
        Cause::Busy => {
            let holders = holder::holders(Path::new(path));
            let named: Vec<String> = holders.iter().take(3).map(|h| h.to_string()).collect();
            if named.is_empty() {
                "; another program has it open (`fuser -v` names it)".to_string()
            } else {
                format!("; in use by {}", named.join(", "))
            }
        }
        Cause::Denied => format!(
            "; add yourself to the group that owns it ({}: `sudo usermod -aG {} $USER`) and log \
             in again",
            owner_group(path).unwrap_or_else(|| "often dialout".into()),
            owner_group(path).unwrap_or_else(|| "dialout".into()),
        ),
        Cause::Missing if Path::new(path).exists() => {
            "; the device file is there but no device answers behind it: is the adapter \
             plugged in? `tmclsh ports` lists the ports"
                .to_string()
        }
        Cause::Missing => "; is the adapter plugged in? `tmclsh ports` lists the ports".into(),
        Cause::Other => String::new(),
    };
    format!("cannot open serial port {path}: {error}{hint}")
}

/// The name of the group owning the device file.
fn owner_group(path: &str) -> Option<String> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let gid = std::fs::metadata(path).ok()?.gid();
        let groups = std::fs::read_to_string("/etc/group").ok()?;
        groups.lines().find_map(|line| {
            let mut fields = line.split(':');
            let name = fields.next()?;
            let id = fields.nth(1)?.parse::<u32>().ok()?;
            (id == gid).then(|| name.to_string())
        })
    }
    #[cfg(not(unix))]
    {
        let _ = path;
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_busy_port_is_not_taken_for_a_missing_one() {
        let err = |kind, text: &str| serialport::Error::new(kind, text);
        use serialport::ErrorKind as K;
        // EBUSY from TIOCEXCL comes as NoDevice; flock's refusal names the lock.
        assert_eq!(
            cause(&err(K::NoDevice, "Device or resource busy")),
            Cause::Busy
        );
        assert_eq!(
            cause(&err(
                K::NoDevice,
                "Unable to acquire exclusive lock on serial port"
            )),
            Cause::Busy
        );
        assert_eq!(
            cause(&err(
                K::Io(std::io::ErrorKind::PermissionDenied),
                "Permission denied"
            )),
            Cause::Denied
        );
        assert_eq!(
            cause(&err(K::Io(std::io::ErrorKind::NotFound), "No such file")),
            Cause::Missing
        );
        assert_eq!(
            cause(&err(K::Unknown, "No such device or address")),
            Cause::Missing
        );
        let denied = open_hint(
            "/nonexistent/ttyUSB0",
            &err(
                K::Io(std::io::ErrorKind::PermissionDenied),
                "Permission denied",
            ),
        );
        assert!(denied.contains("dialout"), "{denied}");
        assert!(!denied.contains("plugged in"), "{denied}");
    }
}
