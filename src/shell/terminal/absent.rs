//! No terminal faces (built without the `cli` feature): nothing is interactive.

use std::io::{self, Write};
use std::marker::PhantomData;
use std::time::Duration;

use crate::commission::watch::{Key, Screen};

/// Nothing is: a helper that needs keys or redraws says it needs a terminal.
pub fn interactive() -> bool {
    false
}

/// The width to draw in: 80 columns.
pub fn width() -> usize {
    80
}

/// No screen can be taken over without the terminal faces.
pub struct TerminalScreen<'a>(PhantomData<&'a mut dyn Write>);

impl<'a> TerminalScreen<'a> {
    /// Always refused: built without the terminal faces.
    pub fn new(_out: &'a mut dyn Write) -> io::Result<TerminalScreen<'a>> {
        Err(io::Error::new(
            io::ErrorKind::Unsupported,
            "no terminal screen: built without the terminal faces (the cli feature)",
        ))
    }
}

impl Screen for TerminalScreen<'_> {
    fn draw(&mut self, _lines: &[String]) -> io::Result<()> {
        Ok(())
    }

    fn key(&mut self, _timeout: Duration) -> io::Result<Option<Key>> {
        Ok(Some(Key::Stop))
    }
}
