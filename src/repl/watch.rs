//! The link watched while the REPL waits at its prompt: nobody reads the port then, so a USB
//! adapter pulled out would go unnoticed until the next line. A thread polls a duplicate of the
//! port's descriptor asking for no events — poll(2) still reports a hang-up or an error, and no
//! byte is read, so nothing is taken from the session — and, once the link is gone, wakes the
//! line editor as a signal does (SIGINT to the prompting thread), until the prompt is left.

use std::io::Read;
use std::os::fd::{AsFd, OwnedFd};
use std::os::unix::net::UnixStream;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use nix::poll::{PollFd, PollFlags, PollTimeout, poll};

use crate::session::interrupt;

/// How often the editor is woken again while the loss is not yet seen (the first SIGINT may come
/// before the editor's handler is in place).
const AGAIN: Duration = Duration::from_millis(100);

/// A watch over the link while the prompt waits; stopped when dropped.
pub(super) struct LinkWatch {
    lost: Arc<AtomicBool>,
    stop: Option<UnixStream>,
    thread: Option<JoinHandle<()>>,
}

impl LinkWatch {
    /// Watches `fd` (a duplicate of the link's descriptor) from the calling thread's prompt.
    pub(super) fn start(fd: OwnedFd) -> Option<LinkWatch> {
        let (stop, stopped) = UnixStream::pair().ok()?;
        let lost = Arc::new(AtomicBool::new(false));
        let flag = lost.clone();
        let waiter = nix::sys::pthread::pthread_self();
        let thread = std::thread::Builder::new()
            .name("link watch".into())
            .spawn(move || watch(&fd, &stopped, &flag, waiter))
            .ok()?;
        Some(LinkWatch {
            lost,
            stop: Some(stop),
            thread: Some(thread),
        })
    }

    /// Whether the link was seen to go away.
    pub(super) fn lost(&self) -> bool {
        self.lost.load(Ordering::SeqCst)
    }
}

impl Drop for LinkWatch {
    fn drop(&mut self) {
        // The other end reads end-of-file and the thread ends.
        drop(self.stop.take());
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// Waits for the link's hang-up or the stop; after a hang-up wakes the prompt until stopped.
fn watch(
    fd: &OwnedFd,
    stopped: &UnixStream,
    lost: &AtomicBool,
    waiter: nix::sys::pthread::Pthread,
) {
    loop {
        let mut fds = [
            PollFd::new(fd.as_fd(), PollFlags::empty()),
            PollFd::new(stopped.as_fd(), PollFlags::POLLIN),
        ];
        match poll(&mut fds, PollTimeout::NONE) {
            Ok(_) => {}
            Err(nix::errno::Errno::EINTR) => continue,
            Err(_) => return,
        }
        if fds[1].revents().is_some_and(|r| !r.is_empty()) {
            return;
        }
        let gone = PollFlags::POLLHUP | PollFlags::POLLERR | PollFlags::POLLNVAL;
        if fds[0].revents().is_some_and(|r| r.intersects(gone)) {
            break;
        }
    }
    lost.store(true, Ordering::SeqCst);
    let timeout = PollTimeout::try_from(AGAIN).unwrap_or(PollTimeout::MAX);
    loop {
        if interrupt::prompting() {
            let _ = nix::sys::pthread::pthread_kill(waiter, nix::sys::signal::Signal::SIGINT);
        }
        let mut fds = [PollFd::new(stopped.as_fd(), PollFlags::POLLIN)];
        match poll(&mut fds, timeout) {
            Ok(0) | Err(nix::errno::Errno::EINTR) => continue,
            _ => {
                let mut byte = [0u8; 1];
                let _ = (&*stopped).read(&mut byte);
                return;
            }
        }
    }
}
