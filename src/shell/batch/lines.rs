//! Piped input split into lines as bytes: CR, LF and CRLF each end a line (files from any system,
//! and mixed ones, read alike), a line longer than [`MAX_LINE`] bytes is reported as soon as it
//! passes the limit and its rest skipped (memory stays bounded whatever arrives, even an endless
//! line), and a line that is not UTF-8 is reported with where the bad byte is.

use std::io::{self, BufRead};

/// The longest line kept, in bytes; longer lines are refused. A TMCL or SMD4 command line is under
/// 100 bytes; helper lines with paths are the longest.
pub const MAX_LINE: usize = 4096;

/// Why a line cannot be used.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum LineError {
    /// Longer than [`MAX_LINE`].
    #[error("longer than the {MAX_LINE} bytes a line may have")]
    TooLong,
    /// Not UTF-8.
    #[error("not valid UTF-8 (byte 0x{byte:02X} at column {column})")]
    NotUtf8 {
        /// The first bad byte.
        byte: u8,
        /// Its place in the line, from 1.
        column: usize,
    },
}

/// Lines of a byte stream, numbered from 1 as an editor numbers them.
pub struct LineReader<R> {
    input: R,
    line: Vec<u8>,
    /// Whether a line has begun (it may be empty so far only if it is skipped).
    started: bool,
    /// The rest of a line reported too long is being skipped.
    skipping: bool,
    /// The last line ended with CR: an LF right after it belongs to the same ending.
    after_cr: bool,
    done: bool,
}

impl<R: BufRead> LineReader<R> {
    /// Lines of `input`.
    pub fn new(input: R) -> Self {
        LineReader {
            input,
            line: Vec::new(),
            started: false,
            skipping: false,
            after_cr: false,
            done: false,
        }
    }

    /// The line just read, or why it cannot be used; the buffer is reset for the next.
    fn finish(&mut self) -> Result<String, LineError> {
        self.started = false;
        let bytes = std::mem::take(&mut self.line);
        String::from_utf8(bytes).map_err(|e| {
            let at = e.utf8_error().valid_up_to();
            LineError::NotUtf8 {
                byte: e.as_bytes()[at],
                column: at + 1,
            }
        })
    }
}

impl<R: BufRead> Iterator for LineReader<R> {
    type Item = io::Result<Result<String, LineError>>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        loop {
            let available = match self.input.fill_buf() {
                Ok(bytes) => bytes,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => {
                    self.done = true;
                    return Some(Err(e));
                }
            };
            if available.is_empty() {
                self.done = true;
                return (self.started && !self.skipping).then(|| Ok(self.finish()));
            }
            if std::mem::take(&mut self.after_cr) && available[0] == b'\n' {
                self.input.consume(1);
                continue;
            }
            let end = available.iter().position(|&b| b == b'\r' || b == b'\n');
            let body = &available[..end.unwrap_or(available.len())];
            let mut too_long = false;
            if !self.skipping {
                self.started |= !body.is_empty();
                let room = MAX_LINE - self.line.len();
                too_long = body.len() > room;
                self.line.extend_from_slice(&body[..body.len().min(room)]);
            }
            let used = match end {
                Some(end) => {
                    self.after_cr = available[end] == b'\r';
                    end + 1
                }
                None => available.len(),
            };
            self.input.consume(used);
            if too_long {
                // Report now; an endless line must not keep the run waiting.
                self.line.clear();
                self.started = false;
                self.skipping = end.is_none();
                return Some(Ok(Err(LineError::TooLong)));
            }
            if end.is_some() {
                if std::mem::take(&mut self.skipping) {
                    continue; // the end of a line already reported
                }
                return Some(Ok(self.finish()));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn lines(bytes: &[u8]) -> Vec<Result<String, LineError>> {
        LineReader::new(bytes).map(Result::unwrap).collect()
    }

    fn ok(texts: &[&str]) -> Vec<Result<String, LineError>> {
        texts.iter().map(|t| Ok(t.to_string())).collect()
    }

    #[test]
    fn cr_lf_and_crlf_each_end_one_line() {
        assert_eq!(lines(b"a\rb\nc\r\nd"), ok(&["a", "b", "c", "d"]));
        assert_eq!(lines(b"a\r\rb\n\n"), ok(&["a", "", "b", ""]));
        assert_eq!(lines(b"a\n\rb"), ok(&["a", "", "b"]));
        assert_eq!(lines(b""), ok(&[]));
        assert_eq!(lines(b"\r\n"), ok(&[""]));
    }

    #[test]
    fn a_long_line_is_reported_once_and_skipped() {
        let mut input = vec![b'x'; 1 << 20];
        input.extend_from_slice(b"\r\nGAP 1, 0\n");
        assert_eq!(
            lines(&input),
            vec![Err(LineError::TooLong), Ok("GAP 1, 0".into())]
        );
        let exact = vec![b'y'; MAX_LINE];
        assert_eq!(lines(&exact)[0].as_ref().unwrap().len(), MAX_LINE);
        let mut over = vec![b'y'; MAX_LINE + 1];
        over.push(b'\n');
        assert_eq!(lines(&over), vec![Err(LineError::TooLong)]);
    }

    #[test]
    fn an_endless_line_is_reported_without_waiting_for_its_end() {
        let endless = std::io::BufReader::new(std::io::repeat(b'x'));
        let first = LineReader::new(endless).next().unwrap().unwrap();
        assert_eq!(first, Err(LineError::TooLong));
    }

    #[test]
    fn invalid_utf8_says_where() {
        assert_eq!(
            lines(b"ok\nGAP \xFF1\n"),
            vec![
                Ok("ok".into()),
                Err(LineError::NotUtf8 {
                    byte: 0xFF,
                    column: 5
                })
            ]
        );
    }

    proptest! {
        /// However the input is cut into reads, the lines are the same.
        #[test]
        fn lines_do_not_depend_on_how_the_input_arrives(
            input in proptest::collection::vec(prop_oneof![
                Just(b'\r'), Just(b'\n'), Just(b'a'), Just(0xC3u8), Just(0xA9u8)
            ], 0..200),
            chunk in 1usize..7,
        ) {
            let whole = lines(&input);
            let chunked = LineReader::new(io::BufReader::with_capacity(chunk, input.as_slice()))
                .map(Result::unwrap)
                .collect::<Vec<_>>();
            prop_assert_eq!(&whole, &chunked);
            let endings = input.iter().filter(|&&b| b == b'\n').count()
                + input.iter().filter(|&&b| b == b'\r').count()
                - input.windows(2).filter(|w| w == b"\r\n").count();
            let tail = usize::from(input.last().is_some_and(|b| !matches!(b, b'\r' | b'\n')));
            prop_assert_eq!(whole.len(), endings + tail);
        }
    }
}
