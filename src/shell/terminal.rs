//! The terminal, for the shell's helpers that take it over: `:watch` and `:record` draw on it in
//! raw mode and stop on a key; `:plot` fits its width. Everything crossterm does for the shell is
//! here, so the commissioning core only sees a [`Screen`].
//!
//! [`TerminalScreen`] puts the terminal in raw mode (so a key arrives without Enter and Ctrl-C
//! arrives as a key) and restores it on every way out, panics included, through its `Drop`.

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
        for line in lines {
            // Raw mode: a line feed does not return the carriage.
            write!(self.out, "{line}\r\n")?;
        }
        self.drawn = lines.len() as u16;
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
