//! TCP connections (Ethernet modules, serial servers, `tmclsh sim --listen`). On Unix the
//! socket is non-blocking, so a look at what has arrived is one read(2) and a write one
//! write(2) (`fd.rs`).

use std::net::{TcpStream, ToSocketAddrs};
use std::time::{Duration, Instant};

use super::{Link, LinkError};

/// How long a write waits for room in the socket's buffer (a peer that stopped reading).
#[cfg(unix)]
const WRITE_BOUND: Duration = Duration::from_secs(2);

/// An open TCP connection.
pub struct TcpLink {
    address: String,
    stream: TcpStream,
}

impl TcpLink {
    /// Connects to `address` (`host:port`), giving up after `timeout`.
    pub fn connect(address: &str, timeout: Duration) -> Result<Self, LinkError> {
        let stream = connect(address, timeout)?;
        Ok(TcpLink {
            address: address.to_string(),
            stream,
        })
    }
}

fn connect(address: &str, timeout: Duration) -> Result<TcpStream, LinkError> {
    let fail =
        |e: &dyn std::fmt::Display| LinkError::Open(format!("cannot connect to {address}: {e}"));
    let addrs = address.to_socket_addrs().map_err(|e| fail(&e))?;
    let mut last = None;
    for addr in addrs {
        match TcpStream::connect_timeout(&addr, timeout) {
            Ok(stream) => {
                stream.set_nodelay(true).map_err(|e| fail(&e))?;
                #[cfg(unix)]
                stream.set_nonblocking(true).map_err(|e| fail(&e))?;
                return Ok(stream);
            }
            Err(e) => last = Some(e),
        }
    }
    Err(match last {
        Some(e) => fail(&e),
        None => fail(&"no address"),
    })
}

impl Link for TcpLink {
    #[cfg(unix)]
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        super::fd::write_all(std::os::fd::AsFd::as_fd(&self.stream), bytes, WRITE_BOUND)
    }

    #[cfg(not(unix))]
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        std::io::Write::write_all(&mut self.stream, bytes).map_err(LinkError::from_io)
    }

    #[cfg(unix)]
    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        let fd = std::os::fd::AsFd::as_fd(&self.stream);
        match super::fd::read(fd, buf, deadline)? {
            0 => Err(LinkError::Lost(format!(
                "{} closed the connection",
                self.address
            ))),
            n => Ok(n),
        }
    }

    #[cfg(not(unix))]
    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        use std::io::Read;
        let wait = deadline.saturating_duration_since(Instant::now());
        // A deadline already past still takes what has arrived (a non-blocking read), so the
        // session's drain before each request really empties the socket.
        let now_only = wait.is_zero();
        if now_only {
            self.stream
                .set_nonblocking(true)
                .map_err(LinkError::from_io)?;
        } else {
            self.stream
                .set_read_timeout(Some(wait))
                .map_err(LinkError::from_io)?;
        }
        let result = self.stream.read(buf);
        if now_only {
            self.stream
                .set_nonblocking(false)
                .map_err(LinkError::from_io)?;
        }
        match result {
            Ok(0) => Err(LinkError::Lost(format!(
                "{} closed the connection",
                self.address
            ))),
            Ok(n) => Ok(n),
            Err(e) => Err(LinkError::from_io(e)),
        }
    }

    fn describe(&self) -> String {
        format!("tcp {}", self.address)
    }

    fn reads_all(&self) -> bool {
        true
    }

    fn reopen(&mut self) -> Result<(), LinkError> {
        self.stream = connect(&self.address, Duration::from_secs(2))?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use std::io::Write;
    use std::net::TcpListener;

    use super::*;

    #[test]
    fn a_past_deadline_still_takes_what_has_arrived() {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let address = listener.local_addr().unwrap().to_string();
        let mut link = TcpLink::connect(&address, Duration::from_secs(5)).unwrap();
        let (mut peer, _) = listener.accept().unwrap();
        peer.write_all(b"abc").unwrap();
        let mut buf = [0u8; 1];
        let deadline = Instant::now() + Duration::from_secs(5);
        assert_eq!(
            link.recv(&mut buf, deadline).unwrap(),
            1,
            "the first byte is there"
        );
        let mut rest = [0u8; 8];
        let n = link.recv(&mut rest, Instant::now()).unwrap();
        assert_eq!(&rest[..n], b"bc", "taken without waiting");
        assert!(matches!(
            link.recv(&mut rest, Instant::now()),
            Err(LinkError::Timeout)
        ));
        drop(peer);
        let n = link.recv(&mut rest, Instant::now() + Duration::from_secs(5));
        assert!(
            matches!(n, Err(LinkError::Lost(_))),
            "a closed peer is a lost link"
        );
    }
}
