//! A pseudo-terminal that looks like a serial port to any program (tmclsh, PyTrinamic, a
//! terminal). The server keeps the slave side open itself, so a client closing the port does not
//! hang up the terminal and the next client finds it ready.

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

impl Server {
    /// Serves on a new pseudo-terminal until an I/O error; `announce` gets its path, and the
    /// path of a fresh one after the device hung up (like an adapter unplugged and plugged in).
    pub fn serve_pty(&mut self, announce: &mut dyn FnMut(&Path)) -> io::Result<()> {
        loop {
            let mut pty = open_pty()?;
            self.fresh_connection();
            announce(&pty.path);
            match self.pump(&mut pty.master, None)? {
                End::HungUp => (self.log)(&format!("hung up {}", pty.path.display())),
                End::Closed | End::Other => {
                    (self.log)(&format!("{} closed; opening a new one", pty.path.display()))
                }
            }
        }
    }
}
