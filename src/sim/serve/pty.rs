//! A pseudo-terminal that looks like a serial port to any program (tmclsh, PyTrinamic, a
//! terminal). The server keeps the slave side open itself, so a client closing the port does not
//! hang up the terminal and the next client finds it ready. A stable symlink (`--link`) follows
//! the current pseudo-terminal, as udev's `/dev/serial/by-id` names follow a replugged adapter.

use std::fs::File;
use std::io;
use std::os::fd::OwnedFd;
use std::path::{Path, PathBuf};

use nix::fcntl::{FcntlArg, OFlag, fcntl};
use nix::sys::termios::{SetArg, cfmakeraw, tcgetattr, tcsetattr};

use super::{End, Server};

struct Pty {
    master: File,
    _slave: OwnedFd,
    path: PathBuf,
}

fn open_pty() -> io::Result<Pty> {
    let pair = nix::pty::openpty(None, None)?;
    let mut termios = tcgetattr(&pair.slave)?;
    cfmakeraw(&mut termios);
    tcsetattr(&pair.slave, SetArg::TCSANOW, &termios)?;
    let path = nix::unistd::ttyname(&pair.slave)?;
    // A full line (nobody reading) must not block the simulator.
    fcntl(&pair.master, FcntlArg::F_SETFL(OFlag::O_NONBLOCK))?;
    Ok(Pty {
        master: File::from(pair.master),
        _slave: pair.slave,
        path,
    })
}

/// Points the symlink `link` at `target`, replacing it in one step (a new link renamed over the
/// old), so a client never finds it half made. Anything at `link` that is not a symlink is left
/// alone and refused: it is not ours to replace.
fn point_link(link: &Path, target: &Path) -> io::Result<()> {
    if let Ok(meta) = link.symlink_metadata() {
        if !meta.file_type().is_symlink() {
            return Err(io::Error::new(
                io::ErrorKind::AlreadyExists,
                format!(
                    "{} exists and is not a symlink; --link makes and replaces only symlinks",
                    link.display()
                ),
            ));
        }
    }
    let mut fresh = link.as_os_str().to_owned();
    fresh.push(format!(".new-{}", std::process::id()));
    let fresh = PathBuf::from(fresh);
    let _ = std::fs::remove_file(&fresh);
    let named = |e: io::Error| {
        io::Error::new(
            e.kind(),
            format!(
                "cannot point --link {} at {}: {e} (does its directory exist, and may you write \
                 there?)",
                link.display(),
                target.display()
            ),
        )
    };
    std::os::unix::fs::symlink(target, &fresh).map_err(named)?;
    std::fs::rename(&fresh, link).map_err(named)
}

/// Removes the symlink `link` (the adapter is gone, and so is its udev name).
fn remove_link(link: &Path) {
    if link
        .symlink_metadata()
        .is_ok_and(|m| m.file_type().is_symlink())
    {
        let _ = std::fs::remove_file(link);
    }
}

impl Server {
    /// Serves on a new pseudo-terminal until an I/O error; `announce` gets its path, and the
    /// path of a fresh one after the device hung up (like an adapter unplugged and plugged in).
    pub fn serve_pty(&mut self, announce: &mut dyn FnMut(&Path)) -> io::Result<()> {
        self.serve_pty_linked(None, announce)
    }

    /// [`serve_pty`](Self::serve_pty), keeping the symlink `link` pointed at the current
    /// pseudo-terminal. The next terminal is opened while the last is still held, so it gets
    /// another number, as a replugged USB adapter does (ttyUSB0 → ttyUSB1).
    pub fn serve_pty_linked(
        &mut self,
        link: Option<&Path>,
        announce: &mut dyn FnMut(&Path),
    ) -> io::Result<()> {
        let mut pty = open_pty()?;
        loop {
            if let Some(link) = link {
                point_link(link, &pty.path)?;
            }
            self.fresh_connection();
            announce(&pty.path);
            let end = self.pump(&mut pty.master, None)?;
            let next = open_pty()?;
            let old = std::mem::replace(&mut pty, next);
            match end {
                End::HungUp => (self.log)(&format!("hung up {}", old.path.display())),
                End::Closed | End::Other => {
                    (self.log)(&format!("{} closed; opening a new one", old.path.display()))
                }
                End::Unplugged(outage) => {
                    if let Some(link) = link {
                        remove_link(link);
                    }
                    (self.log)(&format!(
                        "unplugged {} for {} s",
                        old.path.display(),
                        outage.as_secs_f64()
                    ));
                    // The client sees the port vanish now (EOF or EIO, POLLHUP); the adapter is
                    // away for the outage asked for, which is the point of the command.
                    drop(old);
                    std::thread::sleep(outage);
                }
            }
        }
    }
}
