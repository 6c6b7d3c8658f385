//! The terminal through crossterm.

use std::io::{self, IsTerminal, Write};
use std::time::{Duration, Instant};

use crossterm::event::{self, Event, KeyCode, KeyEventKind, KeyModifiers};
use crossterm::{cursor, queue, terminal};

use crate::commission::watch::{Key, Screen};
use crate::session::interrupt;

/// Whether a person is at a terminal: keys can stop a helper and frames can be redrawn.
pub fn interactive() -> bool {
    std::io::stdin().is_terminal() && std::io::stdout().is_terminal()
}

/// The width to draw in: the terminal's, or 80 columns when stdout is not one.
pub fn width() -> usize {
    if std::io::stdout().is_terminal() {
        terminal::size().map_or(80, |(w, _)| w as usize)
    } else {
        80
    }
}

/// `line` as the rows a terminal `width` columns wide shows it in (`width` 0: unknown, one row).
fn rows_of(line: &str, width: usize) -> Vec<String> {
    let chars: Vec<char> = line.chars().collect();
    if width == 0 || chars.len() <= width {
        return vec![line.to_string()];
    }
    chars.chunks(width).map(|c| c.iter().collect()).collect()
}

/// The terminal as a [`Screen`]: raw mode and a hidden cursor while it lives.
pub struct TerminalScreen<'a> {
    out: &'a mut dyn Write,
    drawn: u16,
}

impl<'a> TerminalScreen<'a> {
    /// Takes over the terminal (raw mode, hidden cursor) until dropped.
    pub fn new(out: &'a mut dyn Write) -> io::Result<TerminalScreen<'a>> {
        terminal::enable_raw_mode()?;
        let mut screen = TerminalScreen { out, drawn: 0 };
        queue!(&mut screen.out, cursor::Hide)?;
        Ok(screen)
    }
}

impl Screen for TerminalScreen<'_> {
    fn draw(&mut self, lines: &[String]) -> io::Result<()> {
        if self.drawn > 0 {
            queue!(&mut self.out, cursor::MoveToPreviousLine(self.drawn))?;
        }
        queue!(
            &mut self.out,
            cursor::MoveToColumn(0),
            terminal::Clear(terminal::ClearType::FromCursorDown)
        )?;
        // Each row is cut at the terminal's width here, so the rows drawn are the rows counted and
        // the next frame moves up exactly over this one, however narrow the terminal.
        let width = terminal::size().map_or(0, |(w, _)| usize::from(w));
        let mut rows = 0u16;
        for line in lines {
            for row in rows_of(line, width) {
                // Raw mode: a line feed does not return the carriage.
                write!(self.out, "{row}\r\n")?;
                rows = rows.saturating_add(1);
            }
        }
        self.drawn = rows;
        self.out.flush()
    }

    fn key(&mut self, timeout: Duration) -> io::Result<Option<Key>> {
        let deadline = Instant::now() + timeout;
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            if !event::poll(left.min(interrupt::SLICE))? {
                if interrupt::pending() {
                    return Ok(Some(Key::Interrupt));
                }
                if left.is_zero() {
                    return Ok(None);
                }
                continue;
            }
            if let Event::Key(key) = event::read()? {
                if key.kind != KeyEventKind::Press {
                    continue;
                }
                let ctrl_c =
                    key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL);
                return Ok(Some(if ctrl_c { Key::Interrupt } else { Key::Stop }));
            }
        }
    }
}

impl Drop for TerminalScreen<'_> {
    fn drop(&mut self) {
        let _ = queue!(&mut self.out, cursor::Show);
        let _ = self.out.flush();
        let _ = terminal::disable_raw_mode();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_line_takes_as_many_rows_as_the_width_needs() {
        assert_eq!(rows_of("abcdef", 0), ["abcdef"]);
        assert_eq!(rows_of("abcdef", 6), ["abcdef"]);
        assert_eq!(rows_of("abcdefg", 3), ["abc", "def", "g"]);
        assert_eq!(rows_of("é—é", 2), ["é—", "é"]);
        assert_eq!(rows_of("", 5), [""]);
    }
}
