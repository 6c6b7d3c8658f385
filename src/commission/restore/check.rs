//! What can be wrong with a snapshot before a restore sends anything: the file is of another
//! module type or dialect, names a motor or bank the module lacks, a name the module does not
//! have, a number that disagrees with its name, or a value the module's own validator refuses
//! (type, range, access). A restore refuses the whole file while any problem remains, so the
//! module is never left half-changed by a bad file; `--force` lets through the problems where
//! the name still says what to write (another module type, numbers, unknown names and motors,
//! which are then skipped), never a value that cannot be written.
//!
//! Each problem can be told without quoting the file (for scripts, which may be pointed at files
//! that are not theirs) or with the file's text (for people reading their own file).

use std::fmt;

/// One reason a snapshot cannot be restored as it is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// What it concerns.
    pub subject: Subject,
    /// What is wrong, in words that quote nothing from the file.
    pub what: String,
    /// The same with the file's text that shows it, where that helps.
    pub detail: Option<String>,
    /// Whether `--force` may go on regardless (writing by name, skipping what the module lacks).
    pub forceable: bool,
}

/// What a problem concerns.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Subject {
    /// The file as a whole.
    File,
    /// A section of the file (`axis.3`): numbers only, never file text.
    Section(String),
    /// A parameter the module has, by the module's name for it.
    Param(String),
    /// An entry whose name the module does not have: the name is the file's text.
    Entry {
        /// Its section (`axis.0`).
        section: String,
        /// The name as written in the file.
        name: String,
    },
}

impl Problem {
    /// A problem that `--force` may pass.
    pub fn forceable(subject: Subject, what: impl Into<String>, detail: Option<String>) -> Self {
        Problem {
            subject,
            what: what.into(),
            detail,
            forceable: true,
        }
    }

    /// A problem nothing may pass.
    pub fn fatal(subject: Subject, what: impl Into<String>, detail: Option<String>) -> Self {
        Problem {
            subject,
            what: what.into(),
            detail,
            forceable: false,
        }
    }

    /// The problem in one line; `quote` lets it show the file's text.
    pub fn text(&self, quote: bool) -> String {
        let what = match (&self.detail, quote) {
            (Some(detail), true) => detail,
            _ => &self.what,
        };
        match &self.subject {
            Subject::File => what.clone(),
            Subject::Section(section) => format!("[{section}]: {what}"),
            Subject::Param(name) => format!("{name}: {what}"),
            Subject::Entry { section, name } if quote => format!("[{section}] {name}: {what}"),
            Subject::Entry { section, .. } => format!("[{section}] an entry: {what}"),
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text(true))
    }
}

/// The problems that stop a restore: all of them, unless `force` (then only those it cannot
/// pass); empty when the restore may go on.
pub fn blocking(problems: &[Problem], force: bool) -> Vec<&Problem> {
    problems.iter().filter(|p| !force || !p.forceable).collect()
}

/// The message of a refused restore: every problem on a line of its own, and what `--force`
/// would do where it would help.
pub fn refusal(file: &str, target: &str, problems: &[&Problem], quote: bool) -> String {
    let mut message = format!(
        "{file} cannot be restored onto {target}; nothing was sent ({} problem{}):",
        problems.len(),
        if problems.len() == 1 { "" } else { "s" }
    );
    for problem in problems {
        message.push_str("\n  ");
        message.push_str(&problem.text(quote));
    }
    if problems.iter().all(|p| p.forceable) {
        message
            .push_str("\n--force restores by name anyway, skipping what the module does not have");
    }
    message
}
