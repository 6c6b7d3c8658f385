//! The terminal, for the shell's helpers that take it over: `:watch` and `:record` draw on it in
//! raw mode and stop on a key; `:plot` fits its width. Everything crossterm does for the shell is
//! here, so the commissioning core only sees a [`Screen`].
//!
//! [`TerminalScreen`] puts the terminal in raw mode (so a key arrives without Enter and Ctrl-C
//! arrives as a key) and restores it on every way out, panics included, through its `Drop`.
//!
//! The terminal comes with the `cli` feature (crossterm); without it nothing is interactive, the
//! width is 80 columns and there is no screen to take over.

#[cfg(not(feature = "cli"))]
mod absent;
#[cfg(feature = "cli")]
mod crossterm_screen;

#[cfg(not(feature = "cli"))]
pub use absent::{TerminalScreen, interactive, width};
#[cfg(feature = "cli")]
pub use crossterm_screen::{TerminalScreen, interactive, width};
