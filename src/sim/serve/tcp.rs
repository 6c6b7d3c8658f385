//! TCP: one client at a time, like a serial server. A client that connects while another is
//! served takes over (the old connection is closed), so a client that lost its connection can
//! always come back.

use std::io;
use std::net::{Shutdown, TcpListener, TcpStream};
use std::os::fd::AsFd;
use std::time::Duration;

use super::{End, Server};

fn prepare(stream: &TcpStream) -> io::Result<()> {
    stream.set_nodelay(true)?;
    stream.set_nonblocking(false)?;
    stream.set_write_timeout(Some(Duration::from_secs(2)))
}

impl Server {
    /// Serves clients of `listener`, one at a time, until an I/O error of the listener.
    pub fn serve_tcp(&mut self, listener: &TcpListener) -> io::Result<()> {
        let mut next: Option<TcpStream> = None;
        loop {
            let mut stream = match next.take() {
                Some(stream) => stream,
                None => listener.accept()?.0,
            };
            let peer = stream
                .peer_addr()
                .map_or_else(|_| "?".to_string(), |a| a.to_string());
            if prepare(&stream).is_err() {
                continue;
            }
            self.fresh_connection();
            (self.log)(&format!("client {peer} connected"));
            match self.pump(&mut stream, Some(listener.as_fd()))? {
                End::Closed => (self.log)(&format!("client {peer} disconnected")),
                // The console refuses `unplug` on TCP; taken as a hang-up all the same.
                End::HungUp | End::Unplugged(_) => {
                    let _ = stream.shutdown(Shutdown::Both);
                    (self.log)(&format!("hung up on client {peer}"));
                }
                End::Other => {
                    next = Some(listener.accept()?.0);
                    (self.log)(&format!("client {peer} replaced by a new connection"));
                }
            }
        }
    }
}
