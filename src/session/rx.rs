//! Bytes received and not yet consumed by an exchange.

/// The receive buffer of a session.
#[derive(Debug, Default)]
pub(crate) struct Rx {
    buf: Vec<u8>,
}

impl Rx {
    pub fn bytes(&self) -> &[u8] {
        &self.buf
    }

    pub fn extend(&mut self, bytes: &[u8]) {
        self.buf.extend_from_slice(bytes);
    }

    /// Removes and returns the first `n` bytes.
    pub fn take(&mut self, n: usize) -> Vec<u8> {
        self.buf.drain(..n.min(self.buf.len())).collect()
    }

    /// Drops the first `n` bytes, keeping the buffer's capacity.
    pub fn consume(&mut self, n: usize) {
        self.buf.drain(..n.min(self.buf.len()));
    }

    pub fn clear(&mut self) -> Vec<u8> {
        std::mem::take(&mut self.buf)
    }

    pub fn len(&self) -> usize {
        self.buf.len()
    }
}
