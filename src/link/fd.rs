//! The system calls of a transaction on a Unix descriptor (a serial port, a socket), kept to
//! what each one needs: the descriptor is non-blocking, so a write is one write(2) while the
//! driver has room (it has, for a request) and a look at what has arrived is one read(2); only a
//! real wait polls. A serial port through serialport's own `Write` polls before every write, a
//! socket with a read timeout sets it before every read.

use std::os::fd::{AsFd, BorrowedFd};
use std::time::{Duration, Instant};

use nix::errno::Errno;
use nix::fcntl::{FcntlArg, OFlag, fcntl};
use nix::poll::{PollFd, PollFlags, ppoll};
use nix::sys::time::TimeSpec;

use super::LinkError;

/// Makes `fd` non-blocking (its open file description: a duplicate shares it).
pub(super) fn set_nonblocking(fd: BorrowedFd) -> Result<(), LinkError> {
    let lost = |e: Errno| LinkError::Lost(e.to_string());
    let flags = fcntl(fd, FcntlArg::F_GETFL).map_err(lost)?;
    let flags = OFlag::from_bits_truncate(flags) | OFlag::O_NONBLOCK;
    fcntl(fd, FcntlArg::F_SETFL(flags)).map_err(lost)?;
    Ok(())
}

/// Writes all of `bytes`; a full driver buffer is waited for up to `bound`, then
/// [`LinkError::Timeout`].
pub(super) fn write_all(
    fd: BorrowedFd,
    mut bytes: &[u8],
    bound: Duration,
) -> Result<(), LinkError> {
    let give_up = Instant::now() + bound;
    while !bytes.is_empty() {
        match nix::unistd::write(fd, bytes) {
            Ok(n) => bytes = &bytes[n..],
            Err(Errno::EAGAIN) => {
                if !wait(fd, PollFlags::POLLOUT, give_up)? {
                    return Err(LinkError::Timeout);
                }
            }
            Err(Errno::EINTR) => {}
            Err(e) => return Err(LinkError::from_io(e.into())),
        }
    }
    Ok(())
}

/// Reads what has arrived, waiting until `deadline` for a first byte: one read(2) when the
/// deadline has passed (a look), a poll and a read when it has not. `Ok(0)` is the end of the
/// stream.
pub(super) fn read(fd: BorrowedFd, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
    let mut ready = deadline <= Instant::now();
    loop {
        if !ready && !wait(fd, PollFlags::POLLIN, deadline)? {
            return Err(LinkError::Timeout);
        }
        match nix::unistd::read(fd, buf) {
            Ok(n) => return Ok(n),
            Err(Errno::EAGAIN) if deadline > Instant::now() => ready = false,
            Err(Errno::EAGAIN | Errno::EINTR) => return Err(LinkError::Timeout),
            Err(e) => return Err(LinkError::from_io(e.into())),
        }
    }
}

/// Waits until `fd` is ready for `events` (or hung up) or `until` passes: false when it passed.
/// A signal ends the wait early, as a time-out the caller's loop looks at again.
fn wait(fd: BorrowedFd, events: PollFlags, until: Instant) -> Result<bool, LinkError> {
    let left = until.saturating_duration_since(Instant::now());
    if left.is_zero() {
        return Ok(false);
    }
    let mut fds = [PollFd::new(fd.as_fd(), events)];
    match ppoll(&mut fds, Some(TimeSpec::from(left)), None) {
        Ok(0) | Err(Errno::EINTR) => Ok(false),
        Ok(_) => Ok(true),
        Err(e) => Err(LinkError::from_io(e.into())),
    }
}
