//! `:help` for any dialect: the helper list and the exit codes here, how lines are typed and each
//! command from the session's dialect.

use std::io::{self, Write};

use crate::dialect::helper::Helper;
use crate::dialect::{Dialect, Faces};
use crate::wrap::write_fitted;

use super::helpers;

/// `:help time`: the one grammar of times (`crate::duration`).
const TIMES: &str = "Times (:scan, :watch, :record, run --max-time, the simulator's advance) are a number with a unit \
(250ms, 2s, 1.5s, 1m) or a bare number of milliseconds (250 is 250ms), at most 7 days.";

/// The width of the usage column of the helper table.
const USAGE_COLUMN: usize = 30;

/// A helper's usage and summary in two columns after `indent`; a usage wider than its column
/// has a line of its own, so that every summary starts in the same column.
fn helper_rows(h: &Helper, indent: &str, width: Option<usize>) -> String {
    let summary_at = indent.len() + USAGE_COLUMN + 1;
    let row = |usage: &str| format!("{indent}{usage:<USAGE_COLUMN$} {}", h.summary);
    if h.usage.chars().count() <= USAGE_COLUMN {
        return crate::wrap::fit(&row(h.usage), summary_at, width);
    }
    format!(
        "{indent}{}\n{}",
        h.usage,
        crate::wrap::fit(&row(""), summary_at, width)
    )
}

/// Writes the help on `topic` (empty: the overview) in a session of `dialect` showing `faces`.
pub(super) fn write_help(
    topic: &str,
    dialect: &'static Dialect,
    faces: &(impl Faces + ?Sized),
    out: &mut dyn Write,
) -> io::Result<()> {
    let topic = topic.trim().trim_start_matches(':');
    if topic.is_empty() {
        faces.help_intro(out)?;
        writeln!(out, "Helper commands:")?;
        let width = crate::wrap::terminal_width();
        for h in helpers::available(dialect) {
            writeln!(out, "{}", helper_rows(h, "  ", width))?;
        }
        let more = format!("More: {}", faces.help_more());
        return writeln!(out, "\n{}", crate::wrap::fit(&more, 6, width));
    }
    let word = topic.to_ascii_lowercase();
    if word == "exit" {
        for line in [
            "Leave with :quit, quit or exit (anything typed after them is ignored: exit 1 leaves with the session's own exit code) or Ctrl-D; the modules go back to the mode they were found in.",
            "Ctrl-C stops a command and the motor; at the prompt it stops the motors this session set moving.",
            "Exit codes: 0 success, 1 device error or failed assertion, 2 refused before sending, 3 connection/timeout/lost link, 130 Ctrl-C.",
        ] {
            write_fitted(out, line, 0)?;
        }
        return Ok(());
    }
    if word == "time" || word == "times" {
        return write_fitted(out, TIMES, 0);
    }
    if faces.help_topic(&word, out)? {
        return Ok(());
    }
    if let Ok(h) = helpers::find(&word, dialect) {
        return writeln!(out, "{}", helper_rows(h, "", crate::wrap::terminal_width()));
    }
    if faces.help_command(&word, out)? {
        return Ok(());
    }
    if let Some(function) = crate::dialect::functions::find(dialect, topic) {
        let text = crate::script::registry::help_line(function);
        return write_fitted(out, &text, 0);
    }
    writeln!(out, "no help on '{topic}'; :help lists topics")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_summary_of_the_helper_table_starts_in_the_same_column() {
        for dialect in crate::dialect::all() {
            for h in helpers::available(dialect) {
                let rows = helper_rows(h, "  ", None);
                let summary = rows.lines().last().unwrap();
                let at = summary.find(h.summary).unwrap();
                assert_eq!(at, 2 + USAGE_COLUMN + 1, "{rows}");
                assert!(rows.starts_with(&format!("  {}", h.usage)), "{rows}");
            }
        }
    }
}
