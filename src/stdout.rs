//! Standard output, and what a closed one means. When the reader of a pipe goes away (`| head -1`,
//! `| true`) a Unix tool ends at its next write, quietly, and the shell sees 141 (128 + SIGPIPE).
//! tmclsh keeps SIGPIPE ignored (Rust's default) so that a run cut short still stops what it set
//! moving and closes its session; instead every write to stdout goes through [`Stdout`], which
//! notes a broken pipe here, and the binary decides the ending in one place (`cli::main`): no
//! message, exit [`EXIT`]. Bounded work already under way (a snapshot's file) may finish; a run of
//! lines or a script ends at that write.

use std::io::{self, Write};
use std::sync::atomic::{AtomicBool, Ordering};

use crate::exit::Exit;

/// SIGPIPE's number, for the exit code a pipe's reader going away gives.
const SIGPIPE: u8 = 13;

/// The exit code of a run whose stdout was closed: 141, as for a tool SIGPIPE ended.
pub const EXIT: Exit = Exit::Terminated(SIGPIPE);

static CLOSED: AtomicBool = AtomicBool::new(false);

/// Whether a write to stdout found its reader gone: the run ends quietly.
pub fn closed() -> bool {
    CLOSED.load(Ordering::Relaxed)
}

/// The process's stdout, noting a broken pipe for [`closed`]. Unlocked between writes: `sim`
/// prints from its console thread too.
#[derive(Debug, Default, Clone, Copy)]
pub struct Stdout;

impl Stdout {
    fn noted<T>(result: io::Result<T>) -> io::Result<T> {
        if matches!(&result, Err(e) if e.kind() == io::ErrorKind::BrokenPipe) {
            CLOSED.store(true, Ordering::Relaxed);
        }
        result
    }
}

impl Write for Stdout {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        Self::noted(io::stdout().write(buf))
    }

    fn write_all(&mut self, buf: &[u8]) -> io::Result<()> {
        // One lock for the whole buffer, so lines from two threads do not interleave.
        Self::noted(io::stdout().lock().write_all(buf))
    }

    fn write_fmt(&mut self, args: std::fmt::Arguments<'_>) -> io::Result<()> {
        self.write_all(args.to_string().as_bytes())
    }

    fn flush(&mut self) -> io::Result<()> {
        Self::noted(io::stdout().flush())
    }
}

/// Prints a line on stdout, as `println!` does, without its panic when the reader is gone.
pub fn line(text: &str) {
    let _ = Stdout.write_all(format!("{text}\n").as_bytes());
}

/// Output that ignores a closed pipe (`| head`): the work goes on (the file is written, the scan
/// finishes), the rest of the report is dropped; the run then ends quietly with [`EXIT`], since
/// the write underneath (through [`Stdout`]) noted the closed pipe.
pub struct PipeSafe<'a>(pub &'a mut dyn Write);

fn unbroken<T>(result: io::Result<T>, done: T) -> io::Result<T> {
    match result {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(done),
        other => other,
    }
}

impl Write for PipeSafe<'_> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        unbroken(self.0.write(buf), buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        unbroken(self.0.flush(), ())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_pipe_ends_with_141() {
        assert_eq!(EXIT.code(), 141);
    }

    struct Closed;

    impl Write for Closed {
        fn write(&mut self, _: &[u8]) -> io::Result<usize> {
            Err(io::ErrorKind::BrokenPipe.into())
        }

        fn flush(&mut self) -> io::Result<()> {
            Err(io::ErrorKind::PermissionDenied.into())
        }
    }

    #[test]
    fn pipe_safe_output_drops_what_a_closed_pipe_refuses_and_passes_other_errors() {
        let mut closed = Closed;
        let mut out = PipeSafe(&mut closed);
        assert!(writeln!(out, "dropped").is_ok());
        assert!(out.flush().is_err());
    }
}
