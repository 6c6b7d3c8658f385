//! Who holds a port tmclsh cannot open: the processes that have the device open (read from
//! `/proc/*/fd`, as `fuser` does), the one holding its `flock` first (`/proc/locks`), and UUCP
//! lock files (`/var/lock/LCK..ttyUSB0`, the holder's PID in 10 ASCII characters), which tmclsh
//! honours: a live holder's lock refuses the port. Linux only; elsewhere nobody is named.

use std::path::{Path, PathBuf};

/// A process holding a port.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Holder {
    /// Its process id.
    pub pid: u32,
    /// Its command line, as far as it can be read.
    pub command: Option<String>,
}

impl std::fmt::Display for Holder {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.command {
            Some(command) => write!(
                f,
                "PID {} ({})",
                self.pid,
                crate::escape::escape_control(command)
            ),
            None => write!(f, "PID {}", self.pid),
        }
    }
}

/// A UUCP lock file and the process it names.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Lock {
    /// The lock file.
    pub file: PathBuf,
    /// The process it names, if the file holds a PID.
    pub holder: Option<Holder>,
    /// Whether that process is still running.
    pub live: bool,
}

/// The PID a UUCP lock file holds: 10 ASCII characters (HDB style, space-padded), or an old
/// binary 4-byte integer.
pub fn lock_pid(content: &[u8]) -> Option<u32> {
    let text = String::from_utf8_lossy(content);
    match text.trim().parse::<u32>() {
        Ok(pid) if pid > 0 => Some(pid),
        _ if content.len() == 4 => {
            let pid = u32::from_ne_bytes(content.try_into().ok()?);
            (pid > 0).then_some(pid)
        }
        _ => None,
    }
}

/// The command line of process `pid`, arguments joined by spaces, at most 100 characters.
fn command_of(pid: u32) -> Option<String> {
    let raw = std::fs::read(format!("/proc/{pid}/cmdline")).ok()?;
    let words: Vec<String> = raw
        .split(|b| *b == 0)
        .filter(|w| !w.is_empty())
        .map(|w| String::from_utf8_lossy(w).into_owned())
        .collect();
    let mut line = words.join(" ");
    if line.is_empty() {
        return None;
    }
    if line.chars().count() > 100 {
        line = line.chars().take(99).collect::<String>() + "…";
    }
    Some(line)
}

fn holder(pid: u32) -> Holder {
    Holder {
        pid,
        command: command_of(pid),
    }
}

/// The UUCP lock file of the port at `path` under the tree `root`, if there is one.
pub fn lock(root: &Path, path: &Path) -> Option<Lock> {
    super::sysfs::tty_names(path)
        .into_iter()
        .rev()
        .map(|name| root.join("var/lock").join(format!("LCK..{name}")))
        .find(|file| file.is_file())
        .map(|file| {
            let pid = std::fs::read(&file).ok().as_deref().and_then(lock_pid);
            let live = pid.is_some_and(|pid| Path::new(&format!("/proc/{pid}")).exists());
            Lock {
                file,
                holder: pid.map(holder),
                live,
            }
        })
}

/// The other processes that have the device at `path` open, the one holding its `flock`
/// first; empty where this cannot be told.
pub fn holders(path: &Path) -> Vec<Holder> {
    #[cfg(target_os = "linux")]
    {
        linux::holders(path)
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = path;
        Vec::new()
    }
}

#[cfg(target_os = "linux")]
mod linux {
    use std::os::unix::fs::MetadataExt;
    use std::path::Path;

    use super::{Holder, holder};

    pub(super) fn holders(path: &Path) -> Vec<Holder> {
        let Ok(device) = path.canonicalize() else {
            return Vec::new();
        };
        let own = std::process::id();
        let Ok(procs) = std::fs::read_dir("/proc") else {
            return Vec::new();
        };
        let mut pids: Vec<u32> = procs
            .filter_map(Result::ok)
            .filter_map(|e| e.file_name().to_str()?.parse::<u32>().ok())
            .filter(|pid| *pid != own)
            .filter(|pid| {
                std::fs::read_dir(format!("/proc/{pid}/fd")).is_ok_and(|fds| {
                    fds.filter_map(Result::ok)
                        .any(|fd| std::fs::read_link(fd.path()).is_ok_and(|to| to == device))
                })
            })
            .collect();
        pids.sort_unstable();
        if let Some(locker) = flock_holder(&device) {
            if let Some(at) = pids.iter().position(|p| *p == locker) {
                pids.remove(at);
                pids.insert(0, locker);
            }
        }
        pids.into_iter().map(holder).collect()
    }

    /// The process holding an `flock` on `device`, from `/proc/locks` (`1: FLOCK ADVISORY
    /// WRITE 1234 00:19:6 0 EOF`: the PID, then major:minor of the file system (hex) and the
    /// inode).
    fn flock_holder(device: &Path) -> Option<u32> {
        let meta = std::fs::metadata(device).ok()?;
        let dev = meta.dev();
        let major = ((dev >> 8) & 0xfff) | ((dev >> 32) & !0xfff);
        let minor = (dev & 0xff) | ((dev >> 12) & !0xff);
        let locks = std::fs::read_to_string("/proc/locks").ok()?;
        locks.lines().find_map(|line| {
            let fields: Vec<&str> = line.split_whitespace().collect();
            let at = fields.iter().position(|f| *f == "FLOCK")?;
            let pid = fields.get(at + 3)?.parse::<u32>().ok()?;
            let mut id = fields.get(at + 4)?.split(':');
            let ma = u64::from_str_radix(id.next()?, 16).ok()?;
            let mi = u64::from_str_radix(id.next()?, 16).ok()?;
            let ino = id.next()?.parse::<u64>().ok()?;
            (ma == major && mi == minor && ino == meta.ino()).then_some(pid)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lock_files_hold_a_pid_as_text_or_binary() {
        assert_eq!(lock_pid(b"      1234\n"), Some(1234));
        assert_eq!(lock_pid(b"1234"), Some(1234));
        assert_eq!(lock_pid(&5678u32.to_ne_bytes()), Some(5678));
        assert_eq!(lock_pid(b""), None);
        assert_eq!(lock_pid(b"         0\n"), None);
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn a_process_holding_a_file_is_named_with_its_command() {
        // This test's own process is left out; a child holding the file is found.
        let dir = std::env::temp_dir().join(format!("tmclsh-holder-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("port");
        std::fs::write(&file, "").unwrap();
        let mut child = std::process::Command::new("sh")
            .arg("-c")
            .arg("exec 3<\"$0\"; read x")
            .arg(&file)
            .stdin(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let pid = child.id();
        let found = (0..500).find_map(|_| {
            let holders = holders(&file);
            if holders.iter().any(|h| h.pid == pid) {
                Some(holders)
            } else {
                std::thread::sleep(std::time::Duration::from_millis(10));
                None
            }
        });
        let _ = child.kill();
        let _ = child.wait();
        let holders = found.expect("the child is named");
        let named = holders.iter().find(|h| h.pid == pid).unwrap();
        assert!(
            named.to_string().starts_with(&format!("PID {pid} (sh -c")),
            "{named}"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
