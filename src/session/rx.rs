//! Bytes received and not yet consumed by an exchange. Capped, consumed from the front without
//! moving the rest each time, and searched for line ends once per byte, so that whatever a device
//! sends costs linear time and bounded memory.

/// The most bytes the buffer holds. Exchanges consume what they have judged as they go, and a
/// partial line longer than any reply is dropped as noise, so only a flood reaches this.
pub(crate) const RX_CAP: usize = 64 * 1024;

/// The receive buffer of a session.
#[derive(Debug, Default)]
pub(crate) struct Rx {
    buf: Vec<u8>,
    /// The first byte not yet consumed.
    head: usize,
    /// `buf[no_end.0..no_end.1]` holds no line end (already searched).
    no_end: (usize, usize),
}

/// Bytes that did not fit under [`RX_CAP`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Overflow;

impl Rx {
    /// The bytes not yet consumed.
    pub(crate) fn bytes(&self) -> &[u8] {
        &self.buf[self.head..]
    }

    pub(crate) fn len(&self) -> usize {
        self.buf.len() - self.head
    }

    /// Appends `bytes`, or refuses all of them when the buffer would hold more than [`RX_CAP`].
    pub(crate) fn extend(&mut self, bytes: &[u8]) -> Result<(), Overflow> {
        if self.len() + bytes.len() > RX_CAP {
            return Err(Overflow);
        }
        // Moving the live bytes down only once at least as many have been consumed keeps the
        // cost per byte constant.
        let full = self.buf.len() + bytes.len() > self.buf.capacity();
        if self.head > 0 && (self.head >= self.len() || full) {
            self.compact();
        }
        self.buf.extend_from_slice(bytes);
        Ok(())
    }

    fn compact(&mut self) {
        let head = self.head;
        self.buf.drain(..head);
        self.head = 0;
        self.no_end = (
            self.no_end.0.saturating_sub(head),
            self.no_end.1.saturating_sub(head),
        );
    }

    /// Drops the first `n` bytes.
    pub(crate) fn consume(&mut self, n: usize) {
        self.head += n.min(self.len());
        if self.head == self.buf.len() {
            self.buf.clear();
            self.head = 0;
            self.no_end = (0, 0);
        }
    }

    /// Removes and returns the first `n` bytes.
    pub(crate) fn take(&mut self, n: usize) -> Vec<u8> {
        let n = n.min(self.len());
        let taken = self.bytes()[..n].to_vec();
        self.consume(n);
        taken
    }

    /// Removes and returns everything.
    pub(crate) fn clear(&mut self) -> Vec<u8> {
        self.take(self.len())
    }

    /// The offset of the first CR or LF at or after offset `from`. A search that finds none
    /// remembers so, and the next search starts where it stopped: a partial line that grows a
    /// byte at a time is not searched again from its start.
    pub(crate) fn line_end(&mut self, from: usize) -> Option<usize> {
        let start = self.head + from.min(self.len());
        let (known_from, known_to) = self.no_end;
        let resume = if (known_from..=known_to).contains(&start) {
            known_to.max(start)
        } else {
            start
        };
        match self.buf[resume..]
            .iter()
            .position(|&b| b == b'\r' || b == b'\n')
        {
            Some(i) => Some(resume + i - self.head),
            None => {
                let from = if resume == start { start } else { known_from };
                self.no_end = (from, self.buf.len());
                None
            }
        }
    }
}

/// Whether a byte only separates lines: CR, LF, or the NUL some RS-485 adapters produce when the
/// line turns round.
pub(crate) fn is_line_break(byte: u8) -> bool {
    matches!(byte, b'\r' | b'\n' | 0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn consumes_from_the_front_and_keeps_the_rest() {
        let mut rx = Rx::default();
        rx.extend(b"BA 100 5\rBA 100 6\r").unwrap();
        assert_eq!(rx.line_end(0), Some(8));
        assert_eq!(rx.take(9), b"BA 100 5\r");
        assert_eq!(rx.bytes(), b"BA 100 6\r");
        assert_eq!(rx.line_end(0), Some(8));
        rx.extend(b"more").unwrap();
        assert_eq!(rx.clear(), b"BA 100 6\rmore");
        assert_eq!(rx.len(), 0);
    }

    #[test]
    fn a_partial_line_is_not_searched_again_from_its_start() {
        let mut rx = Rx::default();
        rx.extend(b"12345").unwrap();
        assert_eq!(rx.line_end(0), None);
        assert_eq!(rx.no_end, (0, 5));
        rx.extend(b"678").unwrap();
        assert_eq!(rx.line_end(0), None);
        assert_eq!(rx.no_end, (0, 8), "the search resumed at 5");
        rx.extend(b"9\rX").unwrap();
        assert_eq!(rx.line_end(0), Some(9));
        assert_eq!(
            rx.line_end(3),
            Some(9),
            "a later start inside the known span"
        );
        assert_eq!(rx.line_end(10), None);
    }

    #[test]
    fn positions_survive_compaction() {
        let mut rx = Rx::default();
        rx.extend(&[b'x'; 100]).unwrap();
        assert_eq!(rx.line_end(0), None);
        rx.consume(90);
        // Enough consumed that the next extend moves the rest down.
        rx.extend(b"\r").unwrap();
        assert_eq!(rx.len(), 11);
        assert_eq!(rx.line_end(0), Some(10));
    }

    #[test]
    fn the_buffer_is_capped() {
        let mut rx = Rx::default();
        let chunk = [b'7'; 4096];
        for _ in 0..RX_CAP / chunk.len() {
            rx.extend(&chunk).unwrap();
        }
        assert_eq!(rx.extend(b"8"), Err(Overflow));
        assert_eq!(rx.len(), RX_CAP);
        rx.consume(1);
        rx.extend(b"8").unwrap();
    }

    #[test]
    fn memory_stays_flat_when_lines_are_consumed_as_they_come() {
        let mut rx = Rx::default();
        for _ in 0..100_000 {
            rx.extend(b"junk line\r").unwrap();
            let end = rx.line_end(0).unwrap();
            rx.consume(end + 1);
            rx.extend(b"half").unwrap();
            assert_eq!(rx.line_end(0), None);
            rx.consume(2);
        }
        assert!(rx.buf.capacity() <= 4096, "{}", rx.buf.capacity());
    }
}
