//! The ASCII interface's line input (manual §6.6): the first character of a line is the address
//! character; a module collects only lines addressed to it, echoing them as global parameter 67
//! bits 4/5 say — every character as it arrives (with backspace), the whole line after CR, or
//! nothing.
//!
//! Choices: CR or LF ends a line (so CR LF works too); blanks before the address character are
//! skipped; a line whose address character is erased with backspace is no longer addressed;
//! characters beyond the line limit are dropped. GP 67 with both echo bits set behaves like
//! "no echo".

use super::options::Quirks;

/// Echo behaviour from GP 67 bits 4 and 5.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Echo {
    /// Bits 5..4 = 00: every character while the module is addressed.
    Characters,
    /// Bit 4: the complete line after CR.
    Line,
    /// Bit 5: nothing, only the reply.
    Off,
}

impl Echo {
    /// The echo mode of a GP 67 value.
    pub(super) fn from_config(gp67: i32) -> Echo {
        match (gp67 >> 4) & 3 {
            0 => Echo::Characters,
            1 => Echo::Line,
            _ => Echo::Off,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum State {
    /// Waiting for the address character.
    Idle,
    /// A line for this module.
    Mine,
    /// A line for another module: ignored up to its end.
    Other,
}

/// The line being typed.
#[derive(Debug, Clone)]
pub(crate) struct LineInput {
    state: State,
    buf: Vec<u8>,
}

/// What the line input needs to know about the module.
pub(crate) struct Context<'a> {
    /// The module's address character (upper case), if it has one.
    pub address: Option<u8>,
    pub echo: Echo,
    pub quirks: &'a Quirks,
    pub max: usize,
}

impl LineInput {
    pub(super) fn new() -> LineInput {
        LineInput {
            state: State::Idle,
            buf: Vec::with_capacity(64),
        }
    }

    /// Forgets a partial line.
    pub(super) fn clear(&mut self) {
        self.state = State::Idle;
        self.buf.clear();
    }

    /// Takes one byte, appending any echo to `out`; true when a complete line for this module
    /// is ready in [`LineInput::line`].
    pub(super) fn feed(&mut self, byte: u8, cx: &Context, out: &mut Vec<u8>) -> bool {
        match (byte, self.state) {
            (b'\r' | b'\n', State::Mine) => {
                match cx.echo {
                    Echo::Characters => out.extend_from_slice(cx.quirks.echo_end.bytes()),
                    Echo::Line => {
                        out.extend_from_slice(&self.buf);
                        out.extend_from_slice(cx.quirks.echo_end.bytes());
                    }
                    Echo::Off => {}
                }
                self.state = State::Idle;
                true
            }
            (b'\r' | b'\n', _) => {
                self.clear();
                false
            }
            (0x08 | 0x7F, State::Mine) => {
                if self.buf.pop().is_some() && cx.echo == Echo::Characters {
                    out.extend_from_slice(cx.quirks.backspace.bytes());
                }
                if self.buf.is_empty() {
                    self.state = State::Idle;
                }
                false
            }
            (b' ' | b'\t' | 0x08 | 0x7F, State::Idle) | (_, State::Other) => false,
            (_, State::Idle) => {
                if Some(byte.to_ascii_uppercase()) == cx.address {
                    self.state = State::Mine;
                    self.buf.clear();
                    self.accept(byte, cx, out);
                } else {
                    self.state = State::Other;
                }
                false
            }
            (_, State::Mine) => {
                if self.buf.len() < cx.max {
                    self.accept(byte, cx, out);
                }
                false
            }
        }
    }

    fn accept(&mut self, byte: u8, cx: &Context, out: &mut Vec<u8>) {
        self.buf.push(byte);
        if cx.echo == Echo::Characters {
            out.push(byte);
        }
    }

    /// The completed line after its address character (invalid UTF-8 gives `None`).
    pub(super) fn line(&self) -> Option<&str> {
        std::str::from_utf8(self.buf.get(1..)?).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn typed(input: &[u8], echo: Echo, address: u8) -> (Vec<String>, Vec<u8>) {
        let quirks = Quirks::default();
        let cx = Context {
            address: Some(address),
            echo,
            quirks: &quirks,
            max: 20,
        };
        let mut line = LineInput::new();
        let mut out = Vec::new();
        let mut lines = Vec::new();
        for &b in input {
            if line.feed(b, &cx, &mut out) {
                lines.push(line.line().unwrap().to_string());
            }
        }
        (lines, out)
    }

    #[test]
    fn character_echo_repeats_what_is_typed_and_erases_with_backspace() {
        let (lines, out) = typed(b"AGAX\x08P 1, 0\r", Echo::Characters, b'A');
        assert_eq!(lines, ["GAP 1, 0"]);
        assert_eq!(out, b"AGAX\x08 \x08P 1, 0\r");
    }

    #[test]
    fn line_echo_repeats_the_line_after_cr() {
        let (lines, out) = typed(b" aMST 0\r", Echo::Line, b'A');
        assert_eq!(lines, ["MST 0"]);
        assert_eq!(out, b"aMST 0\r");
    }

    #[test]
    fn no_echo_sends_nothing() {
        let (lines, out) = typed(b"AMST 0\r\n", Echo::Off, b'A');
        assert_eq!(lines, ["MST 0"]);
        assert!(out.is_empty());
    }

    #[test]
    fn lines_for_other_modules_are_ignored_silently() {
        let (lines, out) = typed(b"BGAP 1, 0\rAMST 0\r", Echo::Characters, b'A');
        assert_eq!(lines, ["MST 0"]);
        assert_eq!(out, b"AMST 0\r");
    }

    #[test]
    fn erasing_the_address_character_unaddresses_the_line() {
        let (lines, _) = typed(b"A\x08BMST 0\rA\x08AMST 0\r", Echo::Characters, b'A');
        assert_eq!(lines, ["MST 0"]);
    }

    #[test]
    fn overlong_lines_are_cut() {
        let (lines, out) = typed(b"A123456789012345678901234\r", Echo::Characters, b'A');
        assert_eq!(lines, ["1234567890123456789"]);
        assert_eq!(out.len(), 21);
    }
}
