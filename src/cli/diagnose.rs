//! One line of diagnostics on stderr: what every command says besides its output.

use crate::escape::escape_control;

/// One line of diagnostics on stderr, its device and input text escaped.
pub(crate) fn diagnose(message: &str) {
    eprintln!("tmclsh: {}", escape_control(message));
}
